//! Inputs the fuzzer (`fuzz/`, target `pipeline`) found, replayed in the stable suite: each once
//! panicked in the Close2GL stage.

use close2gl_core::glam::Vec3;
use close2gl_core::{
    Camera, Clipping, Close2glFrame, Mesh, PipelineSettings, Rasterizer, RenderMode, Viewport,
};
use close2gl_pipeline::{FastPipeline, textbook};

/// A triangle with coordinates near f32's limits (1e30, 3e38: finite numbers a model file may
/// hold) straddling the view volume of an ordinary camera. The distances to the planes overflow
/// and round the clipped polygon out of convexity; one plane then added several vertices and
/// Sutherland–Hodgman wrote past its 9-vertex array ("index out of bounds: the len is 9 but the
/// index is 9" in `clip.rs`, in release builds too). Such a piece is now dropped as clipped.
#[test]
fn a_triangle_near_f32_limits_clips_without_overrunning_the_polygon() {
    let camera = Camera::default()
        .looking_at(Vec3::new(0.3, 0.2, 2.0), Vec3::ZERO, Vec3::Y)
        .expect("a valid pose");
    let mesh = Mesh {
        face_normals: Vec::new(),
        name: "fuzz".into(),
        positions: vec![
            Vec3::new(-1e20, -1e30, 1.0),
            Vec3::new(-1e5, 1.0, 1e10),
            Vec3::new(1e20, -1e5, -3e38),
        ],
        normals: vec![Vec3::Z; 3],
        uvs: Vec::new(),
        triangles: vec![[0, 1, 2]],
    };
    let viewport = Viewport {
        width: 64,
        height: 64,
    };
    for mode in RenderMode::ALL {
        for close2gl_raster in Rasterizer::ALL {
            let settings = PipelineSettings {
                mode: *mode,
                clipping: Clipping::Full,
                backface_culling: false,
                close2gl_raster: *close2gl_raster,
                ..PipelineSettings::default()
            };
            let mut frame = Close2glFrame::default();
            FastPipeline::default().run(
                &mesh,
                &camera,
                &settings,
                viewport,
                &mut frame,
                &mut Default::default(),
            );
            let textbook = textbook::run(&mesh, &camera, &settings, viewport);
            assert_eq!(
                frame.counts, textbook.counts,
                "{mode:?} {close2gl_raster:?}"
            );
            assert_eq!(frame.counts.triangles_in, 1);
            for v in &frame.vertices {
                assert!(v.iter().all(|x| x.is_finite()), "{mode:?}: {v:?}");
            }
        }
    }
}

//! Inputs the fuzzer (`fuzz/`, target `pipeline`) found, replayed in the stable suite: each once
//! panicked in the software rasterizer.

use close2gl_core::glam::Vec3;
use close2gl_core::{
    Appearance, Camera, Mesh, PipelineSettings, Rasterizer, RenderMode, Shading, Viewport,
};

mod common;
use common::{Drawing, Scene};

/// Every mode through the Close2GL stage and the software rasterizer, as the app runs them: a
/// whole image, every triangle accounted for once, and the same pixels when drawn again (no
/// state left over from the broken input).
fn draw_every_mode(mesh: &Mesh, camera: &Camera, viewport: Viewport) {
    let scene = Scene {
        camera: *camera,
        ..Scene::new(mesh, viewport, None)
    };
    for mode in RenderMode::ALL {
        let pipeline = PipelineSettings {
            mode: *mode,
            backface_culling: false,
            close2gl_raster: Rasterizer::Software,
            ..PipelineSettings::default()
        };
        let look = Appearance {
            shading: Shading::Phong,
            ..Appearance::default()
        };
        let mut drawing = Drawing::default();
        drawing.draw(&scene, &pipeline, &look, false);
        let image = drawing.image.image.clone();
        let pixels = (viewport.width * viewport.height) as usize;
        assert_eq!(image.pixels.len(), pixels, "{mode:?}");
        let c = drawing.frame.counts;
        assert_eq!(
            c.drawn + c.culled + c.clipped,
            c.triangles_in,
            "{mode:?}: {c:?}"
        );
        assert_eq!(c.triangles_in, mesh.triangles.len(), "{mode:?}");
        drawing.draw(&scene, &pipeline, &look, true);
        assert_eq!(
            drawing.image.image, image,
            "{mode:?}: drawn again, recording fates"
        );
    }
}

fn mesh(positions: [Vec3; 3], triangles: Vec<[u32; 3]>) -> Mesh {
    Mesh {
        face_normals: Vec::new(),
        name: "fuzz".into(),
        positions: positions.to_vec(),
        normals: vec![Vec3::Z; 3],
        uvs: Vec::new(),
        triangles,
    }
}

/// The fuzzer's own find, minimised: a lens no config allows (hfov -31.5°, far -30.5 below
/// near 16) and degenerate triangles of two points 1e38 apart: clipping left vertices at
/// -2.2e38 pixels (finite, as the stage promises, but rounding noise), and setup's subtraction
/// of their fixed-point positions overflowed ("attempt to subtract with overflow" in
/// `setup.rs`; in release builds, a wrapped, meaningless triangle). A primitive with a corner
/// beyond the guard band (`GUARD_PX`, 2^21 pixels) is now not drawn.
#[test]
fn the_fuzzers_degenerate_triangles_under_a_nonsense_lens_do_not_overflow() {
    let camera = Camera {
        hfov: -31.5,
        vfov: 30.25,
        near: 16.0,
        far: -30.5,
        ..Camera::default()
            .looking_at(
                Vec3::new(1.25, 30.25, 0.0),
                Vec3::new(-1.0, 0.0, 1.504_632_8e-36),
                Vec3::new(-1e38, -30.5, -1e38),
            )
            .expect("a valid pose")
    };
    let mesh = mesh(
        [
            Vec3::new(0.0, -1.701_413_5e38, 0.0),
            Vec3::new(2.350_988_6e-38, 0.0, -1e38),
            Vec3::ZERO,
        ],
        vec![[0, 0, 1], [0, 1, 1], [1, 1, 1], [0, 0, 1], [1, 0, 0]],
    );
    let viewport = Viewport {
        width: 45,
        height: 52,
    };
    draw_every_mode(&mesh, &camera, viewport);
}

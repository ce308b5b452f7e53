//! Every path that draws Close2GL's view draws the same thing: the textbook path, the fast path
//! (exactly, to the bit) and a program without mistakes (the path a frame with a mistake takes;
//! to a hundredth of a pixel, since it computes its matrices and divides in double precision),
//! in every mode, with either clipping, culling on or off and either front face, on random
//! triangles around the camera (many cut by the near and side planes).

use close2gl_core::glam::Vec3;
use close2gl_core::{
    Camera, Clipping, Close2glFrame, Fates, FrontFace, Mesh, PipelineSettings, Rasterizer,
    RenderMode, Viewport,
};
use close2gl_pipeline::mistakes::Mistakes;
use close2gl_pipeline::program::{self, Program};
use close2gl_pipeline::{FastPipeline, textbook};
use proptest::prelude::*;

const VIEWPORT: Viewport = Viewport {
    width: 320,
    height: 200,
};

/// 6 units from the origin, looking at it; near 1, far 20.
fn camera() -> Camera {
    Camera {
        near: 1.0,
        far: 20.0,
        ..Camera::default()
    }
    .looking_at(Vec3::new(0.5, 0.2, 6.0), Vec3::ZERO, Vec3::Y)
    .expect("a valid pose")
}

fn one_triangle(corners: [Vec3; 3]) -> Mesh {
    Mesh {
        name: "one".into(),
        positions: corners.to_vec(),
        normals: vec![Vec3::Z; 3],
        uvs: Vec::new(),
        triangles: vec![[0, 1, 2]],
        face_normals: Vec::new(),
    }
}

fn corner() -> impl Strategy<Value = Vec3> {
    let axis = || -12.0f32..12.0;
    (axis(), axis(), axis()).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

fn settings() -> impl Strategy<Value = PipelineSettings> {
    (
        0usize..3,
        any::<bool>(),
        any::<bool>(),
        any::<bool>(),
        any::<bool>(),
    )
        .prop_map(|(mode, simple, culling, cw, software)| PipelineSettings {
            mode: [RenderMode::Points, RenderMode::Wireframe, RenderMode::Solid][mode],
            clipping: if simple {
                Clipping::Simple
            } else {
                Clipping::Full
            },
            backface_culling: culling,
            front_face: if cw { FrontFace::Cw } else { FrontFace::Ccw },
            close2gl_raster: if software {
                Rasterizer::Software
            } else {
                Rasterizer::Gpu
            },
            ..PipelineSettings::default()
        })
}

/// The fast path's frame and fates, recorded.
fn fast(mesh: &Mesh, settings: &PipelineSettings) -> (Close2glFrame, Fates) {
    let (mut frame, mut fates) = (Close2glFrame::default(), Fates::default());
    fates.record = true;
    FastPipeline::default().run(mesh, &camera(), settings, VIEWPORT, &mut frame, &mut fates);
    (frame, fates)
}

/// Whether two window positions are the same to a hundredth of a pixel (and what f32 keeps of
/// a position far off screen).
fn close(a: [f32; 2], b: [f32; 2]) -> bool {
    let near = |x: f32, y: f32| (x - y).abs() < 1e-2 + 1e-5 * y.abs();
    near(a[0], b[0]) && near(a[1], b[1])
}

/// Holds every path to the textbook's on one triangle; returns whether the program's was
/// compared (not when a corner lies on a plane, or the triangle is seen edge-on, to rounding:
/// there either answer is right).
fn every_path_agrees(mesh: &Mesh, settings: &PipelineSettings) -> Result<bool, TestCaseError> {
    let (textbook, textbook_fates) = textbook::run_recording(mesh, &camera(), settings, VIEWPORT);
    let (fast, fast_fates) = fast(mesh, settings);
    prop_assert_eq!(&fast.vertices, &textbook.vertices);
    // Debug text, so that the NaN areas of clipped triangles compare equal.
    let fates = |f: &Fates| format!("{:?}", f.triangles);
    prop_assert_eq!(fates(&fast_fates), fates(&textbook_fates));
    prop_assert_eq!(fast.counts, textbook.counts);
    let program = Program::for_view(&camera(), settings, VIEWPORT, Mistakes::NONE);
    let outcome = program.triangle(mesh, 0).expect("triangle 0");
    if outcome.near_a_plane || outcome.near_edge_on {
        return Ok(false);
    }
    let (view, view_fates) =
        program::view::run(mesh, &camera(), settings, VIEWPORT, Mistakes::NONE);
    prop_assert_eq!(
        view_fates.triangles[0].kind,
        textbook_fates.triangles[0].kind
    );
    prop_assert_eq!(view.counts, textbook.counts);
    prop_assert_eq!(view.vertices.len(), textbook.vertices.len());
    for (a, b) in view.vertices.iter().zip(&textbook.vertices) {
        prop_assert!(close(*a, *b), "{:?} against {:?}", a, b);
    }
    // With the software rasterizer, the same primitives, each with its triangle.
    prop_assert_eq!(view.raster.primitives.len(), fast.raster.primitives.len());
    prop_assert_eq!(&view.raster.triangles, &fast.raster.triangles);
    Ok(true)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2000))]

    #[test]
    fn every_path_draws_the_same(
        corners in [corner(), corner(), corner()],
        settings in settings(),
    ) {
        every_path_agrees(&one_triangle(corners), &settings)?;
    }
}

/// Issue 52's case: in point mode with full clipping, a triangle across the left plane shows
/// its two corners inside, and nothing on the border, whichever path draws it (the program's
/// path drew the two border corners of the clipped polygon too).
#[test]
fn a_triangle_across_the_left_plane_shows_two_points_in_every_path() {
    let mesh = one_triangle([
        Vec3::new(-30.0, 0.0, 0.0),
        Vec3::new(0.0, -1.0, 0.0),
        Vec3::new(0.0, 1.0, 0.0),
    ]);
    let settings = PipelineSettings {
        mode: RenderMode::Points,
        clipping: Clipping::Full,
        ..PipelineSettings::default()
    };
    assert!(every_path_agrees(&mesh, &settings).expect("every path agrees"));
    let (view, _) = program::view::run(&mesh, &camera(), &settings, VIEWPORT, Mistakes::NONE);
    assert_eq!(view.vertices.len(), 2);
}

//! The fast path writes exactly the textbook path's 2D buffer and fates on the bundled models and the
//! primitives, framed and from poses where the near plane and the view's sides cut the model.

use close2gl::config::Config;
use close2gl::core::glam::Vec3;
use close2gl::core::{
    Camera, Clipping, Close2glFrame, Fates, Mesh, ModelSource, PipelineSettings, RenderMode,
    Viewport,
};
use close2gl::pipeline::{FastPipeline, textbook};

fn scene(model: &str) -> (Mesh, Camera) {
    let config = Config {
        model: ModelSource::parse(model),
        ..Config::default()
    };
    let mut app = close2gl::build_app(
        &config,
        Viewport {
            width: 320,
            height: 240,
        },
    )
    .expect(model);
    let world = app.world_mut();
    let mesh = world.query::<&Mesh>().single(world).expect("mesh").clone();
    let camera = *world.query::<&Camera>().single(world).expect("camera");
    (mesh, camera)
}

#[test]
fn the_fast_path_equals_the_textbook_path_on_real_meshes() {
    let models = [
        "assets/knot.obj",
        "assets/cube.in",
        "assets/far_away.in",
        "sphere",
        "torus",
        "cone",
        "cylinder",
        "box",
    ];
    for model in models {
        let source = match model.contains('/') {
            true => format!("{}/{model}", env!("CARGO_MANIFEST_DIR")),
            false => model.to_string(),
        };
        let (mesh, framed) = scene(&source);
        let close_up = Camera {
            position: framed.target + framed.n * framed.distance() * 0.3,
            ..framed
        };
        let inside = Camera {
            position: framed.target,
            near: framed.near * 0.01,
            ..framed
        };
        let clipped_somewhere = [framed, close_up, inside]
            .iter()
            .map(|camera| fast_equals_textbook(model, &mesh, camera))
            .fold(false, |any, clipped| any | clipped);
        assert!(clipped_somewhere, "{model}: the poses exercise clipping");
    }
}

/// Both paths on every mode and clipping from `camera`; returns whether any triangle was clipped.
fn fast_equals_textbook(model: &str, mesh: &Mesh, camera: &Camera) -> bool {
    let mut clipped = false;
    for mode in [RenderMode::Solid, RenderMode::Wireframe, RenderMode::Points] {
        for clipping in [Clipping::Full, Clipping::Simple] {
            let settings = PipelineSettings {
                mode,
                clipping,
                ..PipelineSettings::default()
            };
            let viewport = Viewport {
                width: 640,
                height: 360,
            };
            let (slow, slow_fates) = textbook::run_recording(mesh, camera, &settings, viewport);
            let mut fast = Close2glFrame::default();
            let mut fates = Fates {
                record: true,
                ..Fates::default()
            };
            FastPipeline::default().run(mesh, camera, &settings, viewport, &mut fast, &mut fates);
            let pose = format!("{model} {mode:?} {clipping:?} from {:?}", camera.position);
            assert_eq!(slow, fast, "{pose}");
            assert_eq!(slow_fates.counts, fates.counts, "{pose}");
            // Debug text, so that the NaN areas of clipped triangles compare equal.
            let text = |f: &Fates| format!("{:?}", f.triangles);
            assert!(text(&slow_fates) == text(&fates), "fates differ: {pose}");
            clipped |= slow.counts.clipped > 0;
        }
    }
    clipped
}

/// A sphere big enough for several of the fast path's parallel chunks, seen from close by: each
/// chunk writes its own slice of the fates, and they must line up with the mesh's triangles.
#[test]
fn the_fast_paths_chunks_write_their_fates_in_mesh_order() {
    let mesh = close2gl_testkit::sphere(Vec3::ZERO, 3.0, 160, 160);
    assert!(mesh.triangles.len() > 40_000);
    let camera = Camera::default()
        .looking_at(Vec3::new(0.5, 0.3, 3.1), Vec3::new(3.0, 0.0, 0.0), Vec3::Y)
        .expect("a valid pose");
    let viewport = Viewport {
        width: 400,
        height: 300,
    };
    let settings = PipelineSettings::default();
    let (_, slow) = textbook::run_recording(&mesh, &camera, &settings, viewport);
    let mut fates = Fates {
        record: true,
        ..Fates::default()
    };
    let mut frame = Close2glFrame::default();
    FastPipeline::default().run(&mesh, &camera, &settings, viewport, &mut frame, &mut fates);
    let c = fates.counts;
    assert!(
        c.drawn > 0 && c.cut > 0 && c.clipped > 0 && c.culled > 0,
        "{c:?}"
    );
    assert_eq!(slow.counts, fates.counts);
    assert!(format!("{:?}", slow.triangles) == format!("{:?}", fates.triangles));
}

//! The viewer's side of a trace, headless: the probe on a trace names the mesh triangle the trace
//! drew at the pixel, close2gl's fate for it and what check found; the trace's camera and
//! settings become the viewer's.

use close2gl_check::program_for;
use close2gl_core::{Camera, Clipping, FrontFace, PipelineSettings, RenderMode, Viewport};
use close2gl_pipeline::mistakes::Mistakes;
use close2gl_pipeline::program::{ClipPlanes, ClipRule};
use close2gl_trace::view::probe::probe;
use close2gl_trace::view::{Shown, TraceView};
use close2gl_trace_format::{CameraLines, Piece, System2d, Trace};
use glam::{DVec2, DVec3};

/// The cube seen from +z, 4 units away, in a 100 × 100 window with y up; its 2D output as
/// close2gl draws it, but for triangle `moved`, drawn 30 units to the right.
fn trace(mesh: &close2gl_core::Mesh, moved: usize) -> Trace {
    let mut trace = Trace {
        file: "cube.trace".into(),
        model: None,
        triangles: None,
        window: (100, 100),
        ortho2d: System2d {
            left: 0.0,
            right: 100.0,
            bottom: 0.0,
            top: 100.0,
        },
        camera: CameraLines {
            position: DVec3::new(0.3, 0.2, 4.0),
            u: DVec3::X,
            v: DVec3::Y,
            n: DVec3::Z,
            hfov: 60.0,
            vfov: 60.0,
            near: 1.0,
            far: 10.0,
        },
        culling: Some(FrontFace::Ccw),
        winding: None,
        clipping: ClipRule::Full,
        planes: ClipPlanes::All,
        mode: Some(RenderMode::Solid),
        m: None,
        p: None,
        v: None,
        model_matrix: None,
        clip: Vec::new(),
        pieces: Vec::new(),
        drawn: None,
        ended: true,
    };
    let frame = program_for(&trace, Mistakes::NONE).frame(mesh);
    for (t, outcome) in frame.iter().enumerate().filter(|(_, o)| o.drawn()) {
        let shift = DVec2::new(if t == moved { 30.0 } else { 0.0 }, 0.0);
        trace.pieces.push(Piece {
            triangle: t,
            corners: outcome.polygon.iter().map(|&p| p + shift).collect(),
            depths: None,
            line: 10 + t,
        });
    }
    trace
}

#[test]
fn a_probe_where_the_trace_differs_names_the_triangle_its_fate_and_the_difference() {
    let mesh = close2gl_testkit::cube();
    let drawn: Vec<usize> = {
        let t = trace(&mesh, usize::MAX);
        t.pieces.iter().map(|p| p.triangle).collect()
    };
    let moved = drawn[0];
    let trace = trace(&mesh, moved);
    let report = close2gl_check::check(&mesh, &trace).expect("fits the cube");
    assert!(!report.agrees());
    let piece = trace
        .pieces
        .iter()
        .find(|p| p.triangle == moved)
        .expect("drawn");
    let centre = piece.corners.iter().sum::<DVec2>() / piece.corners.len() as f64;
    let view = TraceView {
        shown: Some(Shown { trace, report }),
        ..TraceView::default()
    };
    // The window is 100 × 100 with y up; the view's pixels count y down.
    let pixel = (centre.x as u32, (100.0 - centre.y) as u32);
    let viewport = Viewport {
        width: 100,
        height: 100,
    };
    let answer = probe(&view, pixel, viewport).expect("a trace is shown");
    assert_eq!(answer.triangle, Some(moved));
    let text = answer.lines.join("\n");
    assert!(
        text.contains(&format!("The trace drew triangle {moved} ")),
        "{text}"
    );
    assert!(
        text.contains(&format!(
            "Triangle {moved}: close2gl drew it; the trace differs: moved (window stage)"
        )),
        "{text}"
    );
}

#[test]
fn the_viewer_takes_the_traces_camera_and_settings() {
    let mesh = close2gl_testkit::cube();
    let trace = trace(&mesh, usize::MAX);
    let camera = close2gl_trace::view::trace_camera(&trace, &Camera::default(), &mesh);
    assert_eq!(camera.position, glam::Vec3::new(0.3, 0.2, 4.0));
    assert_eq!((camera.hfov, camera.near, camera.far), (60.0, 1.0, 10.0));
    let settings = close2gl_trace::view::trace_settings(&trace, PipelineSettings::default());
    assert_eq!(settings.clipping, Clipping::Full);
    assert!(settings.backface_culling);
    assert_eq!(settings.close2gl_raster, close2gl_core::Rasterizer::Gpu);
}

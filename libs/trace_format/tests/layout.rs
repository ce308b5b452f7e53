//! What the layout of a file does not change (line ends, tabs, runs of blanks, comments, a
//! byte-order mark, the spellings of numbers), what a file that leaves lines out reads as, and
//! that the values are the lines' as written.

mod common;

use close2gl_core::declaration::ClipRule;
use close2gl_core::{FrontFace, RenderMode};
use close2gl_trace_format::{Axis, Motion, SceneCamera, System2d, parse_scene, parse_trace};
use common::{SCENE, TRACE, replaced, scene_error, trace_error};
use glam::{DVec2, DVec3, DVec4};

#[test]
fn crlf_line_ends_read_as_lf_and_errors_keep_their_lines() {
    let text = format!("{TRACE}tri 0 0 0 1 0 0 1\nclip 0 0 0 0 1 1 0 0 1 0 1 0 1\nend\n");
    let crlf = text.replace('\n', "\r\n");
    assert_eq!(parse_trace(&crlf, "t"), parse_trace(&text, "t"));
    assert!(parse_trace(&crlf, "t").is_ok());
    let scene = format!("{SCENE}move u 1\n");
    assert_eq!(
        parse_scene(&scene.replace('\n', "\r\n"), "s"),
        parse_scene(&scene, "s")
    );
    let bad = format!("{TRACE}tri 3 1.0\n").replace('\n', "\r\n");
    assert_eq!(
        trace_error(&bad),
        "t.trace:11: expected 'tri T x0 y0 x1 y1 x2 y2', found 'tri 3 1.0'"
    );
}

#[test]
fn tabs_runs_of_blanks_comments_and_a_byte_order_mark_change_nothing() {
    let plain = parse_trace(TRACE, "t").unwrap();
    let messy = "\u{feff}# made by hand\n\n  close2gl-trace\t1   # the magic\n\
                 window\t\t640 480\n\
                 \tcamera position 0   0 5#no space before the comment\n\
                 camera u 1 0 0\n# between\ncamera v 0 1 0\n   \ncamera n 0 0 1\n\
                 camera hfov 60\t\ncamera vfov 45\ncamera near 1\ncamera far 100";
    assert_eq!(parse_trace(messy, "t").unwrap(), plain);
    let error = trace_error(&format!("{messy}\n\t tri  3\t1.0  # half a triangle"));
    assert_eq!(
        error,
        "t.trace:15: expected 'tri T x0 y0 x1 y1 x2 y2', found 'tri  3\t1.0'".replace('\t', "?")
    );
}

/// As in the C reader: a `\r` anywhere separates fields, so none can end in one (a model name
/// ending in `\r` would lose it when written out and read back).
#[test]
fn a_lone_carriage_return_is_a_blank() {
    let text = replaced(TRACE, 2, "window 640\r480\r\r\nmodel cow.in\r# comment");
    let trace = parse_trace(&text, "t").unwrap();
    assert_eq!(trace.window, (640, 480));
    assert_eq!(trace.model.as_deref(), Some("cow.in"));
    let error = trace_error(&replaced(TRACE, 2, "window 640\r"));
    assert_eq!(
        error,
        "t.trace:2: expected 'window W H', found 'window 640'"
    );
}

#[test]
fn every_spelling_printf_gives_reads() {
    let text = replaced(
        TRACE,
        3,
        "camera position 1. .5 -2.5E+02\nculling ccw\ntriangles +12\nmodel 007.in",
    );
    let trace = parse_trace(&text, "t").unwrap();
    assert_eq!(trace.camera.position, DVec3::new(1.0, 0.5, -250.0));
    assert_eq!(trace.triangles, Some((12, 5)));
    assert_eq!(trace.model.as_deref(), Some("007.in"));
    let text = replaced(TRACE, 10, "camera far 1e-0\ncamera near 5e-1");
    let trace = parse_trace(&replaced(&text, 9, ""), "t").unwrap();
    assert_eq!((trace.camera.near, trace.camera.far), (0.5, 1.0));
}

#[test]
fn a_trace_that_gives_only_what_it_must_reads_with_the_defaults() {
    let trace = parse_trace(TRACE, "t.trace").unwrap();
    assert_eq!(trace.file, "t.trace");
    assert_eq!(trace.window, (640, 480));
    assert_eq!(
        trace.ortho2d,
        System2d {
            left: 0.0,
            right: 640.0,
            bottom: 0.0,
            top: 480.0
        }
    );
    assert_eq!(trace.culling, None);
    assert_eq!(trace.clipping, ClipRule::Simple);
    assert_eq!(
        (trace.mode, trace.model, trace.triangles),
        (None, None, None)
    );
    assert_eq!((trace.m, trace.p, trace.v), (None, None, None));
    assert!(trace.clip.is_empty() && trace.pieces.is_empty() && !trace.ended);
    let c = trace.camera;
    assert_eq!(
        (c.position, c.u, c.v, c.n),
        (DVec3::Z * 5.0, DVec3::X, DVec3::Y, DVec3::Z)
    );
    assert_eq!((c.hfov, c.vfov, c.near, c.far), (60.0, 45.0, 1.0, 100.0));
}

#[test]
fn a_trace_of_only_the_camera_and_matrices_reads() {
    let text = format!(
        "{TRACE}matrix M 1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16\n\
         matrix V 320 0 0 320 0 240 0 240 0 0 0.5 0.5 0 0 0 1\nend\n"
    );
    let trace = parse_trace(&text, "t").unwrap();
    let m = trace.m.unwrap();
    // Row by row as written, whatever glam keeps inside.
    assert_eq!(m.row(0), glam::DVec4::new(1.0, 2.0, 3.0, 4.0));
    assert_eq!(m.row(3), glam::DVec4::new(13.0, 14.0, 15.0, 16.0));
    assert_eq!(m.col(0), glam::DVec4::new(1.0, 5.0, 9.0, 13.0));
    let v = trace.v.unwrap();
    assert_eq!(
        v.transform_point3(DVec3::new(-1.0, 1.0, 0.0)),
        DVec3::new(0.0, 480.0, 0.5)
    );
    assert_eq!(trace.p, None);
    assert!(trace.pieces.is_empty() && trace.ended);
}

#[test]
fn output_lines_keep_their_values_and_line_numbers() {
    let text = format!(
        "{TRACE}tri 4 0 0 1 0 0 1\n# a comment\ntri 4 0 0 -0.5 1 0 0.5 0 1 1\n\
         poly 9 4 0 0 1 0 1 1 0 1\npoly 9 3 0 0 0.1 1 0 0.2 0 1 0.3\n\
         clip 4 1 2 3 4 5 6 7 8 9 10 11 12\nmode points\nclipping none\nculling cw\n"
    );
    let trace = parse_trace(&text, "t").unwrap();
    let summary: Vec<_> = trace
        .pieces
        .iter()
        .map(|p| (p.triangle, p.corners.len(), p.depths.clone(), p.line))
        .collect();
    assert_eq!(
        summary,
        vec![
            (4, 3, None, 11),
            (4, 3, Some(vec![-0.5, 0.5, 1.0]), 13),
            (9, 4, None, 14),
            (9, 3, Some(vec![0.1, 0.2, 0.3]), 15),
        ]
    );
    assert_eq!(
        trace.pieces[1].corners,
        vec![DVec2::ZERO, DVec2::X, DVec2::Y]
    );
    assert_eq!(trace.pieces[2].corners[2], DVec2::ONE);
    let clip = &trace.clip[0];
    assert_eq!((clip.triangle, clip.line), (4, 16));
    assert_eq!(clip.corners[1], DVec4::new(5.0, 6.0, 7.0, 8.0));
    assert_eq!(trace.mode, Some(RenderMode::Points));
    assert_eq!(trace.clipping, ClipRule::Nothing);
    assert_eq!(trace.culling, Some(FrontFace::Cw));
}

#[test]
fn a_scene_reads_with_its_defaults_and_its_motions_in_order() {
    let scene = parse_scene(SCENE, "s.scene").unwrap();
    assert_eq!(scene.model, "cow.in");
    assert_eq!(scene.window, (640, 480));
    assert_eq!(
        scene.camera,
        SceneCamera::Framed {
            hfov: None,
            vfov: None,
            near: None,
            far: None
        }
    );
    assert_eq!((scene.culling, scene.clipping), (None, ClipRule::Simple));
    assert_eq!((scene.mode, scene.lookat), (None, None));
    assert!(scene.motions.is_empty());

    let text = format!(
        "{SCENE}camera vfov 40\ncamera far 50\nlookat 1 2 3\nmove n -1\nrotate u 10\n\
         orbit v 0.5\nmove u 2\nend\n"
    );
    let scene = parse_scene(&text, "s.scene").unwrap();
    assert_eq!(
        scene.camera,
        SceneCamera::Framed {
            hfov: None,
            vfov: Some(40.0),
            near: None,
            far: Some(50.0)
        }
    );
    assert_eq!(scene.lookat, Some(DVec3::new(1.0, 2.0, 3.0)));
    assert_eq!(
        scene.motions,
        vec![
            Motion::Move(Axis::N, -1.0),
            Motion::Rotate(Axis::U, 10.0),
            Motion::Orbit(Axis::V, 0.5),
            Motion::Move(Axis::U, 2.0),
        ]
    );
}

#[test]
fn a_scene_may_give_the_eight_camera_lines_in_any_order() {
    let text = replaced(
        SCENE,
        4,
        "camera far 10\ncamera n 0 0 1\ncamera near 0.1\ncamera hfov 50\ncamera vfov 40\n\
         camera v 0 1 0\ncamera u 1 0 0\ncamera position 1 2 3",
    );
    let SceneCamera::Given(camera) = parse_scene(&text, "s").unwrap().camera else {
        panic!("a framed camera");
    };
    assert_eq!(camera.position, DVec3::new(1.0, 2.0, 3.0));
    assert_eq!(
        (camera.hfov, camera.vfov, camera.near, camera.far),
        (50.0, 40.0, 0.1, 10.0)
    );
    // The far-beyond-near rule holds for a given camera too.
    let bad = text.replace("camera near 0.1", "camera near 10");
    assert_eq!(
        scene_error(&bad),
        "s.scene:6: expected 'camera near D' with D < far (10.0, line 4), found 'camera near 10'"
    );
}

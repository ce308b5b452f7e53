//! Every way a scene can be wrong, each a one-line error naming the file and the line. `SCENE`
//! is lines 1 to 4: magic, model, window, `camera framed`.

mod common;

use close2gl_trace_format::parse_scene;
use common::{SCENE, replaced, scene_error};

/// The eight camera lines, in place of `camera framed`.
const GIVEN: &str = "camera position 0 0 5
camera u 1 0 0
camera v 0 1 0
camera n 0 0 1
camera hfov 60
camera vfov 60
camera near 1
camera far 10";

fn check(cases: &[(String, &str)]) {
    for (text, error) in cases {
        assert_eq!(scene_error(text), *error, "{text}");
    }
}

fn plus(lines: &str) -> String {
    format!("{SCENE}{lines}\n")
}

const SCENE_LINE: &str = "expected a scene line (model, window, camera, culling, clipping, mode, \
                          lookat, move, rotate, orbit, shading, color, background, light, texture, \
                          filter or end)";

#[test]
fn the_first_line_is_the_magic_and_version() {
    check(&[
        (
            String::new(),
            "s.scene:1: expected 'close2gl-scene 1', found end of file",
        ),
        (
            replaced(SCENE, 1, "close2gl-scene 3"),
            "s.scene:1: expected 'close2gl-scene 1', found 'close2gl-scene 3' \
             (this close2gl reads version 1)",
        ),
        (
            common::TRACE.to_string(),
            "s.scene:1: expected 'close2gl-scene 1', found 'close2gl-trace 1' \
             (a trace file, not a scene)",
        ),
    ]);
}

#[test]
fn unknown_keys_and_wrong_shapes_are_errors() {
    check(&[
        (
            plus("tri 0 0 0 1 0 0 1"),
            &format!("s.scene:5: {SCENE_LINE}, found 'tri 0 0 0 1 0 0 1'"),
        ),
        (
            plus("zoom 2"),
            &format!("s.scene:5: {SCENE_LINE}, found 'zoom 2'"),
        ),
        (
            replaced(SCENE, 2, "model"),
            "s.scene:2: expected 'model PATH', found 'model'",
        ),
        (
            replaced(SCENE, 2, "model my cow.in"),
            "s.scene:2: expected 'model PATH', found 'model my cow.in'",
        ),
        (
            replaced(SCENE, 4, "camera framed tight"),
            "s.scene:4: expected 'camera framed', found 'camera framed tight'",
        ),
        (
            plus("lookat 0 0"),
            "s.scene:5: expected 'lookat X Y Z', found 'lookat 0 0'",
        ),
        (
            plus("lookat 0 0 z"),
            "s.scene:5: expected a number for Z in 'lookat X Y Z', found 'z'",
        ),
        (
            plus("move w 1"),
            "s.scene:5: expected 'move u|v|n D', found 'move w 1'",
        ),
        (
            plus("move u"),
            "s.scene:5: expected 'move u|v|n D', found 'move u'",
        ),
        (
            plus("rotate U 10"),
            "s.scene:5: expected 'rotate u|v|n DEG', found 'rotate U 10'",
        ),
        (
            plus("rotate u ten"),
            "s.scene:5: expected a number for DEG in 'rotate u|v|n DEG', found 'ten'",
        ),
        (
            plus("orbit n 1"),
            "s.scene:5: expected 'orbit u|v D', found 'orbit n 1'",
        ),
        (
            plus("orbit u 1 2"),
            "s.scene:5: expected 'orbit u|v D', found 'orbit u 1 2'",
        ),
        (
            plus("orbit v inf"),
            "s.scene:5: expected a number for D in 'orbit u|v D', found 'inf'",
        ),
        (
            plus("culling back"),
            "s.scene:5: expected 'culling off|ccw|cw', found 'culling back'",
        ),
    ]);
}

#[test]
fn a_framed_camera_takes_only_the_view_volume() {
    check(&[
        (
            plus("camera position 0 0 5"),
            "s.scene:5: expected only 'camera hfov|vfov|near|far' after 'camera framed' \
             (line 4), found 'camera position 0 0 5'",
        ),
        (
            plus("camera hfov 30\ncamera n 0 0 1"),
            "s.scene:6: expected only 'camera hfov|vfov|near|far' after 'camera framed' \
             (line 4), found 'camera n 0 0 1'",
        ),
        (
            replaced(SCENE, 4, "camera u 1 0 0\ncamera framed"),
            "s.scene:5: expected 'camera framed' or a pose (line 4), not both, \
             found 'camera framed'",
        ),
        (
            plus("camera framed"),
            "s.scene:5: expected one 'camera framed' line (the first is line 4), \
             found 'camera framed'",
        ),
        (
            plus("camera far 2\ncamera near 3"),
            "s.scene:6: expected 'camera near D' with D < far (2.0, line 5), \
             found 'camera near 3'",
        ),
        (
            plus("camera vfov 200"),
            "s.scene:5: expected 'camera vfov DEG' with DEG in (0, 180), found 'camera vfov 200'",
        ),
    ]);
}

#[test]
fn a_key_given_twice_is_an_error_at_the_second() {
    check(&[
        (
            plus("model other.obj"),
            "s.scene:5: expected one 'model' line (the first is line 2), found 'model other.obj'",
        ),
        (
            plus("window 1 1"),
            "s.scene:5: expected one 'window' line (the first is line 3), found 'window 1 1'",
        ),
        (
            plus("lookat 0 0 0\nlookat 1 1 1"),
            "s.scene:6: expected one 'lookat' line (the first is line 5), found 'lookat 1 1 1'",
        ),
        (
            plus("camera hfov 30\ncamera hfov 40"),
            "s.scene:6: expected one 'camera hfov' line (the first is line 5), \
             found 'camera hfov 40'",
        ),
        (
            replaced(SCENE, 4, &format!("{GIVEN}\ncamera v 0 1 0")),
            "s.scene:12: expected one 'camera v' line (the first is line 6), \
             found 'camera v 0 1 0'",
        ),
        (
            plus("mode solid\nmode points"),
            "s.scene:6: expected one 'mode' line (the first is line 5), found 'mode points'",
        ),
    ]);
    // Motions may repeat: they are applied in order.
    let scene = parse_scene(&plus("move n -1\nmove n -1\norbit u 1"), "s.scene").unwrap();
    assert_eq!(scene.motions.len(), 3);
}

#[test]
fn a_missing_required_line_is_named_at_the_last_line() {
    check(&[
        (
            replaced(SCENE, 2, ""),
            "s.scene:3: the scene ends without 'model PATH'",
        ),
        (
            replaced(SCENE, 3, ""),
            "s.scene:3: the scene ends without 'window W H'",
        ),
        (
            replaced(SCENE, 4, "# no camera"),
            "s.scene:4: the scene ends without 'camera framed' or 'camera position X Y Z'",
        ),
        (
            replaced(SCENE, 4, "camera hfov 50"),
            "s.scene:4: the scene ends without 'camera framed' or 'camera position X Y Z'",
        ),
        (
            replaced(&replaced(SCENE, 4, GIVEN), 8, ""),
            "s.scene:10: the scene ends without 'camera hfov DEG'",
        ),
        (
            replaced(&replaced(SCENE, 4, GIVEN), 4, ""),
            "s.scene:10: the scene ends without 'camera position X Y Z'",
        ),
    ]);
}

#[test]
fn nothing_but_comments_may_follow_end() {
    check(&[
        (
            plus("end\nmove u 1"),
            "s.scene:6: expected nothing after 'end' (line 5), found 'move u 1'",
        ),
        (
            plus("end\ncamera framed"),
            "s.scene:6: expected nothing after 'end' (line 5), found 'camera framed'",
        ),
    ]);
    assert!(parse_scene(&plus("end\n# done"), "s.scene").is_ok());
}

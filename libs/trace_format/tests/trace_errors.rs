//! Every way a trace can be wrong, each a one-line error naming the file and the line, as a
//! user reads it. `TRACE` is lines 1 to 10: magic, window, position, u, v, n, hfov, vfov, near,
//! far.

mod common;

use common::{TRACE, replaced, trace_error};

/// Checks each `(text, error)`.
fn check(cases: &[(String, &str)]) {
    for (text, error) in cases {
        assert_eq!(trace_error(text), *error, "{text}");
    }
}

/// [`TRACE`] and then `lines`.
fn plus(lines: &str) -> String {
    format!("{TRACE}{lines}\n")
}

#[test]
fn the_first_line_is_the_magic_and_version() {
    check(&[
        (
            String::new(),
            "t.trace:1: expected 'close2gl-trace 1', found end of file",
        ),
        (
            "# just a comment\n\n".into(),
            "t.trace:2: expected 'close2gl-trace 1', found end of file",
        ),
        (
            replaced(TRACE, 1, "close2gl-trace 2"),
            "t.trace:1: expected 'close2gl-trace 1', found 'close2gl-trace 2' \
             (this close2gl reads version 1)",
        ),
        (
            replaced(TRACE, 1, "# a scene\nclose2gl-scene 1"),
            "t.trace:2: expected 'close2gl-trace 1', found 'close2gl-scene 1' \
             (a scene file, not a trace)",
        ),
        (
            replaced(TRACE, 1, ""),
            "t.trace:1: expected 'close2gl-trace 1', found 'window 640 480'",
        ),
        (
            replaced(TRACE, 1, "close2gl-trace 1 extra"),
            "t.trace:1: expected 'close2gl-trace 1', found 'close2gl-trace 1 extra'",
        ),
        (
            replaced(TRACE, 1, "CLOSE2GL-TRACE 1"),
            "t.trace:1: expected 'close2gl-trace 1', found 'CLOSE2GL-TRACE 1'",
        ),
    ]);
}

#[test]
fn unknown_keys_are_errors() {
    check(&[
        (
            plus("color 1 0 0"),
            "t.trace:11: expected a trace line (model, triangles, window, ortho2d, camera, \
             culling, clipping, mode, matrix, clip, tri, poly, drawn or end), found 'color 1 0 0'",
        ),
        (
            plus("lookat 0 0 0"),
            "t.trace:11: expected a trace line (model, triangles, window, ortho2d, camera, \
             culling, clipping, mode, matrix, clip, tri, poly, drawn or end), found 'lookat 0 0 0'",
        ),
        (
            plus("camera framed"),
            "t.trace:11: expected 'camera position|u|v|n X Y Z' or \
             'camera hfov|vfov|near|far D', found 'camera framed'",
        ),
        (
            replaced(TRACE, 4, "camera"),
            "t.trace:4: expected 'camera position|u|v|n X Y Z' or \
             'camera hfov|vfov|near|far D', found 'camera'",
        ),
    ]);
}

#[test]
fn missing_and_extra_fields_are_errors() {
    check(&[
        (
            replaced(TRACE, 2, "window 640"),
            "t.trace:2: expected 'window W H', found 'window 640'",
        ),
        (
            replaced(TRACE, 4, "camera u 1 0 0 0"),
            "t.trace:4: expected 'camera u X Y Z', found 'camera u 1 0 0 0'",
        ),
        (
            replaced(TRACE, 7, "camera hfov"),
            "t.trace:7: expected 'camera hfov DEG', found 'camera hfov'",
        ),
        (
            plus("model"),
            "t.trace:11: expected 'model NAME', found 'model'",
        ),
        (
            plus("model my cow.in"),
            "t.trace:11: expected 'model NAME', found 'model my cow.in'",
        ),
        (
            plus("triangles"),
            "t.trace:11: expected 'triangles N', found 'triangles'",
        ),
        (
            plus("ortho2d 0 1 0"),
            "t.trace:11: expected 'ortho2d L R B T', found 'ortho2d 0 1 0'",
        ),
        (
            plus("culling front"),
            "t.trace:11: expected 'culling off|ccw|cw', found 'culling front'",
        ),
        (
            plus("clipping"),
            "t.trace:11: expected 'clipping simple|full|none', found 'clipping'",
        ),
        (
            plus("mode fill 1"),
            "t.trace:11: expected 'mode points|wireframe|solid', found 'mode fill 1'",
        ),
        (
            plus("end now"),
            "t.trace:11: expected 'end', found 'end now'",
        ),
        (
            plus("matrix Q 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1"),
            "t.trace:11: expected 'matrix M|P|V|model m00 m01 m02 m03 m10 … m33', \
             found 'matrix Q 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1'",
        ),
        (
            plus("matrix M 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0"),
            "t.trace:11: expected 'matrix M|P|V|model m00 m01 m02 m03 m10 … m33', \
             found 'matrix M 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0'",
        ),
        (
            plus("clip 0 0 0 0 1 0 0 0 1 0 0 0"),
            "t.trace:11: expected 'clip T x0 y0 z0 w0 x1 y1 z1 w1 x2 y2 z2 w2', \
             found 'clip 0 0 0 0 1 0 0 0 1 0 0 0'",
        ),
    ]);
}

#[test]
fn tri_and_poly_take_their_counts_of_numbers() {
    check(&[
        (
            plus("tri 3 1.0"),
            "t.trace:11: expected 'tri T x0 y0 x1 y1 x2 y2', found 'tri 3 1.0'",
        ),
        (
            plus("tri"),
            "t.trace:11: expected 'tri T x0 y0 x1 y1 x2 y2', found 'tri'",
        ),
        (
            plus("tri 3 0 0 0 1 0 0 0 1"),
            "t.trace:11: expected 'tri T x0 y0 z0 x1 y1 z1 x2 y2 z2', found 'tri 3 0 0 0 1 0 0 0 1'",
        ),
        (
            plus("tri 3 0 0 0 1 0 0 0 1 0 1"),
            "t.trace:11: expected 'tri T x0 y0 z0 x1 y1 z1 x2 y2 z2', \
             found 'tri 3 0 0 0 1 0 0 0 1 0 1'",
        ),
        (
            plus("poly 0"),
            "t.trace:11: expected 'poly T K x0 y0 x1 y1 …', found 'poly 0'",
        ),
        (
            plus("poly 0 2 0 0 1 1"),
            "t.trace:11: expected 'poly T K x0 y0 x1 y1 …' with K in 3..=64, \
             found 'poly 0 2 0 0 1 1'",
        ),
        (
            plus("poly 0 65 0 0"),
            "t.trace:11: expected 'poly T K x0 y0 x1 y1 …' with K in 3..=64, found 'poly 0 65 0 0'",
        ),
        (
            plus("poly 0 4 0 0 1 0 1 1"),
            "t.trace:11: expected 'poly T K' and 8 or 12 numbers (2K or 3K for K = 4), \
             found 'poly 0 4 0 0 1 0 1 1'",
        ),
        (
            plus("poly 0 3 0 0 1 0 1 1 0 1"),
            "t.trace:11: expected 'poly T K' and 6 or 9 numbers (2K or 3K for K = 3), \
             found 'poly 0 3 0 0 1 0 1 1 0 1'",
        ),
    ]);
}

#[test]
fn numbers_are_as_printf_prints_them() {
    check(&[
        (
            replaced(TRACE, 7, "camera hfov nan"),
            "t.trace:7: expected a number for DEG in 'camera hfov DEG', found 'nan'",
        ),
        (
            replaced(TRACE, 3, "camera position 0 inf 5"),
            "t.trace:3: expected a number for Y in 'camera position X Y Z', found 'inf'",
        ),
        (
            replaced(TRACE, 3, "camera position 0x10 0 5"),
            "t.trace:3: expected a number for X in 'camera position X Y Z', found '0x10'",
        ),
        (
            replaced(TRACE, 3, "camera position 0 0 5,0"),
            "t.trace:3: expected a number for Z in 'camera position X Y Z', found '5,0'",
        ),
        (
            replaced(TRACE, 10, "camera far 1e999"),
            "t.trace:10: expected a finite number for D in 'camera far D', found '1e999'",
        ),
        (
            plus("tri 0 0 0 1 0 0 x"),
            "t.trace:11: expected a number for y2 in 'tri T x0 y0 x1 y1 x2 y2', found 'x'",
        ),
        (
            plus("tri 0 0 0 0 1 0 0 0 1 -"),
            "t.trace:11: expected a number for z2 in 'tri T x0 y0 z0 x1 y1 z1 x2 y2 z2', found '-'",
        ),
        (
            plus("matrix P 1 0 0 0 0 1 0 0 0 0 1 . 0 0 0 1"),
            "t.trace:11: expected a number for m23 in 'matrix M|P|V|model m00 m01 m02 m03 m10 … m33', \
             found '.'",
        ),
        (
            plus("clip 0 0 0 0 1 0 0 0 1 0 0 0 NaN"),
            "t.trace:11: expected a number for w2 in 'clip T x0 y0 z0 w0 x1 y1 z1 w1 x2 y2 z2 w2', \
             found 'NaN'",
        ),
        (
            plus("ortho2d 0 1 0 1e"),
            "t.trace:11: expected a number for T in 'ortho2d L R B T', found '1e'",
        ),
    ]);
}

#[test]
fn counts_and_indices_are_non_negative_integers() {
    check(&[
        (
            replaced(TRACE, 2, "window 640.0 480"),
            "t.trace:2: expected a non-negative integer for W in 'window W H', found '640.0'",
        ),
        (
            replaced(TRACE, 2, "window 640 4.8e2"),
            "t.trace:2: expected a non-negative integer for H in 'window W H', found '4.8e2'",
        ),
        (
            plus("tri -1 0 0 1 0 0 1"),
            "t.trace:11: expected a non-negative integer for T in 'tri T x0 y0 x1 y1 x2 y2', \
             found '-1'",
        ),
        (
            plus("tri 99999999999999999999 0 0 1 0 0 1"),
            "t.trace:11: expected an integer of at most 18446744073709551615 for T in \
             'tri T x0 y0 x1 y1 x2 y2', found '99999999999999999999'",
        ),
        (
            plus("poly 0 3.0 0 0 1 0 0 1"),
            "t.trace:11: expected a non-negative integer for K in 'poly T K x0 y0 x1 y1 …', \
             found '3.0'",
        ),
        (
            plus("triangles 1e3"),
            "t.trace:11: expected a non-negative integer for N in 'triangles N', found '1e3'",
        ),
        (
            plus("clip +-2 0 0 0 1 0 0 0 1 0 0 0 1"),
            "t.trace:11: expected a non-negative integer for T in \
             'clip T x0 y0 z0 w0 x1 y1 z1 w1 x2 y2 z2 w2', found '+-2'",
        ),
    ]);
}

#[test]
fn out_of_range_values_are_errors() {
    let window = "expected 'window W H' with W and H in 1..=16384";
    check(&[
        (
            replaced(TRACE, 2, "window 0 480"),
            &format!("t.trace:2: {window}, found 'window 0 480'"),
        ),
        (
            replaced(TRACE, 2, "window 640 16385"),
            &format!("t.trace:2: {window}, found 'window 640 16385'"),
        ),
        (
            replaced(TRACE, 2, "window 4294967296 1"),
            &format!("t.trace:2: {window}, found 'window 4294967296 1'"),
        ),
        (
            replaced(TRACE, 7, "camera hfov 0"),
            "t.trace:7: expected 'camera hfov DEG' with DEG in (0, 180), found 'camera hfov 0'",
        ),
        (
            replaced(TRACE, 8, "camera vfov 180"),
            "t.trace:8: expected 'camera vfov DEG' with DEG in (0, 180), found 'camera vfov 180'",
        ),
        (
            replaced(TRACE, 9, "camera near -0.0"),
            "t.trace:9: expected 'camera near D' with D > 0, found 'camera near -0.0'",
        ),
        (
            replaced(TRACE, 10, "camera far 1"),
            "t.trace:10: expected 'camera far D' with D > near (1.0, line 9), \
             found 'camera far 1'",
        ),
        (
            replaced(TRACE, 9, "camera far 0.5\ncamera near 1"),
            "t.trace:10: expected 'camera near D' with D < far (0.5, line 9), \
             found 'camera near 1'",
        ),
        (
            replaced(TRACE, 9, "camera far -1\ncamera near 1"),
            "t.trace:9: expected 'camera far D' with D > 0, found 'camera far -1'",
        ),
        (
            plus("ortho2d 0 1 1 1"),
            "t.trace:11: expected 'ortho2d L R B T' with L != R and B != T, \
             found 'ortho2d 0 1 1 1'",
        ),
        (
            plus("ortho2d 2 2 0 1"),
            "t.trace:11: expected 'ortho2d L R B T' with L != R and B != T, \
             found 'ortho2d 2 2 0 1'",
        ),
    ]);
    for (n, ok) in [
        (2, "window 1 16384"),
        (7, "camera hfov 179.99"),
        (8, "camera vfov 0.01"),
    ] {
        let text = replaced(TRACE, n, ok);
        assert!(
            close2gl_trace_format::parse_trace(&text, "t.trace").is_ok(),
            "{ok}"
        );
    }
}

#[test]
fn a_key_given_twice_is_an_error_at_the_second() {
    let twice = |line: &str, key: &str, first: usize| {
        let (text, second) = if first <= 10 {
            (plus(line), 11)
        } else {
            (plus(&format!("{line}\n{line}")), 12)
        };
        let error = format!(
            "t.trace:{second}: expected one '{key}' line (the first is line {first}), found '{line}'"
        );
        (text, error)
    };
    let cases = [
        twice("window 3 3", "window", 2),
        twice("camera position 0 0 1", "camera position", 3),
        twice("camera u 1 0 0", "camera u", 4),
        twice("camera v 0 1 0", "camera v", 5),
        twice("camera n 0 0 1", "camera n", 6),
        twice("camera hfov 30", "camera hfov", 7),
        twice("camera vfov 30", "camera vfov", 8),
        twice("camera near 2", "camera near", 9),
        twice("camera far 50", "camera far", 10),
        twice("model a.in", "model", 11),
        twice("triangles 3", "triangles", 11),
        twice("ortho2d 0 1 0 1", "ortho2d", 11),
        twice("culling off", "culling", 11),
        twice("clipping simple", "clipping", 11),
        twice("mode solid", "mode", 11),
        twice("matrix M 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1", "matrix M", 11),
        twice("matrix P 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1", "matrix P", 11),
        twice("matrix V 1 0 0 0 0 1 0 0 0 0 1 0 0 0 0 1", "matrix V", 11),
        twice("clip 5 0 0 0 1 1 0 0 1 0 1 0 1", "clip 5", 11),
    ];
    let cases: Vec<(String, &str)> = cases.iter().map(|(t, e)| (t.clone(), e.as_str())).collect();
    check(&cases);
    // Different triangles' clip lines, and several pieces for one triangle, are fine.
    let text = plus(
        "clip 5 0 0 0 1 1 0 0 1 0 1 0 1\nclip 6 0 0 0 1 1 0 0 1 0 1 0 1\n\
                     tri 5 0 0 1 0 0 1\ntri 5 0 0 1 0 0 1",
    );
    assert!(close2gl_trace_format::parse_trace(&text, "t.trace").is_ok());
}

#[test]
fn nothing_but_comments_may_follow_end() {
    check(&[
        (
            plus("end\n\nwindow 3 3"),
            "t.trace:13: expected nothing after 'end' (line 11), found 'window 3 3'",
        ),
        (
            plus("end\nend"),
            "t.trace:12: expected nothing after 'end' (line 11), found 'end'",
        ),
        (
            plus("end\ncolor 1"),
            "t.trace:12: expected nothing after 'end' (line 11), found 'color 1'",
        ),
    ]);
    let text = plus("end\n# a comment\n   \n\t# another");
    assert!(
        close2gl_trace_format::parse_trace(&text, "t.trace")
            .unwrap()
            .ended
    );
}

#[test]
fn a_missing_required_line_is_named_at_the_last_line() {
    check(&[
        (
            replaced(TRACE, 2, ""),
            "t.trace:9: the trace ends without 'window W H'",
        ),
        (
            replaced(TRACE, 4, "") + "# trailing comment\n\n",
            "t.trace:11: the trace ends without 'camera u X Y Z'",
        ),
        (
            replaced(&replaced(TRACE, 10, ""), 5, ""),
            "t.trace:8: the trace ends without 'camera v X Y Z'",
        ),
        (
            replaced(TRACE, 10, "end"),
            "t.trace:10: the trace ends without 'camera far D'",
        ),
        (
            "close2gl-trace 1\nwindow 1 1".into(),
            "t.trace:2: the trace ends without 'camera position X Y Z'",
        ),
    ]);
}

#[test]
fn errors_quote_long_or_strange_lines_on_one_line() {
    let long = format!("tri 0 {}", "1 ".repeat(100));
    let error = trace_error(&plus(&long));
    assert!(
        error.starts_with(
            "t.trace:11: expected 'tri T x0 y0 z0 x1 y1 z1 x2 y2 z2', found 'tri 0 1 1"
        )
    );
    assert!(error.ends_with("…'"), "{error}");
    let error = trace_error(&plus("color\u{7}\u{1b}[31m red"));
    assert_eq!(
        error,
        "t.trace:11: expected a trace line (model, triangles, window, ortho2d, camera, culling, \
         clipping, mode, matrix, clip, tri, poly, drawn or end), found 'color??[31m red'"
    );
}

#[test]
fn the_additions_within_version_1_are_read_and_their_faults_named() {
    let read = |lines: &str| close2gl_trace_format::parse_trace(&plus(lines), "t.trace").unwrap();
    let trace = read("culling cw ndc\nclipping full near_far\ndrawn 0");
    assert_eq!(trace.drawn, Some((0, 13)));
    assert!(trace.gives_output());
    check(&[
        (
            plus("tri 0 0 0 1 0 0 1\ndrawn 2"),
            "t.trace:12: expected 'drawn 1' (the trace has 1 'tri' and 'poly' lines), \
             found 'drawn 2'",
        ),
        (
            plus("culling off ndc"),
            "t.trace:11: expected 'culling ccw|cw ndc|window', found 'culling off ndc'",
        ),
        (
            plus("culling ccw screen"),
            "t.trace:11: expected 'culling ccw|cw ndc|window', found 'culling ccw screen'",
        ),
        (
            plus("clipping none near_far"),
            "t.trace:11: expected 'clipping simple|full near_far', found 'clipping none near_far'",
        ),
        (
            plus("drawn -1"),
            "t.trace:11: expected a non-negative integer for N in 'drawn N', found '-1'",
        ),
    ]);
}

#[test]
fn a_scene_does_not_say_where_a_program_culls() {
    let scene = format!("{}culling ccw ndc\n", common::SCENE);
    let error = common::scene_error(&scene);
    assert!(error.contains("expected 'culling off|ccw|cw'"), "{error}");
}

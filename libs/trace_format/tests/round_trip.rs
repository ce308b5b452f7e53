//! Writing a trace or a scene and reading it back gives the same value, bit for bit: fixed
//! files with every kind of line, and random values of every kind the readers produce.

mod common;

use close2gl_trace_format::{Trace, parse_scene, parse_trace};
use common::{SCENE, TRACE, without_lines};
use proptest::prelude::*;

/// A trace with every kind of line, in an order the writer does not use, with comments.
const FULL: &str = "# written by hand
close2gl-trace 1
tri 7 0.5 0.5 100 0.5 0.5 100
model cow.in
triangles 5804
window 640 480
ortho2d 0 1 0 1
camera position 0.1 -2.5E+02 1e-3
camera u 1 0 0
camera v 0 1 0
camera n 0 0 1
camera hfov 60
camera vfov 45.5
camera near .5
camera far 100.
culling cw
clipping full
mode wireframe
matrix M 1 0 0 0 0 1 0 0 0 0 1 -5 0 0 0 1
matrix P 1.299 0 0 0 0 1.732 0 0 0 0 -1.01 -1.005 0 0 -1 0
matrix V 320 0 0 320 0 240 0 240 0 0 0.5 0.5 0 0 0 1
clip 7 0 0 0 1 1 0 0 1 0 1 0 1
clip 2 -0.0 0 0 1 1 0 0 1 0 1 0 1
poly 7 4 0 0 -0.5 1 0 -0.5 1 1 -0.5 0 1 -0.5
tri 2 0 0 0.1 1 0 0.2 0 1 0.3
end
";

/// `trace` written and read back; equal but for the line numbers, which become the written
/// text's, and writing that again gives the very same text.
fn written_back(trace: &Trace) -> Trace {
    let text = trace.to_text();
    let back = parse_trace(&text, &trace.file).unwrap_or_else(|e| panic!("{e}\n{text}"));
    assert_eq!(back.to_text(), text);
    back
}

#[test]
fn a_trace_with_every_kind_of_line_reads_back_the_same() {
    let trace = parse_trace(FULL, "full.trace").unwrap();
    let back = written_back(&trace);
    assert_eq!(without_lines(back.clone()), without_lines(trace));
    // In the writer's own layout, the line numbers are the same too.
    assert_eq!(written_back(&back), back);
}

#[test]
fn the_smallest_trace_and_scene_read_back_the_same() {
    let trace = parse_trace(TRACE, "t.trace").unwrap();
    assert_eq!(written_back(&trace), trace);
    let scene = parse_scene(SCENE, "s.scene").unwrap();
    assert_eq!(parse_scene(&scene.to_text(), "s.scene").unwrap(), scene);
}

#[test]
fn a_scene_with_every_kind_of_line_reads_back_the_same() {
    for text in [
        format!("{SCENE}camera hfov 50\ncamera far 20\nlookat 0 1 -2\nmove n -1\nrotate u 10\n"),
        "close2gl-scene 1\nmodel ../models/cow.in\nwindow 800 600\nculling ccw\nclipping none\n\
         mode points\ncamera position 1 2 3\ncamera u 1 0 0\ncamera v 0 1 0\ncamera n 0 0 1\n\
         camera hfov 60\ncamera vfov 60\ncamera near 0.1\ncamera far 1000\norbit u 2.5\n\
         orbit v -1e-3\nend\n"
            .to_string(),
    ] {
        let scene = parse_scene(&text, "s.scene").unwrap();
        let written = scene.to_text();
        let back = parse_scene(&written, "s.scene").unwrap();
        assert_eq!(back, scene, "{written}");
        assert_eq!(back.to_text(), written);
    }
}

#[test]
fn numbers_keep_every_bit() {
    let odd = [
        0.1,
        -0.0,
        1e-300,
        5e-324,
        f64::MAX,
        -f64::MIN_POSITIVE,
        1.0 / 3.0,
    ];
    let mut trace = parse_trace(TRACE, "t.trace").unwrap();
    trace.camera.position = glam::DVec3::new(odd[0], odd[1], odd[2]);
    trace.camera.u = glam::DVec3::new(odd[3], odd[4], odd[5]);
    trace.camera.near = odd[6];
    let back = written_back(&trace).camera;
    let bits = |v: glam::DVec3| v.to_array().map(f64::to_bits);
    assert_eq!(bits(back.position), bits(trace.camera.position));
    assert_eq!(bits(back.u), bits(trace.camera.u));
    assert_eq!(back.near.to_bits(), odd[6].to_bits());
}

proptest! {
    #[test]
    fn any_trace_reads_back_the_same(trace in common::trace()) {
        let back = written_back(&trace);
        prop_assert_eq!(without_lines(back), trace);
    }

    #[test]
    fn any_scene_reads_back_the_same(scene in common::scene()) {
        let text = scene.to_text();
        let back = parse_scene(&text, &scene.file);
        prop_assert_eq!(back, Ok(scene), "{}", text);
    }
}

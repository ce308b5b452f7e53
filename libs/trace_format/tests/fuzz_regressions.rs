//! The inputs the fuzzers (`fuzz/fuzz_targets/trace_parser.rs`, `scene_parser.rs`) found, cut to
//! what made them fail, replayed with the fuzzers' checks.

mod common;

use close2gl_trace_format::{parse_scene, parse_trace};
use common::{SCENE, TRACE, without_lines};

/// The trace reads, and written out it reads back the same but for the line numbers.
fn reads_back(text: &str) {
    let trace = parse_trace(text, "f").unwrap();
    let written = trace.to_text();
    let back = parse_trace(&written, "f").unwrap();
    assert_eq!(back.to_text(), written);
    assert_eq!(without_lines(back), without_lines(trace));
}

/// A model name ending in `\r` (before `\r\n`, or before a comment) lost it when written out,
/// where that `\r` became part of the line's end: `\r` is a blank now, as in the C reader.
#[test]
fn a_model_name_ending_in_carriage_returns() {
    reads_back(&format!("{TRACE}model cow.in\r\r\r\r\n"));
    let text = SCENE.replace("model cow.in", "model /da\0\u{1}\r#\0\0\0in");
    let scene = parse_scene(&text, "f").unwrap();
    assert_eq!(scene.model, "/da\0\u{1}");
    assert_eq!(parse_scene(&scene.to_text(), "f").unwrap(), scene);
}

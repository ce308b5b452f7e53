//! Every way a raster trace can be wrong is a one-line error naming the file and the line (or,
//! for its buffers, the file), and nothing half-read.

use close2gl_trace_format::raster::images::{read_pfm, read_ppm};
use close2gl_trace_format::{RasterFrame, parse_raster_trace};

const HEAD: &str = "close2gl-raster 1\nwindow 4 3\nframebuffer f.ppm\nattributes window uv\n";

fn error(text: &str) -> String {
    parse_raster_trace(text, "r.trace")
        .expect_err(text)
        .to_string()
}

#[test]
fn a_good_trace_reads_whole() {
    let text = format!("{HEAD}tri 7 0 0 0.5 1 0 0 4 0 0.5 1 1 0 0 3 0.5 1 0 1\ndrawn 1\nend\n");
    let trace = parse_raster_trace(&text, "r.trace").expect("a good trace");
    assert_eq!(trace.triangles.len(), 1);
    assert_eq!(trace.triangles[0].mesh, 7);
    assert_eq!(trace.triangles[0].corners[1].uv, [1.0, 0.0]);
    assert!(trace.y_up);
}

#[test]
fn each_fault_names_its_line_and_what_was_expected() {
    let cases = [
        (
            "close2gl-trace 1\n".to_string(),
            "r.trace:1: expected 'close2gl-raster 1', found 'close2gl-trace 1' (a trace file, not a raster trace)",
        ),
        (
            format!("{HEAD}tri 0 1 2 3\n"),
            "r.trace:5: expected 'tri T and 3 corners of window uv (6 numbers each)', found 'tri 0 1 2 3'",
        ),
        (
            "close2gl-raster 1\nwindow 4 3\ntri 0 1\n".into(),
            "r.trace:3: expected an 'attributes' line before the first 'tri', found 'tri 0 1'",
        ),
        (
            format!("{HEAD}shading gouraud\n"),
            "r.trace:5: expected 'shading none|gouraud_ad|gouraud_ads|phong', found 'shading gouraud'",
        ),
        (
            format!("{HEAD}origin middle\n"),
            "r.trace:5: expected 'origin bottom-left|top-left', found 'origin middle'",
        ),
        (
            format!("{HEAD}subpixel 40\n"),
            "r.trace:5: expected 'subpixel B' with B in 0..=16, found 'subpixel 40'",
        ),
        (
            format!("{HEAD}attributes window\n"),
            "r.trace:5: expected one 'attributes' line (the first is line 4), found 'attributes window'",
        ),
        (
            "close2gl-raster 1\nwindow 4 3\nattributes uv window\n".into(),
            "r.trace:3: expected 'attributes window [rgb] [eye] [normal] [uv]', found 'attributes uv window'",
        ),
        (
            format!("{HEAD}drawn 2\n"),
            "r.trace:5: expected 2 tri lines (as 'drawn 2' on line 5 says), found 0",
        ),
        (
            format!("{HEAD}end\nwindow 1 1\n"),
            "r.trace:6: expected nothing after 'end' (line 5), found 'window 1 1'",
        ),
        (
            "close2gl-raster 1\nwindow 4 3\nattributes window\n".into(),
            "r.trace:3: the raster trace ends without 'framebuffer PATH'",
        ),
        (
            format!("{HEAD}shading phong\n"),
            "r.trace:5: the raster trace ends without 'light X Y Z' (the shading is lit)",
        ),
        (
            format!("{HEAD}fog on\n"),
            "r.trace:5: expected a raster trace line (model, window, origin, subpixel, shading, color, background, light, matrix, lighting, texture, filter, framebuffer, depthbuffer, attributes, tri, drawn or end), found 'fog on'",
        ),
    ];
    for (text, expected) in cases {
        assert_eq!(error(&text), expected, "{text}");
    }
}

#[test]
fn buffers_that_do_not_fit_the_window_are_errors_naming_their_file() {
    let trace =
        parse_raster_trace(&format!("{HEAD}depthbuffer d.pfm\n"), "r.trace").expect("a trace");
    let frame = RasterFrame::read_with(trace.clone(), |name| match name {
        "f.ppm" => Ok(b"P6\n2 2\n255\n\0\0\0\0\0\0\0\0\0\0\0\0".to_vec()),
        _ => Err("no such file".into()),
    });
    let error = frame
        .expect_err("a 2×2 framebuffer for a 4×3 window")
        .to_string();
    assert_eq!(
        error,
        "f.ppm:0: expected 4×3 pixels (the trace's window), found 2×2"
    );
    let missing = RasterFrame::read_with(trace, |_| Err("no such file".into()));
    assert_eq!(
        missing.expect_err("no files").to_string(),
        "f.ppm:0: cannot read: no such file"
    );
    assert!(
        read_pfm(b"Pf\n1 1\n0\n", "d.pfm").is_err(),
        "a PFM scale of 0"
    );
    assert!(
        read_ppm(b"P6\n0 1\n255\n", "f.ppm").is_err(),
        "a PPM of no pixels"
    );
}

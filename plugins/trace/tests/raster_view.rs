//! A raster trace in the viewer, headless, from `examples/raster/raster.c` built with a catalogue
//! mistake (so that the program's frame and close2gl's differ): the Close2GL view's image is the
//! program's framebuffer, the reference's close2gl's drawing of the same triangles, the panel
//! has check's raster report, a bad raster trace leaves what was shown with its error, and the
//! probe answers with check's probe of the pixel.

use std::path::{Path, PathBuf};

use close2gl_check::raster::{self, report};
use close2gl_core::{
    App, Camera, CameraRequest, Close2glFrame, RasterMistakes, TraceFindings, ViewImages, Viewport,
};
use close2gl_testkit::student::{self, mistake_flag};
use close2gl_testkit::{TempDir, cube, world_with};
use close2gl_trace::view::raster::raster_probe;
use close2gl_trace::view::{TraceRequest, TraceView};
use close2gl_trace_format::read_raster_frame;

/// `raster.c` with `mistake` drawing the square scene into `dir/name.raster`.
fn raster_trace(dir: &Path, name: &str, mistake: &str) -> PathBuf {
    student::raster_trace(dir, name, &[&mistake_flag(mistake)], "square.scene")
}

/// The trace plugin on a bare world, asked to show `path`: one frame run.
fn app_showing(path: &Path) -> App {
    let viewport = Viewport {
        width: 128,
        height: 128,
    };
    let mut app = world_with(cube(), Camera::default(), viewport);
    app.init_resource::<CameraRequest>()
        .init_resource::<Close2glFrame>()
        .add_plugins(close2gl_trace::TracePlugin);
    open(&mut app, path);
    app
}

fn open(app: &mut App, path: &Path) {
    app.world_mut().resource_mut::<TraceRequest>().0 = Some(path.to_path_buf());
    app.update();
}

#[test]
fn a_raster_trace_shows_the_programs_frame_beside_close2gls_and_checks_report() {
    let dir = TempDir::new("raster_view_open");
    let path = raster_trace(&dir.0, "swapped", "channels_swapped");
    let app = app_showing(&path);
    let frame = read_raster_frame(&path).expect("the program's trace reads");
    let report = raster::check_raster(&frame);
    let redraw = raster::judge(&frame)
        .redraw
        .draw(report.rules(), RasterMistakes::NONE);
    let images = app.world().resource::<ViewImages>().0.clone();
    let images = images.expect("a raster trace shows two images");
    let rgb = |pixels: &[[u8; 4]]| {
        pixels
            .iter()
            .map(|p| [p[0], p[1], p[2]])
            .collect::<Vec<_>>()
    };
    assert_ne!(rgb(&frame.framebuffer.pixels), rgb(&redraw.image.pixels));
    assert_eq!(
        rgb(&images.close2gl.pixels),
        rgb(&frame.framebuffer.pixels),
        "the Close2GL view shows the program's own pixels"
    );
    assert_eq!(
        images.reference, redraw.image,
        "the reference shows close2gl's"
    );
    let findings = app.world().resource::<TraceFindings>();
    let text = report::text(&report, &path.display().to_string());
    let lines: Vec<String> = text.lines().map(str::to_string).collect();
    assert_eq!(findings.raster_report.as_ref(), Some(&lines));
    assert_eq!(findings.mistakes, vec!["channels_swapped"]);
    assert!(!findings.agrees);
    assert_eq!(findings.path.as_deref(), Some(path.as_path()));
}

#[test]
fn a_bad_raster_trace_keeps_what_was_shown_with_its_error() {
    let dir = TempDir::new("raster_view_bad");
    let path = raster_trace(&dir.0, "exclusive", "fill_rule_exclusive");
    let mut app = app_showing(&path);
    let shown = app.world().resource::<ViewImages>().0.clone();
    let bad = dir.0.join("bad.raster");
    std::fs::write(&bad, "close2gl-raster 1\nwindow 4 3\nshading gouraud\n").expect("write");
    open(&mut app, &bad);
    let findings = app.world().resource::<TraceFindings>();
    assert_eq!(
        findings.error.as_deref(),
        Some(format!("{}:3: expected 'shading none|gouraud_ad|gouraud_ads|phong', found 'shading gouraud'", bad.display()).as_str())
    );
    assert_eq!(
        findings.path.as_deref(),
        Some(path.as_path()),
        "still shown"
    );
    assert!(findings.raster_report.is_some());
    assert!(shown.is_some());
    assert_eq!(app.world().resource::<ViewImages>().0, shown);
}

#[test]
fn a_geometry_trace_after_a_raster_trace_gives_the_views_back() {
    let dir = TempDir::new("raster_view_replaced");
    let path = raster_trace(&dir.0, "correct", "none");
    let mut app = app_showing(&path);
    assert!(app.world().resource::<ViewImages>().0.is_some());
    let geometry = dir.0.join("one.trace");
    let trace = "close2gl-trace 1\nwindow 640 480\ncamera position 0 0 5\ncamera u 1 0 0\n\
                 camera v 0 1 0\ncamera n 0 0 1\ncamera hfov 60\ncamera vfov 60\ncamera near 1\n\
                 camera far 10\ntri 0 10 10 100 10 10 100\n";
    std::fs::write(&geometry, trace).expect("write the trace");
    open(&mut app, &geometry);
    assert_eq!(app.world().resource::<ViewImages>().0, None);
    let findings = app.world().resource::<TraceFindings>();
    assert_eq!(findings.raster_report, None);
    assert_eq!(findings.path.as_deref(), Some(geometry.as_path()));
}

#[test]
fn the_probe_answers_with_checks_probe_of_the_pixel_under_the_cursor() {
    let dir = TempDir::new("raster_view_probe");
    let path = raster_trace(&dir.0, "swapped", "channels_swapped");
    let app = app_showing(&path);
    let view = app.world().resource::<TraceView>();
    let frame = read_raster_frame(&path).expect("reads");
    // The square scene's window is 64 × 64 with y up, shown over a 128 × 128 view: view pixel
    // (41, 21) is the trace's (20, 53), inside the square (its corners at 8.5 and 55.5).
    let viewport = Viewport {
        width: 128,
        height: 128,
    };
    let lines = raster_probe(view, (41, 21), viewport).expect("a raster trace is shown");
    let expected = raster::probe::probe(&frame, 20, 53).expect("inside the window");
    assert_eq!(lines, expected);
    assert!(
        lines[0].starts_with("pixel (20, 53): yours colour 51 153 255"),
        "{lines:?}"
    );
    assert!(
        lines
            .iter()
            .any(|l| l.starts_with("  channels_swapped would give")),
        "{lines:?}"
    );
}

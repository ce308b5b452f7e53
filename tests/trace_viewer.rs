//! A program's trace in the real windowed app under a real X server: `close2gl MODEL --trace
//! FILE` shows the trace's 2D output as the Close2GL view, the live difference (V) compares it
//! with the reference, and a probe (Ctrl+click) on it selects the triangle the trace drew there.
//! A raster trace (the rasterizer assignment's) shows the program's framebuffer beside close2gl's
//! drawing of its triangles. The traces come from the student programs of `examples/trace` and
//! `examples/raster`, compiled with `cc`. Needs Xvfb
//! (`apt-get install xvfb`); without it these tests fail, they never skip.

mod common;

use close2gl_core::{Letterbox, Viewport};
use close2gl_gpu::Image;
use close2gl_testkit::student::{asset, compile_pipeline, mistake_flag, raster_trace};
use close2gl_trace_format::read_raster_frame;
use common::{TempDir, Xvfb, assert_one_triangle_highlighted, run_app};

/// The window's size: the panel, then the two views side by side.
const SIZE: [u32; 2] = [900, 420];

/// A replay of 14 frames: V on frame 3 when `difference`, a probe at `probe` (window pixels) on
/// frame 11, the screenshot key on the last.
fn recording(difference: bool, probe: Option<[u32; 2]>) -> String {
    let mut lines = vec![format!(
        "{{\"close2gl_recording\":1,\"size\":[{},{}]}}",
        SIZE[0], SIZE[1]
    )];
    for frame in 0..14 {
        let mut line = format!("{{\"frame\":{frame},\"dt\":0.016666668");
        if difference && frame == 3 {
            line += ",\"pressed\":[\"v\"]";
        }
        if let (Some([x, y]), 11) = (probe, frame) {
            line += &format!(",\"probe\":[{x},{y}],\"probe_close2gl_window\":false");
        }
        if frame == 13 {
            line += ",\"pressed\":[\"f12\"]";
        }
        lines.push(line + "}");
    }
    lines.join("\n") + "\n"
}

/// A trace of the knot, turned a little, from the program built with `flags`.
fn knot_trace(dir: &TempDir, name: &str, flags: &[&str]) -> String {
    let program = compile_pipeline(dir, name, flags);
    let scene = dir.write(
        &format!("{name}.scene"),
        format!(
            "close2gl-scene 1\nmodel {}\nwindow 640 480\ncamera framed\nculling ccw\n\
             clipping full\nrotate u 20\n",
            asset("knot.obj").display()
        )
        .as_bytes(),
    );
    let trace = dir.join(format!("{name}.trace"));
    let ran = std::process::Command::new(program)
        .arg(&scene)
        .arg(&trace)
        .status();
    assert!(ran.expect("the program runs").success());
    trace.display().to_string()
}

/// Runs the app on the trace with the replay; returns the two views the screenshot key saved.
fn views(xvfb: &Xvfb, dir: &TempDir, name: &str, trace: &str, replay: &str) -> [Image; 2] {
    let rec = dir.write(&format!("{name}.rec"), replay.as_bytes());
    let shots = dir.join(format!("{name}-shots"));
    let (rec, shots_arg) = (rec.display().to_string(), shots.display().to_string());
    let knot = asset("knot.obj").display().to_string();
    run_app(
        xvfb,
        &[
            &knot,
            "--trace",
            trace,
            "--replay",
            &rec,
            "--screenshot-dir",
            &shots_arg,
        ],
    );
    ["reference", "close2gl"].map(|view| {
        let file = shots.join(format!("close2gl-001-{view}.png"));
        Image::read_png(&file).unwrap_or_else(|e| panic!("{name}: {e}"))
    })
}

/// The pixels the live difference colours: covered only in the reference (magenta) or only in
/// the Close2GL view (green).
fn differing(image: &Image) -> usize {
    let only = |p: &[u8; 4]| matches!(p[..3], [255, 0, 255] | [0, 255, 0]);
    image.pixels.iter().filter(|p| only(p)).count()
}

#[test]
fn the_difference_shows_where_a_trace_with_a_mistake_differs_and_nowhere_for_a_correct_one() {
    let dir = TempDir::new("trace_viewer_difference");
    let xvfb = Xvfb::start();
    let correct = knot_trace(&dir, "correct", &[]);
    let flipped = knot_trace(&dir, "flipped", &[&mistake_flag("viewport_y_flipped")]);
    let replay = recording(true, None);
    let [_, agree] = views(&xvfb, &dir, "correct", &correct, &replay);
    let [_, differ] = views(&xvfb, &dir, "flipped", &flipped, &replay);
    let total = agree.pixels.len();
    // Edges may round to the other side of a pixel centre; a mirrored image differs in bulk.
    assert!(
        differing(&agree) < total / 200,
        "correct: {} of {total}",
        differing(&agree)
    );
    assert!(
        differing(&differ) > total / 10,
        "flipped: {} of {total}",
        differing(&differ)
    );
}

#[test]
fn a_probe_on_the_trace_selects_the_triangle_it_drew_there() {
    let dir = TempDir::new("trace_viewer_probe");
    let xvfb = Xvfb::start();
    let flipped = knot_trace(&dir, "flipped", &[&mistake_flag("viewport_y_flipped")]);
    let [reference, close2gl] = views(&xvfb, &dir, "plain", &flipped, &recording(false, None));
    // A pixel of the Close2GL view (the right half of the views) the trace covers.
    let background = close2gl.pixel(0, 0);
    let (cx, cy) = (close2gl.width / 2, close2gl.height / 2);
    let [x, y] = (0..close2gl.height / 2)
        .flat_map(|r| [[cx, cy + r], [cx, cy - r]])
        .find(|&[x, y]| close2gl.pixel(x, y) != background)
        .expect("the trace covers the Close2GL view's middle column");
    let at = [reference.width + x, y];
    let probed = views(&xvfb, &dir, "probed", &flipped, &recording(false, Some(at)));
    for (name, (before, after)) in ["reference", "close2gl"]
        .iter()
        .zip([&reference, &close2gl].into_iter().zip(&probed))
    {
        assert_one_triangle_highlighted(name, before, after);
    }
}

#[test]
fn a_raster_trace_shows_the_programs_framebuffer_beside_close2gls_drawing_of_it() {
    let dir = TempDir::new("trace_viewer_raster");
    let xvfb = Xvfb::start();
    let flags = [mistake_flag("channels_swapped")];
    let flags: Vec<&str> = flags.iter().map(String::as_str).collect();
    let path = raster_trace(&dir.0, "swapped", &flags, "square.scene");
    let frame = read_raster_frame(&path).expect("the program's trace reads");
    let trace = path.display().to_string();
    let [reference, close2gl] = views(&xvfb, &dir, "raster", &trace, &recording(false, None));
    // The views' middles show the square's middle, the frame letterboxed in each view.
    let (width, height) = frame.trace.window;
    let view = Viewport {
        width: close2gl.width,
        height: close2gl.height,
    };
    let middle = (view.width / 2, view.height / 2);
    let (x, y) = Letterbox::new((width, height), view)
        .frame_pixel(middle, view, (width, height))
        .expect("the middle shows the frame");
    let [r, g, b, _] = frame.framebuffer.pixel(x, y);
    let theirs = close2gl.pixel(middle.0, middle.1);
    let ours = reference.pixel(middle.0, middle.1);
    assert_eq!(
        theirs[..3],
        [r, g, b],
        "the Close2GL view: the program's pixel"
    );
    assert_eq!(
        ours[..3],
        [b, g, r],
        "the reference: close2gl's, red and blue the right way"
    );
    assert_ne!(r, b, "the square's colour shows the channels swapped");
    // Outside the frame: bars of the view's background, the same in both views (stretched, the
    // frame's own backgrounds would be there, red and blue swapped in one).
    let corner = if view.width * height > width * view.height {
        (0, middle.1)
    } else {
        (middle.0, 0)
    };
    assert_eq!(
        close2gl.pixel(corner.0, corner.1),
        reference.pixel(corner.0, corner.1)
    );
}

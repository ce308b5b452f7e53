//! The user's tools in the real app under a real X server: the screenshot key and the command it
//! writes (which must render the very pixels the window showed), copy as command, and record and
//! replay (a flight recorded from real key presses, replayed twice). Needs Xvfb and xdotool
//! (`apt-get install xvfb xdotool`); without them these tests fail, they never skip.

mod common;

use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use close2gl_core::parity::CoverageComparison;
use close2gl_gpu::Image;
use common::{
    APP_TIMEOUT, TempDir, Xvfb, assert_one_triangle_highlighted, finish, run_app, spawn_app,
};

/// A recording of `frames` frames at 60 Hz: `d` held over frames 2..12 (the camera moves right),
/// Shift+P on frame 14 (Phong), the copy-command key two frames before the end (the panel
/// carries it out on the next frame) and the screenshot key on the last frame.
fn flight(frames: u32, size: [u32; 2]) -> String {
    flight_probing(frames, size, None)
}

/// [`flight`], with a probe (Ctrl+click) on the frame before the screenshot: at a pixel of the
/// panel's window, or of the Close2GL window (`true`) in the windows layout.
fn flight_probing(frames: u32, size: [u32; 2], probe: Option<([u32; 2], bool)>) -> String {
    let mut lines = vec![format!(
        "{{\"close2gl_recording\":1,\"size\":[{},{}]}}",
        size[0], size[1]
    )];
    for frame in 0..frames {
        let mut line = format!("{{\"frame\":{frame},\"dt\":0.016666668");
        if (2..12).contains(&frame) {
            line += ",\"held\":[\"d\"]";
        }
        if frame == 2 {
            line += ",\"pressed\":[\"d\"]";
        }
        if frame == 14 {
            line += ",\"held\":[\"shift\"],\"pressed\":[\"shift+p\"]";
        }
        if frame == frames - 3 {
            line += ",\"pressed\":[\"c\"]";
        }
        if let (Some(([x, y], close2gl)), true) = (probe, frame == frames - 2) {
            line += &format!(",\"probe\":[{x},{y}],\"probe_close2gl_window\":{close2gl}");
        }
        if frame == frames - 1 {
            line += ",\"pressed\":[\"f12\"]";
        }
        lines.push(line + "}");
    }
    lines.join("\n") + "\n"
}

fn png(path: &Path) -> Image {
    Image::read_png(path).unwrap_or_else(|e| panic!("{e}"))
}

/// Runs `command` (a line the app wrote) with `close2gl` meaning the binary under test.
fn run_command_line(command: &str) {
    let bin = Path::new(env!("CARGO_BIN_EXE_close2gl"));
    let path = format!(
        "{}:{}",
        bin.parent().expect("the binary's folder").display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let output = Command::new("sh")
        .args(["-c", command])
        .env("PATH", path)
        .current_dir(&*TempDir::new("elsewhere"))
        .output()
        .expect("sh runs");
    assert!(
        output.status.success(),
        "{command}\nfailed: {}",
        String::from_utf8_lossy(&output.stderr)
    );
}

fn assert_same_pixels(what: &str, window: &Image, rendered: &Image) {
    assert_eq!(
        (window.width, window.height),
        (rendered.width, rendered.height),
        "{what}: sizes"
    );
    // Both PNGs keep their view's coverage in alpha: the screenshot key's as `render`'s.
    let comparison = CoverageComparison::of_images(window, rendered);
    let differing = window
        .pixels
        .iter()
        .zip(&rendered.pixels)
        .filter(|(a, b)| a != b)
        .count();
    assert!(
        comparison.covered_pixels > 1000,
        "{what}: the view shows the model ({} pixels)",
        comparison.covered_pixels
    );
    assert_eq!(
        comparison.coverage_agreement, 1.0,
        "{what}: coverage agreement"
    );
    assert_eq!(differing, 0, "{what}: pixels that differ");
}

#[test]
fn the_screenshot_key_saves_both_views_and_a_command_that_renders_the_same_pixels() {
    let dir = TempDir::new("tools-shot");
    let recording = dir.join("flight.rec");
    std::fs::write(&recording, flight(20, [900, 420])).expect("the recording");
    let shots = dir.join("shots");
    let xvfb = Xvfb::start();
    let output = run_app(
        &xvfb,
        &[
            "--replay",
            &recording.display().to_string(),
            "--screenshot-dir",
            &shots.display().to_string(),
            // Close2GL rasterizes too, and a setting off its default goes into the command.
            "--set",
            "render.close2gl_raster=software",
            "--set",
            "camera.hfov=50",
        ],
    );

    let command = std::fs::read_to_string(shots.join("close2gl-001-command.txt"))
        .expect("the command beside the screenshots");
    let command = command.trim();
    assert!(command.starts_with("close2gl render "), "{command}");
    for part in [
        "render.close2gl_raster=software",
        "render.shading=phong",
        "camera.hfov=50.0",
    ] {
        assert!(command.contains(part), "{part} in {command}");
    }
    // The copy-command key printed the same line.
    let stdout = String::from_utf8_lossy(&output.stdout);
    let printed = stdout.replace(&shots.join("close2gl-001-render").display().to_string(), "");
    assert!(
        printed.contains(
            &command.replace(&shots.join("close2gl-001-render").display().to_string(), "")
        ),
        "copy as command printed {stdout:?}"
    );
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(
        stderr.contains("Saved close2gl-001-reference.png"),
        "{stderr}"
    );

    run_command_line(command);
    let rendered = shots.join("close2gl-001-render");
    assert_same_pixels(
        "reference view",
        &png(&shots.join("close2gl-001-reference.png")),
        &png(&rendered.join("reference.png")),
    );
    assert_same_pixels(
        "Close2GL view",
        &png(&shots.join("close2gl-001-close2gl.png")),
        &png(&rendered.join("close2gl.png")),
    );
}

/// Whole-window screenshot after `args`.
fn window_shot(xvfb: &Xvfb, dir: &Path, name: &str, args: &[&str]) -> Image {
    let file = dir.join(format!("{name}.png"));
    let file_arg = file.display().to_string();
    let mut all = args.to_vec();
    all.extend(["--screenshot", &file_arg]);
    run_app(xvfb, &all);
    png(&file)
}

/// The app recording, live, while xdotool flies it (holds `d`, turns with an arrow key) and
/// presses the screenshot key; then the window is closed. No frame budget: the app waits for
/// the keys however long the window takes to appear. Returns the recording and the folder of
/// the views the screenshot key saved.
fn record_a_flight(xvfb: &Xvfb, dir: &Path) -> (PathBuf, PathBuf) {
    let recording = dir.join("recorded.rec");
    let shots = dir.join("recorded-shots");
    let app = spawn_app(
        xvfb,
        &[
            "--size",
            "900x420",
            "--record",
            &recording.display().to_string(),
            "--screenshot-dir",
            &shots.display().to_string(),
        ],
    );
    let xdotool = |args: &[&str]| {
        let output = Command::new("xdotool")
            .args(args)
            .env("DISPLAY", &xvfb.display)
            .output();
        match output {
            Ok(output) if output.status.success() => {
                Some(String::from_utf8_lossy(&output.stdout).into_owned())
            }
            Ok(_) => None,
            Err(e) => panic!("xdotool is needed (apt-get install xdotool): {e}"),
        }
    };
    let started = Instant::now();
    let until = |what: &str, done: &mut dyn FnMut() -> bool| {
        while !done() {
            assert!(started.elapsed() < APP_TIMEOUT, "{what}");
            std::thread::sleep(Duration::from_millis(100));
        }
    };
    let mut window = String::new();
    until("the window did not appear", &mut || {
        let found = xdotool(&["search", "--name", "Close2GL viewer"]);
        window = found
            .and_then(|out| out.lines().next().map(str::to_string))
            .unwrap_or_default();
        !window.is_empty()
    });
    until("the window did not take the focus", &mut || {
        xdotool(&["windowfocus", "--sync", &window]).is_some()
    });
    xdotool(&["keydown", "d"]).expect("keydown d");
    std::thread::sleep(Duration::from_millis(400));
    xdotool(&["keyup", "d", "key", "Left", "key", "F12"]).expect("keyup d, Left, F12");
    // The command is written after both views.
    until("the screenshot key saved nothing", &mut || {
        shots.join("close2gl-001-command.txt").exists()
    });
    xdotool(&["windowclose", &window]).expect("the window closes");
    finish(app, "the recording app");
    (recording, shots)
}

/// The two views of a 900x420 split window (the panel at the right).
fn views(image: &Image) -> Image {
    let width = (image.width - close2gl_ui::PANEL_WIDTH as u32) / 2 * 2;
    Image {
        width,
        height: image.height,
        pixels: (0..image.height)
            .flat_map(|y| (0..width).map(move |x| (x, y)))
            .map(|(x, y)| image.pixel(x, y))
            .collect(),
    }
}

#[test]
fn a_recorded_flight_replays_to_the_same_image_every_time() {
    let dir = TempDir::new("tools-replay");
    let xvfb = Xvfb::start();
    let (recording, recorded) = record_a_flight(&xvfb, &dir);
    let text = std::fs::read_to_string(&recording).expect("the recording");
    // Left and F12 may come in one frame.
    assert!(
        text.contains("\"held\":[\"d\"]") && text.contains("\"left\"") && text.contains("\"f12\""),
        "the key presses were recorded: {text}"
    );

    // Each replay saves its screenshot-key views in the same folder, moved away after it, so
    // that the notice naming the files reads the same in both windows.
    let replay = recording.display().to_string();
    let shots = dir.join("shots");
    let replayed = |name: &str| {
        let args = [
            "--replay",
            &replay,
            "--screenshot-dir",
            &shots.display().to_string(),
        ];
        let window = window_shot(&xvfb, &dir, name, &args);
        let kept = dir.join(format!("{name}-shots"));
        std::fs::rename(&shots, &kept).expect("the replay's screenshot-key views");
        (window, kept)
    };
    let (first, first_shots) = replayed("replay1");
    let (second, _) = replayed("replay2");
    assert!(
        first.pixels == second.pixels,
        "two replays drew different windows"
    );
    // The replay flew where the recording flew: the screenshot key, replayed on its frame, saw
    // the views the recording's saw.
    for view in ["reference", "close2gl"] {
        let file = format!("close2gl-001-{view}.png");
        assert!(
            png(&first_shots.join(&file)).pixels == png(&recorded.join(&file)).pixels,
            "the replay's {view} view differs from the recorded run's"
        );
    }
    let start = window_shot(
        &xvfb,
        &dir,
        "start",
        &["--size", "900x420", "--exit-after-frames", "3"],
    );
    assert!(
        views(&start).pixels != views(&first).pixels,
        "the flight moved the camera"
    );
}

#[test]
fn a_recorded_probe_click_selects_the_triangle_under_it_and_highlights_it_in_both_views() {
    let dir = TempDir::new("tools-probe");
    let xvfb = Xvfb::start();
    // The views the screenshot key saves after a flight in `layout`, probed or not.
    let views_after = |name: &str, layout: &str, probe: Option<([u32; 2], bool)>| {
        let recording = dir.join(format!("{name}.rec"));
        std::fs::write(&recording, flight_probing(20, [900, 420], probe)).expect("recording");
        let shots = dir.join(name);
        let (replay, shots_arg) = (recording.display().to_string(), shots.display().to_string());
        let layout = format!("window.layout={layout}");
        let args = [
            "--replay",
            &replay,
            "--screenshot-dir",
            &shots_arg,
            "--set",
            &layout,
        ];
        run_app(&xvfb, &args);
        ["reference", "close2gl"].map(|view| png(&shots.join(format!("close2gl-001-{view}.png"))))
    };
    // A pixel the model covers near the middle of the views (the same in both).
    let covered = |reference: &Image| {
        let background = reference.pixel(0, 0);
        let (cx, cy) = (reference.width / 2, reference.height / 2);
        (0..reference.width / 2)
            .flat_map(|r| [[cx + r, cy], [cx - r, cy]])
            .find(|&[x, y]| reference.pixel(x, y) != background)
            .expect("the model covers the reference view's middle row")
    };
    // The split layout's reference view is the window's left column, so its pixels are the
    // window's; in the windows layout the Close2GL window is its view.
    for (layout, in_close2gl_window) in [("split", false), ("windows", true)] {
        let plain = views_after(&format!("{layout}-plain"), layout, None);
        let [x, y] = covered(&plain[0]);
        let probed = views_after(layout, layout, Some(([x, y], in_close2gl_window)));
        for (view, (before, after)) in ["reference", "close2gl"]
            .iter()
            .zip(plain.iter().zip(&probed))
        {
            assert_one_triangle_highlighted(&format!("{layout} {view}"), before, after);
            assert_ne!(
                before.pixel(x, y),
                after.pixel(x, y),
                "{layout} {view}: under the click"
            );
        }
    }
}

/// A first run on a small screen opens its window fitted to the monitor, smaller than the
/// configuration asks: the recording remembers the fitted size, so that its replay (which
/// opens at the recorded size, not fitted) shows the views as they were recorded and a
/// recorded click lands on the same pixel.
#[test]
fn a_recording_made_in_a_window_fitted_to_a_small_screen_replays_at_that_size() {
    let dir = TempDir::new("tools-fitted");
    let xvfb = Xvfb::with_screen("1366x768x24");
    let recording = dir.join("fitted.rec").display().to_string();
    // The app's window as `--screenshot` saves it, run as `mode` (`--record` or `--replay`) says.
    let shot = |mode: &str, name: &str| {
        let path = dir.join(name);
        let path_text = path.display().to_string();
        run_app(&xvfb, &[mode, &recording, "--screenshot", &path_text]);
        png(&path)
    };
    let recorded = shot("--record", "recorded.png");
    assert!(recorded.width <= 1366, "fitted: {}", recorded.width);
    let replayed = shot("--replay", "replayed.png");
    assert_eq!(
        (replayed.width, replayed.height),
        (recorded.width, recorded.height),
        "the replay's window is the recorded one's"
    );
}

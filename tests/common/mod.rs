//! What the tests that run the real app under a real X server share: an Xvfb of their own, the
//! app run to its end with a deadline, and what its window should show (the model in both
//! views). Xvfb must be installed (`apt-get install xvfb`); without it these tests fail, they
//! never skip.

// Each test file that includes this module uses a part of it.
#![allow(dead_code)]

use std::io::{BufRead, BufReader};
use std::process::{Child, Command, Output, Stdio};
use std::time::{Duration, Instant};

use close2gl::config;
use close2gl_gpu::Image;
pub use close2gl_testkit::TempDir;

/// How long the app may take to open, draw and save (a debug build on a software GPU).
pub const APP_TIMEOUT: Duration = Duration::from_secs(120);

/// An Xvfb server on a display of its own, killed when dropped.
pub struct Xvfb {
    child: Child,
    pub display: String,
}

impl Xvfb {
    /// Xvfb picks a free display itself and names it (`-displayfd`) once it accepts clients:
    /// tests running in parallel that each chose a number could take the same one, and one test
    /// ending would kill the other's server.
    pub fn start() -> Xvfb {
        Xvfb::with_screen("1920x1080x24")
    }

    /// An Xvfb whose one monitor is `screen` (WIDTHxHEIGHTxDEPTH).
    pub fn with_screen(screen: &str) -> Xvfb {
        let child = Command::new("Xvfb")
            .args([
                "-displayfd",
                "1",
                "-screen",
                "0",
                screen,
                "-nolisten",
                "tcp",
                // Without it the server resets when its last client leaves, and an app started
                // in that moment fails to connect (seen between two runs of a test).
                "-noreset",
            ])
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn();
        let mut child = match child {
            Ok(child) => child,
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                panic!("Xvfb is not installed; the windowed tests need it: apt-get install xvfb")
            }
            Err(e) => panic!("cannot start Xvfb: {e}"),
        };
        let mut number = String::new();
        let stdout = child.stdout.take().expect("Xvfb's stdout");
        // Ends with the display's number, or with nothing if Xvfb gave up.
        let _ = BufReader::new(stdout).read_line(&mut number);
        let number = number.trim();
        if number.is_empty() {
            let _ = child.kill();
            let status = child.wait();
            panic!("Xvfb did not start: {status:?}");
        }
        Xvfb {
            display: format!(":{number}"),
            child,
        }
    }
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// The app (`close2gl ARGS`) on `xvfb`, from the repository's root, until it exits (killed
/// after [`APP_TIMEOUT`]); panics unless it exits successfully.
pub fn run_app(xvfb: &Xvfb, args: &[&str]) -> Output {
    finish(spawn_app(xvfb, args), &format!("close2gl {args:?}"))
}

/// The app started on `xvfb`, from the repository's root, its output captured.
pub fn spawn_app(xvfb: &Xvfb, args: &[&str]) -> Child {
    Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("DISPLAY", &xvfb.display)
        .env_remove("WAYLAND_DISPLAY")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the close2gl binary starts")
}

/// Waits for `child` (`what`) to exit, killing it after [`APP_TIMEOUT`]; panics unless it
/// exits successfully.
pub fn finish(mut child: Child, what: &str) -> Output {
    let started = Instant::now();
    let status = loop {
        if let Some(status) = child.try_wait().expect("the app can be waited on") {
            break status;
        }
        if started.elapsed() > APP_TIMEOUT {
            let _ = child.kill();
            panic!("{what} did not exit within {APP_TIMEOUT:?}");
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    let output = child.wait_with_output().expect("the app's output");
    assert!(
        status.success(),
        "{what} exited with {status}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    output
}

/// The model's colour as the window stores it (a linear 8-bit surface, flat shading).
pub fn model_color() -> [u8; 3] {
    let color = config::load(None, &[])
        .expect("the repository's config")
        .render
        .appearance
        .color;
    color.to_array().map(|c| (c * 255.0).round() as u8)
}

/// Pixels in columns `x0..x1` that are not the views' background: the model, shaded or flat
/// (and a view's small label).
pub fn covered_pixels(image: &Image, x0: u32, x1: u32) -> usize {
    let background = background_color();
    (0..image.height)
        .flat_map(|y| (x0..x1).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let p = image.pixel(x, y);
            (0..3).any(|c| p[c].abs_diff(background[c]) > 2)
        })
        .count()
}

/// Asserts that a probe's highlight changed `after` from `before` (a view's pixels): somewhere,
/// and no more than one triangle's worth (a twentieth of the view).
pub fn assert_one_triangle_highlighted(what: &str, before: &Image, after: &Image) {
    let changed = before
        .pixels
        .iter()
        .zip(&after.pixels)
        .filter(|(a, b)| a != b)
        .count();
    assert!(changed > 0, "{what}: the selected triangle is highlighted");
    assert!(
        changed < before.pixels.len() / 20,
        "{what}: only one triangle is highlighted ({changed} pixels changed)"
    );
}

/// The views' background as the window stores it.
pub fn background_color() -> [u8; 3] {
    let color = config::load(None, &[])
        .expect("the repository's config")
        .render
        .appearance
        .background;
    color.to_array().map(|c| (c * 255.0).round() as u8)
}

/// Whether both views (columns `reference` and `close2gl` of `image`) show the model, and about
/// as much of it: the same model from the same camera. The error says what they show instead.
pub fn both_views_show_the_model(
    image: &Image,
    reference: (u32, u32),
    close2gl: (u32, u32),
) -> Result<(), String> {
    let r = covered_pixels(image, reference.0, reference.1);
    let c = covered_pixels(image, close2gl.0, close2gl.1);
    let area = ((reference.1 - reference.0) * image.height) as usize;
    if r <= area / 100 || c <= area / 100 {
        return Err(format!(
            "covered pixels: reference {r}, Close2GL {c}, of {area} per view"
        ));
    }
    let (lo, hi) = (r.min(c) as f64, r.max(c) as f64);
    if lo / hi <= 0.95 {
        return Err(format!(
            "the views differ: reference {r}, Close2GL {c} pixels"
        ));
    }
    Ok(())
}

/// Panics unless both views show the model (see [`both_views_show_the_model`]).
pub fn assert_both_views_show_the_model(
    name: &str,
    image: &Image,
    reference: (u32, u32),
    close2gl: (u32, u32),
) {
    if let Err(e) = both_views_show_the_model(image, reference, close2gl) {
        panic!("{name}: {e}");
    }
}

//! The real windowed app under a real X server: each test starts its own Xvfb, runs
//! `close2gl --screenshot FILE --exit-after-frames N` on the default model (the repository's
//! config.toml), and checks that the window showed the model in both views. Xvfb must be
//! installed (`apt-get install xvfb`); without it these tests fail, they never skip.

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use close2gl::config::{self, Layout};
use close2gl_gpu::Image;

/// How long the app may take to open, draw and save (a debug build on a software GPU).
const APP_TIMEOUT: Duration = Duration::from_secs(120);

/// An Xvfb server on a display of its own, killed when dropped.
struct Xvfb {
    child: Child,
    display: String,
}

impl Xvfb {
    fn start() -> Xvfb {
        for number in 90..190 {
            if Path::new(&format!("/tmp/.X{number}-lock")).exists() {
                continue;
            }
            let child = Command::new("Xvfb")
                .args([
                    &format!(":{number}"),
                    "-screen",
                    "0",
                    "1920x1080x24",
                    "-nolisten",
                    "tcp",
                ])
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .spawn();
            let mut child = match child {
                Ok(child) => child,
                Err(e) if e.kind() == std::io::ErrorKind::NotFound => panic!(
                    "Xvfb is not installed; the windowed smoke test needs it: apt-get install xvfb"
                ),
                Err(e) => panic!("cannot start Xvfb: {e}"),
            };
            let socket = PathBuf::from(format!("/tmp/.X11-unix/X{number}"));
            let deadline = Instant::now() + Duration::from_secs(10);
            while Instant::now() < deadline {
                if let Ok(Some(_)) = child.try_wait() {
                    break; // The display was taken meanwhile (another test): try the next one.
                }
                if socket.exists() {
                    return Xvfb {
                        child,
                        display: format!(":{number}"),
                    };
                }
                std::thread::sleep(Duration::from_millis(50));
            }
            let _ = child.kill();
            let _ = child.wait();
        }
        panic!("no free X display between :90 and :189 for Xvfb");
    }
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// Runs the app on `xvfb` with `args` until it exits; returns its screenshot.
fn screenshot(xvfb: &Xvfb, name: &str, args: &[&str]) -> Image {
    let dir = std::env::temp_dir().join(format!("close2gl-smoke-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temporary directory");
    let file = dir.join(format!("{name}.png"));
    let _ = std::fs::remove_file(&file);
    let mut child = Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .args(args)
        .arg("--screenshot")
        .arg(&file)
        // Ten frames: the two-window layout settles its windows' sizes over the first few.
        .args(["--exit-after-frames", "10"])
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env("DISPLAY", &xvfb.display)
        .env_remove("WAYLAND_DISPLAY")
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the close2gl binary starts");
    let deadline = Instant::now() + APP_TIMEOUT;
    let status = loop {
        if let Some(status) = child.try_wait().expect("the app can be waited on") {
            break status;
        }
        if Instant::now() > deadline {
            let _ = child.kill();
            panic!("close2gl {args:?} did not exit within {APP_TIMEOUT:?}");
        }
        std::thread::sleep(Duration::from_millis(50));
    };
    let output = child.wait_with_output().expect("the app's output");
    assert!(
        status.success(),
        "close2gl {args:?} exited with {status}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    Image::read_png(&file).unwrap_or_else(|e| panic!("the screenshot: {e}"))
}

/// The model's colour as the window stores it (a linear 8-bit surface, flat shading).
fn model_color() -> [u8; 3] {
    let color = config::load(None, &[])
        .expect("the repository's config")
        .render
        .color;
    color.to_array().map(|c| (c * 255.0).round() as u8)
}

/// Pixels of the model's colour in columns `x0..x1`.
fn model_pixels(image: &Image, x0: u32, x1: u32) -> usize {
    let color = model_color();
    (0..image.height)
        .flat_map(|y| (x0..x1).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let p = image.pixel(x, y);
            (0..3).all(|c| p[c].abs_diff(color[c]) <= 2)
        })
        .count()
}

/// Both views show the model, and about as much of it: the same model from the same camera.
fn assert_both_views_show_the_model(
    name: &str,
    image: &Image,
    reference: (u32, u32),
    close2gl: (u32, u32),
) {
    let r = model_pixels(image, reference.0, reference.1);
    let c = model_pixels(image, close2gl.0, close2gl.1);
    let area = ((reference.1 - reference.0) * image.height) as usize;
    assert!(
        r > area / 100 && c > area / 100,
        "{name}: model-coloured pixels: reference {r}, Close2GL {c}, of {area} per view"
    );
    let (lo, hi) = (r.min(c) as f64, r.max(c) as f64);
    assert!(
        lo / hi > 0.95,
        "{name}: the views differ: reference {r}, Close2GL {c} pixels"
    );
}

#[test]
fn the_split_window_shows_the_default_model_in_both_views() {
    assert_eq!(
        config::load(None, &[]).expect("config").window.layout,
        Layout::Split
    );
    let xvfb = Xvfb::start();
    let image = screenshot(&xvfb, "split", &["--size", "1000x600"]);
    assert_eq!((image.width, image.height), (1000, 600));
    // The panel is on the right; the views share the rest in equal halves.
    let views = 1000 - close2gl_ui::PANEL_WIDTH as u32;
    let half = views / 2;
    assert_both_views_show_the_model("split", &image, (0, half), (half, views));
}

#[test]
fn the_two_windows_show_the_default_model_in_both_views() {
    let xvfb = Xvfb::start();
    let image = screenshot(
        &xvfb,
        "windows",
        &["--size", "1000x600", "--set", "window.layout=windows"],
    );
    // Side by side: the reference window (panel included), then the 500x600 Close2GL window.
    let reference_window = image.width - 500;
    let panel = close2gl_ui::PANEL_WIDTH as u32;
    assert_eq!(image.height, 600);
    assert_both_views_show_the_model(
        "windows",
        &image,
        (0, reference_window - panel),
        (reference_window, image.width),
    );
}

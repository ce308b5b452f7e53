//! What desktops do to a window, done to the real app under its own Xvfb with xdotool: resized
//! rapidly while it starts on a model big enough that its first frames are slow; minimised and
//! restored (unmapped and mapped: with no window manager, that is what minimising does to an X
//! window); resized to 1x1, to exactly the GPU's largest texture and wider (the surface is clamped
//! and keeps drawing); then, read back from the X server, the window shows the model in both views
//! again, and when the window is destroyed under it the app exits 0 with no panic and no wgpu
//! error. X cannot make a 0x0 window, nor a surface outdated, lost or failing on demand: those are
//! unit tests of the viewer's surface and layout. Then the window is destroyed by another client
//! at many different moments of a frame, fifty times: every run must end as if closed. xdotool
//! must be installed (`apt-get install
//! xdotool`); without it this fails, it never skips.

mod common;

use std::fmt::Write as _;
use std::fs::File;
use std::path::{Path, PathBuf};
use std::process::{Child, Command, ExitStatus, Output, Stdio};
use std::time::{Duration, Instant};

use close2gl_gpu::Image;
use common::{TempDir, Xvfb};
use x11rb::connection::Connection;
use x11rb::protocol::xproto::{ConnectionExt, ImageFormat, ImageOrder};

/// How long one step may take: the app's first frames on the big model, in a debug build on a
/// software GPU, are the slowest.
const STEP_TIMEOUT: Duration = Duration::from_secs(90);

/// The split window's title (regular expression for `xdotool search --name`).
const TITLE: &str = "^Close2GL viewer";

/// The window's size before and after the faults.
const WIDTH: u32 = 800;
const HEIGHT: u32 = 400;

#[test]
fn the_window_survives_resizes_minimising_and_huge_sizes_then_draws_the_model_again() {
    let xvfb = Xvfb::start();
    let dir = TempDir::new("faults");
    let model = dir.join("big.in");
    write_sphere(&model, 200_000);
    let size = format!("{WIDTH}x{HEIGHT}");
    let mut app = Running::start(
        &xvfb,
        &dir,
        &[model.to_str().expect("a UTF-8 path"), "--size", &size],
    );
    let window = app.window(&xvfb);
    let x = XServer::connect(&xvfb);
    let (narrow, tall) = (WIDTH.to_string(), HEIGHT.to_string());
    let views = WIDTH - close2gl_ui::PANEL_WIDTH as u32;
    let half = views / 2;
    let mut last = None;
    // Resized back to WIDTH x HEIGHT, the window must show the model in both views again.
    let mut shows_the_model = |app: &mut Running, when: &str| {
        xdo(&xvfb, &["windowsize", "--sync", &window, &narrow, &tall]);
        app.until(&format!("model in both views {when}"), || {
            last = x.pixels(&window, (0, 0), (WIDTH, HEIGHT));
            last.as_ref().is_some_and(|image| {
                common::both_views_show_the_model(image, (0, half), (half, views)).is_ok()
            })
        });
    };

    // While the model's first frames are computed (and, with models loaded on a worker thread,
    // while it loads): forty resizes, each before the app has drawn the last.
    for i in 0..40u32 {
        let (w, h) = (1 + (i * 397) % 1200, 1 + (i * 251) % 700);
        xdo(
            &xvfb,
            &["windowsize", &window, &w.to_string(), &h.to_string()],
        );
    }
    shows_the_model(&mut app, "after the rapid resizes");

    // Minimised, then restored: an unmapped window loses its pixels, so the model showing again
    // is a new frame.
    xdo(&xvfb, &["windowunmap", "--sync", &window]);
    std::thread::sleep(Duration::from_millis(300));
    xdo(&xvfb, &["windowmap", "--sync", &window]);
    shows_the_model(&mut app, "after minimising");

    xdo(&xvfb, &["windowsize", "--sync", &window, "1", "1"]);
    std::thread::sleep(Duration::from_millis(300));
    app.assert_running();

    // Exactly the largest texture, then wider (X's own limit is 32767): each is drawn, and shows
    // beyond where the window used to end.
    let max = close2gl_testkit::gpu()
        .device
        .limits()
        .max_texture_dimension_2d;
    for width in [max, (max + 3000).min(32767)] {
        // Narrow first, so that what shows beyond the narrow edge can only be a new frame.
        xdo(&xvfb, &["windowsize", "--sync", &window, &narrow, &tall]);
        xdo(
            &xvfb,
            &["windowsize", "--sync", &window, &width.to_string(), "300"],
        );
        app.until(&format!("a {width}x300 window drawn"), || {
            x.pixels(&window, (WIDTH, 0), (1920 - WIDTH, 300))
                .is_some_and(|image| is_drawn(&image))
        });
    }

    shows_the_model(&mut app, "after the huge sizes");
    let image = last.expect("the window read back");
    image
        .write_png(&dir.join("after.png"))
        .expect("the final window saved");

    // Destroyed by another client: the app stops, as if closed.
    xdo(&xvfb, &["windowclose", &window]);
    let (status, stderr) = app.finish();
    let _ = std::fs::remove_file(&model);
    assert!(status.success(), "the app exited with {status}: {stderr}");
    for bad in ["panicked", "wgpu error", "Validation Error"] {
        assert!(
            !stderr.contains(bad),
            "the app's stderr has \"{bad}\": {stderr}"
        );
    }
}

/// Runs of the app whose window is destroyed under it in [`a_window_destroyed_at_any_moment_of_a_frame_ends_the_run_cleanly`].
const DESTROYED_RUNS: u32 = 50;

#[test]
fn a_window_destroyed_at_any_moment_of_a_frame_ends_the_run_cleanly() {
    let xvfb = Xvfb::start();
    let dir = TempDir::new("destroyed");
    let x = XServer::connect(&xvfb);
    // Frame after frame without pause (`--exit-after-frames` draws continuously), each frame a
    // few milliseconds to tens of them: a destroy a few milliseconds later every run lands in
    // every part of a frame (acquire, configure, the panel's input, present) over the runs.
    for run in 0..DESTROYED_RUNS {
        let mut app = Running::start(
            &xvfb,
            &dir,
            &[
                "torus",
                "--size",
                "480x320",
                "--exit-after-frames",
                "1000000",
            ],
        );
        let window = app.window(&xvfb);
        std::thread::sleep(Duration::from_millis(u64::from(run * 7 % 97)));
        x.destroy(&window);
        let (status, stderr) = app.finish();
        assert!(
            status.success(),
            "run {run}: the app exited with {status}: {stderr}"
        );
        for bad in ["panicked", "wgpu error", "Validation Error"] {
            assert!(
                !stderr.contains(bad),
                "run {run}: the app's stderr has \"{bad}\": {stderr}"
            );
        }
    }
}

/// A UV sphere of about `triangles` triangles as a `.in` file: big enough that loading and the
/// first frames take a while in a debug build.
fn write_sphere(path: &Path, triangles: u32) {
    let rings = ((triangles / 2) as f64).sqrt() as u32;
    let segments = triangles / 2 / rings;
    let point = |ring: u32, segment: u32| {
        let theta = std::f64::consts::PI * ring as f64 / rings as f64;
        let phi = std::f64::consts::TAU * segment as f64 / segments as f64;
        [
            theta.sin() * phi.cos(),
            theta.cos(),
            theta.sin() * phi.sin(),
        ]
    };
    let mut text = format!(
        "Object name = SPHERE\n# triangles = {}\nMaterial count = 1\nambient color 0.2 0.2 0.2\n\
         diffuse color 0.8 0.6 0.2\nspecular color 1.0 1.0 1.0\nmaterial shine 20.0\nTexture = NO\n\
         -- 3*[pos(x,y,z) normal(x,y,z) color_index] face_normal(x,y,z)\n",
        rings * segments * 2
    );
    for ring in 0..rings {
        for segment in 0..segments {
            let [a, b, c, d] = [(0, 0), (1, 0), (1, 1), (0, 1)]
                .map(|(r, s)| point(ring + r, (segment + s) % segments));
            for triangle in [[a, c, b], [a, d, c]] {
                for (i, p) in triangle.iter().enumerate() {
                    // On a unit sphere the normal is the position.
                    let _ = writeln!(
                        text,
                        "v{i} {:.3} {:.3} {:.3} {:.3} {:.3} {:.3} 0",
                        p[0], p[1], p[2], p[0], p[1], p[2]
                    );
                }
                let n = triangle[0];
                let _ = writeln!(text, "face normal {:.3} {:.3} {:.3}", n[0], n[1], n[2]);
            }
        }
    }
    std::fs::write(path, text).expect("the model written");
}

/// Whether a piece of the window shows a frame: every pixel the views' background or the model's
/// colour, and some background (an undrawn X window shows neither).
fn is_drawn(image: &Image) -> bool {
    let background = common::background_color();
    let model = common::model_color();
    let near = |p: [u8; 4], c: [u8; 3]| (0..3).all(|i| p[i].abs_diff(c[i]) <= 2);
    image.pixels.iter().any(|&p| near(p, background))
        && image
            .pixels
            .iter()
            .all(|&p| near(p, background) || near(p, model))
}

/// The app on an Xvfb, its output in files (a pipe nobody reads could block it); killed if the
/// test ends first.
struct Running {
    child: Child,
    stderr: PathBuf,
}

impl Running {
    /// The app with `args`, in flat colour (the GPU drawing Close2GL's 2D buffer), so that a
    /// drawn frame is told from an undrawn window by its colours alone ([`is_drawn`]).
    fn start(xvfb: &Xvfb, dir: &Path, args: &[&str]) -> Running {
        let stderr = dir.join("stderr.txt");
        let flat = ["render.shading=none", "render.close2gl_raster=gpu"];
        let child = Command::new(env!("CARGO_BIN_EXE_close2gl"))
            .args(args)
            .args(flat.iter().flat_map(|set| ["--set", set]))
            .current_dir(env!("CARGO_MANIFEST_DIR"))
            .env("DISPLAY", &xvfb.display)
            .env_remove("WAYLAND_DISPLAY")
            .stdout(File::create(dir.join("stdout.txt")).expect("a stdout file"))
            .stderr(File::create(&stderr).expect("a stderr file"))
            .spawn()
            .expect("the close2gl binary starts");
        Running { child, stderr }
    }

    fn stderr(&self) -> String {
        std::fs::read_to_string(&self.stderr).unwrap_or_default()
    }

    fn assert_running(&mut self) {
        if let Some(status) = self.child.try_wait().expect("the app can be waited on") {
            panic!("the app exited with {status}: {}", self.stderr());
        }
    }

    /// Waits until `done` holds, while the app runs, for at most [`STEP_TIMEOUT`].
    fn until(&mut self, what: &str, mut done: impl FnMut() -> bool) {
        let started = Instant::now();
        while !done() {
            self.assert_running();
            assert!(
                started.elapsed() < STEP_TIMEOUT,
                "no {what} within {STEP_TIMEOUT:?}"
            );
            std::thread::sleep(Duration::from_millis(100));
        }
    }

    /// The id of the app's window, once it has one.
    fn window(&mut self, xvfb: &Xvfb) -> String {
        let mut found = None;
        self.until("window", || {
            let search = xdotool(xvfb, &["search", "--name", TITLE]);
            found = String::from_utf8_lossy(&search.stdout)
                .lines()
                .next()
                .map(str::to_owned);
            found.is_some()
        });
        found.expect("a window id")
    }

    /// The app's exit status and stderr, once it exits by itself.
    fn finish(mut self) -> (ExitStatus, String) {
        let started = Instant::now();
        loop {
            if let Some(status) = self.child.try_wait().expect("the app can be waited on") {
                return (status, self.stderr());
            }
            assert!(
                started.elapsed() < STEP_TIMEOUT,
                "the app did not exit within {STEP_TIMEOUT:?}"
            );
            std::thread::sleep(Duration::from_millis(50));
        }
    }
}

impl Drop for Running {
    fn drop(&mut self) {
        let _ = self.child.kill();
        let _ = self.child.wait();
    }
}

/// `xdotool ARGS` on `xvfb`, whatever its exit status; killed after [`STEP_TIMEOUT`] (`--sync`
/// waits for the window).
fn xdotool(xvfb: &Xvfb, args: &[&str]) -> Output {
    let child = Command::new("xdotool")
        .args(args)
        .env("DISPLAY", &xvfb.display)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn();
    let mut child = match child {
        Ok(child) => child,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            panic!(
                "xdotool is not installed; the window-fault test needs it: apt-get install xdotool"
            )
        }
        Err(e) => panic!("cannot run xdotool: {e}"),
    };
    let started = Instant::now();
    while child
        .try_wait()
        .expect("xdotool can be waited on")
        .is_none()
    {
        if started.elapsed() > STEP_TIMEOUT {
            let _ = child.kill();
            panic!("xdotool {args:?} did not finish within {STEP_TIMEOUT:?}");
        }
        std::thread::sleep(Duration::from_millis(10));
    }
    child.wait_with_output().expect("xdotool's output")
}

/// `xdotool ARGS`, which must succeed.
fn xdo(xvfb: &Xvfb, args: &[&str]) {
    let output = xdotool(xvfb, args);
    assert!(
        output.status.success(),
        "xdotool {args:?}: {}",
        String::from_utf8_lossy(&output.stderr)
    );
}

/// A connection to the X server, to read back what a window shows (xdotool cannot).
struct XServer(x11rb::rust_connection::RustConnection);

impl XServer {
    fn connect(xvfb: &Xvfb) -> XServer {
        let (connection, _) = x11rb::connect(Some(&xvfb.display)).expect("a connection to Xvfb");
        assert_eq!(
            connection.setup().image_byte_order,
            ImageOrder::LSB_FIRST,
            "Xvfb's pixels are read as little-endian"
        );
        XServer(connection)
    }

    /// Destroys `window`, as another client (or a crashing window manager) may.
    fn destroy(&self, window: &str) {
        let id = window
            .parse()
            .expect("xdotool prints window ids in decimal");
        self.0.destroy_window(id).expect("the destroy request sent");
        self.0.flush().expect("the destroy request flushed");
    }

    /// The `size` pixels of `window` at `at`, as the X server shows them; `None` while they cannot
    /// be read (the window unmapped, smaller, or off the screen).
    fn pixels(&self, window: &str, at: (u32, u32), size: (u32, u32)) -> Option<Image> {
        let id = window
            .parse()
            .expect("xdotool prints window ids in decimal");
        let reply = self
            .0
            .get_image(
                ImageFormat::Z_PIXMAP,
                id,
                at.0 as i16,
                at.1 as i16,
                size.0 as u16,
                size.1 as u16,
                !0,
            )
            .ok()?
            .reply()
            .ok()?;
        // Depth 24 is stored 32 bits a pixel, blue first.
        let pixels: Vec<[u8; 4]> = reply
            .data
            .chunks_exact(4)
            .map(|p| [p[2], p[1], p[0], 255])
            .collect();
        (reply.depth == 24 && pixels.len() == (size.0 * size.1) as usize).then_some(Image {
            width: size.0,
            height: size.1,
            pixels,
        })
    }
}

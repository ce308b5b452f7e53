//! The real windowed app under a real X server: each test starts its own Xvfb, runs
//! `close2gl --screenshot FILE --exit-after-frames N` on the default model (the repository's
//! config.toml), and checks that the window showed the model in both views. Xvfb must be
//! installed (`apt-get install xvfb`); without it these tests fail, they never skip.

mod common;

use close2gl::config::{self, Layout};
use close2gl_gpu::Image;
use common::{TempDir, Xvfb, assert_both_views_show_the_model, run_app};

/// Runs the app on `xvfb` with `args` until it exits; returns its screenshot.
fn screenshot(xvfb: &Xvfb, name: &str, args: &[&str]) -> Image {
    let dir = TempDir::new("smoke");
    let file = dir.join(format!("{name}.png"));
    let file_arg = file.display().to_string();
    let mut all = args.to_vec();
    // Ten frames: the two-window layout settles its windows' sizes over the first few.
    all.extend(["--screenshot", &file_arg, "--exit-after-frames", "10"]);
    run_app(xvfb, &all);
    Image::read_png(&file).unwrap_or_else(|e| panic!("the screenshot: {e}"))
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

#[test]
fn in_the_two_windows_layout_the_outside_view_opens_a_window_of_its_own() {
    let xvfb = Xvfb::start();
    let args = [
        "--size",
        "1000x600",
        "--set",
        "window.layout=windows",
        "--set",
        "outside.show=true",
    ];
    let image = screenshot(&xvfb, "windows-outside", &args);
    // Side by side: the reference window (panel included), the 500x600 Close2GL window, then
    // the outside view's 500x600 window.
    let outside = image.width - 500;
    let close2gl = outside - 500;
    let panel = close2gl_ui::PANEL_WIDTH as u32;
    assert_eq!(image.height, 600);
    assert_both_views_show_the_model(
        "windows",
        &image,
        (0, close2gl - panel),
        (close2gl, outside),
    );
    let background = image.pixel(outside, 599);
    let drawn = (outside..image.width)
        .flat_map(|x| (0..600).map(move |y| (x, y)))
        .filter(|&(x, y)| image.pixel(x, y) != background)
        .count();
    assert!(
        drawn > 2000,
        "the outside window shows the volume and the model: {drawn} pixels"
    );
}

#[test]
fn the_first_run_fits_a_small_laptop_screen_and_shades_both_views() {
    // The repository's config asks for a window wider than 1366 pixels.
    let config = config::load(None, &[]).expect("config");
    assert!(config.window.width > 1366);
    let xvfb = Xvfb::with_screen("1366x768x24");
    let image = screenshot(&xvfb, "laptop", &[]);
    assert!(
        image.width <= 1366 && image.height <= 768,
        "the window fits the monitor: {}x{}",
        image.width,
        image.height
    );
    let views = image.width - close2gl_ui::PANEL_WIDTH as u32;
    let half = views / 2;
    assert_both_views_show_the_model("laptop", &image, (0, half), (half, views));
    // Shaded, not flat: the model takes many colours in each view.
    for (view, (from, to)) in [("reference", (0, half)), ("Close2GL", (half, views))] {
        let colours: std::collections::HashSet<[u8; 4]> = (from..to)
            .flat_map(|x| (0..image.height).map(move |y| (x, y)))
            .map(|(x, y)| image.pixel(x, y))
            .collect();
        assert!(colours.len() > 100, "{view}: {} colours", colours.len());
    }
}

//! `close2gl [MODEL]`: the interactive viewer, both views and the control panel.

use std::path::PathBuf;

use close2gl_viewer::{ViewerOptions, ViewerPlugin};

use super::CliError;
use super::scene::{SceneArgs, print_warnings, viewport};

/// Frames drawn before `--screenshot` saves one, when `--exit-after-frames` does not say.
const SCREENSHOT_FRAMES: u32 = 5;

#[derive(clap::Args, Debug, Default)]
pub struct RunArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// The window's size, WIDTHxHEIGHT (default: window.width x window.height from the config).
    #[arg(long, value_name = "WxH")]
    pub size: Option<String>,
    /// Save the window as PNG after the last frame (see --exit-after-frames; default 5), then
    /// exit. With window.layout = "windows", both windows side by side.
    #[arg(long, value_name = "FILE")]
    pub screenshot: Option<PathBuf>,
    /// Draw this many frames, then exit.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
    pub exit_after_frames: Option<u32>,
}

pub fn run(args: RunArgs) -> Result<(), CliError> {
    let config = args.scene.config()?;
    let size = viewport(args.size.as_deref(), &config)?;
    // The first frame's layout replaces this with the views' real size.
    let mut app = crate::build_app(&config, size).map_err(CliError::Input)?;
    print_warnings(&app);
    let exit_after_frames = args
        .exit_after_frames
        .or(args.screenshot.is_some().then_some(SCREENSHOT_FRAMES));
    app.add_plugins(ViewerPlugin(ViewerOptions {
        layout: config.window.layout,
        width: size.width,
        height: size.height,
        screenshot: args.screenshot,
        exit_after_frames,
    }));
    app.run().map_err(CliError::Runtime)
}

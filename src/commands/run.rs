//! `close2gl [MODEL]`: the interactive viewer, both views and the control panel.

use std::path::PathBuf;
use std::sync::Arc;

use close2gl_trace::view::{TraceRequest, TraceView};
use close2gl_viewer::{Recording, ViewerOptions, ViewerPlugin};

use super::CliError;
use super::scene_args::{SceneArgs, print_warnings, viewport};
use crate::watch::WatchPlugin;
use close2gl_config::Config;

/// Frames drawn before `--screenshot` saves one, when `--exit-after-frames` does not say.
const SCREENSHOT_FRAMES: u32 = 5;

#[derive(clap::Args, Debug, Default)]
pub struct RunArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// The window's size, WIDTHxHEIGHT (default: window.width x window.height from the config).
    #[arg(long, value_name = "WxH")]
    pub size: Option<String>,
    /// Save the window as PNG after the last frame (see --exit-after-frames; default 5, or the
    /// last frame of --replay), then exit. With window.layout = "windows", both windows side by
    /// side.
    #[arg(long, value_name = "FILE")]
    pub screenshot: Option<PathBuf>,
    /// Draw this many frames, then exit.
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..))]
    pub exit_after_frames: Option<u32>,
    /// Where the screenshot key (F12) saves both views and the command that renders them.
    #[arg(long, value_name = "DIR", default_value = ".")]
    pub screenshot_dir: PathBuf,
    /// Reload the model, its texture and the config file when they change on disk, keeping the
    /// camera where it is.
    #[arg(long)]
    pub watch: bool,
    /// Write every frame's input to FILE (one JSON line a frame), for --replay.
    #[arg(long, value_name = "FILE", conflicts_with = "replay")]
    pub record: Option<PathBuf>,
    /// Play FILE's input back, frame by frame with its recorded time steps (the window opens at
    /// the recorded size; live input is ignored meanwhile), then exit (see --keep-open).
    #[arg(long, value_name = "FILE", conflicts_with = "size")]
    pub replay: Option<PathBuf>,
    /// Show a program's trace (close2gl-trace 1) as the Close2GL view, with its camera and
    /// settings, beside the reference, and check's report on it in the panel (docs/checking.md).
    /// A raster trace (close2gl-raster 1, told by its first line) shows the program's framebuffer
    /// as the Close2GL view and close2gl's drawing of its triangles as the reference, a fixed
    /// frame, with check's raster report (docs/viewer.md). With --watch, the trace is read again
    /// when the program writes it again.
    #[arg(long, value_name = "FILE")]
    pub trace: Option<PathBuf>,
    /// After --replay, stay open for live input instead of exiting.
    #[arg(long, requires = "replay", conflicts_with = "exit_after_frames")]
    pub keep_open: bool,
}

pub fn run(args: RunArgs) -> Result<(), CliError> {
    let replay = args
        .replay
        .as_deref()
        .map(Recording::read)
        .transpose()
        .map_err(CliError::Input)?;
    let (scene, config, size) = scene_and_size(&args, replay.as_ref())?;
    // The first frame's layout replaces this with the views' real size.
    let mut app = close2gl_app::build_app(&config, size).map_err(CliError::Input)?;
    print_warnings(&app);
    if let Some(path) = &args.trace {
        open_trace_at_start(&mut app, path)?;
    }
    let (exit_after_frames, screenshot_frame) = last_frames(&args, replay.as_ref());
    if args.watch {
        app.add_plugins(watch(scene.clone()));
    }
    app.add_plugins(ViewerPlugin(ViewerOptions {
        layout: config.window.layout,
        width: size.width,
        height: size.height,
        fit_to_monitor: replay.is_none() && args.size.is_none(),
        screenshot: args.screenshot,
        screenshot_frame,
        exit_after_frames,
        screenshot_dir: args.screenshot_dir,
        record: args.record,
        scene: scene.words(),
        replay,
    }));
    app.run().map_err(CliError::Runtime)
}

/// Shows the trace (geometry or raster) at `path` from the first frame on; a trace that does
/// not read or does not fit the model is an error here, before anything is shown.
fn open_trace_at_start(
    app: &mut close2gl_core::App,
    path: &std::path::Path,
) -> Result<(), CliError> {
    app.world_mut().resource_mut::<TraceRequest>().0 = Some(path.to_path_buf());
    app.update();
    match &app.world().resource::<TraceView>().error {
        Some(error) => Err(CliError::Input(error.clone())),
        None => Ok(()),
    }
}

/// The scene (a replay given none shows the one it was recorded on), its configuration, and
/// the size of the views (a replay's own).
fn scene_and_size(
    args: &RunArgs,
    replay: Option<&Recording>,
) -> Result<(SceneArgs, Config, close2gl_core::Viewport), CliError> {
    let scene = match replay {
        Some(recording) if args.scene.is_empty() => {
            SceneArgs::from_words(&recording.header.scene).map_err(CliError::Input)?
        }
        _ => args.scene.clone(),
    };
    let config = scene.config()?;
    let size = match replay {
        Some(recording) => close2gl_core::Viewport {
            width: recording.header.size[0],
            height: recording.header.size[1],
        },
        None => viewport(args.size.as_deref(), &config)?,
    };
    Ok((scene, config, size))
}

/// The frame after which the app exits, and the one the screenshot is taken on: a replay's
/// last (staying open with --keep-open); else as asked, a screenshot waiting a few frames.
fn last_frames(args: &RunArgs, replay: Option<&Recording>) -> (Option<u32>, Option<u32>) {
    match replay {
        Some(recording) => {
            let frames = recording.frames.len() as u32;
            ((!args.keep_open).then_some(frames), Some(frames))
        }
        None => {
            let exit = args
                .exit_after_frames
                .or(args.screenshot.is_some().then_some(SCREENSHOT_FRAMES));
            (exit, exit)
        }
    }
}

/// Watches the scene's files, reloading its configuration when one changes.
fn watch(scene: SceneArgs) -> WatchPlugin {
    WatchPlugin {
        config_file: close2gl_config::file_to_read(scene.config.as_deref()),
        reload: Arc::new(move || {
            scene.config().map_err(|e| match e {
                CliError::Input(m) | CliError::Runtime(m) => m,
                CliError::Verdict | CliError::Interrupted => "the configuration was refused".into(),
            })
        }),
    }
}

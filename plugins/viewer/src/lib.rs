//! The interactive viewer: winit windows with wgpu surfaces, the egui control panel, and the
//! event loop that drives the app. It owns the windows (one split window, or a "Reference
//! (wgpu)" and a "Close2GL" window), turns window events into `InputState` (keys, drags,
//! scroll) and dropped files into `ModelRequest` (an image into `TextureRequest`), places the
//! views before each frame (`ViewPlacement`, from which its system keeps `Viewport` equal to the
//! Close2GL view's size), runs one app frame per redraw, and draws both views and the panel (skipping a window
//! without pixels, drawing one wider than the GPU's largest texture up to that size, and ending
//! the run with its reason when the GPU device is lost). It inserts the `Gpu`
//! and `Views` resources the GPU plugin's upload systems need (and the `OutsideRenderer` of the
//! third view, the pipeline seen from outside, a third column of the split layout, whose orbit
//! camera takes the drags and scrolls over it), and fills `ViewStats`. Redraws
//! are on demand (input, held keys, the panel's own animations, a `Wake` from background work),
//! so an idle viewer sleeps. A Ctrl+click is answered by its probe system
//! (`pixel_probe::answer_probe`, asking the probe's one home, `close2gl_gpu::ProbedFrame`), which
//! writes `ProbeAnswer` (a type of the ui crate) and `SelectedTriangle`. After drawing it
//! carries out the screenshot key (`ToolRequests::screenshot`: both views as PNGs beside the
//! command that renders them again, and a `Notice`) and a comparison of the views
//! (`ToolRequests::compare_views`, into `ViewStats`), and records or replays every frame's input
//! (`--record`, `--replay`). It adds the GPU and UI plugins unless the app has them, and needs
//! the input, model, settings and Close2GL plugins' resources (checked before the windows
//! open). Its event loop only sizes (input, layout), updates (the app's frame), draws and
//! presents.

mod acquire;
#[cfg(target_arch = "wasm32")]
pub mod browser;
mod draw;
mod frame_capture;
mod gui;
mod handler;
pub mod input_tracker;
mod orbit_input;
mod pacing;
pub mod pixel_probe;
pub mod placed_views;
mod present;
mod recording;
mod routing;
mod screenshot;
mod session;
mod surface;
mod surface_source;
pub mod view_layout;
mod windows;

use std::path::PathBuf;

use bevy_ecs::prelude::*;
pub use close2gl_core::Layout;
use close2gl_core::Owner;
use close2gl_core::{
    App, Fates, FrameSet, InputState, ModelRequest, OutputStep, PipelineSettings, Plugin,
    SelectedTriangle, Update, Viewport, Wake,
};
use close2gl_gpu::Gpu;
pub use recording::Recording;
pub use routing::drop_file;
use winit::event_loop::{ControlFlow, EventLoop};

#[derive(Clone, Debug, PartialEq)]
pub struct ViewerOptions {
    pub layout: Layout,
    /// Inner size of the window (split), or of both windows together (windows), in pixels.
    pub width: u32,
    pub height: u32,
    /// Shrink that size to fit the monitor the windows open on (the configured size; a size
    /// given with `--size` or by a recording is kept as asked).
    pub fit_to_monitor: bool,
    /// Save the window's frame as PNG after `screenshot_frame` frames. In the windows layout
    /// the two windows are saved side by side in one image.
    pub screenshot: Option<PathBuf>,
    pub screenshot_frame: Option<u32>,
    /// Exit after drawing this many frames (drawing continuously until then).
    pub exit_after_frames: Option<u32>,
    /// Where the screenshot key saves both views and the command that renders them again.
    pub screenshot_dir: PathBuf,
    /// `--record`: every frame's input written to this file.
    pub record: Option<PathBuf>,
    /// The command line's words that chose the scene, for a recording's header.
    pub scene: Vec<String>,
    /// `--replay`: the frames' input taken from this recording instead of the window system.
    pub replay: Option<Recording>,
}

/// Adds the GPU upload systems, the panel (unless the app has them already) and the viewer's
/// own systems ([`ViewerSystemsPlugin`]), and makes `app.run()` open the windows and run the
/// event loop until they close.
pub struct ViewerPlugin(pub ViewerOptions);

impl Plugin for ViewerPlugin {
    fn build(&self, app: &mut App) {
        app.add_plugin_once(close2gl_gpu::GpuPlugin)
            .add_plugin_once(close2gl_gpu::outside::OutsidePlugin)
            .add_plugin_once(close2gl_ui::UiPlugin)
            .add_plugin_once(ViewerSystemsPlugin)
            .requires::<ModelRequest>(Owner::Model)
            .requires::<Wake>(Owner::Settings);
        let options = self.0.clone();
        app.set_runner(move |app| run(app, options));
    }
}

/// The viewer's systems in the frame: the `Viewport` from the views it placed
/// (`placed_views::set_viewport`, in `FrameSet::Input`), and the Ctrl+click probe answered once
/// the frame is uploaded (`pixel_probe::answer_probe`, in `OutputStep::Report`, while there is
/// a `Gpu`). [`ViewerPlugin`] adds it; an app that runs the viewer's frames without windows
/// (a test's) may add it alone.
pub struct ViewerSystemsPlugin;

impl Plugin for ViewerSystemsPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<placed_views::ViewPlacement>()
            .requires::<InputState>(Owner::Input)
            .requires::<Viewport>(Owner::Settings)
            .requires::<PipelineSettings>(Owner::Settings)
            .requires::<SelectedTriangle>(Owner::Settings)
            .requires::<Fates>(Owner::Close2gl)
            .add_systems(Update, placed_views::set_viewport.in_set(FrameSet::Input));
        #[cfg(not(target_arch = "wasm32"))]
        let probe = pixel_probe::answer_probe;
        #[cfg(target_arch = "wasm32")]
        let probe = (pixel_probe::answer_probe, pixel_probe::arrive_probe).chain();
        app.add_systems(
            Update,
            probe
                .in_set(OutputStep::Report)
                .run_if(resource_exists::<Gpu>),
        );
    }
}

/// Opens the windows and runs `app` until they close (or the screenshot is taken).
#[cfg(not(target_arch = "wasm32"))]
pub fn run(app: App, options: ViewerOptions) -> Result<(), String> {
    let event_loop = EventLoop::new().map_err(|e| {
        format!("cannot open a window: {e} (no display? set DISPLAY, or run under Xvfb)")
    })?;
    event_loop.set_control_flow(ControlFlow::Wait);
    let instance = surface_source::instance(&event_loop.owned_display_handle());
    let session = session::Session::for_options(&options)?;
    let mut viewer = handler::Viewer::new(app, options, session, instance);
    event_loop
        .run_app(&mut viewer)
        .map_err(|e| format!("the window system failed: {e}"))?;
    viewer.finish()
}

/// Starts the viewer on the page's canvas; it runs after this returns, for as long as the page
/// lives (the event loop is the browser's, which winit hands the viewer to).
#[cfg(target_arch = "wasm32")]
pub fn run(app: App, options: ViewerOptions) -> Result<(), String> {
    use winit::platform::web::EventLoopExtWebSys;
    wasm_bindgen_futures::spawn_local(async move {
        let instance = browser::instance().await;
        let event_loop = match EventLoop::new() {
            Ok(event_loop) => event_loop,
            Err(e) => return browser::report(&format!("cannot start the page's event loop: {e}")),
        };
        event_loop.set_control_flow(ControlFlow::Wait);
        let session = match session::Session::for_options(&options) {
            Ok(session) => session,
            Err(e) => return browser::report(&e),
        };
        let connections = surface_source::Connections::Winit;
        let viewer = handler::Viewer::new(app, options, session, (instance, connections));
        event_loop.spawn_app(viewer);
    });
    Ok(())
}

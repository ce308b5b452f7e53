//! close2gl as a library: the default plugins, the configuration, and the app builder the
//! command line uses. A user's own program does the same:
//!
//! ```no_run
//! use close2gl::DefaultPlugins;
//! use close2gl::core::bevy_ecs::prelude::*;
//! use close2gl::core::{App, Close2glFrame, FrameSet, Plugin, Update};
//!
//! /// Prints how many triangles Close2GL drew, where each frame's results go out.
//! struct DrawnCount;
//!
//! impl Plugin for DrawnCount {
//!     fn build(&self, app: &mut App) {
//!         app.add_systems(Update, print_drawn.in_set(FrameSet::Output));
//!     }
//! }
//!
//! fn print_drawn(frame: Res<Close2glFrame>) {
//!     println!("{} triangles drawn", frame.counts.drawn);
//! }
//!
//! let mut app = App::new();
//! app.add_plugins(DefaultPlugins).add_plugins(DrawnCount);
//! app.update();
//! ```

// The command line and --watch run processes, threads and terminals: not in a browser.
#[cfg(not(target_arch = "wasm32"))]
pub mod commands;
pub mod config;
mod progress_bar;
#[cfg(not(target_arch = "wasm32"))]
pub mod watch;

pub use close2gl_camera as camera;
pub use close2gl_core as core;
pub use close2gl_input as input;
pub use close2gl_model as model;
pub use close2gl_pipeline as pipeline;
pub use close2gl_raster as raster;

use close2gl_core::bevy_ecs::world::World;
use close2gl_core::{
    App, Camera, ModelRequest, ModelStatus, Plugin, SettingsPlugin, TextureRequest, Viewport,
};

use config::Config;

/// Everything headless: the shared settings, model loading, the camera, input mapping, the
/// Close2GL pipeline and its software rasterizer, a program's trace shown in its place, and the
/// copied command's writer (`config::command`). The GPU renderers and the windows are added on
/// top by the commands that need them. A plugin already in the app is not added again, so an app
/// may add one of these by hand first.
pub struct DefaultPlugins;

impl Plugin for DefaultPlugins {
    fn build(&self, app: &mut App) {
        app.add_plugin_once(SettingsPlugin)
            .add_plugin_once(close2gl_model::ModelPlugin)
            .add_plugin_once(close2gl_camera::CameraPlugin)
            .add_plugin_once(close2gl_input::InputPlugin)
            .add_plugin_once(close2gl_pipeline::Close2glPlugin)
            .add_plugin_once(close2gl_raster::RasterPlugin)
            .add_plugin_once(close2gl_trace::TracePlugin)
            .add_plugin_once(config::command::CommandPlugin);
    }
}

/// Builds the headless app for `config` and runs one frame, in which the model plugin loads the
/// configured model (and texture), the camera frames it and the Close2GL frame is computed; a
/// big model file loads on a worker thread meanwhile, with its progress on stderr, and the app
/// runs frames until it is in. A model or texture that does not load is an error here, before
/// anything is shown.
pub fn build_app(config: &Config, viewport: Viewport) -> Result<App, String> {
    let mut app = App::new();
    apply_settings(app.world_mut(), config);
    app.insert_resource(config.camera.speeds)
        .insert_resource(viewport)
        .insert_resource(ModelRequest(Some(config.model.clone())))
        .insert_resource(TextureRequest(config.texture.clone()))
        .add_plugins(DefaultPlugins);
    let mut camera = Camera::default();
    config.camera.set_lens(&mut camera);
    app.world_mut().spawn(camera);
    app.update();
    wait_for_model(&mut app);
    match &app.world().resource::<ModelStatus>().error {
        Some(error) => Err(error.clone()),
        None => Ok(app),
    }
}

/// The settings of `config` that a running app takes as they are: render switches, lighting,
/// primitives, the outside view, key bindings and the framing rules (the camera, the model and the speeds are the
/// caller's, who knows whether they are new).
pub fn apply_settings(world: &mut World, config: &Config) {
    config.render.insert_into(world);
    world.insert_resource(config.lighting);
    world.insert_resource(config.primitives);
    world.insert_resource(config.outside);
    world.insert_resource(config.input.clone());
    world.insert_resource(config.camera.framing());
}

/// Runs frames until a model loading in the background is in, showing its progress.
fn wait_for_model(app: &mut App) {
    /// Often enough for a bar that moves, rarely enough that the frames cost nothing.
    const POLL: std::time::Duration = std::time::Duration::from_millis(50);
    let Some(loading) = app.world().resource::<ModelStatus>().loading.clone() else {
        return;
    };
    let mut bar = progress_bar::TerminalProgress::new(&loading.source);
    while let Some(loading) = &app.world().resource::<ModelStatus>().loading {
        bar.show(loading.fraction);
        std::thread::sleep(POLL);
        app.update();
    }
    bar.finish(app.world().resource::<ModelStatus>().error.is_none());
}

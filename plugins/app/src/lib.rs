//! The headless app: [`DefaultPlugins`] (every plugin that needs no GPU and no window) and
//! [`build_app`], which turns a configuration into an app with its model loaded. It reads a
//! `close2gl_config::Config` and writes the settings resources it names (`apply_settings`), the
//! model and texture requests, the viewport and the camera; a big model's loading progress goes
//! to stderr (`progress_bar.rs`, which the grade command's progress uses too). The GPU renderers
//! and the windows are added on top by whoever shows the app: the commands, the web page.

pub mod progress_bar;

use close2gl_config::Config;
use close2gl_core::bevy_ecs::world::World;
use close2gl_core::{
    App, Camera, ModelRequest, ModelStatus, Plugin, SettingsPlugin, TextureRequest, Viewport,
    insert_if_changed,
};

/// Everything headless: the shared settings, model loading, the camera, input mapping, the
/// Close2GL pipeline and its software rasterizer, a program's trace shown in its place, and the
/// copied command's writer (`close2gl_config::command`). The GPU renderers and the windows are
/// added on top by the commands that need them. A plugin already in the app is not added again,
/// so an app may add one of these by hand first.
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
            .add_plugin_once(close2gl_config::command::CommandPlugin);
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
/// primitives, the outside view, key bindings and the framing rules (the camera, the model and
/// the speeds are the caller's, who knows whether they are new).
pub fn apply_settings(world: &mut World, config: &Config) {
    // Each only where its value changed: a reload wakes only the systems that follow it.
    config.render.insert_into(world);
    insert_if_changed(world, config.lighting);
    insert_if_changed(world, config.primitives);
    insert_if_changed(world, config.outside);
    insert_if_changed(world, config.input.clone());
    insert_if_changed(world, config.camera.framing());
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

#[cfg(test)]
mod tests {
    use close2gl_core::CommandLine;

    use super::*;

    #[test]
    fn the_default_plugins_give_the_app_its_command_writer() {
        let mut app = App::new();
        app.add_plugins(DefaultPlugins);
        let write = app.world().get_resource::<CommandLine>().map(|c| c.0);
        assert!(
            write.is_some_and(|write| write(app.world_mut(), "out").is_none()),
            "no model shown yet, nothing to write"
        );
    }
}

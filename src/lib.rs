//! close2gl as a library: the default plugins, the configuration, and the app builder the
//! command line uses. A user's own program does the same:
//!
//! ```no_run
//! use close2gl::{DefaultPlugins, core::{App, Plugin, Update}};
//!
//! struct Hello;
//! impl Plugin for Hello {
//!     fn build(&self, app: &mut App) {
//!         app.add_systems(Update, || println!("a frame"));
//!     }
//! }
//!
//! let mut app = App::new();
//! app.add_plugins(DefaultPlugins).add_plugins(Hello);
//! app.update();
//! ```

pub mod commands;
pub mod config;

pub use close2gl_camera as camera;
pub use close2gl_core as core;
pub use close2gl_input as input;
pub use close2gl_model as model;
pub use close2gl_pipeline as pipeline;
pub use close2gl_raster as raster;

use close2gl_core::{
    App, Camera, CameraActions, Close2glFrame, Framing, InputState, ModelRequest, ModelStatus,
    Plugin, Viewport,
};

use config::Config;

/// Everything headless: model loading, input mapping, the camera, the Close2GL pipeline and its
/// software rasterizer.
/// The GPU renderers and the windows are added on top by the commands that need them.
pub struct DefaultPlugins;

impl Plugin for DefaultPlugins {
    fn build(&self, app: &mut App) {
        app.add_plugins(close2gl_model::ModelPlugin)
            .add_plugins(close2gl_input::InputPlugin)
            .add_plugins(close2gl_camera::CameraPlugin)
            .add_plugins(close2gl_pipeline::Close2glPlugin)
            .add_plugins(close2gl_raster::RasterPlugin);
    }
}

/// Builds the headless app for `config` with its model already loaded (a model that does not
/// load is an error here, before anything is shown) and one frame run, so the camera is framed
/// and the Close2GL frame computed.
pub fn build_app(config: &Config, viewport: Viewport) -> Result<App, String> {
    let loaded = close2gl_model::load(&config.model, &config.primitives)?;
    let mut app = App::new();
    app.insert_resource(config.render)
        .insert_resource(config.lighting)
        .insert_resource(config.primitives)
        .insert_resource(config.camera.speeds)
        .insert_resource(config.input.clone())
        .insert_resource(viewport)
        .insert_resource(Framing {
            pose: config.camera.pose().map(|p| [p.position, p.target, p.up]),
            near: config.camera.near,
            far: config.camera.far,
        })
        .init_resource::<InputState>()
        .init_resource::<CameraActions>()
        .init_resource::<Close2glFrame>()
        .init_resource::<ModelRequest>()
        .insert_resource(ModelStatus {
            source: Some(config.model.clone()),
            warnings: loaded.warnings,
            error: None,
            generation: 1,
        })
        .add_plugins(DefaultPlugins);
    let world = app.world_mut();
    world.spawn(Camera {
        hfov: config.camera.hfov,
        vfov: config.camera.vfov,
        mode: config.camera.mode,
        ..Camera::default()
    });
    world.spawn(loaded.mesh);
    app.update();
    Ok(app)
}

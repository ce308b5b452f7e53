//! The TOML configuration: every setting with its default, read from a file (`config.toml`)
//! and then from `--set section.key=value` overrides, each key checked for type and range as it
//! is set. It owns [`Config`], the key table both directions go through ([`keys::KEYS`]), the
//! config ↔ `Camera` mapping (`camera.rs`) and [`command::CommandPlugin`], whose "copy as
//! command" reads what the world shows (the camera, the model and the settings resources) back
//! into a configuration and writes it as a `close2gl render` line: the one resource it inserts
//! is the app's `CommandLine`. Turning a configuration into an app is `close2gl_app`'s.

mod camera;
pub mod command;
pub mod keys;
mod load;

use std::path::{Path, PathBuf};

pub use close2gl_core::Layout;
use close2gl_core::bevy_ecs::world::World;
use close2gl_core::glam::Vec3;
use close2gl_core::limits::DEFAULT_FOV;
use close2gl_core::{
    Appearance, CameraMode, CameraSpeeds, InputBindings, Lighting, ModelSource, OutsideView,
    Overlay, PipelineSettings, PrimitiveParams, insert_if_changed,
};

pub use keys::parse_stage;
pub use load::{file_to_read, load, load_text, parse_size};

/// `[camera]`: the optional pose and the lens; near and far follow the model unless pinned. How
/// it reaches the app's `Camera`, and how a camera is written back as one: `camera.rs`.
#[derive(Clone, Debug, PartialEq)]
pub struct CameraConfig {
    pub position: Option<Vec3>,
    pub target: Option<Vec3>,
    pub up: Vec3,
    /// `camera.u`, `camera.v`, `camera.n`: an exact basis (all three or none), as a copied
    /// view's command gives it.
    pub u: Option<Vec3>,
    pub v: Option<Vec3>,
    pub n: Option<Vec3>,
    pub hfov: f32,
    pub vfov: f32,
    pub near: Option<f32>,
    pub far: Option<f32>,
    pub mode: CameraMode,
    pub speeds: CameraSpeeds,
}

/// `[render]`: read straight into the three resources the app holds, each for its own readers,
/// so that applying it wakes only the readers of a part whose value changed.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RenderConfig {
    pub pipeline: PipelineSettings,
    pub appearance: Appearance,
    /// The inspector's display over both views.
    pub overlay: Overlay,
}

impl RenderConfig {
    /// Inserts each part that differs from what `world` holds.
    pub fn insert_into(self, world: &mut World) {
        insert_if_changed(world, self.pipeline);
        insert_if_changed(world, self.appearance);
        insert_if_changed(world, self.overlay);
    }

    /// The table `world` shows, `None` while one of its three resources is missing.
    pub fn of_world(world: &World) -> Option<Self> {
        Some(Self {
            pipeline: *world.get_resource()?,
            appearance: *world.get_resource()?,
            overlay: *world.get_resource()?,
        })
    }
}

/// `[window]`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WindowConfig {
    pub width: u32,
    pub height: u32,
    pub layout: Layout,
}

/// The whole configuration, defaults first (see config.toml at the repository's root).
#[derive(Clone, Debug, PartialEq)]
pub struct Config {
    pub model: ModelSource,
    /// `[model] texture`: a PNG or JPEG file (relative to the config file) for a model with
    /// texture coordinates; without it, such a model gets the course's checkerboard.
    pub texture: Option<PathBuf>,
    pub camera: CameraConfig,
    pub render: RenderConfig,
    pub lighting: Lighting,
    pub primitives: PrimitiveParams,
    pub window: WindowConfig,
    pub input: InputBindings,
    /// `[outside]`: the outside view shown or not, and its stage.
    pub outside: OutsideView,
}

impl Default for Config {
    fn default() -> Self {
        Self {
            model: ModelSource::File(default_model_path()),
            texture: None,
            camera: CameraConfig {
                position: None,
                target: None,
                up: Vec3::Y,
                u: None,
                v: None,
                n: None,
                hfov: DEFAULT_FOV,
                vfov: DEFAULT_FOV,
                near: None,
                far: None,
                mode: CameraMode::Free,
                speeds: CameraSpeeds::default(),
            },
            render: RenderConfig::default(),
            lighting: Lighting::default(),
            primitives: PrimitiveParams::default(),
            // Two square 700-pixel views beside the panel: with hfov = vfov nothing is stretched.
            window: WindowConfig {
                width: 1690,
                height: 700,
                layout: Layout::Split,
            },
            input: InputBindings::default(),
            outside: OutsideView::default(),
        }
    }
}

/// The bundled model the app opens when nothing else is asked for.
pub fn default_model_path() -> PathBuf {
    repository_root().join("assets/knot.obj")
}

/// The checkout this crate was built in: two folders above `plugins/config`.
fn repository_root() -> &'static Path {
    let crate_dir = Path::new(env!("CARGO_MANIFEST_DIR"));
    crate_dir.ancestors().nth(2).unwrap_or(crate_dir)
}

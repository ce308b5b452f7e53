//! close2gl as a library: the command line's commands and `--watch`, over the default plugins,
//! the configuration and the app builder (`close2gl_app`, `close2gl_config`), which it shows
//! under its own name. A user's own program does the same:
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

// The command line and --watch run processes, threads and terminals: this crate is never built
// for a browser (the web page builds on close2gl_app and close2gl_config).
pub mod commands;
pub mod watch;

pub use close2gl_app::{DefaultPlugins, apply_settings, build_app};
pub use close2gl_camera as camera;
pub use close2gl_config as config;
pub use close2gl_core as core;
pub use close2gl_input as input;
pub use close2gl_model as model;
pub use close2gl_pipeline as pipeline;
pub use close2gl_raster as raster;

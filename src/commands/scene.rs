//! The arguments every command shares: which model, which config, which overrides.

use std::path::PathBuf;

use close2gl_core::{App, ModelSource, ModelStatus, Viewport};

use super::CliError;
use crate::config::{self, Config};

#[derive(clap::Args, Debug, Clone, Default)]
pub struct SceneArgs {
    /// A .in or .obj file, or a primitive's name: box, sphere, torus, cone, cylinder.
    pub model: Option<String>,
    /// The TOML configuration (default: ./config.toml when present, else built-in defaults).
    #[arg(long, value_name = "FILE")]
    pub config: Option<PathBuf>,
    /// Overrides one config key, e.g. --set camera.hfov=45 --set render.mode=wireframe.
    #[arg(long = "set", value_name = "SECTION.KEY=VALUE")]
    pub set: Vec<String>,
}

impl SceneArgs {
    /// The configuration with the overrides and the MODEL argument applied.
    pub fn config(&self) -> Result<Config, CliError> {
        let mut config =
            config::load(self.config.as_deref(), &self.set).map_err(CliError::Input)?;
        if let Some(model) = &self.model {
            config.model = ModelSource::parse(model);
        }
        Ok(config)
    }
}

/// `--size WxH`, or the configured window size.
pub fn viewport(size: Option<&str>, config: &Config) -> Result<Viewport, CliError> {
    let (width, height) = match size {
        Some(text) => config::parse_size(text).map_err(CliError::Input)?,
        None => (config.window.width, config.window.height),
    };
    Ok(Viewport { width, height })
}

/// What the loader forgave about the model (a header that lies about its triangle count, say),
/// one line each on stderr.
pub fn print_warnings(app: &App) {
    for warning in &app.world().resource::<ModelStatus>().warnings {
        eprintln!("close2gl: warning: {warning}");
    }
}

//! The arguments every command shares: which model, which config, which overrides.

use std::path::PathBuf;

use close2gl_core::{App, ModelSource, ModelStatus, RecordFates, Viewport};

use super::CliError;
use close2gl_config::{self as config, Config};

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

/// The scene's words alone, parsed as the command line parses them.
#[derive(clap::Parser)]
struct SceneWords {
    #[command(flatten)]
    scene: SceneArgs,
}

impl SceneArgs {
    /// Nothing given: the config file's (or the defaults') scene.
    pub fn is_empty(&self) -> bool {
        self.model.is_none() && self.config.is_none() && self.set.is_empty()
    }

    /// The command-line words that give this scene, `[MODEL] [--config FILE] [--set ...]`,
    /// with files as absolute paths so that the words mean the same from any directory.
    pub fn words(&self) -> Vec<String> {
        let absolute = |path: &str| match std::fs::canonicalize(path) {
            Ok(path) => path.display().to_string(),
            Err(_) => path.to_string(),
        };
        let mut words: Vec<String> = self.model.iter().map(|m| absolute(m)).collect();
        if let Some(config) = &self.config {
            words.extend(["--config".into(), absolute(&config.display().to_string())]);
        }
        for set in &self.set {
            words.extend(["--set".into(), set.clone()]);
        }
        words
    }

    /// The scene `words` (as [`SceneArgs::words`] writes them) give.
    pub fn from_words(words: &[String]) -> Result<SceneArgs, String> {
        use clap::Parser;
        let all = std::iter::once("close2gl".to_string()).chain(words.iter().cloned());
        SceneWords::try_parse_from(all)
            .map(|w| w.scene)
            .map_err(|e| format!("the recorded scene {words:?}: {}", e.kind()))
    }

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

/// Records every triangle's fate from now on (the headless commands report them), and runs one
/// more frame so that the current one is recorded.
pub fn record_fates(app: &mut App) {
    app.world_mut().resource_mut::<RecordFates>().0 = true;
    app.update();
}

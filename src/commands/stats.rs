//! `close2gl stats`: the Close2GL pipeline once, headless; its counts as one JSON object.

use std::path::PathBuf;

use super::CliError;
use super::scene::{SceneArgs, viewport};

#[derive(clap::Args, Debug, Default)]
pub struct StatsArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// The viewport, WIDTHxHEIGHT (default: the configured window size).
    #[arg(long, value_name = "WxH")]
    pub size: Option<String>,
    /// Also write the 2D buffer: .json (an object) or anything else (CSV, one vertex a line).
    #[arg(long, value_name = "FILE")]
    pub dump: Option<PathBuf>,
}

pub fn run(_args: StatsArgs) -> Result<(), CliError> {
    Err(CliError::Runtime("stats: not built yet".into()))
}

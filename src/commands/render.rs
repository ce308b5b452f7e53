//! Placeholder until the render command lands.

use super::CliError;

#[derive(clap::Args, Debug, Default)]
pub struct RenderArgs {}

pub fn run(_args: RenderArgs) -> Result<(), CliError> {
    Err(CliError::Runtime("the render command is not built yet".into()))
}

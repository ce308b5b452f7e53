//! Placeholder until the run command lands.

use super::CliError;

#[derive(clap::Args, Debug, Default)]
pub struct RunArgs {}

pub fn run(_args: RunArgs) -> Result<(), CliError> {
    Err(CliError::Runtime("the run command is not built yet".into()))
}

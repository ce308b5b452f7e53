//! Placeholder until the bench command lands.

use super::CliError;

#[derive(clap::Args, Debug, Default)]
pub struct BenchArgs {}

pub fn run(_args: BenchArgs) -> Result<(), CliError> {
    Err(CliError::Runtime("the bench command is not built yet".into()))
}

//! One module per subcommand; each parses its own arguments and returns a [`CliError`].

pub mod bench;
pub mod check;
pub mod grade;
pub mod inspect;
pub mod render;
pub mod run;
pub mod scene;
pub mod stats;

use std::process::ExitCode;

/// A failure the user caused (exit 2: bad model, bad config, bad argument) or one the machine
/// caused (exit 1: no GPU adapter, an unwritable output).
#[derive(Debug)]
pub enum CliError {
    Input(String),
    Runtime(String),
    /// The command ran and its answer is no (`check` found a difference): exit 1, its report
    /// already printed.
    Verdict,
    /// Ctrl+C (or SIGTERM, SIGHUP) stopped `grade`: exit 130, as a shell reports SIGINT.
    Interrupted,
}

/// Prints the one-line error and maps it to the process exit code.
pub fn exit(result: Result<(), CliError>) -> ExitCode {
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(CliError::Input(message)) => {
            eprintln!("close2gl: {message}");
            ExitCode::from(2)
        }
        Err(CliError::Runtime(message)) => {
            eprintln!("close2gl: {message}");
            ExitCode::from(1)
        }
        Err(CliError::Verdict) => ExitCode::from(1),
        Err(CliError::Interrupted) => {
            eprintln!("close2gl: grading interrupted; nothing was written");
            ExitCode::from(130)
        }
    }
}

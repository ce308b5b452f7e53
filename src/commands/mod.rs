//! One module per subcommand; each parses its own arguments and returns a [`CliError`].

pub mod bench;
pub mod check;
pub mod grade;
pub mod inspect;
pub mod render;
pub mod run;
pub mod scene_args;
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

/// A command line clap refused, as the one-line error every bad input gets (clap's own message
/// has a usage block after it). `--help` and `--version` are printed as clap prints them (exit
/// 0), and so is the help a command without its required arguments shows (exit 2).
pub fn usage(error: clap::Error) -> CliError {
    use clap::error::ErrorKind;
    match error.kind() {
        ErrorKind::DisplayHelp | ErrorKind::DisplayVersion => {
            let _ = error.print();
            std::process::exit(0);
        }
        ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand => {
            let _ = error.print();
            std::process::exit(2);
        }
        _ => {}
    }
    // The message is clap's first paragraph (a list of missing arguments continues it on the
    // lines below), before its usage block.
    let text = error.render().to_string();
    let paragraph: Vec<&str> = text
        .lines()
        .take_while(|line| !line.trim().is_empty())
        .map(str::trim)
        .collect();
    let message = paragraph.join(" ");
    let message = message.strip_prefix("error: ").unwrap_or(&message);
    CliError::Input(format!("{message} (see --help)"))
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

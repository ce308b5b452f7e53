//! `close2gl check MODEL TRACE`: a program's trace of one frame against close2gl's pipeline,
//! stage by stage, and the catalogue mistake that reproduces it (docs/checking.md).

use std::path::{Path, PathBuf};

use close2gl_check::{Report, picture, report};
use close2gl_core::{Mesh, ModelSource, PrimitiveParams};
use close2gl_trace_format::{Trace, read_trace};

use super::CliError;

#[derive(clap::Args, Debug)]
pub struct CheckArgs {
    /// The model the program drew: a .in or .obj file, or a primitive's name.
    pub model: String,
    /// The trace the program wrote (close2gl-trace 1).
    pub trace: PathBuf,
    /// Print the report as one JSON object.
    #[arg(long)]
    pub json: bool,
    /// Also write close2gl's 2D output, the trace's and their difference (PNG), and the report.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
}

/// Exit 0 when everything the trace gives agrees, 1 when something differs, 2 for bad input.
pub fn run(args: CheckArgs) -> Result<(), CliError> {
    let mesh = load_model(&args.model)?;
    let trace = read_trace(&args.trace).map_err(|e| CliError::Input(e.to_string()))?;
    let report =
        close2gl_check::check(&mesh, &trace).map_err(|e| CliError::Input(e.to_string()))?;
    let name = args.trace.display().to_string();
    let text = report::text(&report, &name);
    let json = report::json(&report);
    if let Some(dir) = &args.out {
        write_out(dir, &report, &trace, &text, &json)?;
    }
    match args.json {
        true => println!("{json}"),
        false => print!("{text}"),
    }
    match report.agrees() {
        true => Ok(()),
        false => Err(CliError::Verdict),
    }
}

/// The model as the pipeline sees it; an error names the file and line.
pub fn load_model(model: &str) -> Result<Mesh, CliError> {
    let source = ModelSource::parse(model);
    let loaded =
        close2gl_model::load(&source, &PrimitiveParams::default()).map_err(CliError::Input)?;
    Ok(loaded.mesh)
}

fn write_out(
    dir: &Path,
    report: &Report,
    trace: &Trace,
    text: &str,
    json: &serde_json::Value,
) -> Result<(), CliError> {
    let fail =
        |e: std::io::Error| CliError::Runtime(format!("{}: cannot write: {e}", dir.display()));
    std::fs::create_dir_all(dir).map_err(fail)?;
    let [ours, theirs, difference] = picture::pictures(report, trace);
    for (image, name) in [
        (ours, "close2gl.png"),
        (theirs, "trace.png"),
        (difference, "difference.png"),
    ] {
        image
            .write_png(&dir.join(name))
            .map_err(CliError::Runtime)?;
    }
    std::fs::write(dir.join("report.txt"), text).map_err(fail)?;
    std::fs::write(dir.join("report.json"), format!("{json:#}\n")).map_err(fail)
}

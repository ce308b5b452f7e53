//! `close2gl check MODEL TRACE`: a program's trace of one frame against close2gl's pipeline,
//! stage by stage, and the catalogue mistake that reproduces it (docs/checking.md); and
//! `close2gl check RASTER_TRACE`, a student's own rasterizer against close2gl's textbook one
//! ([`raster`]).

use std::path::{Path, PathBuf};

use close2gl_check::{Report, picture, report};
use close2gl_core::{Image, Mesh, ModelSource, PrimitiveParams};
use close2gl_trace_format::{Trace, read_trace};

use super::CliError;

mod raster;

#[derive(clap::Args, Debug)]
pub struct CheckArgs {
    /// The model the program drew: a .in or .obj file, or a primitive's name. Or a raster trace
    /// (close2gl-raster 1) alone: the program's own rasterizer, checked on its own triangles.
    pub model: String,
    /// The trace the program wrote (close2gl-trace 1).
    pub trace: Option<PathBuf>,
    /// Print the report as one JSON object.
    #[arg(long)]
    pub json: bool,
    /// Also write close2gl's 2D output, the trace's and their difference (PNG), and the report.
    #[arg(long, value_name = "DIR")]
    pub out: Option<PathBuf>,
    /// A raster trace's pixel to probe, in the program's window coordinates: its colour and
    /// depth, close2gl's, and what each mistake would give there.
    #[arg(long, num_args = 2, value_names = ["X", "Y"])]
    pub pixel: Option<Vec<u32>>,
}

/// Exit 0 when everything the trace gives agrees, 1 when something differs, 2 for bad input.
pub fn run(args: CheckArgs) -> Result<(), CliError> {
    let Some(trace_path) = &args.trace else {
        return raster::run(&args);
    };
    if args.pixel.is_some() {
        return Err(CliError::Input(
            "--pixel probes a raster trace (close2gl check RASTER_TRACE --pixel X Y)".into(),
        ));
    }
    let mesh = load_model(&args.model)?;
    let trace = read_trace(trace_path).map_err(|e| CliError::Input(e.to_string()))?;
    let report =
        close2gl_check::check(&mesh, &trace).map_err(|e| CliError::Input(e.to_string()))?;
    let name = trace_path.display().to_string();
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

/// Makes `dir` and writes `files` (name, bytes) into it.
fn write_files(dir: &Path, files: &[(&str, Vec<u8>)]) -> Result<(), CliError> {
    let fail =
        |e: std::io::Error| CliError::Runtime(format!("{}: cannot write: {e}", dir.display()));
    std::fs::create_dir_all(dir).map_err(fail)?;
    for (name, bytes) in files {
        std::fs::write(dir.join(name), bytes).map_err(fail)?;
    }
    Ok(())
}

fn write_out(
    dir: &Path,
    report: &Report,
    trace: &Trace,
    text: &str,
    json: &serde_json::Value,
) -> Result<(), CliError> {
    let [ours, theirs, difference] = picture::pictures(report, trace);
    let png = |image: Image| image.to_png().map_err(CliError::Runtime);
    write_files(
        dir,
        &[
            ("close2gl.png", png(ours)?),
            ("trace.png", png(theirs)?),
            ("difference.png", png(difference)?),
            ("report.txt", text.as_bytes().to_vec()),
            ("report.json", format!("{json:#}\n").into_bytes()),
        ],
    )
}

//! The `close2gl` command line: the interactive viewer and its headless tools.

use std::process::ExitCode;

use clap::{Parser, Subcommand};
use close2gl::commands::{self, bench, check, grade, inspect, render, run, stats};

#[derive(Parser)]
#[command(
    name = "close2gl",
    version,
    about = "The geometry half of the OpenGL pipeline, done by hand and shown beside the GPU's."
)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
    #[command(flatten)]
    run: run::RunArgs,
}

#[derive(Subcommand)]
enum Command {
    /// Run the Close2GL pipeline once, headless, and print its counts as JSON.
    Stats(stats::StatsArgs),
    /// Render both views offscreen to PNGs with a parity report.
    Render(render::RenderArgs),
    /// Time the Close2GL geometry stage against the straightforward version; --raster the
    /// software frame beside the GPU's (--grid: a million sub-pixel triangles), --fill the fill
    /// rate, --load a model's loading.
    Bench(bench::BenchArgs),
    /// One triangle's journey through the pipeline (--triangle N), or who drew one pixel in
    /// each view and why the others lost (--pixel X,Y), as JSON.
    Inspect(inspect::InspectArgs),
    /// Check a program's trace of one frame against close2gl's pipeline, stage by stage, and
    /// name the classic mistake that reproduces it (exit 0 agree, 1 differs, 2 bad input).
    Check(check::CheckArgs),
    /// Grade a program on the assignment's rubric: run it on the rubric's scenes under limits,
    /// each run sandboxed (Landlock; its own user, network and PID namespace where the kernel
    /// allows them: docs/grading.md), and score its 200 points line by line with the evidence;
    /// --submissions grades a folder of them into grades.csv.
    Grade(grade::GradeArgs),
}

fn main() -> ExitCode {
    let cli = match Cli::try_parse() {
        Ok(cli) => cli,
        Err(error) => return commands::exit(Err(commands::usage(error))),
    };
    let result = match cli.command {
        None => run::run(cli.run),
        Some(Command::Stats(args)) => stats::run(args),
        Some(Command::Render(args)) => render::run(args),
        Some(Command::Bench(args)) => bench::run(args),
        Some(Command::Inspect(args)) => inspect::run(args),
        Some(Command::Check(args)) => check::run(args),
        Some(Command::Grade(args)) => grade::run(args),
    };
    commands::exit(result)
}

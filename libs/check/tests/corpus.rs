//! `check` on the corpus of `examples/corpus/`: programs written the way students write them (C,
//! C++ with glm, Python; double and float32; window, unit or NDC output; culling on screen, in
//! NDC or in window numbers; first-person cameras; far from the origin), each with its intended
//! bug, or none, written in its header before it was ever checked. Each program is compiled (or
//! started with python3) and run as a process on its scenes; its trace is checked, and check
//! must say what the program's header expects: agree, or differ at the right stage with exactly
//! the right names, or honestly "unexplained". Never a false name, never a false agreement.

#[path = "corpus/expect.rs"]
mod expect;
#[path = "corpus/scenes.rs"]
mod scenes;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::process::Command;

use close2gl_check as check;
use close2gl_testkit::TempDir;
use close2gl_testkit::student::{compile_c, compile_cpp, corpus_programs, repository};
use expect::{Expectation, Outcome};
use rayon::prelude::*;
use scenes::SceneFile;

fn corpus() -> PathBuf {
    repository().join("examples/corpus")
}

/// How to start a program built with some flags: a compiled program, or python3 with the script.
#[derive(Clone)]
enum Runner {
    Compiled(PathBuf),
    Python(PathBuf),
}

/// Builds `program` with `flags` into `dir` (C, C++); a Python program is started as it is.
fn build(program: &Path, flags: &[String], dir: &Path) -> Runner {
    let name = program
        .file_stem()
        .and_then(|s| s.to_str())
        .expect("a file name");
    let include =
        [repository().join("examples/trace"), corpus()].map(|p| format!("-I{}", p.display()));
    let mut all: Vec<&str> = include.iter().map(String::as_str).collect();
    all.extend(flags.iter().map(String::as_str));
    let out = dir.join(format!("{name}{}", flags.concat()));
    match program.extension().and_then(|e| e.to_str()) {
        Some("c") => Runner::Compiled(compile_c(program, &out, &all)),
        Some("cpp") => Runner::Compiled(compile_cpp(program, &out, &all)),
        _ => Runner::Python(program.to_path_buf()),
    }
}

/// The command for one run: the scene and the trace, then (Python) the flags as arguments, with
/// the helper and the loader on python3's path.
fn command(runner: &Runner, flags: &[String], scene: &Path, trace: &Path) -> Command {
    let mut command = match runner {
        Runner::Compiled(program) => Command::new(program),
        Runner::Python(script) => {
            let path = std::env::join_paths([repository().join("examples/trace"), corpus()]);
            let mut python = Command::new("python3");
            python
                .env("PYTHONPATH", path.expect("a PYTHONPATH"))
                .arg(script);
            python
        }
    };
    command.arg(scene).arg(trace);
    if matches!(runner, Runner::Python(_)) {
        command.args(flags);
    }
    command
}

/// One run: what check said (as an outcome, and as its text report), or why there is no report.
fn run(mut command: Command, scene: &SceneFile, trace: &Path) -> Result<(Outcome, String), String> {
    let ran = command.output().map_err(|e| format!("cannot start: {e}"))?;
    if !ran.status.success() {
        return Err(format!(
            "exit {}: {}",
            ran.status,
            String::from_utf8_lossy(&ran.stderr)
        ));
    }
    let read =
        close2gl_trace_format::read_trace(trace).map_err(|e| format!("trace not readable: {e}"))?;
    let report = check::check(&scene.mesh, &read)
        .map_err(|e| format!("trace does not fit the model: {e}"))?;
    Ok((
        expect::observed(&report),
        check::report::text(&report, "trace"),
    ))
}

/// Every program's expectations, in the corpus's order.
fn expectations() -> Vec<(PathBuf, Expectation)> {
    corpus_programs()
        .into_iter()
        .flat_map(|p| {
            let expectations = expect::read(&p).unwrap_or_else(|e| panic!("{e}"));
            assert!(
                !expectations.is_empty(),
                "{}: no 'expect' line",
                p.display()
            );
            expectations.into_iter().map(move |e| (p.clone(), e))
        })
        .collect()
}

/// One expectation held to account: a line for the summary, and the failure in full.
fn judge(
    i: usize,
    program: &Path,
    e: &Expectation,
    runner: &Runner,
    scenes: &BTreeMap<&str, SceneFile>,
    dir: &Path,
) -> (String, Option<String>) {
    let file = program.file_name().and_then(|n| n.to_str()).unwrap_or("?");
    let name = format!("{file} {} {}", e.scene, e.flags.join(" "));
    let scene = scenes
        .get(e.scene.as_str())
        .unwrap_or_else(|| panic!("{file}: no scene '{}'", e.scene));
    let trace = dir.join(format!("run{i}.trace"));
    match run(
        command(runner, &e.flags, &scene.path, &trace),
        scene,
        &trace,
    ) {
        Ok((seen, _)) if expect::holds(&e.outcome, &seen) => (format!("pass {name}"), None),
        Ok((seen, text)) => {
            let text: Vec<&str> = text.lines().take(30).collect();
            let why = format!(
                "{name}\n  expected {:?}\n  observed {seen:?}\n{}",
                e.outcome,
                text.join("\n")
            );
            (format!("FAIL {name}"), Some(why))
        }
        Err(why) => (format!("FAIL {name}"), Some(format!("{name}\n  {why}"))),
    }
}

/// Runs every expectation of every program; returns a line per run and the failures in full.
fn run_corpus(dir: &Path) -> (Vec<String>, Vec<String>) {
    let scenes = scenes::write_all(dir);
    let runs = expectations();
    let builds: BTreeMap<(PathBuf, Vec<String>), Runner> = runs
        .iter()
        .map(|(p, e)| (p.clone(), e.flags.clone()))
        .collect::<std::collections::BTreeSet<_>>()
        .into_par_iter()
        .map(|(p, flags)| {
            let runner = build(&p, &flags, dir);
            ((p, flags), runner)
        })
        .collect();
    let results: Vec<(String, Option<String>)> = runs
        .par_iter()
        .enumerate()
        .map(|(i, (p, e))| {
            judge(
                i,
                p,
                e,
                &builds[&(p.clone(), e.flags.clone())],
                &scenes,
                dir,
            )
        })
        .collect();
    let lines = results.iter().map(|(line, _)| line.clone()).collect();
    (
        lines,
        results
            .into_iter()
            .filter_map(|(_, failure)| failure)
            .collect(),
    )
}

#[test]
fn check_says_what_each_corpus_program_expects() {
    let dir = TempDir::new("corpus");
    let (lines, failures) = run_corpus(&dir);
    eprintln!("{}", lines.join("\n"));
    assert!(
        failures.is_empty(),
        "{} of {} corpus runs do not hold their expectation:\n\n{}",
        failures.len(),
        lines.len(),
        failures.join("\n\n")
    );
}

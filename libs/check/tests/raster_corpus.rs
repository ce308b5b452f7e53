//! `check` on the rasterizer corpus of `examples/corpus/raster/`: whole second-assignment
//! programs written the way students write them (a float32 scanline rasterizer in C, a double
//! bounding-box rasterizer with area weights in C++, a numpy one in Python; y down or up; their
//! own tie handling, clipping and mip chains), each with its intended bugs, or none, written in
//! its header as `expect` lines before it was ever checked. Each program is compiled (or started
//! with python3) with each variant's flags and run as a process on its scenes; its raster trace is
//! read with its buffers and checked, and check must say what the header expects: agree, or
//! differ with exactly the catalogue mistakes named, or honestly "unexplained". Never a false
//! name, never a false agreement. (The `expect-grade` lines are another test's.)

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::Command;

use close2gl_check::raster::{check_raster, report};
use close2gl_testkit::TempDir;
use close2gl_testkit::student::{compile_c, compile_cpp, repository};
use rayon::prelude::*;

fn corpus() -> PathBuf {
    repository().join("examples/corpus/raster")
}

/// What one run must give.
#[derive(Clone, Debug, PartialEq)]
enum Outcome {
    Agree,
    /// Exactly these catalogue ids named (sorted).
    Names(Vec<String>),
    /// Nothing named, and not agreeing.
    Unexplained,
}

/// One `expect SCENE [FLAG ...]: OUTCOME` line.
#[derive(Clone, Debug)]
struct Expectation {
    scene: String,
    flags: Vec<String>,
    outcome: Outcome,
}

/// The `expect` lines of the program at `path` (`expect-grade` lines are not these).
fn read_expectations(path: &Path) -> Vec<Expectation> {
    let text = std::fs::read_to_string(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut found = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let line = line.trim_start_matches([' ', '/', '*', '#']);
        let Some(rest) = line.strip_prefix("expect ") else {
            continue;
        };
        let parsed = rest.split_once(':').and_then(|(run, outcome)| {
            let mut run = run.split_whitespace().map(String::from);
            let scene = run.next()?;
            let flags = run.collect();
            let words: Vec<&str> = outcome.split_whitespace().collect();
            let outcome = match words.as_slice() {
                ["agree"] => Outcome::Agree,
                ["differs", "unexplained"] => Outcome::Unexplained,
                ["differs", list] => {
                    let mut names: Vec<String> = list
                        .strip_prefix("mistakes=")?
                        .split(',')
                        .map(String::from)
                        .collect();
                    names.sort();
                    Outcome::Names(names)
                }
                _ => return None,
            };
            Some(Expectation {
                scene,
                flags,
                outcome,
            })
        });
        found.push(parsed.unwrap_or_else(|| {
            panic!(
                "{}:{}: expected 'expect SCENE [FLAG ...]: agree|differs mistakes=ID[,ID...]|differs unexplained', found '{line}'",
                path.display(),
                number + 1
            )
        }));
    }
    assert!(!found.is_empty(), "{}: no 'expect' line", path.display());
    found
}

/// The corpus's programs (every .c, .cpp and .py but the shared rcommon), in name order.
fn programs() -> Vec<PathBuf> {
    let mut found: Vec<PathBuf> = std::fs::read_dir(corpus())
        .expect("examples/corpus/raster")
        .map(|e| e.expect("a directory entry").path())
        .filter(|p| {
            matches!(
                p.extension().and_then(|e| e.to_str()),
                Some("c" | "cpp" | "py")
            )
        })
        .filter(|p| p.file_stem().is_some_and(|s| s != "rcommon"))
        .collect();
    found.sort();
    found
}

fn is_python(program: &Path) -> bool {
    program.extension().is_some_and(|e| e == "py")
}

/// Whether python3 can import numpy (CI installs python3-numpy).
fn numpy_available() -> bool {
    Command::new("python3")
        .args(["-c", "import numpy"])
        .output()
        .is_ok_and(|o| o.status.success())
}

/// How to start a program built with some flags.
#[derive(Clone)]
enum Runner {
    Compiled(PathBuf),
    Python(PathBuf),
}

fn build(program: &Path, flags: &[String], dir: &Path) -> Runner {
    let name = program
        .file_stem()
        .and_then(|s| s.to_str())
        .expect("a file name");
    let include = [
        repository().join("examples/trace"),
        repository().join("examples/raster"),
        corpus(),
    ]
    .map(|p| format!("-I{}", p.display()));
    let mut all: Vec<&str> = include.iter().map(String::as_str).collect();
    all.extend(flags.iter().map(String::as_str));
    let out = dir.join(format!("{name}{}", flags.concat()));
    match program.extension().and_then(|e| e.to_str()) {
        Some("c") => Runner::Compiled(compile_c(program, &out, &all)),
        Some("cpp") => Runner::Compiled(compile_cpp(program, &out, &all)),
        _ => Runner::Python(program.to_path_buf()),
    }
}

/// One run, checked: check's outcome and its text report, or why there is none.
fn run(
    runner: &Runner,
    flags: &[String],
    scene: &Path,
    trace: &Path,
) -> Result<(Outcome, String), String> {
    let mut command = match runner {
        Runner::Compiled(program) => Command::new(program),
        Runner::Python(script) => {
            let path = std::env::join_paths([
                repository().join("examples/trace"),
                repository().join("examples/raster"),
                corpus(),
            ])
            .expect("a PYTHONPATH");
            let mut python = Command::new("python3");
            python.env("PYTHONPATH", path).arg(script);
            python
        }
    };
    command.arg(scene).arg(trace);
    if matches!(runner, Runner::Python(_)) {
        command.args(flags);
    }
    let ran = command.output().map_err(|e| format!("cannot start: {e}"))?;
    if !ran.status.success() {
        return Err(format!(
            "exit {}: {}",
            ran.status,
            String::from_utf8_lossy(&ran.stderr)
        ));
    }
    let frame = close2gl_trace_format::read_raster_frame(trace)
        .map_err(|e| format!("raster trace not readable: {e}"))?;
    let checked = check_raster(&frame);
    let outcome = if checked.agrees() {
        Outcome::Agree
    } else {
        let mut names: Vec<String> = checked.mistakes().into_iter().map(String::from).collect();
        names.sort();
        if names.is_empty() {
            Outcome::Unexplained
        } else {
            Outcome::Names(names)
        }
    };
    Ok((outcome, report::text(&checked, "trace")))
}

#[test]
fn check_says_what_each_raster_corpus_program_expects() {
    let dir = TempDir::new("raster_corpus");
    let numpy = numpy_available();
    if !numpy {
        eprintln!(
            "skipping the Python programs of examples/corpus/raster: `python3 -c \"import numpy\"` \
             fails here (CI installs python3-numpy, where they run)"
        );
    }
    let runs: Vec<(PathBuf, Expectation)> = programs()
        .into_iter()
        .filter(|p| numpy || !is_python(p))
        .flat_map(|p| {
            read_expectations(&p)
                .into_iter()
                .map(move |e| (p.clone(), e))
        })
        .collect();
    let builds: BTreeMap<(PathBuf, Vec<String>), Runner> = runs
        .iter()
        .map(|(p, e)| (p.clone(), e.flags.clone()))
        .collect::<BTreeSet<_>>()
        .into_par_iter()
        .map(|(p, flags)| {
            let runner = build(&p, &flags, &dir);
            ((p, flags), runner)
        })
        .collect();
    let results: Vec<(String, Option<String>)> = runs
        .par_iter()
        .enumerate()
        .map(|(i, (program, e))| {
            let file = program.file_name().and_then(|n| n.to_str()).unwrap_or("?");
            let name = format!("{file} {} {}", e.scene, e.flags.join(" "));
            let scene = corpus().join("scenes").join(format!("{}.scene", e.scene));
            assert!(scene.is_file(), "{file}: no scene {}", scene.display());
            let trace = dir.join(format!("run{i}.raster"));
            let runner = &builds[&(program.clone(), e.flags.clone())];
            match run(runner, &e.flags, &scene, &trace) {
                Ok((seen, _)) if seen == e.outcome => (format!("pass {name}"), None),
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
        })
        .collect();
    let lines: Vec<&str> = results.iter().map(|(line, _)| line.as_str()).collect();
    eprintln!("{}", lines.join("\n"));
    let failures: Vec<&str> = results.iter().filter_map(|(_, f)| f.as_deref()).collect();
    assert!(
        failures.is_empty(),
        "{} of {} raster corpus runs do not hold their expectation:\n\n{}",
        failures.len(),
        lines.len(),
        failures.join("\n\n")
    );
}

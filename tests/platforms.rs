//! `close2gl grade` where teachers grade, run as each platform runs it: Gradescope's
//! `setup.sh` and `run_autograder` (examples/gradescope) in an `/autograder`-shaped folder,
//! GitHub Classroom's workflow (examples/github-classroom) step by step as written, with
//! `$GITHUB_OUTPUT`, and a class's gradebook CSV for Moodle and Canvas. The correct program
//! scores 200 in each; a mistaken one the points `grade --json` gives it.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use close2gl_testkit::TempDir;
use close2gl_testkit::student::{asset, compile_pipeline, mistake_flag, repository};
use serde_json::Value;

mod platform_rules;
use platform_rules::{
    assert_gradescope_format, assert_line_answers, classroom_result, reporter_points,
};

const MISTAKE: &str = "never_culls";

fn close2gl() -> &'static str {
    env!("CARGO_BIN_EXE_close2gl")
}

fn bash(script: &Path, dir: &Path, env: &[(&str, String)]) -> Output {
    let mut command = Command::new("bash");
    command.arg(script).current_dir(dir);
    for (key, value) in env {
        command.env(key, value);
    }
    command.output().expect("bash")
}

/// What `grade --json` gives the pipeline built with `flags` on the cube: its total.
fn expected_total(dir: &Path, flags: &[&str]) -> u64 {
    let program = compile_pipeline(dir, "expected", flags);
    let output = Command::new(close2gl())
        .args(["grade", "--json", "--jobs", "2", "--model"])
        .arg(asset("cube.in"))
        .arg("--run")
        .arg(format!("'{}' {{scene}} {{trace}}", program.display()))
        .output()
        .expect("grade");
    let grade: Value = serde_json::from_slice(&output.stdout).expect("JSON");
    grade["total"].as_u64().expect("total")
}

/// An `/autograder`-shaped folder: `source/` as the autograder's zip unpacks (the scripts,
/// the trace header, close2gl, the cube), `submission/` with the student's C file, `results/`.
fn autograder(dir: &Path) -> PathBuf {
    let root = dir.join("autograder");
    let source = root.join("source");
    std::fs::create_dir_all(source.join("models")).expect("source/models");
    std::fs::create_dir_all(root.join("submission")).expect("submission");
    let copy = |from: PathBuf, to: PathBuf| std::fs::copy(&from, to).expect("copy");
    let example = repository().join("examples/gradescope");
    copy(example.join("setup.sh"), source.join("setup.sh"));
    copy(example.join("run_autograder"), root.join("run_autograder"));
    let trace = repository().join("examples/trace");
    copy(
        trace.join("close2gl_trace.h"),
        source.join("close2gl_trace.h"),
    );
    copy(PathBuf::from(close2gl()), source.join("close2gl"));
    copy(asset("cube.in"), source.join("models/cube.in"));
    copy(trace.join("pipeline.c"), root.join("submission/pipeline.c"));
    root
}

/// Runs Gradescope's `setup.sh` (installing into a folder of the test's) and `run_autograder`
/// with `build` as the course's command; the results.json it wrote.
fn gradescope(dir: &Path, build: Option<&str>) -> Value {
    let root = autograder(dir);
    let prefix = dir.join("prefix");
    let setup = bash(
        &root.join("source/setup.sh"),
        &root,
        &[("CLOSE2GL_PREFIX", prefix.display().to_string())],
    );
    assert!(
        setup.status.success(),
        "{}",
        String::from_utf8_lossy(&setup.stderr)
    );
    let path = format!(
        "{}:{}",
        prefix.join("bin").display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let mut env = vec![
        ("AUTOGRADER_ROOT", root.display().to_string()),
        ("PATH", path),
    ];
    env.extend(build.map(|b| ("CLOSE2GL_BUILD", b.to_string())));
    let run = bash(&root.join("run_autograder"), &root, &env);
    assert!(
        run.status.success(),
        "{}",
        String::from_utf8_lossy(&run.stderr)
    );
    let text = std::fs::read_to_string(root.join("results/results.json")).expect("results.json");
    serde_json::from_str(&text).expect("results.json is JSON")
}

#[test]
fn gradescope_gives_the_correct_program_200_and_a_mistaken_one_its_points() {
    let dir = TempDir::new("platform_gradescope");
    let correct = gradescope(&dir.join("correct"), None);
    assert_gradescope_format(&correct);
    assert_eq!(correct["score"], 200, "{correct:#}");
    let flag = mistake_flag(MISTAKE);
    let build = format!("cc -O2 {flag} -I \"$AUTOGRADER_ROOT/source\" -o \"$program\" *.c -lm");
    let mistaken = gradescope(&dir.join("mistaken"), Some(&build));
    assert_gradescope_format(&mistaken);
    assert_eq!(
        mistaken["score"].as_u64(),
        Some(expected_total(&dir, &[&flag]))
    );
    // The lines are visible, with the mistake named; the scenes' numbers are not.
    let tests = mistaken["tests"].as_array().expect("tests");
    let numbered = |number: &str| {
        let test = tests.iter().find(|t| t["number"] == number).expect(number);
        let text = |key: &str| test[key].as_str().unwrap_or_default().to_string();
        (text("visibility"), text("output"))
    };
    let (visibility, output) = numbered("culling");
    assert!(
        visibility == "visible" && output.contains(MISTAKE),
        "{output}"
    );
    let (visibility, output) = numbered("culling.details");
    assert!(
        visibility == "hidden" && output.contains("the scene file"),
        "{output}"
    );
    for test in tests.iter().filter(|t| t["visibility"] == "visible") {
        let output = test["output"].as_str().unwrap_or_default();
        assert!(
            !output.contains("camera"),
            "a visible test shows a scene: {output}"
        );
    }
}

#[test]
fn gradescope_gives_a_submission_that_does_not_build_0_and_its_compilers_words() {
    let dir = TempDir::new("platform_gradescope_broken");
    let root = dir.join("broken");
    let results = {
        std::fs::create_dir_all(&root).expect("a folder");
        let autograder = autograder(&root);
        std::fs::write(
            autograder.join("submission/pipeline.c"),
            "int main(void) { return x; }",
        )
        .expect("a broken submission");
        let env = [("AUTOGRADER_ROOT", autograder.display().to_string())];
        let run = bash(&autograder.join("run_autograder"), &autograder, &env);
        assert!(run.status.success());
        let text =
            std::fs::read_to_string(autograder.join("results/results.json")).expect("results.json");
        serde_json::from_str::<Value>(&text).expect("JSON")
    };
    assert_gradescope_format(&results);
    assert_eq!(results["score"], 0);
    let output = results["output"].as_str().unwrap_or_default();
    assert!(output.starts_with("Your program did not build"), "{output}");
    assert!(output.contains("undeclared"), "{output}");
}

/// The `run:` command of the step named `name` in the workflow, as written.
fn step_command(workflow: &str, name: &str) -> String {
    let mut lines = workflow
        .lines()
        .skip_while(|l| l.trim() != format!("- name: {name}"));
    lines.next().expect("the step");
    let run = lines
        .take_while(|l| !l.trim_start().starts_with("- name:"))
        .find_map(|l| l.trim().strip_prefix("run: ").map(str::to_string));
    run.expect("a one-line run: command")
}

/// The workflow's Build and close2gl steps run as written in a checkout of `source`, with
/// `$GITHUB_OUTPUT`; the result the reporter would read, decoded.
fn classroom(dir: &Path, source: &str) -> Value {
    std::fs::create_dir_all(dir).expect("a checkout");
    std::fs::write(dir.join("pipeline.c"), source).expect("the student's program");
    let trace = repository().join("examples/trace/close2gl_trace.h");
    std::fs::copy(trace, dir.join("close2gl_trace.h")).expect("the header");
    let workflow =
        std::fs::read_to_string(repository().join("examples/github-classroom/classroom.yml"))
            .expect("the workflow");
    let output = dir.join("github_output");
    let bin = Path::new(close2gl())
        .parent()
        .expect("close2gl's folder")
        .display()
        .to_string();
    let path = format!("{bin}:{}", std::env::var("PATH").unwrap_or_default());
    for step in ["Build", "close2gl"] {
        let command = step_command(&workflow, step);
        let run = Command::new("bash")
            .args(["-e", "-c", &command])
            .current_dir(dir)
            .env("PATH", &path)
            .env("GITHUB_OUTPUT", &output)
            .output()
            .expect("bash");
        assert!(
            run.status.success(),
            "{step}: {}",
            String::from_utf8_lossy(&run.stderr)
        );
    }
    classroom_result(&output)
}

#[test]
fn github_classroom_runs_the_workflow_as_written_with_partial_credit() {
    let dir = TempDir::new("platform_classroom");
    let source = std::fs::read_to_string(repository().join("examples/trace/pipeline.c"))
        .expect("pipeline.c");
    let correct = classroom(&dir.join("correct"), &source);
    assert_eq!(reporter_points(&correct), (200, 200), "{correct:#}");
    assert_eq!(correct["status"], "pass");
    // The mistake as a student writes it: the switch in the source, not a compiler flag.
    let define = format!("#define MISTAKE_{}\n", MISTAKE.to_ascii_uppercase());
    let mistaken = classroom(&dir.join("mistaken"), &format!("{define}{source}"));
    let (points, max) = reporter_points(&mistaken);
    assert_eq!(max, 200);
    assert!(points < 200, "{mistaken:#}");
    assert_eq!(mistaken["status"], "fail");
    let culling = mistaken["tests"]
        .as_array()
        .and_then(|t| t.iter().find(|t| t["name"] == "Backface culling"))
        .expect("the culling test");
    assert_eq!(culling["status"], "fail");
    assert!(
        culling["message"]
            .as_str()
            .unwrap_or_default()
            .contains(MISTAKE)
    );
}

#[test]
fn one_line_at_a_time_passes_or_fails_with_a_one_line_summary() {
    let dir = TempDir::new("platform_line");
    let run = |program: &Path, line: &str| {
        Command::new(close2gl())
            .args(["grade", "--jobs", "2", "--line", line, "--model"])
            .arg(asset("cube.in"))
            .arg("--run")
            .arg(format!("'{}' {{scene}} {{trace}}", program.display()))
            .output()
            .expect("grade --line")
    };
    let correct = compile_pipeline(&dir, "correct", &[]);
    let passed = run(&correct, "culling");
    let mistaken = compile_pipeline(&dir, "mistaken", &[&mistake_flag(MISTAKE)]);
    let failed = run(&mistaken, "culling");
    assert_line_answers(&passed, &failed, "culling", 25, MISTAKE);
    let unknown = run(&correct, "culing");
    assert_eq!(unknown.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&unknown.stderr).contains("--line culing: expected one of"));
}

#[test]
fn a_class_csv_imports_into_moodle_and_canvas_with_the_students_identifiers() {
    let dir = TempDir::new("platform_gradebook");
    let class = dir.join("class");
    for (folder, flags) in [
        ("alice-folder", vec![]),
        ("bob-folder", vec![mistake_flag(MISTAKE)]),
    ] {
        std::fs::create_dir_all(class.join(folder)).expect("a submission");
        let flags: Vec<&str> = flags.iter().map(String::as_str).collect();
        compile_pipeline(&class.join(folder), "prog", &flags);
    }
    let students = dir.join("students.csv");
    std::fs::write(
        &students,
        "# folder,identifier,name\nalice-folder,alice@uni.edu,Alice Ada\n",
    )
    .expect("the mapping");
    let grade = |format: &str| {
        let output = Command::new(close2gl())
            .args(["grade", "--jobs", "2", "--submissions"])
            .arg(&class)
            .args(["--run", "{dir}/prog {scene} {trace}", "--model"])
            .arg(asset("cube.in"))
            .args(["--csv-format", format, "--students"])
            .arg(&students)
            .args(["--assignment", "Close2GL (4242)"])
            .output()
            .expect("grade");
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        std::fs::read_to_string(class.join("grades.csv")).expect("grades.csv")
    };
    let bob = expected_total(&dir, &[&mistake_flag(MISTAKE)]);
    let moodle = grade("moodle");
    let rows: Vec<&str> = moodle.lines().collect();
    assert!(
        rows[0].starts_with("Identifier,Full name,Points (close2gl),"),
        "{moodle}"
    );
    assert!(rows[0].ends_with(",Total (close2gl)"), "{moodle}");
    assert!(rows[1].starts_with("alice@uni.edu,Alice Ada,") && rows[1].ends_with(",200"));
    assert!(rows[2].starts_with("bob-folder,,") && rows[2].ends_with(&format!(",{bob}")));
    let canvas = grade("canvas");
    let expected = format!(
        "Student,ID,SIS User ID,SIS Login ID,Section,Close2GL (4242)\n\
         \x20   Points Possible,,,,,200\n\
         Alice Ada,,,alice@uni.edu,,200\n\
         bob-folder,,,bob-folder,,{bob}\n"
    );
    assert_eq!(canvas, expected);
    std::fs::write(&students, "alice-folder\n").expect("a broken mapping");
    let broken = Command::new(close2gl())
        .args(["grade", "--submissions"])
        .arg(&class)
        .args(["--run", "{dir}/prog {scene} {trace}", "--students"])
        .arg(&students)
        .output()
        .expect("grade");
    assert_eq!(broken.status.code(), Some(2));
    let stderr = String::from_utf8_lossy(&broken.stderr);
    assert!(
        stderr.contains("students.csv:1: expected 'folder,identifier[,name]'"),
        "{stderr}"
    );
}

//! Where teachers already grade: one program's grade in the shapes Gradescope and GitHub
//! Classroom read. Gradescope's `results.json`: a test per rubric line whose output a student
//! sees (points, scenes passed, the first failing scene's name, the mistakes named), and, for
//! each line that lost points, a test of no points holding the scenes' exact numbers (why
//! each scene failed, check's first difference, the scene files), shown as `--details` says
//! (hidden by default: they are the answer key). GitHub Classroom's grading reporter reads a
//! step's `result`: base64 JSON with a test per line and its points, so one step gives
//! partial credit; it is written to `$GITHUB_OUTPUT`.

use std::io::Write;
use std::path::Path;
use std::time::Duration;

use base64::Engine;
use base64::engine::general_purpose::STANDARD;
use serde_json::{Value, json};

use super::CliError;
use super::sheet::{Sheet, SheetLine};

/// Who sees a part of Gradescope's results: Gradescope's own four words.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
#[value(rename_all = "snake_case")]
pub enum Visibility {
    Hidden,
    AfterDueDate,
    AfterPublished,
    Visible,
}

impl Visibility {
    fn word(self) -> &'static str {
        match self {
            Visibility::Hidden => "hidden",
            Visibility::AfterDueDate => "after_due_date",
            Visibility::AfterPublished => "after_published",
            Visibility::Visible => "visible",
        }
    }
}

/// The lines a platform reports: every line, or the one `--line` names.
fn reported<'a>(grade: &'a Sheet, only: Option<&str>) -> Vec<&'a SheetLine> {
    let chosen = |line: &&SheetLine| only.is_none_or(|id| line.id == id);
    grade.lines.iter().filter(chosen).collect()
}

/// What a student may see of a line: its points, the scenes it passed, the first failing
/// scene's name and the mistakes named; no coordinates, no scene file.
fn student_output(line: &SheetLine) -> String {
    let mut out = format!(
        "{}/{} points; {} of {} scenes passed",
        line.points, line.max, line.passed, line.scenes
    );
    if let Some((first, _)) = line.failures.first() {
        out.push_str(&format!("\nfirst failing scene: {first}"));
    }
    if !line.mistakes.is_empty() {
        out.push_str(&format!("\nmistakes named: {}", line.mistakes));
    }
    for note in &line.notes {
        out.push_str(&format!("\naccepted: {note}"));
    }
    out
}

/// What only the teacher sees by default: why each scene failed, with check's numbers, and the
/// first failing scene's file.
fn details_output(line: &SheetLine) -> String {
    let mut out = line.evidence.join("\n");
    for (scene, why) in line.failures.iter().skip(1) {
        out.push_str(&format!("\n{scene}: {}", why.replace('\n', " / ")));
    }
    if let Some(scene_file) = &line.scene_file {
        out.push_str(&format!("\n\nthe scene file:\n{scene_file}"));
    }
    out
}

/// Gradescope's results.json for `grade` (only the line `only` names, with `--line`).
pub fn gradescope(grade: &Sheet, only: Option<&str>, details: Visibility, took: Duration) -> Value {
    let lines = reported(grade, only);
    let mut tests = Vec::new();
    for line in &lines {
        let passed = line.failures.is_empty();
        tests.push(json!({
            "name": line.title.as_str(),
            "number": line.id,
            "score": line.points,
            "max_score": line.max,
            "status": if passed { "passed" } else { "failed" },
            "output": student_output(line),
            "visibility": "visible",
        }));
        if !passed {
            tests.push(json!({
                "name": format!("{}: the scenes' numbers", line.title.as_str()),
                "number": format!("{}.details", line.id),
                "score": 0,
                "max_score": 0,
                "output": details_output(line),
                "visibility": details.word(),
            }));
        }
    }
    let score: u32 = lines.iter().map(|l| l.points).sum();
    json!({
        "score": score,
        "execution_time": took.as_secs(),
        "output": grade.to_fix.join("\n"),
        "visibility": "visible",
        "stdout_visibility": "hidden",
        "tests": tests,
    })
}

/// Writes Gradescope's `results.json` into `dir` (made if missing).
pub fn write_gradescope(dir: &Path, results: &Value) -> Result<(), CliError> {
    let path = dir.join("results.json");
    let fail =
        |e: std::io::Error| CliError::Runtime(format!("{}: cannot write: {e}", path.display()));
    std::fs::create_dir_all(dir).map_err(fail)?;
    std::fs::write(&path, format!("{results:#}\n")).map_err(fail)
}

/// The grading reporter's result for `grade`: a test per line, its points its score, so that
/// one step gives partial credit.
pub fn classroom(grade: &Sheet, only: Option<&str>) -> Value {
    let lines = reported(grade, only);
    let tests: Vec<Value> = lines
        .iter()
        .map(|line| {
            let passed = line.failures.is_empty();
            json!({
                "name": line.title.as_str(),
                "status": if passed { "pass" } else { "fail" },
                "message": student_output(line),
                "score": line.points,
                "line_no": 0,
                "test_code": format!("close2gl grade --line {}", line.id),
            })
        })
        .collect();
    let max: u32 = lines.iter().map(|l| l.max).sum();
    let full = lines.iter().all(|l| l.failures.is_empty());
    json!({
        "version": 1,
        "status": if full { "pass" } else { "fail" },
        "max_score": max,
        "tests": tests,
    })
}

/// Appends `result=<base64 JSON>` to the file `$GITHUB_OUTPUT` names (a step's outputs);
/// without it, prints the line.
pub fn write_classroom(result: &Value) -> Result<(), CliError> {
    let line = format!("result={}\n", STANDARD.encode(result.to_string()));
    let Some(path) = std::env::var_os("GITHUB_OUTPUT") else {
        print!("{line}");
        return Ok(());
    };
    let fail = |e: std::io::Error| {
        CliError::Runtime(format!(
            "$GITHUB_OUTPUT {}: cannot write: {e}",
            Path::new(&path).display()
        ))
    };
    let mut file = std::fs::OpenOptions::new()
        .append(true)
        .create(true)
        .open(&path)
        .map_err(fail)?;
    file.write_all(line.as_bytes()).map_err(fail)
}

/// The grade as a student may see it, for a log the student reads (GitHub Actions): each
/// line's title and what [`student_output`] says, and what to fix.
pub fn student_table(grade: &Sheet, only: Option<&str>) -> String {
    let mut out = grade.to_fix.join("\n");
    for line in reported(grade, only) {
        out.push_str(&format!(
            "\n{}: {}",
            line.title.as_str(),
            student_output(line)
        ));
    }
    out.push('\n');
    out
}

/// `--line`'s one line: "culling: 8/25 (culling_inverted: 4 of 4 failing scenes)".
pub fn summary(line: &SheetLine) -> String {
    let mut out = format!("{}: {}/{}", line.id, line.points, line.max);
    if !line.mistakes.is_empty() {
        out.push_str(&format!(" ({})", line.mistakes));
    } else if !line.failures.is_empty() {
        out.push_str(&format!(
            " ({} of {} scenes passed)",
            line.passed, line.scenes
        ));
    }
    out
}

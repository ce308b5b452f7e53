//! The grade for a person (the rubric as a table on the terminal) and for a script (one JSON
//! object whose keys and line ids are binding: `total`, `max`, `lines` with `id`, `points`,
//! `max`, `scenes`, `passed`, `mistakes` (the most explaining first), `explained` (each one's
//! failing scenes), `unexplained`, `failures`; `scenes`; `sandbox` with `enforced`,
//! `landlock_abi`, `protections`, `summary`).

use std::fmt::Write;

use close2gl_check::rubric::LineScore;
use serde_json::{Value, json};

use super::graded::Grade;
use super::sandboxing::Sandboxing;
use super::scene_run::SceneResult;
use super::sheet;
use super::to_fix;

/// The rubric table: each line's points of its points and scenes passed of its scenes; under
/// a failing line, its first failing scene with why, check's first difference and the
/// mistakes named; the total.
pub fn table(grade: &Grade, command: &str, sandboxing: &Sandboxing) -> String {
    let mut out = String::new();
    // Writing to a String cannot fail.
    let _ = writeln!(out, "close2gl grade: {command}");
    let _ = writeln!(out, "{}", sandboxing.summary());
    for line in to_fix::lines(grade) {
        let _ = writeln!(out, "{line}");
    }
    let _ = writeln!(out, "{:<40} {:>7} {:>9}", "line", "points", "scenes");
    for line in &grade.lines {
        let points = format!("{}/{}", line.points, line.max);
        let scenes = format!("{}/{}", line.passed, line.scenes);
        let _ = writeln!(out, "{:<40} {points:>7} {scenes:>9}", line.title.as_str());
        for note in &line.notes {
            let _ = writeln!(out, "    accepted: {note}");
        }
        for text in failure_lines(grade, line) {
            let _ = writeln!(out, "    {text}");
        }
    }
    let _ = writeln!(
        out,
        "{:<40} {:>7}",
        "total",
        format!("{}/{}", grade.total, grade.max)
    );
    out
}

/// What the report says under a failing line (`sheet::evidence`), from the line's first
/// failing scene and check's evidence there.
pub fn failure_lines(grade: &Grade, line: &LineScore) -> Vec<String> {
    let first = line.failures.first();
    let scene = first.map(|(i, _)| &grade.scenes[*i]);
    let difference = scene
        .and_then(|s| s.evidence.as_ref())
        .and_then(|e| e.first_difference.as_deref());
    sheet::evidence(
        scene
            .zip(first)
            .map(|(s, (_, why))| (s.id.as_str(), why.as_str())),
        difference,
        &line.mistakes_in_words(),
    )
}

pub fn json(grade: &Grade, sandboxing: &Sandboxing) -> Value {
    let lines: Vec<Value> = grade.lines.iter().map(|l| line_json(grade, l)).collect();
    let scenes: Vec<Value> = grade.scenes.iter().map(scene_json).collect();
    let bugs: Vec<Value> = to_fix::bugs(grade)
        .iter()
        .map(|bug| {
            let lines: Vec<&str> = bug.lines.iter().map(|l| l.id()).collect();
            json!({"cause": bug.cause, "lines": lines, "points_lost": bug.points_lost,
                   "first_scene": bug.first_scene, "example": bug.example})
        })
        .collect();
    json!({
        "total": grade.total,
        "max": grade.max,
        "to_fix": bugs,
        "lines": lines,
        "scenes": scenes,
        "sandbox": sandboxing.json(),
    })
}

/// A line of the rubric: its points, scenes, the mistakes named, why each failing scene failed.
fn line_json(grade: &Grade, line: &LineScore) -> Value {
    let failures: Vec<Value> = line
        .failures
        .iter()
        .map(|(i, why)| json!({"scene": grade.scenes[*i].id, "reason": why}))
        .collect();
    let names: Vec<&str> = line.mistakes.iter().map(|m| m.name).collect();
    let explained: serde_json::Map<String, Value> = line
        .mistakes
        .iter()
        .map(|m| (m.name.to_string(), json!(m.scenes)))
        .collect();
    json!({
        "id": line.line.id(),
        "title": line.title,
        "points": line.points,
        "max": line.max,
        "scenes": line.scenes,
        "passed": line.passed,
        "mistakes": names,
        "explained": explained,
        "unexplained": line.unexplained,
        "failures": failures,
        "accepted": line.notes,
    })
}

/// A scene: each line's verdict on it, why its run failed, and check's evidence.
fn scene_json(scene: &SceneResult) -> Value {
    let verdicts: serde_json::Map<String, Value> = scene
        .verdicts
        .iter()
        .map(|(line, v)| {
            (
                line.id().to_string(),
                json!({"passed": v.passed, "detail": v.detail}),
            )
        })
        .collect();
    let evidence = scene.evidence.as_ref();
    json!({
        "id": scene.id,
        "lines": verdicts,
        "run_failure": scene.run_failure.as_ref().map(|f| &f.reason),
        "first_difference": evidence.and_then(|e| e.first_difference.clone()),
        "mistakes": evidence.map_or(Vec::new(), |e| e.mistakes.clone()),
    })
}

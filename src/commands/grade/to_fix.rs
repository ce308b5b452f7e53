//! What to fix, first: the bugs a grade found, each with the rubric lines it cost and the first
//! scene that shows it. A teacher reads this, not the twelve lines; the table follows it.

use close2gl_check::rubric::{LineId, LineScore};

use super::graded::Grade;

/// One bug: the mistakes check named for it (or, when none, where check first finds the
/// program different, or else the first reason a scene gave), the lines it cost and their
/// points, and the first scene that shows it, with what check found there.
pub struct Bug {
    pub cause: String,
    pub lines: Vec<LineId>,
    pub points_lost: u32,
    pub first_scene: String,
    /// Check's first difference in the first scene (`stage: detail`), when the cause is a
    /// stage rather than a named mistake.
    pub example: Option<String>,
}

/// The bugs of `grade`, the costliest first: failing lines with the same cause are one bug.
pub fn bugs(grade: &Grade) -> Vec<Bug> {
    let mut bugs: Vec<Bug> = Vec::new();
    for line in grade.lines.iter().filter(|l| !l.failures.is_empty()) {
        let (cause, example) = cause(grade, line);
        let lost = line.max - line.points;
        match bugs.iter_mut().find(|b| b.cause == cause) {
            Some(bug) => {
                bug.lines.push(line.line);
                bug.points_lost += lost;
            }
            None => bugs.push(Bug {
                cause,
                lines: vec![line.line],
                points_lost: lost,
                first_scene: grade.scenes[line.failures[0].0].id.clone(),
                example,
            }),
        }
    }
    bugs.sort_by_key(|bug| std::cmp::Reverse(bug.points_lost));
    bugs
}

/// Why `line` failed, as the key lines of one bug share. When every failing scene's run
/// failed (it timed out, crashed, wrote no trace, made too many processes), the way most of
/// the program's runs failed is the cause: one bug, however many lines it cost. Then the mistakes that
/// explain the most of its failing scenes. Without a named mistake, the stage where check
/// first finds the program different in the line's first failing scene: a later stage's
/// difference, and each line's own wording of it ("drew nothing where its clip coordinates
/// show 12", "nothing wide in NDC"), may follow from that one, and the earliest is what to
/// fix first.
fn cause(grade: &Grade, line: &LineScore) -> (String, Option<String>) {
    if let Some(cause) = run_failure_cause(grade, line) {
        return (cause.to_string(), None);
    }
    let leading = line.leading_mistakes();
    if !leading.is_empty() {
        return (leading.join(" or "), None);
    }
    let (first_scene, why) = &line.failures[0];
    let scene = &grade.scenes[*first_scene];
    let evidence = scene.evidence.as_ref();
    match evidence.and_then(|e| e.first_difference.as_ref()) {
        Some(difference) => {
            let stage = difference.split(':').next().unwrap_or(difference);
            let cause = format!("unexplained, check first finds it different at {stage}");
            (cause, Some(difference.clone()))
        }
        None => {
            let first = match &scene.run_failure {
                Some(failure) => failure.cause.as_str(),
                None => why.lines().next().unwrap_or(""),
            };
            (format!("unexplained: {first}"), None)
        }
    }
}

/// When every one of `line`'s failing scenes failed to run: the way most of the program's
/// failed runs failed (the first met of those as many). Counted over the whole program, not
/// the line, so that every such line names the same cause: a fork bomb seen at its limit in
/// most scenes and only timing out in a few, on a loaded machine, is still one bug.
fn run_failure_cause<'a>(grade: &'a Grade, line: &LineScore) -> Option<&'a str> {
    let failed_to_run = |scene: usize| grade.scenes[scene].run_failure.is_some();
    if !line.failures.iter().all(|(scene, _)| failed_to_run(*scene)) {
        return None;
    }
    let mut causes: Vec<(&str, usize)> = Vec::new();
    for failure in grade.scenes.iter().filter_map(|s| s.run_failure.as_ref()) {
        match causes.iter_mut().find(|(c, _)| *c == failure.cause) {
            Some((_, count)) => *count += 1,
            None => causes.push((failure.cause.as_str(), 1)),
        }
    }
    let most = causes.iter().map(|&(_, count)| count).max()?;
    causes
        .into_iter()
        .find(|&(_, count)| count == most)
        .map(|(cause, _)| cause)
}

/// The bugs as lines of text: "1. never_culls: culling (-20), first in culling_inside".
pub fn lines(grade: &Grade) -> Vec<String> {
    let bugs = bugs(grade);
    if bugs.is_empty() {
        return vec!["to fix: nothing, every line passed".into()];
    }
    let mut out = vec![format!("to fix ({}):", bugs.len())];
    for (i, bug) in bugs.iter().enumerate() {
        let lines: Vec<&str> = bug.lines.iter().map(|l| l.id()).collect();
        out.push(format!(
            "  {}. {}: costs {} ({} points); first in scene {}",
            i + 1,
            bug.cause,
            lines.join(", "),
            bug.points_lost,
            bug.first_scene
        ));
        if let Some(example) = &bug.example {
            out.push(format!("     there: {example}"));
        }
    }
    out
}

//! What to fix, first: the bugs a grade found, each with the rubric lines it cost and the first
//! scene that shows it. A teacher reads this, not the twelve lines; the table follows it.

use close2gl_check::rubric::LineId;

use super::graded::Grade;

/// One bug: the mistakes check named for it (or, when none, the first reason a scene gave),
/// the lines it cost and their points, and the first scene that shows it.
pub struct Bug {
    pub cause: String,
    pub lines: Vec<LineId>,
    pub points_lost: u32,
    pub first_scene: String,
}

/// The bugs of `grade`, the costliest first: failing lines with the same cause are one bug.
pub fn bugs(grade: &Grade) -> Vec<Bug> {
    let mut bugs: Vec<Bug> = Vec::new();
    for line in grade.lines.iter().filter(|l| !l.failures.is_empty()) {
        let (scene, why) = &line.failures[0];
        let cause = match line.mistakes.is_empty() {
            false => line.mistakes.join(" or "),
            true => format!("unexplained: {}", why.lines().next().unwrap_or("")),
        };
        let lost = line.line.max_points() - line.points;
        match bugs.iter_mut().find(|b| b.cause == cause) {
            Some(bug) => {
                bug.lines.push(line.line);
                bug.points_lost += lost;
            }
            None => bugs.push(Bug {
                cause,
                lines: vec![line.line],
                points_lost: lost,
                first_scene: grade.scenes[*scene].id.clone(),
            }),
        }
    }
    bugs.sort_by_key(|bug| std::cmp::Reverse(bug.points_lost));
    bugs
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
    }
    out
}

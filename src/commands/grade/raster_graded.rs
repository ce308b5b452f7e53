//! A program graded on the rasterizer's rubric: the rubric's scenes as handed to it, what each
//! gave (check's report, or why the run failed), its lines scored on them, and the mistakes to
//! fix first. What the table, the JSON and the teachers' sheet are written from.

use close2gl_check::raster::RasterReport;
use close2gl_check::raster::report;
use close2gl_check::raster::rubric::{self, Rubric, RubricLine};
use close2gl_core::RasterMistake;

use super::scene_run::RunFailure;

/// A scene of the rubric, ready to hand a program: its text (naming the files beside it) and
/// those files.
pub(super) struct RubricScene {
    pub name: String,
    pub text: String,
    pub files: Vec<(String, Vec<u8>)>,
}

/// What one scene gave: check's report, or why the run failed.
pub(super) type SceneOutcome = Result<RasterReport, RunFailure>;

/// One line scored.
pub(super) struct Scored<'a> {
    pub line: &'a RubricLine,
    pub points: u32,
    pub passed: usize,
    pub failures: Vec<(String, String)>,
}

pub(super) fn score<'a>(
    rubric: &'a Rubric,
    outcomes: &[(String, SceneOutcome)],
) -> Vec<Scored<'a>> {
    (rubric.lines.iter())
        .map(|line| {
            let mut failures = Vec::new();
            for name in &line.scenes {
                let Some((_, outcome)) = outcomes.iter().find(|(n, _)| n == name) else {
                    continue;
                };
                let verdict = match outcome {
                    Ok(report) => rubric::judge(line, report),
                    Err(failure) => Err(failure.reason.clone()),
                };
                if let Err(why) = verdict {
                    failures.push((name.clone(), why));
                }
            }
            let passed = line.scenes.len() - failures.len();
            Scored {
                line,
                points: rubric::points(line, passed, line.scenes.len()),
                passed,
                failures,
            }
        })
        .collect()
}

/// The mistakes check named, each once with the scenes it was named in, most scenes first: one
/// bug to fix however many scenes show it; two lines of text each, under a heading; none when
/// check named none.
pub(super) fn to_fix(outcomes: &[(String, SceneOutcome)]) -> Vec<String> {
    let mut bugs: Vec<(&'static str, Vec<&str>)> = Vec::new();
    for (scene, outcome) in outcomes {
        let Ok(report) = outcome else { continue };
        for mistake in report.mistakes() {
            match bugs.iter_mut().find(|(m, _)| *m == mistake) {
                Some((_, scenes)) => scenes.push(scene),
                None => bugs.push((mistake, vec![scene])),
            }
        }
    }
    bugs.sort_by_key(|(_, scenes)| std::cmp::Reverse(scenes.len()));
    if bugs.is_empty() {
        return Vec::new();
    }
    let heading =
        "to fix first, the mistakes check named (`close2gl check` a scene's trace for pictures):";
    let mut out = vec![heading.to_string()];
    for (mistake, scenes) in bugs {
        let stage = RasterMistake::from_name(mistake).map_or("", |m| m.stage().name());
        let meaning = RasterMistake::from_name(mistake).map_or("", report::meaning);
        out.push(format!("  {mistake} ({stage}): {meaning}"));
        out.push(format!(
            "    in {} scenes: {}",
            scenes.len(),
            scenes.join(", ")
        ));
    }
    out
}

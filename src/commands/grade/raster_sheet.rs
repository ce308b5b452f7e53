//! The rasterizer assignment's grade as a [`Sheet`], the shape the page, the platforms and the
//! gradebook read: each line with the mistakes of its stages check named in its failing
//! scenes, and the legal choices its passing scenes were accepted with.

use close2gl_check::raster::report::{self, legal_choices};
use close2gl_check::rubric::NamedMistake;
use close2gl_check::rubric::score::mistakes_in_words;
use close2gl_core::RasterMistake;

use super::raster_graded::{RubricScene, SceneOutcome, Scored, to_fix};
use super::sheet::{self, FailingScene, NOTHING_TO_FIX, Sheet, SheetLine};

/// The sheet of a program's scored lines, its scenes' outcomes (by scene name) and the
/// scenes; `max` what the rubric is worth.
pub fn sheet(
    scored: &[Scored],
    outcomes: &[(String, SceneOutcome)],
    scenes: &[RubricScene],
    max: u32,
) -> Sheet {
    let text_of = |name: &str| {
        scenes
            .iter()
            .find(|s| s.name == name)
            .map(|s| s.text.clone())
    };
    let lines = (scored.iter())
        .map(|s| line(s, outcomes, &text_of))
        .collect();
    let failing = (outcomes.iter())
        .filter_map(|(name, outcome)| failing_scene(name, outcome, scored, &text_of))
        .collect();
    let to_fix = match to_fix(outcomes) {
        bugs if bugs.is_empty() => vec![NOTHING_TO_FIX.to_string()],
        bugs => bugs,
    };
    Sheet {
        lines,
        total: scored.iter().map(|s| s.points).sum(),
        max,
        to_fix,
        failing,
        legend: Vec::new(),
    }
}

fn line(
    s: &Scored,
    outcomes: &[(String, SceneOutcome)],
    text_of: &dyn Fn(&str) -> Option<String>,
) -> SheetLine {
    let report = |name: &str| {
        let found = outcomes.iter().find(|(n, _)| n == name);
        found.and_then(|(_, o)| o.as_ref().ok())
    };
    let (named, unexplained) = named_mistakes(s, &report);
    let mistakes = mistakes_in_words(&named, s.failures.len(), unexplained);
    let mut notes: Vec<String> = Vec::new();
    let passing = (s.line.scenes.iter()).filter(|n| s.failures.iter().all(|(f, _)| f != *n));
    for rule in passing
        .filter_map(|n| report(n))
        .flat_map(|r| legal_choices(r.rules()))
    {
        if !notes.contains(&rule) {
            notes.push(rule);
        }
    }
    let first = s.failures.first();
    SheetLine {
        id: s.line.id.clone(),
        title: s.line.title.clone(),
        points: s.points,
        max: s.line.points,
        passed: s.passed,
        scenes: s.line.scenes.len(),
        evidence: sheet::evidence(
            first.map(|(n, why)| (n.as_str(), why.as_str())),
            None,
            &mistakes,
        ),
        mistakes,
        notes,
        failures: s.failures.clone(),
        scene_file: first.and_then(|(n, _)| text_of(n)),
    }
}

/// The mistakes of the line's stages named in its failing scenes, each with how many, the most
/// first; and how many failing scenes name none (a run that failed names none).
fn named_mistakes<'r>(
    s: &Scored,
    report: &dyn Fn(&str) -> Option<&'r close2gl_check::raster::RasterReport>,
) -> (Vec<NamedMistake>, usize) {
    let mut named: Vec<NamedMistake> = Vec::new();
    let mut unexplained = 0;
    for (scene, _) in &s.failures {
        let of_stage = |m: &&'static str| {
            RasterMistake::from_name(m).is_some_and(|m| s.line.stages.contains(&m.stage()))
        };
        let mistakes: Vec<&'static str> = report(scene)
            .map(|r| r.mistakes().into_iter().filter(of_stage).collect())
            .unwrap_or_default();
        unexplained += usize::from(mistakes.is_empty());
        for name in mistakes {
            match named.iter_mut().find(|m| m.name == name) {
                Some(m) => m.scenes += 1,
                None => named.push(NamedMistake { name, scenes: 1 }),
            }
        }
    }
    named.sort_by_key(|m| std::cmp::Reverse(m.scenes));
    (named, unexplained)
}

/// A scene on the page when it failed some line: the lines and why, check's report.
fn failing_scene(
    name: &str,
    outcome: &SceneOutcome,
    scored: &[Scored],
    text_of: &dyn Fn(&str) -> Option<String>,
) -> Option<FailingScene> {
    let lines: Vec<(String, String)> = (scored.iter())
        .filter_map(|s| {
            let (_, why) = s.failures.iter().find(|(n, _)| n == name)?;
            Some((s.line.id.clone(), why.clone()))
        })
        .collect();
    if lines.is_empty() {
        return None;
    }
    Some(FailingScene {
        id: name.to_string(),
        lines,
        pictures: Vec::new(),
        check: outcome.as_ref().ok().map(|r| report::text(r, name)),
        scene_text: text_of(name).unwrap_or_default(),
    })
}

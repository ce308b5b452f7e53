//! The scenes' verdicts added up into the rubric's lines: rotations settled on the program's
//! convention, each line's points shared out over its scenes, the mistakes check named in its
//! failing scenes, and what was accepted. Pure: the scenes come judged, running the programs
//! and writing the reports is the grade command's.

use super::judge::{Verdict, settle_rotations};
use super::lines::LineId;

/// One judged scene, as scoring reads it.
pub struct Judged<'a> {
    /// Each line the scene counts for, judged; settling the rotations may fail some.
    pub verdicts: &'a mut [(LineId, Verdict)],
    /// The catalogue mistakes check named in the scene (none when it agrees or was not run).
    pub mistakes: &'a [&'static str],
}

/// One line's score.
pub struct LineScore {
    pub line: LineId,
    pub points: u32,
    pub scenes: usize,
    pub passed: usize,
    /// The catalogue mistakes of the line's stage check named in every one of its failing
    /// scenes (a scene names all those it cannot tell apart; across scenes only the
    /// explanation of them all stays).
    pub mistakes: Vec<&'static str>,
    /// The failing scenes (indices into the scenes scored) with why each failed the line.
    pub failures: Vec<(usize, String)>,
    /// What its passing scenes had to say ("an arc around the look-at point"), each once.
    pub notes: Vec<String>,
}

/// The rubric's lines scored on a program's scenes, in the rubric's order, and their total.
pub struct Score {
    pub lines: Vec<LineScore>,
    pub total: u32,
}

impl Score {
    pub fn new(scenes: &mut [Judged]) -> Self {
        let mut rotations: Vec<&mut Verdict> = scenes
            .iter_mut()
            .flat_map(|s| s.verdicts.iter_mut())
            .filter(|(line, _)| *line == LineId::Rotation)
            .map(|(_, verdict)| verdict)
            .collect();
        settle_rotations(&mut rotations);
        let lines: Vec<LineScore> = LineId::ALL.iter().map(|&l| score(l, scenes)).collect();
        let total = lines.iter().map(|l| l.points).sum();
        Self { lines, total }
    }
}

fn score(line: LineId, scenes: &[Judged]) -> LineScore {
    let mut score = LineScore {
        line,
        points: 0,
        scenes: 0,
        passed: 0,
        mistakes: Vec::new(),
        failures: Vec::new(),
        notes: Vec::new(),
    };
    for (i, scene) in scenes.iter().enumerate() {
        let Some((_, verdict)) = scene.verdicts.iter().find(|(l, _)| *l == line) else {
            continue;
        };
        score.scenes += 1;
        if verdict.passed {
            score.passed += 1;
            if !verdict.detail.is_empty() && !score.notes.contains(&verdict.detail) {
                score.notes.push(verdict.detail.clone());
            }
            continue;
        }
        score.failures.push((i, verdict.detail.clone()));
    }
    let failing = score.failures.iter().map(|(i, _)| scenes[*i].mistakes);
    score.mistakes = consistent_mistakes(failing, line);
    score.points = line.points(score.passed, score.scenes);
    score
}

/// The mistakes of the line's stage named in every failing scene. A scene no mistake
/// explains leaves none: a mistake that explains only some of a line's failures is not what
/// cost the line (each scene's own names stay in its evidence).
fn consistent_mistakes<'a>(
    mut scenes: impl Iterator<Item = &'a [&'static str]>,
    line: LineId,
) -> Vec<&'static str> {
    let named = |mistakes: &[&'static str]| -> Vec<&'static str> {
        let of_stage = |name: &&'static str| {
            line.stage_mistakes()
                .is_none_or(|stage| stage.iter().any(|m| m.name() == *name))
        };
        mistakes.iter().copied().filter(of_stage).collect()
    };
    let Some(first) = scenes.next() else {
        return Vec::new();
    };
    scenes.fold(named(first), |mut everywhere, scene| {
        let here = named(scene);
        everywhere.retain(|m| here.contains(m));
        everywhere
    })
}

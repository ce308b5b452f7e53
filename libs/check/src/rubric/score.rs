//! The scenes' verdicts added up into the rubric's lines: rotations settled on the program's
//! convention, each line's points shared out over its scenes, the mistakes check named in its
//! failing scenes, and what was accepted. Pure: the scenes come judged, running the programs
//! and writing the reports is the grade command's.

use super::judge::{Verdict, settle_rotations};
use super::lines::{LineId, LinePoints};

/// One judged scene, as scoring reads it.
pub struct Judged<'a> {
    /// Each line the scene counts for, judged; settling the rotations may fail some.
    pub verdicts: &'a mut [(LineId, Verdict)],
    /// The catalogue mistakes check named in the scene (none when it agrees or was not run).
    pub mistakes: &'a [&'static str],
}

/// A mistake a line names, and how many of its failing scenes it explains.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NamedMistake {
    pub name: &'static str,
    pub scenes: usize,
}

/// One line's score.
pub struct LineScore {
    pub line: LineId,
    /// Its title and what it is worth, as the rubric says.
    pub title: String,
    pub max: u32,
    pub points: u32,
    pub scenes: usize,
    pub passed: usize,
    /// The catalogue mistakes of the line's stage check named in some of its failing scenes,
    /// each with how many, the most first (a scene names all those it cannot tell apart).
    pub mistakes: Vec<NamedMistake>,
    /// Failing scenes that name none of them.
    pub unexplained: usize,
    /// The failing scenes (indices into the scenes scored) with why each failed the line.
    pub failures: Vec<(usize, String)>,
    /// What its passing scenes had to say ("an arc around the look-at point"), each once.
    pub notes: Vec<String>,
}

/// The rubric's lines scored on a program's scenes, in the rubric's order, and their total.
pub struct Score {
    pub lines: Vec<LineScore>,
    pub total: u32,
    /// What the whole rubric is worth.
    pub max: u32,
}

impl Score {
    pub fn new(scenes: &mut [Judged], rubric: &LinePoints) -> Self {
        let mut rotations: Vec<&mut Verdict> = scenes
            .iter_mut()
            .flat_map(|s| s.verdicts.iter_mut())
            .filter(|(line, _)| *line == LineId::Rotation)
            .map(|(_, verdict)| verdict)
            .collect();
        settle_rotations(&mut rotations);
        let lines: Vec<LineScore> = (LineId::ALL.iter())
            .map(|&l| score(l, scenes, rubric))
            .collect();
        let total = lines.iter().map(|l| l.points).sum();
        Self {
            lines,
            total,
            max: rubric.total(),
        }
    }
}

fn score(line: LineId, scenes: &[Judged], rubric: &LinePoints) -> LineScore {
    let mut score = LineScore {
        line,
        title: rubric.title(line).to_string(),
        max: rubric.max(line),
        points: 0,
        scenes: 0,
        passed: 0,
        mistakes: Vec::new(),
        unexplained: 0,
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
    let failing: Vec<_> = score
        .failures
        .iter()
        .map(|(i, _)| scenes[*i].mistakes)
        .collect();
    (score.mistakes, score.unexplained) = named_mistakes(&failing, line);
    score.points = rubric.points(line, score.passed, score.scenes);
    score
}

/// Mistakes named for a line with `failing` failing scenes, `unexplained` of them naming none,
/// in a report's words (either assignment's): "culling_inverted: 12 of 16 failing scenes;
/// 4 unexplained"; empty when none is.
pub fn mistakes_in_words(mistakes: &[NamedMistake], failing: usize, unexplained: usize) -> String {
    let mut parts: Vec<String> = mistakes
        .iter()
        .map(|m| format!("{}: {} of {failing} failing scenes", m.name, m.scenes))
        .collect();
    if !parts.is_empty() && unexplained > 0 {
        parts.push(format!("{unexplained} unexplained"));
    }
    parts.join("; ")
}

impl LineScore {
    /// The mistakes named, in a report's words: "culling_inverted: 12 of 16 failing scenes;
    /// 4 unexplained"; empty when none is.
    pub fn mistakes_in_words(&self) -> String {
        mistakes_in_words(&self.mistakes, self.failures.len(), self.unexplained)
    }

    /// The mistakes that explain the most failing scenes (several when as many), when they
    /// explain at least half of them: what to fix first for this line. None when no mistake
    /// explains that many: a mistake that fits a few scenes of a program that goes wrong
    /// everywhere (one that draws nothing looks like inverted culling on some frames) is not
    /// its cause.
    pub fn leading_mistakes(&self) -> Vec<&'static str> {
        let most = self.mistakes.first().map_or(0, |m| m.scenes);
        if most == 0 || 2 * most < self.failures.len() {
            return Vec::new();
        }
        let leading = self.mistakes.iter().take_while(|m| m.scenes == most);
        leading.map(|m| m.name).collect()
    }
}

/// Each mistake of the line's stage named in some failing scene, with how many it explains
/// (the most first, then in the order met), and how many failing scenes name none; only those
/// that explain them all when some do. A mistake no failing scene names is never named: it
/// did not cost the line.
fn named_mistakes(scenes: &[&[&'static str]], line: LineId) -> (Vec<NamedMistake>, usize) {
    let of_stage = |name: &&'static str| {
        line.stage_mistakes()
            .is_none_or(|stage| stage.iter().any(|m| m.name() == *name))
    };
    let mut named: Vec<NamedMistake> = Vec::new();
    let mut unexplained = 0;
    for scene in scenes {
        let mut explained = false;
        for name in scene.iter().copied().filter(of_stage) {
            explained = true;
            match named.iter_mut().find(|m| m.name == name) {
                Some(mistake) => mistake.scenes += 1,
                None => named.push(NamedMistake { name, scenes: 1 }),
            }
        }
        unexplained += usize::from(!explained);
    }
    // A mistake that explains every failing scene is the line's: the others a few scenes could
    // not tell from it are alternatives there, not more mistakes the program made.
    if named.iter().any(|m| m.scenes == scenes.len()) {
        named.retain(|m| m.scenes == scenes.len());
    }
    // Stable: ties keep the order in which the scenes met them.
    named.sort_by_key(|m| std::cmp::Reverse(m.scenes));
    (named, unexplained)
}

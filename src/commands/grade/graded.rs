//! A program graded: every scene's result, and the rubric's lines scored on them by check's
//! rubric ([`Score`]).

use close2gl_check::rubric::{LinePoints, LineScore, Score};

use super::scene_run::SceneResult;

/// A program's grade: every scene's result and the rubric's lines.
pub struct Grade {
    pub scenes: Vec<SceneResult>,
    pub lines: Vec<LineScore>,
    pub total: u32,
    /// What the rubric is worth.
    pub max: u32,
}

impl Grade {
    pub fn new(mut scenes: Vec<SceneResult>, rubric: &LinePoints) -> Self {
        let mut judged: Vec<_> = scenes.iter_mut().map(SceneResult::judged).collect();
        let Score { lines, total, max } = Score::new(&mut judged, rubric);
        Self {
            scenes,
            lines,
            total,
            max,
        }
    }
}

//! The first assignment's grade in the shape the teachers' writers read ([`Sheet`]): its lines
//! with their evidence, the scenes that failed with close2gl's pictures, what to fix first.

use super::graded::Grade;
use super::report::failure_lines;
use super::scene_run::SceneResult;
use super::sheet::{FailingScene, Sheet, SheetLine};
use super::to_fix;

impl Grade {
    /// The grade in the shape the teachers' writers read.
    pub fn sheet(&self) -> Sheet {
        let lines = (self.lines.iter())
            .map(|line| SheetLine {
                id: line.line.id().to_string(),
                title: line.title.clone(),
                points: line.points,
                max: line.max,
                passed: line.passed,
                scenes: line.scenes,
                mistakes: line.mistakes_in_words(),
                notes: line.notes.clone(),
                failures: (line.failures.iter())
                    .map(|(i, why)| (self.scenes[*i].id.clone(), why.clone()))
                    .collect(),
                evidence: failure_lines(self, line),
                scene_file: (line.failures.first())
                    .map(|(i, _)| self.scenes[*i].scene_text.clone()),
            })
            .collect();
        Sheet {
            lines,
            total: self.total,
            max: self.max,
            to_fix: to_fix::lines(self),
            failing: self.scenes.iter().filter_map(failing_scene).collect(),
            legend: legend(),
        }
    }
}

/// A scene on the page when it failed some line: the lines, close2gl's pictures and report.
fn failing_scene(scene: &SceneResult) -> Option<FailingScene> {
    let lines: Vec<(String, String)> = (scene.verdicts.iter())
        .filter(|(_, v)| !v.passed)
        .map(|(line, v)| (line.id().to_string(), v.detail.clone()))
        .collect();
    if lines.is_empty() {
        return None;
    }
    let captions = [
        "close2gl (the reference)",
        "the program's trace",
        "the difference",
    ];
    let evidence = scene.evidence.as_ref();
    Some(FailingScene {
        id: scene.id.clone(),
        lines,
        pictures: evidence.map_or(Vec::new(), |e| {
            captions.into_iter().zip(e.pictures.clone()).collect()
        }),
        check: evidence.map(|e| e.text.clone()),
        scene_text: scene.scene_text.clone(),
    })
}

/// The difference picture's colours, as check paints them.
fn legend() -> Vec<(&'static str, [u8; 4])> {
    use close2gl_check::Kind;
    use close2gl_check::picture::kind_color;
    let kinds = [
        Kind::DrawnBehindEye,
        Kind::DrawnOutside,
        Kind::NotDrawn,
        Kind::FrontCulled,
        Kind::BackDrawn,
        Kind::InsideNotDrawn,
        Kind::Moved,
        Kind::Depth,
    ];
    kinds.map(|k| (k.name(), kind_color(k))).to_vec()
}

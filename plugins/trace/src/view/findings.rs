//! Check's findings on the shown trace, in the words the panel shows them: written whenever a
//! trace is taken or refused, so that the panel reads them without check's types.

use bevy_ecs::prelude::*;
use close2gl_core::TraceFindings;

use super::TraceView;

/// `TraceFindings` anew from `TraceView`, when it changed.
pub fn word_findings(view: Res<TraceView>, mut findings: ResMut<TraceFindings>) {
    if view.is_changed() {
        *findings = findings_of(&view);
    }
}

fn findings_of(view: &TraceView) -> TraceFindings {
    let error = view.error.clone();
    let Some(shown) = &view.shown else {
        return TraceFindings {
            error,
            ..TraceFindings::default()
        };
    };
    let (report, stages) = (&shown.report, &shown.report.comparison.stages);
    TraceFindings {
        path: view.path.clone(),
        error,
        agrees: report.agrees(),
        first_difference: (report.comparison.first_difference())
            .map(|s| (s.stage.name(), s.details.clone())),
        mistakes: report.mistakes(),
        unexplained: report.unexplained.clone(),
        stages: stages
            .iter()
            .map(|s| (s.stage.name(), s.in_brief()))
            .collect(),
    }
}

//! Check's findings on the shown trace, in the words the panel shows them: written whenever a
//! trace (geometry or raster) is taken or refused, so that the panel reads them without check's
//! types.

use bevy_ecs::prelude::*;
use close2gl_check::raster::report;
use close2gl_core::TraceFindings;

use super::{RasterShown, TraceView};

/// `TraceFindings` anew from `TraceView`, when it changed.
pub fn word_findings(view: Res<TraceView>, mut findings: ResMut<TraceFindings>) {
    if view.is_changed() {
        *findings = findings_of(&view);
    }
}

fn findings_of(view: &TraceView) -> TraceFindings {
    let error = view.error.clone();
    if let Some(raster) = &view.raster {
        return raster_findings(view, raster);
    }
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
        raster_report: None,
    }
}

/// A raster trace's findings: check's verdict, the mistakes it named, and its report for a
/// person as it is (the facts, the legal rules, what was named and what each does).
fn raster_findings(view: &TraceView, raster: &RasterShown) -> TraceFindings {
    let name = view.path.as_ref().map(|p| p.display().to_string());
    let text = report::text(&raster.report, &name.unwrap_or_default());
    TraceFindings {
        path: view.path.clone(),
        error: view.error.clone(),
        agrees: raster.report.agrees(),
        mistakes: raster.report.mistakes(),
        raster_report: Some(text.lines().map(str::to_string).collect()),
        ..TraceFindings::default()
    }
}

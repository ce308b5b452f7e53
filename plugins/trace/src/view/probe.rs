//! A probe of the Close2GL view while it shows a trace: which mesh triangles the trace drew at
//! the pixel, which close2gl draws there, and for each, close2gl's fate for it and what check
//! found.

use close2gl_core::Viewport;
use glam::DVec2;

use super::TraceView;
use super::show::system;
use crate::check::compare::fate_words;
use crate::check::region::covers;

/// The trace's side of a probe.
#[derive(Clone, Debug, PartialEq)]
pub struct TraceProbe {
    /// The answer, in lines.
    pub lines: Vec<String>,
    /// The mesh triangle the trace drew at the pixel (the first listed, when several).
    pub triangle: Option<usize>,
}

/// The answer, or None when no trace is shown.
pub fn probe(view: &TraceView, pixel: (u32, u32), viewport: Viewport) -> Option<TraceProbe> {
    let shown = view.shown.as_ref()?;
    let system = system(&shown.trace);
    let centre = DVec2::new(f64::from(pixel.0) + 0.5, f64::from(pixel.1) + 0.5);
    let covers = |polygon: &[DVec2]| {
        let pixels: Vec<DVec2> = polygon
            .iter()
            .map(|&p| system.to_pixels(p, viewport.width, viewport.height))
            .collect();
        covers(&pixels, centre)
    };
    let mut drawn: Vec<(usize, usize)> = shown
        .trace
        .pieces
        .iter()
        .filter(|p| covers(&p.corners))
        .map(|p| (p.triangle, p.line))
        .collect();
    drawn.dedup_by_key(|(t, _)| *t);
    let expected: Vec<usize> = (0..shown.report.expected.len())
        .filter(|&t| covers(&shown.report.expected[t].polygon))
        .collect();
    let mut lines = Vec::new();
    match drawn.as_slice() {
        [] => lines.push("The trace drew nothing here.".to_string()),
        _ => {
            let list: Vec<String> = drawn
                .iter()
                .map(|(t, l)| format!("{t} (line {l})"))
                .collect();
            lines.push(format!("The trace drew triangle {} here.", list.join(", ")));
        }
    }
    match expected.as_slice() {
        [] => lines.push("close2gl draws nothing here.".to_string()),
        _ => {
            let list: Vec<String> = expected.iter().map(usize::to_string).collect();
            lines.push(format!("close2gl draws triangle {} here.", list.join(", ")));
        }
    }
    let triangle = drawn.first().map(|(t, _)| *t);
    let mut triangles: Vec<usize> = drawn.iter().map(|(t, _)| *t).chain(expected).collect();
    triangles.sort_unstable();
    triangles.dedup();
    for t in triangles {
        let outcome = &shown.report.expected[t];
        let found = shown
            .report
            .comparison
            .triangles
            .iter()
            .find(|(_, list)| list.binary_search(&t).is_ok())
            .map_or("agrees".to_string(), |(kind, _)| {
                format!("differs: {} ({} stage)", kind.name(), kind.stage().name())
            });
        lines.push(format!(
            "Triangle {t}: close2gl {} it; the trace {found}.",
            fate_words(outcome)
        ));
    }
    Some(TraceProbe { lines, triangle })
}

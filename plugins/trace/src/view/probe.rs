//! A probe of the Close2GL view while it shows a trace: which mesh triangles the trace drew at
//! the pixel, which close2gl draws there, and for each, close2gl's fate for it and what check
//! found.

use close2gl_check::region::covers;
use close2gl_check::words::fate_words;
use close2gl_core::Viewport;
use glam::DVec2;

use super::{Shown, TraceView};

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
    let system = shown.trace.ortho2d;
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
    let mut lines = vec![
        who_drew(
            "The trace drew",
            "triangle",
            drawn.iter().map(|(t, l)| format!("{t} (line {l})")),
        ),
        who_drew(
            "close2gl draws",
            "triangle",
            expected.iter().map(usize::to_string),
        ),
    ];
    let triangle = drawn.first().map(|(t, _)| *t);
    let mut triangles: Vec<usize> = drawn.iter().map(|(t, _)| *t).chain(expected).collect();
    triangles.sort_unstable();
    triangles.dedup();
    lines.extend(triangles.into_iter().map(|t| fate_line(shown, t)));
    Some(TraceProbe { lines, triangle })
}

/// "The trace drew triangle 3 (line 9), 4 (line 10) here.", or "... nothing here.".
fn who_drew(who: &str, what: &str, list: impl Iterator<Item = String>) -> String {
    let list: Vec<String> = list.collect();
    match list.is_empty() {
        true => format!("{who} nothing here."),
        false => format!("{who} {what} {} here.", list.join(", ")),
    }
}

/// Mesh triangle `t`: close2gl's fate for it and what check found.
fn fate_line(shown: &Shown, t: usize) -> String {
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
    format!(
        "Triangle {t}: close2gl {} it; the trace {found}.",
        fate_words(outcome)
    )
}

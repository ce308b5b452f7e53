//! One mesh triangle judged: close2gl's outcome against the trace's pieces for it, as both
//! drew it (the window and depth), or as only one did (clipping's or culling's), within what
//! float32 rounding allows. The drawn stages count its verdicts; the diagnosis asks it of each
//! candidate program, triangle by triangle, stopping at the first that differs.

use close2gl_core::FateKind;
use close2gl_pipeline::program::{Program, TriangleOutcome};
use close2gl_pipeline::rounding;
use close2gl_trace_format::Trace;
use glam::DVec2;

use super::tolerance::within;
use crate::region;
use crate::vocabulary::Kind;
use crate::words::{fate_words, number, vec2};

/// What the trace drew, by mesh triangle (indices into `trace.pieces`).
pub fn pieces_by_triangle(trace: &Trace, triangles: usize) -> Vec<Vec<usize>> {
    let mut pieces: Vec<Vec<usize>> = vec![Vec::new(); triangles];
    for (i, piece) in trace.pieces.iter().enumerate() {
        pieces[piece.triangle].push(i);
    }
    pieces
}

/// What one mesh triangle's comparison found.
pub enum TriangleVerdict {
    /// Both agree; `window`: both drew it (the window stage checked it), `depths`: how many of
    /// the trace's pieces gave depths that were checked.
    Agree { window: bool, depths: usize },
    Differs {
        kind: Kind,
        detail: String,
        window: bool,
        depths: usize,
    },
}

/// Judges mesh triangle `t`: close2gl's outcome `ours` against the trace's pieces for it.
pub fn judge_triangle(
    program: &Program,
    trace: &Trace,
    t: usize,
    ours: &TriangleOutcome,
    pieces: &[usize],
) -> TriangleVerdict {
    let theirs: Vec<&[DVec2]> = pieces
        .iter()
        .map(|&i| trace.pieces[i].corners.as_slice())
        .collect();
    let one = OneTriangle {
        program,
        trace,
        t,
        ours,
        pieces,
        theirs,
    };
    match (ours.drawn(), !one.theirs.is_empty()) {
        (true, true) => one.both_drew(),
        (true, false) => one.only_ours_drew(),
        (false, true) => one.only_theirs_drew(),
        (false, false) => AGREE,
    }
}

/// One mesh triangle as both sides drew it. What is worked out from it (visibility, the
/// trace's line) is worked out only in the branch that reads it: a triangle is judged for
/// every candidate set of mistakes.
struct OneTriangle<'a> {
    program: &'a Program,
    trace: &'a Trace,
    t: usize,
    ours: &'a TriangleOutcome,
    pieces: &'a [usize],
    theirs: Vec<&'a [DVec2]>,
}

impl OneTriangle<'_> {
    /// The trace's line of the triangle's first piece.
    fn line(&self) -> usize {
        self.pieces
            .first()
            .map_or(0, |&i| self.trace.pieces[i].line)
    }

    /// Both drew it: in the same place (the window stage), at the same depths.
    fn both_drew(&self) -> TriangleVerdict {
        let (t, ours) = (self.t, self.ours);
        if let Some(d) = region::compare(&ours.polygon, &ours.errors, &self.theirs) {
            return differs(Kind::Moved, moved(t, &d, self.line()), true, 0);
        }
        let (checked, off) = depths(ours, self.pieces, self.trace);
        match off {
            Some((found, want, line)) => differs(
                Kind::Depth,
                format!(
                    "triangle {t} (line {line}): depth expected {}, found {}",
                    number(want),
                    number(found)
                ),
                true,
                checked,
            ),
            None => TriangleVerdict::Agree {
                window: true,
                depths: checked,
            },
        }
    }

    /// close2gl drew it and the trace did not: culling's (front-facing, or inside with culling
    /// off) or clipping's; nothing when close2gl's piece is within rounding of nothing.
    fn only_ours_drew(&self) -> TriangleVerdict {
        let (t, ours) = (self.t, self.ours);
        if ours.near_a_plane || region::negligible(&ours.polygon, &ours.errors) {
            return AGREE;
        }
        let inside = ours.fate.kind == FateKind::Drawn;
        let culling_on = self.program.declared.culling.is_some();
        if inside && ours.near_edge_on {
            AGREE
        } else if inside && culling_on {
            let detail = format!(
                "triangle {t}: close2gl drew it (front-facing, inside the view volume); the \
                 trace drew nothing"
            );
            differs(Kind::FrontCulled, detail, false, 0)
        } else if inside {
            let detail = format!(
                "triangle {t}: close2gl drew it (inside the view volume, culling off); the trace \
                 drew nothing"
            );
            differs(Kind::InsideNotDrawn, detail, false, 0)
        } else {
            let detail = format!(
                "triangle {t}: close2gl {} it; the trace drew nothing",
                fate_words(ours)
            );
            differs(Kind::NotDrawn, detail, false, 0)
        }
    }

    /// The trace drew it and close2gl did not: clipping's (outside, or behind the eye) or
    /// culling's; nothing when the trace's pieces are within rounding of nothing.
    fn only_theirs_drew(&self) -> TriangleVerdict {
        let (t, ours) = (self.t, self.ours);
        let error = corner_error(self.program, ours);
        let visible = self
            .theirs
            .iter()
            .any(|q| !region::negligible(q, &vec![error; q.len()]));
        if !visible {
            return AGREE;
        }
        match ours.fate.kind {
            FateKind::Clipped if !ours.near_a_plane => {
                let kind = match ours.clip.iter().any(|c| c.w <= 0.0) {
                    true => Kind::DrawnBehindEye,
                    false => Kind::DrawnOutside,
                };
                let detail = format!(
                    "triangle {t}: close2gl {} it; the trace drew it (line {})",
                    fate_words(ours),
                    self.line()
                );
                differs(kind, detail, false, 0)
            }
            FateKind::Culled | FateKind::ZeroArea if !ours.near_edge_on => {
                let detail = format!(
                    "triangle {t}: close2gl culled it as a back face; the trace drew it (line {})",
                    self.line()
                );
                differs(Kind::BackDrawn, detail, false, 0)
            }
            _ => AGREE,
        }
    }
}

fn differs(kind: Kind, detail: String, window: bool, depths: usize) -> TriangleVerdict {
    TriangleVerdict::Differs {
        kind,
        detail,
        window,
        depths,
    }
}

const AGREE: TriangleVerdict = TriangleVerdict::Agree {
    window: false,
    depths: 0,
};

/// How far a float32 program may put the corners of a triangle close2gl did not draw: the
/// largest error of its corners in front of the eye (those behind it are not placed at all).
fn corner_error(program: &Program, ours: &TriangleOutcome) -> f64 {
    ours.clip
        .iter()
        .filter(|c| c.w > 0.0)
        .map(|&c| {
            let p = (program.v * (c / c.w)).truncate().truncate();
            rounding::window_error(program.v, ours.terms, c, p)
        })
        .fold(rounding::PRINTED, f64::max)
}

/// How many of the trace's pieces for this triangle give depths, and the first depth that is
/// off, with close2gl's depth at that corner and the trace's line.
fn depths(
    ours: &TriangleOutcome,
    pieces: &[usize],
    trace: &Trace,
) -> (usize, Option<(f64, f64, usize)>) {
    let (mut checked, mut first) = (0, None);
    for &i in pieces {
        let piece = &trace.pieces[i];
        let Some(found) = &piece.depths else {
            continue;
        };
        checked += 1;
        for (q, &z) in piece.corners.iter().zip(found) {
            let nearest = (0..ours.polygon.len()).min_by(|&a, &b| {
                let d = |i: usize| ours.polygon[i].distance(*q);
                d(a).total_cmp(&d(b))
            });
            if let Some(i) = nearest
                && ours.polygon[i].distance(*q) <= ours.errors[i]
                && !within((z - ours.depths[i]).abs(), ours.depth_errors[i])
                && first.is_none()
            {
                first = Some((z, ours.depths[i], piece.line));
            }
        }
    }
    (checked, first)
}

/// A moved triangle's first difference, in words: the corner that is off, or the areas.
fn moved(t: usize, d: &region::RegionDifference, line: usize) -> String {
    match d.corner {
        (Some(want), Some(found)) => format!(
            "triangle {t} (line {line}): a corner expected at {}, the nearest drawn is {}",
            vec2(want),
            vec2(found)
        ),
        (Some(want), None) => format!(
            "triangle {t} (line {line}): no corner drawn near {}",
            vec2(want)
        ),
        (None, Some(found)) => format!(
            "triangle {t} (line {line}): a corner drawn at {}, outside close2gl's polygon",
            vec2(found)
        ),
        (None, None) => format!(
            "triangle {t} (line {line}): covers {} square units, close2gl's polygon {}",
            number(d.found_area),
            number(d.expected_area)
        ),
    }
}

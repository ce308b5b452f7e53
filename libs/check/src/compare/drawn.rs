//! The stages read from what each side drew, mesh triangle by mesh triangle: clipping,
//! culling, the window and depth, each triangle judged once ([`super::triangle`]) and its
//! difference counted at the stage its kind belongs to.

use close2gl_pipeline::program::{Program, TriangleOutcome};
use close2gl_trace_format::Trace;

use super::triangle::{TriangleVerdict, judge_triangle, pieces_by_triangle};
use crate::vocabulary::{Kind, Stage, StageResult};

/// The clipping, culling, window and depth stages, from what each side drew per triangle.
pub fn compare(
    program: &Program,
    trace: &Trace,
    expected: &[TriangleOutcome],
    mark: &mut impl FnMut(Kind, usize),
) -> [StageResult; 4] {
    if !trace.gives_output() {
        let note = "the trace has no 'tri', 'poly', 'drawn' or 'clip' lines";
        return [Stage::Clipping, Stage::Culling, Stage::Window, Stage::Depth]
            .map(|s| StageResult::not_checked(s, note));
    }
    let pieces = pieces_by_triangle(trace, expected.len());
    let mut stages =
        [Stage::Clipping, Stage::Culling, Stage::Window, Stage::Depth].map(StageResult::new);
    stages[0].checked = expected.len();
    stages[1].checked = expected.len();
    if trace.pieces.is_empty() && trace.drawn.is_none() {
        stages[0].note = Some(
            "the trace gives clip coordinates and no 'tri' or 'poly' line: compared as a \
             program that drew nothing ('drawn 0' says so)"
                .into(),
        );
    }
    for (t, ours) in expected.iter().enumerate() {
        let (window, depths) = match judge_triangle(program, trace, t, ours, &pieces[t]) {
            TriangleVerdict::Agree { window, depths } => (window, depths),
            TriangleVerdict::Differs {
                kind,
                detail,
                window,
                depths,
            } => {
                mark(kind, t);
                stages[kind.stage() as usize - Stage::Clipping as usize].differ(|| detail);
                (window, depths)
            }
        };
        stages[2].checked += usize::from(window);
        stages[3].checked += depths;
    }
    let [clipping, culling, window, mut depth] = stages;
    if depth.checked == 0 {
        depth.note = Some(match trace.pieces.iter().any(|p| p.depths.is_some()) {
            true => "no triangle with depths was drawn where close2gl draws it".into(),
            false => "the trace's 'tri' and 'poly' lines give no depth".into(),
        });
        return [clipping.finish(), culling.finish(), window.finish(), depth];
    }
    [
        clipping.finish(),
        culling.finish(),
        window.finish(),
        depth.finish(),
    ]
}

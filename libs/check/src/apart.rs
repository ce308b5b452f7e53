//! When several sets of mistakes reproduce a trace, each is named (a name is never picked for
//! being likelier); this says what would tell them apart: a line the trace could give, or a
//! frame in which they draw differently.

use close2gl_pipeline::mistakes::Mistakes;
use close2gl_pipeline::program::Program;
use close2gl_trace_format::Trace;
use glam::DMat4;

use crate::declared::program_for;

/// What would tell `sets` apart, each hint once, in a stable order; empty for fewer than two.
pub fn tell_apart(trace: &Trace, sets: &[Mistakes]) -> Vec<String> {
    let programs: Vec<Program> = sets.iter().map(|&s| program_for(trace, s)).collect();
    let mut hints: Vec<String> = Vec::new();
    for (i, a) in programs.iter().enumerate() {
        for b in &programs[i + 1..] {
            for hint in pair(trace, a, b) {
                if !hints.contains(&hint) {
                    hints.push(hint);
                }
            }
        }
    }
    hints
}

/// What tells two programs apart that both reproduce the trace.
fn pair(trace: &Trace, a: &Program, b: &Program) -> Vec<String> {
    let mut hints = Vec::new();
    for (name, x, y, given) in [
        ("M", a.m, b.m, trace.m.is_some()),
        ("P", a.p, b.p, trace.p.is_some()),
        ("V", a.v, b.v, trace.v.is_some()),
    ] {
        if !given && !same(x, y) {
            hints.push(format!("write 'matrix {name}'"));
        }
    }
    if trace.clip.is_empty() && !same(a.clip_matrix, b.clip_matrix) {
        hints.push("write the 'clip' lines".into());
    }
    if a.cull != b.cull {
        hints.push(
            "a frame from outside the model with culling on, where front and back faces are \
             both in view"
                .into(),
        );
    }
    if a.clip != b.clip {
        hints.push("a frame with triangles across the near plane and the window's border".into());
    }
    if hints.is_empty() && a.cull == b.cull {
        // The same program under these declarations (with `culling cw`, taking ccw as front
        // is both inverting and ignoring the declaration).
        hints.push(
            "a frame with other declarations (the other front face, or culling off): under \
             these, they are the same program"
                .into(),
        );
    }
    hints
}

fn same(a: DMat4, b: DMat4) -> bool {
    a.abs_diff_eq(
        b,
        1e-9 * (1.0
            + a.abs()
                .to_cols_array()
                .iter()
                .fold(0.0, |m: f64, x| m.max(*x))),
    )
}

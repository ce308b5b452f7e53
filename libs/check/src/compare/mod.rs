//! One program's frame (close2gl's, or close2gl's with mistakes) against a trace, stage by stage
//! in the pipeline's order, one file per stage's comparison: the camera, the matrices, the clip
//! coordinates, and the stages read from what each side drew (clipping, culling, window, depth;
//! each mesh triangle judged in [`triangle`]). A later assignment's stages (the rasterizer's
//! coverage, depth, interpolation, shading, texturing) are new files beside these, each with its
//! own `compare`. What the trace leaves out is not checked; what it gives is checked within
//! tolerances a float32 program meets (docs/checking.md, "Tolerances").

use close2gl_core::Mesh;
use close2gl_pipeline::program::{Program, TriangleOutcome};
use close2gl_trace_format::Trace;

use crate::own_input::own_program;
use crate::vocabulary::{Comparison, Kind};

pub mod camera;
pub mod clip;
pub mod drawn;
pub mod matrices;
mod tolerance;
pub mod triangle;

/// Compares `trace` with what `program` computes for `mesh` (`expected`: its frame), the whole
/// chain from the camera. The trace's triangle indices must be the mesh's (checked when the
/// trace was read).
pub fn compare(
    program: &Program,
    mesh: &Mesh,
    trace: &Trace,
    expected: &[TriangleOutcome],
) -> Comparison {
    compare_stages([program, program, program], mesh, trace, expected)
}

/// Compares `trace` with `program`, each stage on the program's own input to it: the clip
/// coordinates against its own P·M (when it gives both), clipping, culling and the window from
/// its own clip coordinates and V ([`own_program`]). Two independent bugs then show at once,
/// each at its stage, rather than the first hiding the second under its consequences.
pub fn compare_own_input(program: &Program, mesh: &Mesh, trace: &Trace) -> Comparison {
    let own = own_program(program, mesh, trace, true);
    let expected = own.frame(mesh);
    let mut own_product = *program;
    if let Some((p, m)) = trace.p.zip(trace.m) {
        own_product.clip_matrix = p * m;
    }
    compare_stages([program, &own_product, &own], mesh, trace, &expected)
}

/// The stages in order: the camera and the matrices against `matrices`, the clip coordinates
/// against `clip`'s, the 2D output against `output`'s frame, `expected`.
fn compare_stages(
    [matrices_of, clip_of, output]: [&Program; 3],
    mesh: &Mesh,
    trace: &Trace,
    expected: &[TriangleOutcome],
) -> Comparison {
    let mut triangles: Vec<(Kind, Vec<usize>)> = Vec::new();
    let mut mark = |kind: Kind, t: usize| match triangles.iter_mut().find(|(k, _)| *k == kind) {
        Some((_, list)) => list.push(t),
        None => triangles.push((kind, vec![t])),
    };
    let mut stages = vec![camera::compare(matrices_of, trace)];
    stages.extend(matrices::compare(matrices_of, trace));
    stages.push(clip::compare(clip_of, mesh, trace, &mut mark));
    stages.extend(drawn::compare(output, trace, expected, &mut mark));
    triangles.sort_by_key(|(kind, _)| *kind);
    Comparison { stages, triangles }
}

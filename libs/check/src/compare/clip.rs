//! The clip stage: each corner's clip coordinates the trace gives against the program's P·M
//! of the mesh's corner, within what float32 rounding of the product and printing allow.

use close2gl_core::Mesh;
use close2gl_pipeline::program::Program;
use close2gl_pipeline::rounding::{PRINTED, clip_error, clip_terms};
use close2gl_trace_format::Trace;

use super::tolerance::within;
use crate::vocabulary::{Kind, Stage, StageResult};
use crate::words::vec4;

/// The clip stage of `trace` against `program`; each triangle that differs is `mark`ed.
pub fn compare(
    program: &Program,
    mesh: &Mesh,
    trace: &Trace,
    mark: &mut impl FnMut(Kind, usize),
) -> StageResult {
    if trace.clip.is_empty() {
        return StageResult::not_checked(Stage::Clip, "the trace has no 'clip' lines");
    }
    let mut result = StageResult::new(Stage::Clip);
    let a = program.clip_matrix;
    for line in &trace.clip {
        result.checked += 1;
        let t = line.triangle;
        let corners = mesh.triangles[t].map(|i| program.world(mesh, i));
        for (k, (&found, &corner)) in line.corners.iter().zip(&corners).enumerate() {
            let want = a * corner.extend(1.0);
            let error = clip_error(clip_terms(a, program.camera.position, &[corner]));
            let off = (found - want).abs();
            if (0..4).any(|i| !within(off[i], error[i] + PRINTED)) {
                mark(Kind::ClipCoordinates, t);
                result.differ(|| {
                    format!(
                        "triangle {t}, corner {k} (line {}): expected {}, found {}",
                        line.line,
                        vec4(want),
                        vec4(found)
                    )
                });
                break;
            }
        }
    }
    result.finish()
}

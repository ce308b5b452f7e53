//! The M, P and V stages: each entry the trace gives against the program's matrix, within what
//! float32 rounding and printing allow.

use close2gl_pipeline::program::Program;
use close2gl_pipeline::rounding::{BOUND, PRINTED};
use close2gl_trace_format::Trace;
use glam::DMat4;

use super::tolerance::within;
use crate::vocabulary::{Stage, StageResult};
use crate::words::number;

/// The M, P and V stages (V's depth row is not compared: the format leaves it to the program).
pub fn compare(program: &Program, trace: &Trace) -> [StageResult; 3] {
    [
        matrix(Stage::M, program.m, trace.m, ALL_ROWS),
        matrix(Stage::P, program.p, trace.p, ALL_ROWS),
        matrix(Stage::V, program.v, trace.v, V_ROWS),
    ]
}

/// The rows of M and P compared, and of V (its third, for depth, is the program's own).
pub const ALL_ROWS: &[usize] = &[0, 1, 2, 3];
pub const V_ROWS: &[usize] = &[0, 1, 3];

/// A matrix stage: entries of the given rows, each within [`BOUND`] of its size and of the
/// matrix's (rounding in float32 scales with both), and what printing it adds.
pub fn matrix(stage: Stage, expected: DMat4, found: Option<DMat4>, rows: &[usize]) -> StageResult {
    let Some(found) = found else {
        let note = format!("the trace has no 'matrix {}' line", stage.name());
        return StageResult::not_checked(stage, &note);
    };
    let mut result = StageResult::new(stage);
    let largest = expected
        .to_cols_array()
        .iter()
        .fold(0.0f64, |a, b| a.max(b.abs()));
    for &row in rows {
        for column in 0..4 {
            let (e, f) = (expected.col(column)[row], found.col(column)[row]);
            result.checked += 1;
            // An entry is computed from numbers as large as the matrix's largest (M's
            // translation sums c's terms), and printed.
            let tolerance = BOUND * (e.abs() + largest) + PRINTED;
            if !within((e - f).abs(), tolerance) {
                result.differ(|| {
                    format!(
                        "{}[{}][{}] (row {}, column {}): expected {}, found {}",
                        stage.name(),
                        row,
                        column,
                        row + 1,
                        column + 1,
                        number(e),
                        number(f)
                    )
                });
            }
        }
    }
    result.finish()
}

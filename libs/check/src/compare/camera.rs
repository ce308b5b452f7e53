//! The camera stage: the trace's axes are unit length, square to each other, and as handed as
//! close2gl's (left-handed only for a program with `left_handed`).

use close2gl_core::Mistake;
use close2gl_pipeline::program::Program;
use close2gl_trace_format::Trace;

use crate::vocabulary::{Stage, StageResult};

/// How far apart unit axes may be from unit length or square to each other: a float32
/// program's axes after many turns drift by far less (it renormalises, or the camera stage
/// is where it shows).
const AXES: f64 = 1e-3;

/// The camera stage of `trace` against what `program` expects of its axes.
pub fn compare(program: &Program, trace: &Trace) -> StageResult {
    let mut result = StageResult::new(Stage::Camera);
    // Three lengths, three right angles and the handedness: each can differ once.
    result.checked = 7;
    let c = &trace.camera;
    for (name, axis) in [("u", c.u), ("v", c.v), ("n", c.n)] {
        let length = axis.length();
        if (length - 1.0).abs() > AXES {
            result.differ(|| format!("{name} is not unit length: |{name}| = {length:.6}"));
        }
    }
    for (name, a, b) in [("u·v", c.u, c.v), ("u·n", c.u, c.n), ("v·n", c.v, c.n)] {
        let dot = a.dot(b) / (a.length() * b.length());
        if dot.abs() > AXES {
            result.differ(|| format!("the axes are not square to each other: {name} = {dot:.6}"));
        }
    }
    let handedness = c.u.cross(c.v).dot(c.n);
    let left_expected = program.mistakes.has(Mistake::LeftHanded);
    if (handedness < 0.0) != left_expected {
        result.differ(|| match left_expected {
            true => format!("the axes are right-handed: (u × v)·n = {handedness:.6}"),
            false => format!(
                "the axes are left-handed: (u × v)·n = {handedness:.6} (u points to the \
                 camera's left: u = n × v instead of v × n)"
            ),
        });
    }
    result.finish()
}

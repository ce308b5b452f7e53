//! The program a trace declares: its camera, window, 2D system, culling, clipping, mode, planes
//! and model matrix made into what close2gl runs ([`Program`]), with the mistakes being tried
//! and where the winding is tested. Checking, the diagnosis and the rubric all make it here.

use close2gl_core::RenderMode;
use close2gl_pipeline::mistakes::Mistakes;
use close2gl_pipeline::program::{Declared, Program, WindingSpace};
use close2gl_trace_format::Trace;
use glam::DMat4;

/// The program close2gl runs for this trace: its camera, window, 2D system and settings, with
/// `mistakes`, testing the winding where the trace says (on screen when it does not).
pub fn program_for(trace: &Trace, mistakes: Mistakes) -> Program {
    let winding = trace.winding.unwrap_or(WindingSpace::Screen);
    program_winding(trace, mistakes, winding)
}

/// [`program_for`] testing the winding in `winding`.
pub fn program_winding(trace: &Trace, mistakes: Mistakes, winding: WindingSpace) -> Program {
    Program::new(&trace.camera, declared(trace, winding), mistakes)
}

/// What `trace` declares (its window, 2D system, culling, clipping, mode, planes and model
/// matrix), testing the winding in `winding`: the one way a trace becomes what close2gl runs
/// and what its view shows ([`Declared::onto`]).
pub fn declared(trace: &Trace, winding: WindingSpace) -> Declared {
    let mode = trace.mode.unwrap_or(RenderMode::Solid);
    Declared {
        winding,
        planes: trace.planes,
        model: trace.model_matrix.unwrap_or(DMat4::IDENTITY),
        ..Declared::new(
            trace.window,
            trace.ortho2d,
            trace.culling,
            trace.clipping,
            mode,
        )
    }
}

//! The trace's 2D output as the Close2GL view's: its pieces mapped from its 2D system onto the
//! view's pixels, as the frame's topology draws them.

use bevy_ecs::prelude::*;
use close2gl_core::{Close2glFrame, Topology, TraceOutput, Viewport};
use close2gl_pipeline::emit;
use close2gl_trace_format::Trace;
use glam::DVec2;

use super::TraceView;

/// The shown trace's 2D output, in the view's pixels, whenever the pipeline's frame (its
/// topology), the trace or the view's size changed; none once no trace is shown.
pub fn trace_output_system(
    view: Res<TraceView>,
    viewport: Res<Viewport>,
    frame: Res<Close2glFrame>,
    mut output: ResMut<TraceOutput>,
) {
    let Some(shown) = &view.shown else {
        if output.0.is_some() {
            output.0 = None;
        }
        return;
    };
    if frame.is_changed() || view.is_changed() || viewport.is_changed() {
        output.0 = Some(vertices(&shown.trace, *viewport, frame.topology));
    }
}

/// The pieces in `viewport`'s pixels: fans of triangles, their edges as lines, or their corners.
fn vertices(trace: &Trace, viewport: Viewport, topology: Topology) -> Vec<[f32; 2]> {
    let system = trace.ortho2d;
    let mut out = Vec::new();
    for piece in &trace.pieces {
        let pixel = |p: DVec2| {
            let q = system.to_pixels(p, viewport.width, viewport.height);
            [q.x as f32, q.y as f32]
        };
        let corners: Vec<[f32; 2]> = piece.corners.iter().map(|&p| pixel(p)).collect();
        // A piece's edges are all its own: the trace drew them as they are.
        out.extend(emit::corners(topology, corners.len(), |_| true).map(|i| corners[i]));
    }
    out
}

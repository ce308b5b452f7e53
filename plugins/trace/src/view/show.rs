//! The trace's 2D output as the Close2GL view's: its pieces mapped from its 2D system onto the
//! view's pixels, as the frame's topology draws them.

use bevy_ecs::prelude::*;
use close2gl_core::{Close2glFrame, Topology, Viewport};
use close2gl_pipeline::program::System2d;
use glam::DVec2;

use super::TraceView;
use crate::format::Trace;

/// Replaces the 2D buffer with the shown trace's whenever the pipeline wrote its own, the trace
/// changed or the view was resized.
pub fn show_trace(view: Res<TraceView>, viewport: Res<Viewport>, mut frame: ResMut<Close2glFrame>) {
    let Some(shown) = &view.shown else {
        return;
    };
    if !(frame.is_changed() || view.is_changed() || viewport.is_changed()) {
        return;
    }
    let vertices = vertices(&shown.trace, *viewport, frame.topology);
    frame.vertices = vertices;
}

/// The trace's 2D system.
pub fn system(trace: &Trace) -> System2d {
    let o = trace.ortho2d;
    System2d {
        left: o.left,
        right: o.right,
        bottom: o.bottom,
        top: o.top,
    }
}

/// The pieces in `viewport`'s pixels: fans of triangles, their edges as lines, or their corners.
fn vertices(trace: &Trace, viewport: Viewport, topology: Topology) -> Vec<[f32; 2]> {
    let system = system(trace);
    let mut out = Vec::new();
    for piece in &trace.pieces {
        let pixel = |p: DVec2| {
            let q = system.to_pixels(p, viewport.width, viewport.height);
            [q.x as f32, q.y as f32]
        };
        let corners: Vec<[f32; 2]> = piece.corners.iter().map(|&p| pixel(p)).collect();
        let n = corners.len();
        match topology {
            Topology::Triangles => {
                for i in 1..n - 1 {
                    out.extend([corners[0], corners[i], corners[i + 1]]);
                }
            }
            Topology::Lines => {
                for i in 0..n {
                    out.extend([corners[i], corners[(i + 1) % n]]);
                }
            }
            Topology::Points => out.extend(&corners),
        }
    }
    out
}

//! From the pipeline's primitives to triangles: a triangle as it is; a line as the rectangle one
//! pixel wide around it, and a point as the one-pixel square around it, both as two triangles
//! that share a diagonal (the fill rule then draws each pixel of the rectangle once). These are
//! the shapes the reference's rasterizer gives lines and points of width and size 1: Vulkan's
//! default rectangular lines, and points as squares. Set up in parallel, in submission order.

use close2gl_core::Topology;
use rayon::prelude::*;

use crate::edge::FIXED_ONE;
use crate::setup::{Corner, Triangle, setup};
use crate::varyings::Used;
use crate::vertex::Vertex;

/// Primitives set up per parallel task.
const CHUNK: usize = 4096;

/// Every primitive of `topology` (its vertices' `indices`) to its triangles, in order, in
/// parallel.
pub(crate) fn set_up_all(
    topology: Topology,
    indices: &[u32],
    vertices: &[Vertex],
    params: SetupParams,
    triangles: &mut Vec<Triangle>,
) {
    let per_primitive = indices_per_primitive(topology);
    let triangles_per = triangles_per_primitive(topology);
    let count = indices.len() / per_primitive;
    triangles.resize(count * triangles_per, Triangle::EMPTY);
    triangles
        .par_chunks_mut(CHUNK * triangles_per)
        .zip(indices.par_chunks(CHUNK * per_primitive))
        .for_each(|(out, indices)| set_up(topology, indices, vertices, params, out));
}

/// One task's primitives (their vertices' `indices`) to their triangles.
#[inline(always)]
fn set_up(
    topology: Topology,
    indices: &[u32],
    vertices: &[Vertex],
    params: SetupParams,
    out: &mut [Triangle],
) {
    let vertex = |i: u32| vertices[i as usize];
    let primitives = indices.chunks_exact(indices_per_primitive(topology));
    match topology {
        Topology::Triangles => {
            for (o, p) in out.iter_mut().zip(primitives) {
                *o = triangle([p[0], p[1], p[2]].map(vertex), params);
            }
        }
        Topology::Lines => {
            for (o, p) in out.chunks_exact_mut(2).zip(primitives) {
                o.copy_from_slice(&line(vertex(p[0]), vertex(p[1]), params));
            }
        }
        Topology::Points => {
            for (o, p) in out.chunks_exact_mut(2).zip(primitives) {
                o.copy_from_slice(&point(vertex(p[0]), params));
            }
        }
    }
}

fn indices_per_primitive(topology: Topology) -> usize {
    match topology {
        Topology::Triangles => 3,
        Topology::Lines => 2,
        Topology::Points => 1,
    }
}

/// How many triangles setup makes of each primitive: a line's and a point's rectangles are two.
pub(crate) fn triangles_per_primitive(topology: Topology) -> usize {
    match topology {
        Topology::Triangles => 1,
        Topology::Lines | Topology::Points => 2,
    }
}

/// What the triangle setup needs besides the vertices.
#[derive(Clone, Copy, Debug)]
pub(crate) struct SetupParams {
    pub size: [i32; 2],
    pub used: Used,
}

pub(crate) fn triangle(v: [Vertex; 3], params: SetupParams) -> Triangle {
    if !v.iter().all(Vertex::in_guard_band) {
        return Triangle::EMPTY;
    }
    let corners = v.map(|v| v.corner());
    setup(corners, params.size, params.used)
}

/// A line one pixel wide: the rectangle whose long sides lie half a pixel either side of it and
/// whose short sides pass through its ends.
pub(crate) fn line(a: Vertex, b: Vertex, params: SetupParams) -> [Triangle; 2] {
    if !(a.in_guard_band() && b.in_guard_band()) {
        return [Triangle::EMPTY; 2];
    }
    let (dx, dy) = (a.window[0] - b.window[0], a.window[1] - b.window[1]);
    let length_squared = dx * dx + dy * dy;
    if length_squared == 0.0 || !length_squared.is_finite() {
        return [Triangle::EMPTY; 2];
    }
    let scale = 0.5 / length_squared.sqrt();
    let t = [
        (-dy * scale * FIXED_ONE as f32).round_ties_even() as i64,
        (dx * scale * FIXED_ONE as f32).round_ties_even() as i64,
    ];
    let (fa, fb) = (a.fixed(), b.fixed());
    let corners = [
        a.moved([fa[0] - t[0], fa[1] - t[1]]),
        b.moved([fb[0] - t[0], fb[1] - t[1]]),
        b.moved([fb[0] + t[0], fb[1] + t[1]]),
        a.moved([fa[0] + t[0], fa[1] + t[1]]),
    ];
    quad(corners, params)
}

/// A point of size 1: the square one pixel wide centred on it.
pub(crate) fn point(v: Vertex, params: SetupParams) -> [Triangle; 2] {
    if !v.in_guard_band() {
        return [Triangle::EMPTY; 2];
    }
    let half = FIXED_ONE / 2;
    let [x, y] = v.fixed().map(|f| f - half);
    let corners = [
        v.moved([x, y]),
        v.moved([x + FIXED_ONE, y]),
        v.moved([x + FIXED_ONE, y + FIXED_ONE]),
        v.moved([x, y + FIXED_ONE]),
    ];
    quad(corners, params)
}

fn quad(c: [Corner; 4], params: SetupParams) -> [Triangle; 2] {
    [
        setup([c[0], c[1], c[2]], params.size, params.used),
        setup([c[0], c[2], c[3]], params.size, params.used),
    ]
}

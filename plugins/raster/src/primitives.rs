//! From the pipeline's primitives to triangles: a triangle as it is; a line as the rectangle one
//! pixel wide around it, and a point as the one-pixel square around it, both as two triangles
//! that share a diagonal (the fill rule then draws each pixel of the rectangle once). These are
//! the shapes the reference's rasterizer gives lines and points of width and size 1: Vulkan's
//! default rectangular lines, and points as squares.

use close2gl_core::Topology;

use crate::edge::FIXED_ONE;
use crate::lanes::map3;
use crate::setup::{Corner, Triangle, setup};
use crate::varyings::Used;
use crate::vertex::Vertex;

/// The primitives of `topology` whose vertices' `indices` are given, the first being primitive
/// number `first`, to their triangles, in order: each one that may cover a pixel centre is
/// handed to `emit` with its set-up index (a primitive's index times its triangles, plus which).
#[inline(always)]
pub(crate) fn set_up(
    topology: Topology,
    indices: &[u32],
    first: usize,
    vertices: &[Vertex],
    params: SetupParams,
    mut emit: impl FnMut(u32, &Triangle),
) {
    let vertex = |i: u32| &vertices[i as usize];
    let primitives = indices.chunks_exact(indices_per_primitive(topology));
    let per = triangles_per_primitive(topology);
    let mut emit_all = |primitive: usize, triangles: &[Triangle]| {
        for (k, t) in triangles.iter().enumerate() {
            if !t.is_empty() {
                emit(((first + primitive) * per + k) as u32, t);
            }
        }
    };
    match topology {
        Topology::Triangles => {
            for (i, p) in primitives.enumerate() {
                let t = triangle([vertex(p[0]), vertex(p[1]), vertex(p[2])], params);
                if !t.is_empty() {
                    emit((first + i) as u32, &t);
                }
            }
        }
        Topology::Lines => {
            for (i, p) in primitives.enumerate() {
                emit_all(i, &line(vertex(p[0]), vertex(p[1]), params));
            }
        }
        Topology::Points => {
            for (i, p) in primitives.enumerate() {
                emit_all(i, &point(vertex(p[0]), params));
            }
        }
    }
}

pub(crate) fn indices_per_primitive(topology: Topology) -> usize {
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
    /// Whether triangles that cover no pixel centre are dropped before their planes are built
    /// (drawing), or kept (the probe's questions).
    pub drop_uncovered: bool,
}

/// A triangle's setup. Inlined, with `setup`, into the loop that bins what it returns: returned
/// through memory, the binning's first read of it waited on setup's stores (a million small
/// triangles measured faster inlined:
/// docs/performance.md#snapping-each-vertex-once-setup-inlined-the-geometrys-join-in-parallel).
#[inline(always)]
pub(crate) fn triangle(v: [&Vertex; 3], params: SetupParams) -> Triangle {
    if !v.iter().all(|v| v.drawable()) {
        return Triangle::EMPTY;
    }
    let corners = map3(&v, |v| v.corner());
    setup(corners, params.size, params.used, params.drop_uncovered)
}

/// A line one pixel wide: the rectangle whose long sides lie half a pixel either side of it and
/// whose short sides pass through its ends.
pub(crate) fn line(a: &Vertex, b: &Vertex, params: SetupParams) -> [Triangle; 2] {
    if !(a.drawable() && b.drawable()) {
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
pub(crate) fn point(v: &Vertex, params: SetupParams) -> [Triangle; 2] {
    if !v.drawable() {
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

fn quad(c: [Corner<'_>; 4], params: SetupParams) -> [Triangle; 2] {
    [
        setup(
            [c[0], c[1], c[2]],
            params.size,
            params.used,
            params.drop_uncovered,
        ),
        setup(
            [c[0], c[2], c[3]],
            params.size,
            params.used,
            params.drop_uncovered,
        ),
    ]
}

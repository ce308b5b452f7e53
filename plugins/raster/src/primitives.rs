//! From the pipeline's primitives to triangles: a triangle as it is; a line as the rectangle one
//! pixel wide around it, and a point as the one-pixel square around it, both as two triangles
//! that share a diagonal (the fill rule then draws each pixel of the rectangle once). These are
//! the shapes the reference's rasterizer gives lines and points of width and size 1: Vulkan's
//! default rectangular lines, and points as squares.

use crate::setup::{Corner, FIXED_ONE, GUARD_PX, Triangle, Used, VARYINGS, setup, snap};

/// A vertex as the pipeline and the vertex stage left it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Vertex {
    /// x, y in window pixels, depth, 1/w.
    pub window: [f32; 4],
    pub varyings: [f32; VARYINGS],
}

impl Vertex {
    fn corner(&self, fixed: [i64; 2]) -> Corner {
        Corner {
            fixed,
            window: self.window,
            varyings: self.varyings,
        }
    }

    /// The same vertex moved to a fixed-point position (where a line's or a point's rectangle
    /// has its corners), keeping depth, 1/w and the varyings.
    fn moved(&self, fixed: [i64; 2]) -> Corner {
        let to_window = |f: i64| f as f32 / FIXED_ONE as f32 + 0.5;
        let mut window = self.window;
        window[0] = to_window(fixed[0]);
        window[1] = to_window(fixed[1]);
        Corner {
            fixed,
            window,
            varyings: self.varyings,
        }
    }

    fn fixed(&self) -> [i64; 2] {
        [snap(self.window[0]), snap(self.window[1])]
    }

    /// Whether the fixed-point arithmetic can hold this vertex (see [`GUARD_PX`]); false for
    /// NaN and infinities too. A primitive with a corner outside is not drawn.
    fn in_guard_band(&self) -> bool {
        self.window[..2].iter().all(|x| x.abs() <= GUARD_PX)
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
    let corners = v.map(|v| v.corner(v.fixed()));
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

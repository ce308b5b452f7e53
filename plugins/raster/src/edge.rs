//! The edge functions, in fixed point: window positions snapped to 1/256 pixel, an edge's
//! function with the top-left fill rule, and the three questions the rasterizer asks it: is
//! one pixel centre inside, which pixels of a row are, and is a rectangle all, partly or not
//! inside.
//!
//! The rules are those of the reference view's rasterizer (Mesa's llvmpipe, under lavapipe), so
//! that both views fill the same pixels: 8 sub-pixel bits, round to nearest; a pixel is sampled
//! at its centre; a sample exactly on an edge belongs to the triangle when the edge is a left
//! edge, or a horizontal top edge (y grows downwards), so that two triangles sharing an edge
//! never both draw a pixel and never leave one out.

use crate::target::TileRect;

/// Sub-pixel precision: positions are multiples of 1/256 pixel.
pub(crate) const SUBPIXEL_BITS: u32 = 8;
pub(crate) const FIXED_ONE: i64 = 1 << SUBPIXEL_BITS;

/// How far from the window's origin, in pixels, a vertex may lie and still be drawn: 128 times
/// the widest view. Clipping keeps real vertices inside the view (give or take rounding), but a
/// model with coordinates near f32's limits can come out of the clipper thousands of millions of
/// pixels away, where the edge functions' products of fixed-point differences would overflow
/// i64. 2^21 pixels are 2^29 in fixed point, so every product stays below 2^62.
pub(crate) const GUARD_PX: f32 = (1 << 21) as f32;

/// A position in window pixels as fixed point, moved by half a pixel so that pixel (x, y) is
/// sampled at the integer point (x, y) · [`FIXED_ONE`].
#[inline(always)]
pub(crate) fn snap(window: f32) -> i64 {
    round_ties_even((window - 0.5) * FIXED_ONE as f32) as i64
}

/// `f32::round_ties_even`, inlined: without SSE4.1 in the baseline target it is a call into
/// libm, the largest single cost of setting up a small triangle. Adding 2²³ to a magnitude
/// below it leaves no fraction bits, so the FPU rounds it to nearest even, and taking 2²³ away
/// again is exact; from 2²³ up every f32 is already whole (and NaN stays NaN).
#[inline(always)]
fn round_ties_even(x: f32) -> f32 {
    const TWO_23: f32 = (1 << 23) as f32;
    if x.abs() < TWO_23 {
        ((x.abs() + TWO_23) - TWO_23).copysign(x)
    } else {
        x
    }
}

/// One edge as llvmpipe writes it: the sample (X, Y) (in fixed point) is inside when
/// `c + dcdy·Y − dcdx·X > 0`; `c` already holds the fill rule's +1 for left and top edges. The
/// steps are differences of positions inside the guard band (under 2³⁰), so they fit an i32,
/// which keeps three edges and the bounds in one cache line; all arithmetic is in i64.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Edge {
    pub dcdx: i32,
    pub dcdy: i32,
    pub c: i64,
}

/// How much of a rectangle of pixels lies inside an edge.
pub(crate) enum Cover {
    None,
    Some,
    All,
}

impl Edge {
    pub(crate) const ZERO: Edge = Edge {
        dcdx: 0,
        dcdy: 0,
        c: 0,
    };

    /// The edge from `from` to `to` (fixed point), inside to its left as y grows downwards.
    pub(crate) fn new(from: [i64; 2], to: [i64; 2]) -> Edge {
        let dcdx = from[1] - to[1];
        let dcdy = from[0] - to[0];
        let mut edge = Edge {
            dcdx: dcdx as i32,
            dcdy: dcdy as i32,
            c: dcdx * from[0] - dcdy * from[1],
        };
        edge.c += edge.fill_rule_bias();
        edge
    }

    /// The fill rule's share of `c`: 1 for a left or a horizontal top edge, else 0.
    pub(crate) fn fill_rule_bias(&self) -> i64 {
        (self.dcdx < 0 || (self.dcdx == 0 && self.dcdy > 0)) as i64
    }

    /// The edge function at the centre of pixel (x, y): the sample is inside when it is > 0.
    #[inline(always)]
    pub(crate) fn at(&self, x: i32, y: i32) -> i64 {
        self.c + self.dcdy as i64 * (y as i64 * FIXED_ONE)
            - self.dcdx as i64 * (x as i64 * FIXED_ONE)
    }

    /// The pixels of row `y` inside this edge, as an inclusive range (empty when lo > hi).
    /// Exact: the same integer inequality a per-pixel test would evaluate, solved for x.
    #[inline(always)]
    pub(crate) fn span(&self, y: i32) -> (i32, i32) {
        let k = self.c + self.dcdy as i64 * (y as i64 * FIXED_ONE);
        let d = self.dcdx as i64 * FIXED_ONE;
        // Inside: d·x < k.
        match d.signum() {
            1 => (i32::MIN, clamp_i32((k - 1).div_euclid(d))),
            -1 => (clamp_i32((-k).div_euclid(-d) + 1), i32::MAX),
            _ if k > 0 => (i32::MIN, i32::MAX),
            _ => (i32::MAX, i32::MIN),
        }
    }

    /// Whether the pixels of `area` are all, some or none inside this edge: the edge function
    /// is linear, so its extremes over the rectangle are at corners.
    pub(crate) fn over(&self, area: TileRect) -> Cover {
        let (x0, x1) = (area.x0 as i64 * FIXED_ONE, area.x1 as i64 * FIXED_ONE);
        let (y0, y1) = (area.y0 as i64 * FIXED_ONE, area.y1 as i64 * FIXED_ONE);
        let (dcdx, dcdy) = (self.dcdx as i64, self.dcdy as i64);
        let dy = (dcdy * y0).min(dcdy * y1)..=(dcdy * y0).max(dcdy * y1);
        let dx = (dcdx * x0).min(dcdx * x1)..=(dcdx * x0).max(dcdx * x1);
        // F = c + dcdy·Y − dcdx·X; inside when F > 0.
        if self.c + dy.start() - dx.end() > 0 {
            Cover::All
        } else if self.c + dy.end() - dx.start() <= 0 {
            Cover::None
        } else {
            Cover::Some
        }
    }
}

/// The pixels of row `y` between `lo` and `hi` inside every one of `edges`, as an inclusive
/// range (empty when lo > hi): each edge's span, intersected.
#[inline(always)]
pub(crate) fn row_inside(edges: &[Edge], y: i32, (mut lo, mut hi): (i32, i32)) -> (i32, i32) {
    for edge in edges {
        let (a, b) = edge.span(y);
        lo = lo.max(a);
        hi = hi.min(b);
    }
    (lo, hi)
}

/// The same range as [`row_inside`] for a narrow row (`lo..=hi` a few pixels), found by
/// testing each pixel's centre, one step of each edge function per pixel: cheaper than the
/// division that solving each edge for its span costs, when the span is this short.
#[inline(always)]
pub(crate) fn row_inside_narrow(edges: &[Edge], y: i32, (lo, hi): (i32, i32)) -> (i32, i32) {
    // Missing edges (those that leave the whole area in) stay inside at every pixel.
    let mut f = [1i64; 3];
    let mut step = [0i64; 3];
    for (k, edge) in edges.iter().enumerate().take(3) {
        f[k] = edge.at(lo, y);
        step[k] = edge.dcdx as i64 * FIXED_ONE;
    }
    let (mut first, mut last) = (i32::MAX, i32::MIN);
    for x in lo..=hi {
        // `&`, not `&&`: three compares, no branches.
        let inside = (f[0] > 0) & (f[1] > 0) & (f[2] > 0);
        if inside {
            first = first.min(x);
            last = x;
        }
        for k in 0..3 {
            f[k] -= step[k];
        }
    }
    (first, last)
}

fn clamp_i32(x: i64) -> i32 {
    x.clamp(i32::MIN as i64, i32::MAX as i64) as i32
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_inlined_rounding_is_the_librarys() {
        let special = [
            0.5, 1.5, 2.5, -0.5, -2.5, 4194304.5, -8388607.5, 8388608.0, 1e30, -0.0,
        ];
        let steps = (0..200_000).map(|i| (i as f32 - 100_000.0) * 0.125 + 0.0625 * (i % 3) as f32);
        for x in special.into_iter().chain(steps) {
            assert_eq!(
                round_ties_even(x).to_bits(),
                x.round_ties_even().to_bits(),
                "{x}"
            );
        }
        assert!(round_ties_even(f32::NAN).is_nan());
    }

    #[test]
    fn a_narrow_rows_pixels_are_the_solved_spans() {
        let corners = [[3, 5], [900, 260], [140, 1700]].map(|p| p.map(|v: i64| v * 3 + 7));
        let edges = [
            Edge::new(corners[0], corners[1]),
            Edge::new(corners[1], corners[2]),
            Edge::new(corners[2], corners[0]),
        ];
        for count in 0..=3 {
            for y in -1..9 {
                for lo in -2..14 {
                    for width in 0..8 {
                        let range = (lo, lo + width);
                        let solved = row_inside(&edges[..count], y, range);
                        let tested = row_inside_narrow(&edges[..count], y, range);
                        let normal = |(a, b): (i32, i32)| if a > b { None } else { Some((a, b)) };
                        assert_eq!(normal(solved), normal(tested), "{count} {y} {range:?}");
                    }
                }
            }
        }
    }
}

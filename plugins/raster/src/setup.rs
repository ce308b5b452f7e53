//! Triangle setup: snap the corners to fixed point, build the three edge functions with the
//! top-left fill rule, and the planes along which depth, 1/w and the varyings vary on screen.
//!
//! The rules are those of the reference view's rasterizer (Mesa's llvmpipe, under lavapipe), so
//! that both views fill the same pixels: 8 sub-pixel bits, round to nearest; a pixel is sampled
//! at its centre; a sample exactly on an edge belongs to the triangle when the edge is a left
//! edge, or a horizontal top edge (y grows downwards), so that two triangles sharing an edge
//! never both draw a pixel and never leave one out.

/// Sub-pixel precision: positions are multiples of 1/256 pixel.
pub(crate) const SUBPIXEL_BITS: u32 = 8;
pub(crate) const FIXED_ONE: i64 = 1 << SUBPIXEL_BITS;

/// How far from the window's origin, in pixels, a vertex may lie and still be drawn: 128 times
/// the widest view. Clipping keeps real vertices inside the view (give or take rounding), but a
/// model with coordinates near f32's limits can come out of the clipper thousands of millions of
/// pixels away, where the edge functions' products of fixed-point differences would overflow
/// i64. 2^21 pixels are 2^29 in fixed point, so every product stays below 2^62.
pub(crate) const GUARD_PX: f32 = (1 << 21) as f32;

/// How many floats a vertex carries for shading: eye position and normal (Phong), or the
/// Gouraud intensity in the first three; then the texture coordinates.
pub(crate) const VARYINGS: usize = 8;

/// A position in window pixels as fixed point, moved by half a pixel so that pixel (x, y) is
/// sampled at the integer point (x, y) · [`FIXED_ONE`].
pub(crate) fn snap(window: f32) -> i64 {
    ((window - 0.5) * FIXED_ONE as f32).round_ties_even() as i64
}

/// One edge as llvmpipe writes it: the sample (X, Y) (in fixed point) is inside when
/// `c + dcdy·Y − dcdx·X > 0`; `c` already holds the fill rule's +1 for left and top edges.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Edge {
    pub dcdx: i64,
    pub dcdy: i64,
    pub c: i64,
}

impl Edge {
    fn new(from: [i64; 2], to: [i64; 2]) -> Edge {
        let dcdx = from[1] - to[1];
        let dcdy = from[0] - to[0];
        let mut c = dcdx * from[0] - dcdy * from[1];
        if dcdx < 0 || (dcdx == 0 && dcdy > 0) {
            c += 1;
        }
        Edge { dcdx, dcdy, c }
    }

    /// The pixels of row `y` inside this edge, as an inclusive range (empty when lo > hi).
    /// Exact: the same integer inequality a per-pixel test would evaluate, solved for x.
    #[inline(always)]
    pub(crate) fn span(&self, y: i32) -> (i32, i32) {
        let k = self.c + self.dcdy * (y as i64 * FIXED_ONE);
        let d = self.dcdx * FIXED_ONE;
        // Inside: d·x < k.
        match d.signum() {
            1 => (i32::MIN, clamp_i32((k - 1).div_euclid(d))),
            -1 => (clamp_i32((-k).div_euclid(-d) + 1), i32::MAX),
            _ if k > 0 => (i32::MIN, i32::MAX),
            _ => (i32::MAX, i32::MIN),
        }
    }
}

impl Edge {
    /// The edge function at the centre of pixel (x, y): the sample is inside when it is > 0.
    pub(crate) fn at(&self, x: i32, y: i32) -> i64 {
        self.c + self.dcdy * (y as i64 * FIXED_ONE) - self.dcdx * (x as i64 * FIXED_ONE)
    }

    /// The fill rule's share of `c`: 1 for a left or a horizontal top edge, else 0.
    fn fill_rule_bias(&self) -> i64 {
        (self.dcdx < 0 || (self.dcdx == 0 && self.dcdy > 0)) as i64
    }
}

/// How a triangle's coverage meets one pixel centre.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Coverage {
    Inside,
    /// Exactly on an edge that the top-left rule gives to the neighbour across it.
    LostToFillRule,
    Outside,
}

fn clamp_i32(x: i64) -> i32 {
    x.clamp(i32::MIN as i64, i32::MAX as i64) as i32
}

/// a + dadx·(x − ox) + dady·(y − oy), where (ox, oy) is the triangle's origin.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Plane {
    pub a: f32,
    pub dadx: f32,
    pub dady: f32,
}

/// A triangle ready to rasterize.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Triangle {
    pub edges: [Edge; 3],
    /// Inclusive pixel bounds [x0, y0, x1, y1], within the viewport; empty when x0 > x1.
    pub bbox: [i32; 4],
    /// Where the planes are anchored (a corner, in window pixels).
    pub origin: [f32; 2],
    pub depth: Plane,
    pub inv_w: Plane,
    /// Each varying times 1/w: these, not the varyings, are affine on screen.
    pub varyings: [Plane; VARYINGS],
}

impl Triangle {
    pub(crate) const EMPTY: Triangle = Triangle {
        edges: [Edge {
            dcdx: 0,
            dcdy: 0,
            c: 0,
        }; 3],
        bbox: [0, 0, -1, -1],
        origin: [0.0; 2],
        depth: Plane {
            a: 0.0,
            dadx: 0.0,
            dady: 0.0,
        },
        inv_w: Plane {
            a: 0.0,
            dadx: 0.0,
            dady: 0.0,
        },
        varyings: [Plane {
            a: 0.0,
            dadx: 0.0,
            dady: 0.0,
        }; VARYINGS],
    };

    pub(crate) fn is_empty(&self) -> bool {
        self.bbox[0] > self.bbox[2] || self.bbox[1] > self.bbox[3]
    }

    /// Whether the centre of pixel (x, y) is covered, by the same integer edge functions the
    /// tiles solve for their runs.
    pub(crate) fn coverage(&self, x: i32, y: i32) -> Coverage {
        let [x0, y0, x1, y1] = self.bbox;
        if self.is_empty() || x < x0 || x > x1 || y < y0 || y > y1 {
            return Coverage::Outside;
        }
        let f = self.edges.map(|e| e.at(x, y));
        if f.iter().all(|&f| f > 0) {
            Coverage::Inside
        } else if (0..3).all(|i| f[i] - self.edges[i].fill_rule_bias() >= 0) {
            Coverage::LostToFillRule
        } else {
            Coverage::Outside
        }
    }

    /// Whether its coverage reaches any pixel centre of the viewport: a row at a time, as the
    /// tiles find their runs, stopping at the first row with one.
    pub(crate) fn covers_any_centre(&self) -> bool {
        let [x0, y0, x1, y1] = self.bbox;
        (y0..=y1).any(|y| {
            let spans = self.edges.map(|e| e.span(y));
            let lo = spans.iter().map(|s| s.0).fold(x0, i32::max);
            let hi = spans.iter().map(|s| s.1).fold(x1, i32::min);
            lo <= hi
        })
    }

    /// A plane's value at the centre of pixel (x, y).
    #[inline(always)]
    pub(crate) fn at(&self, plane: &Plane, x: f32, y: f32) -> f32 {
        plane.a + plane.dadx * (x - self.origin[0]) + plane.dady * (y - self.origin[1])
    }
}

/// A corner as setup sees it: fixed-point position for coverage, window x, y, depth and 1/w,
/// and the varyings.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Corner {
    pub fixed: [i64; 2],
    pub window: [f32; 4],
    pub varyings: [f32; VARYINGS],
}

/// Which varyings get planes: the first `shading` ones, and the texture coordinates (at
/// `shading::UV`) when `textured`.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Used {
    pub shading: usize,
    pub textured: bool,
}

impl Used {
    fn indices(self) -> impl Iterator<Item = usize> {
        let uv = crate::shading::UV;
        (0..self.shading).chain((uv..uv + 2).filter(move |_| self.textured))
    }
}

/// Sets up the triangle `corners` in a viewport of `size` pixels, with planes for the varyings
/// `used` (and 1/w when there are any).
pub(crate) fn setup(mut corners: [Corner; 3], size: [i32; 2], used: Used) -> Triangle {
    let [a, b, c] = corners.map(|c| c.fixed);
    let det = (a[0] - b[0]) * (c[1] - a[1]) - (a[1] - b[1]) * (c[0] - a[0]);
    if det == 0
        || corners
            .iter()
            .any(|c| !c.window.iter().all(|x| x.is_finite()))
    {
        return Triangle::EMPTY;
    }
    if det < 0 {
        corners.swap(1, 2);
    }
    let fixed = corners.map(|c| c.fixed);
    let edges = [0, 1, 2].map(|i| Edge::new(fixed[i], fixed[(i + 1) % 3]));
    let ceil_px = |v: i64| (v + FIXED_ONE - 1).div_euclid(FIXED_ONE);
    let floor_px = |v: i64| v.div_euclid(FIXED_ONE);
    let bounds = |axis: usize| {
        let lo = fixed.iter().map(|p| p[axis]).min().unwrap_or(0);
        let hi = fixed.iter().map(|p| p[axis]).max().unwrap_or(-1);
        let (lo, hi) = (ceil_px(lo).max(0), floor_px(hi).min(size[axis] as i64 - 1));
        (lo as i32, hi as i32)
    };
    let ((x0, x1), (y0, y1)) = (bounds(0), bounds(1));

    let [p0, p1, p2] = corners.map(|c| c.window);
    let (ex, ey) = (p1[0] - p0[0], p1[1] - p0[1]);
    let (fx, fy) = (p2[0] - p0[0], p2[1] - p0[1]);
    let area = ex * fy - fx * ey;
    let plane = |v: [f32; 3]| {
        let (dv1, dv2) = (v[1] - v[0], v[2] - v[0]);
        Plane {
            a: v[0],
            dadx: (dv1 * fy - dv2 * ey) / area,
            dady: (dv2 * ex - dv1 * fx) / area,
        }
    };
    let mut triangle = Triangle {
        edges,
        bbox: [x0, y0, x1, y1],
        origin: [p0[0], p0[1]],
        depth: plane([p0[2], p1[2], p2[2]]),
        ..Triangle::EMPTY
    };
    if used.shading > 0 || used.textured {
        let inv_w = corners.map(|c| c.window[3]);
        triangle.inv_w = plane(inv_w);
        for k in used.indices() {
            let v = [0, 1, 2].map(|i| corners[i].varyings[k] * inv_w[i]);
            triangle.varyings[k] = plane(v);
        }
    }
    triangle
}

#[cfg(test)]
mod tests {
    use super::*;

    fn corner(x: f32, y: f32) -> Corner {
        Corner {
            fixed: [snap(x), snap(y)],
            window: [x, y, 0.5, 1.0],
            varyings: [0.0; VARYINGS],
        }
    }

    fn covered(t: &Triangle) -> Vec<(i32, i32)> {
        let mut pixels = Vec::new();
        for y in t.bbox[1]..=t.bbox[3] {
            let spans = t.edges.map(|e| e.span(y));
            let lo = spans.iter().map(|s| s.0).max().unwrap().max(t.bbox[0]);
            let hi = spans.iter().map(|s| s.1).min().unwrap().min(t.bbox[2]);
            pixels.extend((lo..=hi).map(|x| (x, y)));
        }
        pixels
    }

    #[test]
    fn an_axis_aligned_square_covers_the_pixels_whose_centres_it_holds() {
        // Corners on pixel boundaries: the left and top edges pass exactly through no centre,
        // so the square [2, 6] x [1, 3] covers columns 2..=5 and rows 1..=2.
        let size = [16, 16];
        let a = setup(
            [corner(2.0, 1.0), corner(6.0, 1.0), corner(6.0, 3.0)],
            size,
            Used::default(),
        );
        let b = setup(
            [corner(2.0, 1.0), corner(6.0, 3.0), corner(2.0, 3.0)],
            size,
            Used::default(),
        );
        let mut pixels = covered(&a);
        pixels.extend(covered(&b));
        pixels.sort();
        let mut expected: Vec<_> = (1..=2).flat_map(|y| (2..=5).map(move |x| (x, y))).collect();
        expected.sort();
        assert_eq!(pixels, expected);
    }

    #[test]
    fn centres_on_an_edge_go_to_the_left_and_top_edges_only() {
        // A square whose edges pass through pixel centres (x = 2.5 and 5.5, y = 1.5 and 3.5).
        let size = [16, 16];
        let a = setup(
            [corner(2.5, 1.5), corner(5.5, 1.5), corner(5.5, 3.5)],
            size,
            Used::default(),
        );
        let b = setup(
            [corner(2.5, 1.5), corner(5.5, 3.5), corner(2.5, 3.5)],
            size,
            Used::default(),
        );
        let mut pixels = covered(&a);
        pixels.extend(covered(&b));
        pixels.sort();
        // Left column 2 and top row 1 are in; right column 5 and bottom row 3 are out; the
        // diagonal's centres are drawn once.
        let mut expected: Vec<_> = (1..=2).flat_map(|y| (2..=4).map(move |x| (x, y))).collect();
        expected.sort();
        assert_eq!(pixels, expected);
    }

    /// A jittered grid of points (the outer ones beyond the viewport), each cell cut into two
    /// triangles along a random diagonal, with random windings: every pixel of the viewport must
    /// be drawn exactly once. Vertices land on pixel centres and on edges through them often,
    /// the cases a missing or wrong fill rule gets wrong.
    #[test]
    fn triangles_sharing_edges_draw_every_pixel_exactly_once() {
        let size = [97, 61];
        let mut seed = 0x2545_f491_4f6c_dd1du64;
        let mut random = move || {
            seed ^= seed << 13;
            seed ^= seed >> 7;
            seed ^= seed << 17;
            (seed >> 11) as f32 / (1u64 << 53) as f32
        };
        let n = 9;
        let mut points = vec![[0.0f32; 2]; (n + 1) * (n + 1)];
        for j in 0..=n {
            for i in 0..=n {
                let step = [size[0] as f32 / n as f32, size[1] as f32 / n as f32];
                let mut p = [i as f32 * step[0], j as f32 * step[1]];
                let border = i == 0 || j == 0 || i == n || j == n;
                if border {
                    // Push the outer ring out so the whole viewport is inside the mesh.
                    p = [(p[0] - 48.5) * 1.2 + 48.5, (p[1] - 30.5) * 1.2 + 30.5];
                } else {
                    // Moved by at most a fifth of a cell, so every cell stays convex and no two
                    // triangles overlap; half the inner points on pixel centres or half-pixels.
                    let jitter =
                        [(random() - 0.5) * step[0], (random() - 0.5) * step[1]].map(|d| d * 0.4);
                    p = [p[0] + jitter[0], p[1] + jitter[1]];
                    if random() < 0.5 {
                        p = p.map(|x| (x * 2.0).round() / 2.0);
                    }
                }
                points[j * (n + 1) + i] = p;
            }
        }
        let mut count = vec![0u8; (size[0] * size[1]) as usize];
        for j in 0..n {
            for i in 0..n {
                let at = |i: usize, j: usize| points[j * (n + 1) + i];
                let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                let halves = if random() < 0.5 {
                    [[a, b, c], [a, c, d]]
                } else {
                    [[a, b, d], [b, c, d]]
                };
                for mut t in halves {
                    if random() < 0.5 {
                        t.swap(1, 2);
                    }
                    let triangle = setup(t.map(|p| corner(p[0], p[1])), size, Used::default());
                    for (x, y) in covered(&triangle) {
                        count[(y * size[0] + x) as usize] += 1;
                    }
                }
            }
        }
        let wrong: Vec<_> = count
            .iter()
            .enumerate()
            .filter(|(_, c)| **c != 1)
            .map(|(i, c)| (i as i32 % size[0], i as i32 / size[0], *c))
            .collect();
        assert!(wrong.is_empty(), "pixels drawn other than once: {wrong:?}");
    }

    #[test]
    fn a_single_centre_agrees_with_the_runs() {
        // Every pixel the runs cover is Inside, every other one is not; a centre exactly on the
        // shared diagonal is Inside one of the two halves and LostToFillRule in the other.
        let size = [16, 16];
        let halves = [
            [corner(2.5, 1.5), corner(9.5, 1.5), corner(9.5, 8.5)],
            [corner(2.5, 1.5), corner(9.5, 8.5), corner(2.5, 8.5)],
        ]
        .map(|c| setup(c, size, Used::default()));
        for t in &halves {
            assert!(t.covers_any_centre());
            let runs = covered(t);
            for (x, y) in (0..16).flat_map(|y| (0..16).map(move |x| (x, y))) {
                let inside = t.coverage(x, y) == Coverage::Inside;
                assert_eq!(inside, runs.contains(&(x, y)), "({x}, {y})");
            }
        }
        let on_diagonal = halves.map(|t| t.coverage(5, 4));
        assert!(on_diagonal.contains(&Coverage::Inside), "{on_diagonal:?}");
        assert!(
            on_diagonal.contains(&Coverage::LostToFillRule),
            "{on_diagonal:?}"
        );
        let tiny = setup(
            [corner(3.6, 3.6), corner(3.9, 3.6), corner(3.6, 3.9)],
            size,
            Used::default(),
        );
        assert!(!tiny.covers_any_centre(), "between centres");
    }

    #[test]
    fn winding_does_not_matter_and_zero_area_draws_nothing() {
        let size = [16, 16];
        let cw = setup(
            [corner(1.0, 1.0), corner(9.0, 2.0), corner(3.0, 8.0)],
            size,
            Used::default(),
        );
        let ccw = setup(
            [corner(1.0, 1.0), corner(3.0, 8.0), corner(9.0, 2.0)],
            size,
            Used::default(),
        );
        assert_eq!(covered(&cw), covered(&ccw));
        assert!(!covered(&cw).is_empty());
        let line = setup(
            [corner(1.0, 1.0), corner(5.0, 5.0), corner(9.0, 9.0)],
            size,
            Used::default(),
        );
        assert!(line.is_empty());
    }

    #[test]
    fn planes_reproduce_the_corners_values() {
        let mut c = [corner(1.0, 1.0), corner(9.0, 2.0), corner(3.0, 8.0)];
        c[0].window[2] = 0.1;
        c[1].window[2] = 0.5;
        c[2].window[2] = 0.9;
        let t = setup(c, [16, 16], Used::default());
        for corner in c {
            let z = t.at(&t.depth, corner.window[0], corner.window[1]);
            assert!((z - corner.window[2]).abs() < 1e-6, "{z}");
        }
    }
}

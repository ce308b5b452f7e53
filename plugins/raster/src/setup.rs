//! Triangle setup: three corners to a triangle ready for the tiles: its three edge functions
//! (`edge`), the pixel rectangle it may cover, and its planes (`varyings`); and, for the fates
//! and the probe, whether it covers one pixel centre or any.

use crate::edge::{Edge, FIXED_ONE, row_inside};
use crate::lanes::map3;
use crate::varyings::{Planes, Used, VARYINGS};

/// How a triangle's coverage meets one pixel centre.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Coverage {
    Inside,
    /// Exactly on an edge that the top-left rule gives to the neighbour across it.
    LostToFillRule,
    Outside,
}

/// A triangle ready to rasterize: where it draws, which centres when it is small, and its
/// planes.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Triangle {
    pub footprint: Footprint,
    pub centres: Centres,
    pub planes: Planes,
}

impl Triangle {
    pub(crate) const EMPTY: Triangle = Triangle {
        footprint: Footprint::EMPTY,
        centres: Centres::Rows,
        planes: Planes::ZERO,
    };

    pub(crate) fn is_empty(&self) -> bool {
        self.footprint.is_empty()
    }
}

/// Where a triangle may draw: its three edges and the pixels its bounding box holds. One cache
/// line: the tiles read it for every triangle binned there, shaded or not.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Footprint {
    pub edges: [Edge; 3],
    /// Inclusive pixel bounds [x0, y0, x1, y1], within the viewport; empty when x0 > x1.
    pub bbox: [i32; 4],
}

impl Footprint {
    pub(crate) const EMPTY: Footprint = Footprint {
        edges: [Edge::ZERO; 3],
        bbox: [0, 0, -1, -1],
    };

    pub(crate) fn is_empty(&self) -> bool {
        self.bbox[0] > self.bbox[2] || self.bbox[1] > self.bbox[3]
    }

    /// Whether the centre of pixel (x, y) is covered, by the same integer edge functions the
    /// tiles solve for their rows.
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

    /// The pixels of row `y` it covers, as an inclusive range (empty when lo > hi).
    pub(crate) fn row(&self, y: i32) -> (i32, i32) {
        row_inside(&self.edges, y, (self.bbox[0], self.bbox[2]))
    }

    /// Whether its coverage reaches any pixel centre of the viewport: a row at a time, as the
    /// tiles find their rows, stopping at the first row with one.
    pub(crate) fn covers_any_centre(&self) -> bool {
        let [_, y0, _, y1] = self.bbox;
        (y0..=y1).any(|y| {
            let (lo, hi) = self.row(y);
            lo <= hi
        })
    }
}

/// A corner as setup sees it: fixed-point position for coverage, window x, y, depth and 1/w
/// (all finite: it comes from a drawable vertex, see `Vertex::drawable`), and the varyings.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Corner<'a> {
    pub fixed: [i64; 2],
    pub window: [f32; 4],
    /// Borrowed from the vertex: setup copies nothing it may not need.
    pub varyings: &'a [f32; VARYINGS],
}

/// Sets up the triangle `corners` in a viewport of `size` pixels, with planes for the varyings
/// `used` (and 1/w when there are any). With `drop_uncovered`, a triangle that covers no pixel
/// centre comes back empty, found out before its planes are built: the drawing path's early
/// rejection, which most sub-pixel triangles of a big mesh meet (the probe keeps them, to say
/// which centre the fill rule gave away).
#[inline(always)]
pub(crate) fn setup(
    mut corners: [Corner<'_>; 3],
    size: [i32; 2],
    used: Used,
    drop_uncovered: bool,
) -> Triangle {
    let [a, b, c] = map3(&corners, |c| c.fixed);
    let det = (a[0] - b[0]) * (c[1] - a[1]) - (a[1] - b[1]) * (c[0] - a[0]);
    if det == 0 {
        return Triangle::EMPTY;
    }
    if det < 0 {
        corners.swap(1, 2);
    }
    let fixed = map3(&corners, |c| c.fixed);
    let footprint = Footprint {
        edges: [
            Edge::new(fixed[0], fixed[1]),
            Edge::new(fixed[1], fixed[2]),
            Edge::new(fixed[2], fixed[0]),
        ],
        bbox: bounds(fixed, size),
    };
    if footprint.is_empty() {
        return Triangle::EMPTY;
    }
    let centres = footprint.centres();
    if drop_uncovered && centres == Centres::Few(0) {
        return Triangle::EMPTY;
    }
    Triangle {
        footprint,
        centres,
        planes: Planes::new(
            map3(&corners, |c| c.window),
            map3(&corners, |c| c.varyings),
            used,
        ),
    }
}

/// Bounding boxes of at most this many pixels have their centres tested one by one.
const FEW_PIXELS: i32 = 4;

/// Which pixel centres a triangle covers, as far as setup finds out.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Centres {
    /// Its bounding box holds more than [`FEW_PIXELS`]: the rows find out.
    Rows,
    /// Its bounding box holds a few, each tested: bit 4·row + column for each covered one,
    /// counted from the box's corner (none: it covers no centre). Four bits a row, so that a
    /// bit's pixel takes no division to find.
    Few(u16),
}

impl Footprint {
    /// The centres of a small bounding box that the triangle covers, or `Rows` for a larger
    /// one (not empty).
    #[inline(always)]
    fn centres(&self) -> Centres {
        let [x0, y0, x1, y1] = self.bbox;
        if (x1 - x0 + 1) * (y1 - y0 + 1) > FEW_PIXELS {
            return Centres::Rows;
        }
        let mut mask = 0;
        for y in y0..=y1 {
            for x in x0..=x1 {
                let inside = self.edges.iter().all(|e| e.at(x, y) > 0);
                mask |= (inside as u16) << ((y - y0) * 4 + (x - x0));
            }
        }
        Centres::Few(mask)
    }

    /// The pixel of bit `k` of a small bounding box's centres (see [`Centres::Few`]).
    pub(crate) fn centre(&self, k: u32) -> (i32, i32) {
        let [x0, y0, ..] = self.bbox;
        (x0 + (k % 4) as i32, y0 + (k / 4) as i32)
    }
}

/// The pixels whose centres the corners' bounding box holds, within a viewport of `size`:
/// [x0, y0, x1, y1], inclusive.
fn bounds(fixed: [[i64; 2]; 3], size: [i32; 2]) -> [i32; 4] {
    let ceil_px = |v: i64| (v + FIXED_ONE - 1).div_euclid(FIXED_ONE);
    let floor_px = |v: i64| v.div_euclid(FIXED_ONE);
    let axis = |axis: usize| {
        let [a, b, c] = map3(&fixed, |p| p[axis]);
        let (lo, hi) = (a.min(b).min(c), a.max(b).max(c));
        let (lo, hi) = (ceil_px(lo).max(0), floor_px(hi).min(size[axis] as i64 - 1));
        (lo as i32, hi as i32)
    };
    let ((x0, x1), (y0, y1)) = (axis(0), axis(1));
    [x0, y0, x1, y1]
}

#[cfg(test)]
mod tests {
    use std::ops::RangeInclusive;

    use super::*;
    use crate::edge::snap;

    fn corner(x: f32, y: f32) -> Corner<'static> {
        Corner {
            fixed: [snap(x), snap(y)],
            window: [x, y, 0.5, 1.0],
            varyings: &[0.0; VARYINGS],
        }
    }

    fn covered(t: &Triangle) -> Vec<(i32, i32)> {
        let mut pixels = Vec::new();
        for y in t.footprint.bbox[1]..=t.footprint.bbox[3] {
            let (lo, hi) = t.footprint.row(y);
            pixels.extend((lo..=hi).map(|x| (x, y)));
        }
        pixels
    }

    /// The pixels covered by the square from corner (x0, y0) to (x1, y1), drawn as the two
    /// triangles either side of its diagonal, in order (a pixel drawn twice is there twice).
    fn square(x0: f32, y0: f32, x1: f32, y1: f32) -> Vec<(i32, i32)> {
        let halves = [
            [corner(x0, y0), corner(x1, y0), corner(x1, y1)],
            [corner(x0, y0), corner(x1, y1), corner(x0, y1)],
        ];
        let mut pixels: Vec<_> = halves
            .into_iter()
            .flat_map(|half| covered(&setup(half, [16, 16], Used::default(), false)))
            .collect();
        pixels.sort();
        pixels
    }

    /// Columns `xs` of rows `ys`, in order.
    fn block(xs: RangeInclusive<i32>, ys: RangeInclusive<i32>) -> Vec<(i32, i32)> {
        xs.flat_map(|x| ys.clone().map(move |y| (x, y))).collect()
    }

    #[test]
    fn an_axis_aligned_square_covers_the_pixels_whose_centres_it_holds() {
        // Corners on pixel boundaries: the left and top edges pass exactly through no centre,
        // so the square [2, 6] x [1, 3] covers columns 2..=5 and rows 1..=2.
        assert_eq!(square(2.0, 1.0, 6.0, 3.0), block(2..=5, 1..=2));
    }

    #[test]
    fn centres_on_an_edge_go_to_the_left_and_top_edges_only() {
        // A square whose edges pass through pixel centres (x = 2.5 and 5.5, y = 1.5 and 3.5).
        // Left column 2 and top row 1 are in; right column 5 and bottom row 3 are out; the
        // diagonal's centres are drawn once.
        assert_eq!(square(2.5, 1.5, 5.5, 3.5), block(2..=4, 1..=2));
    }

    /// A small xorshift generator: the same numbers on every run.
    struct Random(u64);

    impl Random {
        fn next(&mut self) -> f32 {
            self.0 ^= self.0 << 13;
            self.0 ^= self.0 >> 7;
            self.0 ^= self.0 << 17;
            (self.0 >> 11) as f32 / (1u64 << 53) as f32
        }
    }

    /// An (n + 1)² grid of points over a viewport of `size`, row after row: the outer ring
    /// pushed beyond the viewport, the inner points jittered.
    fn jittered_grid(size: [i32; 2], n: usize, random: &mut Random) -> Vec<[f32; 2]> {
        let step = [size[0] as f32 / n as f32, size[1] as f32 / n as f32];
        let mut points = vec![[0.0f32; 2]; (n + 1) * (n + 1)];
        for j in 0..=n {
            for i in 0..=n {
                let mut p = [i as f32 * step[0], j as f32 * step[1]];
                let border = i == 0 || j == 0 || i == n || j == n;
                if border {
                    // Push the outer ring out so the whole viewport is inside the mesh.
                    p = [(p[0] - 48.5) * 1.2 + 48.5, (p[1] - 30.5) * 1.2 + 30.5];
                } else {
                    // Moved by at most a fifth of a cell, so every cell stays convex and no two
                    // triangles overlap; half the inner points on pixel centres or half-pixels.
                    let jitter = [
                        (random.next() - 0.5) * step[0],
                        (random.next() - 0.5) * step[1],
                    ]
                    .map(|d| d * 0.4);
                    p = [p[0] + jitter[0], p[1] + jitter[1]];
                    if random.next() < 0.5 {
                        p = p.map(|x| (x * 2.0).round() / 2.0);
                    }
                }
                points[j * (n + 1) + i] = p;
            }
        }
        points
    }

    /// A jittered grid of points (the outer ones beyond the viewport), each cell cut into two
    /// triangles along a random diagonal, with random windings: every pixel of the viewport must
    /// be drawn exactly once. Vertices land on pixel centres and on edges through them often,
    /// the cases a missing or wrong fill rule gets wrong.
    #[test]
    fn triangles_sharing_edges_draw_every_pixel_exactly_once() {
        let size = [97, 61];
        let mut random = Random(0x2545_f491_4f6c_dd1d);
        let n = 9;
        let points = jittered_grid(size, n, &mut random);
        let mut count = vec![0u8; (size[0] * size[1]) as usize];
        for j in 0..n {
            for i in 0..n {
                let at = |i: usize, j: usize| points[j * (n + 1) + i];
                let (a, b, c, d) = (at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
                let halves = if random.next() < 0.5 {
                    [[a, b, c], [a, c, d]]
                } else {
                    [[a, b, d], [b, c, d]]
                };
                for mut t in halves {
                    if random.next() < 0.5 {
                        t.swap(1, 2);
                    }
                    let triangle =
                        setup(t.map(|p| corner(p[0], p[1])), size, Used::default(), false);
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
        .map(|c| setup(c, size, Used::default(), false));
        for t in &halves {
            assert!(t.footprint.covers_any_centre());
            let runs = covered(t);
            for (x, y) in (0..16).flat_map(|y| (0..16).map(move |x| (x, y))) {
                let inside = t.footprint.coverage(x, y) == Coverage::Inside;
                assert_eq!(inside, runs.contains(&(x, y)), "({x}, {y})");
            }
        }
        let on_diagonal = halves.map(|t| t.footprint.coverage(5, 4));
        assert!(on_diagonal.contains(&Coverage::Inside), "{on_diagonal:?}");
        assert!(
            on_diagonal.contains(&Coverage::LostToFillRule),
            "{on_diagonal:?}"
        );
        let tiny = setup(
            [corner(3.6, 3.6), corner(3.9, 3.6), corner(3.6, 3.9)],
            size,
            Used::default(),
            false,
        );
        assert!(!tiny.footprint.covers_any_centre(), "between centres");
    }

    #[test]
    fn only_triangles_that_cover_no_centre_are_dropped_before_their_planes() {
        let size = [16, 16];
        let mut random = Random(0x9e37_79b9_7f4a_7c15);
        let (mut dropped, mut kept) = (0, 0);
        for _ in 0..20_000 {
            // Sub-pixel to a few pixels wide, anywhere over the viewport's edge too.
            let (x, y) = (random.next() * 18.0 - 1.0, random.next() * 18.0 - 1.0);
            let reach = 0.2 + random.next() * 3.0;
            let mut point = || corner(x + random.next() * reach, y + random.next() * reach);
            let corners = [point(), point(), point()];
            let full = setup(corners, size, Used::default(), false);
            let early = setup(corners, size, Used::default(), true);
            if early.is_empty() {
                assert!(!full.footprint.covers_any_centre(), "{corners:?}");
                dropped += 1;
            } else {
                assert_eq!(early.footprint.bbox, full.footprint.bbox);
                assert_eq!(
                    early.planes.depth_at(8.5, 8.5),
                    full.planes.depth_at(8.5, 8.5)
                );
                kept += 1;
            }
        }
        // Both ways are met often: the test cannot pass by dropping nothing or everything.
        assert!(
            dropped > 2_000 && kept > 2_000,
            "{dropped} dropped, {kept} kept"
        );
    }

    #[test]
    fn winding_does_not_matter_and_zero_area_draws_nothing() {
        let size = [16, 16];
        let cw = setup(
            [corner(1.0, 1.0), corner(9.0, 2.0), corner(3.0, 8.0)],
            size,
            Used::default(),
            false,
        );
        let ccw = setup(
            [corner(1.0, 1.0), corner(3.0, 8.0), corner(9.0, 2.0)],
            size,
            Used::default(),
            false,
        );
        assert_eq!(covered(&cw), covered(&ccw));
        assert!(!covered(&cw).is_empty());
        let line = setup(
            [corner(1.0, 1.0), corner(5.0, 5.0), corner(9.0, 9.0)],
            size,
            Used::default(),
            false,
        );
        assert!(line.is_empty());
    }

    #[test]
    fn planes_reproduce_the_corners_values() {
        let mut c = [corner(1.0, 1.0), corner(9.0, 2.0), corner(3.0, 8.0)];
        c[0].window[2] = 0.1;
        c[1].window[2] = 0.5;
        c[2].window[2] = 0.9;
        let t = setup(c, [16, 16], Used::default(), false);
        for corner in c {
            let z = t.planes.depth_at(corner.window[0], corner.window[1]);
            assert!((z - corner.window[2]).abs() < 1e-6, "{z}");
        }
    }
}

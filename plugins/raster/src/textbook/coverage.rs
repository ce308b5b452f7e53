//! Coverage: which pixels a triangle covers. A pixel is covered when its centre is inside all
//! three edges, decided in integers on corners snapped to 1/256 pixel, with the tie rule settling
//! a centre exactly on an edge, so that of two triangles sharing the edge exactly one draws it.

use close2gl_core::{RasterMistake as M, RasterMistakes, TieRule};

use super::Rasterization;
use super::vertex::Vertex;

/// Sub-pixel steps per pixel: corners are snapped to 1/256 pixel.
pub(super) const STEPS: f32 = 256.0;

/// A window position snapped to 1/256 pixel, moved by half a pixel so that the centre of pixel
/// (x, y) is the integer point (256x, 256y): None when it is not finite or so far off screen
/// (beyond 2^21 pixels) that the edge functions' products would overflow i64. This decides
/// which pixel centres a triangle covers, so it is the fast rasterizer's snapping to the bit
/// (f32, rounded to nearest even): coverage on the snapped corners is then exact, in integers,
/// and the two rasterizers cover the same pixels.
pub(super) fn snap(window: [f32; 4]) -> Option<[i64; 2]> {
    snap_to(window, 8)
}

/// [`snap`] to a coarser grid, 1/2^`bits` pixel (`bits` at most 8, at least 2 so that the half
/// pixel moved is a whole even number of steps and the rounding's ties fall as the program's),
/// still counted in 1/256 pixel.
fn snap_to(window: [f32; 4], bits: u32) -> Option<[i64; 2]> {
    let far = window[..2].iter().any(|x| x.abs() > (1 << 21) as f32);
    let steps = (1u32 << bits) as f32;
    let snap = |x: f32| ((x - 0.5) * steps).round_ties_even() as i64 * (1 << (8 - bits));
    (!far && window.iter().all(|x| x.is_finite())).then(|| [snap(window[0]), snap(window[1])])
}

/// [`snap_to`] of x, y as a program gave them in f64 (`exact`, y down: a double program snaps its
/// own numbers, not their f32 roundings), the rest of `window` deciding, as there, whether it
/// can be snapped.
fn snap_exact(exact: [f64; 2], window: [f32; 4], bits: u32) -> Option<[i64; 2]> {
    snap_to(window, bits)?;
    let steps = f64::from(1u32 << bits);
    let snap = |x: f64| ((x - 0.5) * steps).round_ties_even() as i64 * (1 << (8 - bits));
    Some([snap(exact[0]), snap(exact[1])])
}

/// The window drawn into and the rules its pixels are decided by.
pub(super) struct Window {
    width: i64,
    height: i64,
    y_up: bool,
    tie: TieRule,
    mistakes: RasterMistakes,
    subpixel_bits: u32,
    /// The rows drawn (`Rasterization::scissor`), first and last.
    rows: [i64; 2],
}

impl Window {
    pub(super) fn new(width: u32, height: u32, how: &Rasterization) -> Window {
        Window {
            width: width as i64,
            height: height as i64,
            y_up: how.y_up,
            tie: how.rules.tie,
            mistakes: how.mistakes,
            subpixel_bits: how.subpixel_bits.clamp(2, 8),
            rows: match how.scissor {
                Some([first, end]) => [i64::from(first), i64::from(end) - 1],
                None => [0, i64::from(height) - 1],
            },
        }
    }

    /// A corner as the program placed it before setup: rounded or truncated to whole pixels by
    /// those mistakes (in its own y), and moved by half a pixel when it samples at the pixel's
    /// corner (sampling (i, j) is sampling the centre of a triangle moved by half a pixel
    /// towards +x and towards its own +y).
    fn placed(&self, mut v: Vertex) -> Vertex {
        let whole: Option<fn(f64) -> f64> = match () {
            _ if self.mistakes.has(M::VerticesRounded) => Some(f64::round),
            _ if self.mistakes.has(M::VerticesTruncated) => Some(f64::trunc),
            _ => None,
        };
        // In the program's own numbers (its y up or down), as it rounded them.
        let mut own = v
            .exact
            .unwrap_or_else(|| [v.window[0], self.own_y(v.window[1])].map(f64::from));
        if let Some(whole) = whole {
            own = own.map(whole);
        }
        if self.mistakes.has(M::PixelCornerSamples) {
            own = own.map(|x| x + 0.5);
        }
        v.window[0] = own[0] as f32;
        v.window[1] = self.down(own[1]) as f32;
        v.exact = v.exact.map(|_| own);
        v.snapped = None;
        v
    }

    /// A y of the picture (down) in the program's own numbers, and back: they are each other's.
    fn own_y(&self, y: f32) -> f32 {
        match self.y_up {
            true => self.height as f32 - y,
            false => y,
        }
    }

    fn down(&self, own_y: f64) -> f64 {
        match self.y_up {
            true => self.height as f64 - own_y,
            false => own_y,
        }
    }

    /// Whether a centre exactly on the edge a → b (of a triangle wound with its inside to the
    /// left of every edge, y down) is inside.
    fn owns_tie(&self, a: [i64; 2], b: [i64; 2]) -> bool {
        if self.mistakes.has(M::FillRuleInclusive) {
            return true;
        }
        if self.mistakes.has(M::FillRuleExclusive) {
            return false;
        }
        // A left edge goes down, a right edge up; a top edge goes left, a bottom edge right.
        let (left, right) = (a[1] < b[1], a[1] > b[1]);
        let (top, bottom) = (a[1] == b[1] && a[0] > b[0], a[1] == b[1] && a[0] < b[0]);
        match self.tie {
            TieRule::TopLeft => left || top,
            TieRule::TopRight => right || top,
            TieRule::BottomLeft => left || bottom,
            TieRule::BottomRight => right || bottom,
        }
    }
}

/// A triangle ready to traverse: its corners wound with the inside to the left of every edge
/// (y down), as placed and as snapped.
pub(super) struct Setup {
    pub(super) corners: [Vertex; 3],
    snapped: [[i64; 2]; 3],
    /// Whether corners 1 and 2 were exchanged to wind it so: the corners' order as given is
    /// 0, 2, 1 (a mistake that follows that order needs it).
    pub(super) swapped: bool,
}

impl Setup {
    /// None for a triangle with no area or a corner that cannot be snapped.
    pub(super) fn new(triangle: &[Vertex; 3], window: &Window) -> Option<Setup> {
        let moves = window.mistakes.has(M::VerticesRounded)
            || window.mistakes.has(M::VerticesTruncated)
            || window.mistakes.has(M::PixelCornerSamples);
        let mut corners = triangle.map(|v| if moves { window.placed(v) } else { v });
        let bits = window.subpixel_bits;
        let at = |v: &Vertex| match (v.snapped, v.exact) {
            (Some(snapped), _) => Some(snapped),
            (None, Some([x, y])) => snap_exact([x, window.down(y)], v.window, bits),
            (None, None) => snap_to(v.window, bits),
        };
        let mut snapped = [at(&corners[0])?, at(&corners[1])?, at(&corners[2])?];
        let area = edge(snapped[0], snapped[1], snapped[2]);
        if area == 0 {
            return None;
        }
        if area < 0 {
            corners.swap(1, 2);
            snapped.swap(1, 2);
        }
        Some(Setup {
            corners,
            snapped,
            swapped: area < 0,
        })
    }

    /// The pixels it covers, row by row from the top: every pixel of its bounding box (within
    /// the window) whose centre it covers.
    pub(super) fn pixels<'a>(
        &'a self,
        window: &'a Window,
    ) -> impl Iterator<Item = (i32, i32)> + 'a {
        let p = &self.snapped;
        let low = |axis: usize| (p.iter().map(|p| p[axis]).min().unwrap_or(0) / 256 - 1).max(0);
        let high = |axis: usize, size: i64| {
            (p.iter().map(|p| p[axis]).max().unwrap_or(0) / 256 + 1).min(size - 1)
        };
        let (rows, columns) = (
            low(1).max(window.rows[0])..=high(1, window.height).min(window.rows[1]),
            low(0)..=high(0, window.width),
        );
        rows.flat_map(move |y| columns.clone().map(move |x| (x, y)))
            .filter(|&(x, y)| self.in_box(x, y, window) && self.covers([x * 256, y * 256], window))
            .map(|(x, y)| (x as i32, y as i32))
    }

    /// Whether the centre `centre` (in 1/256 pixel, centres on the integer points) is inside
    /// every edge, or exactly on one the tie rule gives it.
    fn covers(&self, centre: [i64; 2], window: &Window) -> bool {
        let p = &self.snapped;
        (0..3).all(|i| {
            let (a, b) = (p[i], p[(i + 1) % 3]);
            let f = edge(a, b, centre);
            f > 0 || (f == 0 && window.owns_tie(a, b))
        })
    }

    /// Whether pixel (x, y) is one the program's loops reach: all of them, but for the mistakes
    /// that lose the box's or the window's last column and row (as the program counts rows).
    fn in_box(&self, x: i64, y: i64, window: &Window) -> bool {
        let row = if window.y_up {
            window.height - 1 - y
        } else {
            y
        };
        let mistakes = window.mistakes;
        if mistakes.has(M::ViewportEdgeSkipped)
            && (x == window.width - 1 || row == window.height - 1)
        {
            return false;
        }
        if !mistakes.has(M::BoundingBoxShort) {
            return true;
        }
        // The corners as the program gave them, in its own numbers.
        let own = self.corners.map(|v| {
            v.exact
                .unwrap_or_else(|| [v.window[0], window.own_y(v.window[1])].map(f64::from))
        });
        let span = |k: usize| {
            let values = own.map(|xy| xy[k]);
            let floor =
                |f: fn(f64, f64) -> f64| values.into_iter().fold(values[0], f).floor() as i64;
            floor(f64::min)..floor(f64::max)
        };
        span(0).contains(&x) && span(1).contains(&row)
    }

    /// The barycentric weights of the centre of pixel (x, y) (outside the triangle too), from the
    /// corners where they are placed, unsnapped, as the fast one's planes take them; in f64, so
    /// that the differences from it are its rounding, not ours.
    pub(super) fn weights(&self, x: i32, y: i32) -> [f64; 3] {
        let [a, b, c] = self
            .corners
            .map(|v| [v.window[0] as f64, v.window[1] as f64]);
        let p = [x as f64 + 0.5, y as f64 + 0.5];
        let area = edge(a, b, c);
        [
            edge(b, c, p) / area,
            edge(c, a, p) / area,
            edge(a, b, p) / area,
        ]
    }
}

/// Twice the signed area of triangle (a, b, p): positive when p lies to the left of a → b as y
/// grows downwards. At a pixel centre p it is the edge function of a → b; divided by the
/// triangle's own, it is p's barycentric weight of the corner opposite the edge.
pub(super) fn edge<T: Copy + std::ops::Sub<Output = T> + std::ops::Mul<Output = T>>(
    a: [T; 2],
    b: [T; 2],
    p: [T; 2],
) -> T {
    (b[1] - a[1]) * (p[0] - a[0]) - (b[0] - a[0]) * (p[1] - a[1])
}

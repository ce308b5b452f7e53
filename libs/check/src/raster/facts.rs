//! The facts of a raster trace, held against a drawing of its triangles: which pixels it covers,
//! what its depth buffer holds, what colour each pixel is. Each is compared only where the
//! arithmetic decides it: a pixel centre closer to an edge than the program's and close2gl's
//! snapping can tell apart is neither covered nor uncovered, a colour within two steps of the
//! background neither drawn nor not, and depth and colour may differ by their rounding.

use std::ops::Range;

use close2gl_core::{Image, TextureFilter};
use close2gl_raster::textbook::Buffers;

use close2gl_trace_format::RasterFrame;

/// How many steps of 1/255 a channel may differ by: the program's last rounding and ours.
pub const COLOUR_STEPS: u8 = 2;
/// How far a depth may differ: the program's float barycentrics and ours.
pub const DEPTH_TOLERANCE: f32 = 2e-5;

/// One kind of fact, counted: how many pixels were compared, how many differ, and the first
/// that does (column, row from the top).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Tally {
    pub compared: usize,
    pub differing: usize,
    pub first: Option<(u32, u32)>,
}

impl Tally {
    fn count(&mut self, differs: bool, at: usize, width: u32) {
        self.compared += 1;
        if differs {
            self.differing += 1;
            let at = at as u32;
            self.first.get_or_insert((at % width, at / width));
        }
    }
}

/// The three kinds of fact.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Facts {
    pub coverage: Tally,
    /// Not compared (all zero) when the trace gives no depth buffer.
    pub depth: Tally,
    pub colour: Tally,
    /// The pixels both drew whose colours are not exactly alike: what tells a legal 8-bit
    /// conversion from another, within the tolerance.
    pub inexact: usize,
}

/// What may differ: the share of compared colours that must agree (a depth test's near tie takes
/// another triangle's colour; a nearest texel on a texel's edge takes the one across it). Depth
/// must agree everywhere: where two surfaces tie, their depths are within the tolerance.
#[derive(Clone, Copy, Debug)]
pub struct Allowance {
    pub share: f64,
}

impl Allowance {
    pub fn for_texture(filter: Option<TextureFilter>) -> Allowance {
        let share = match filter {
            None => 0.999,
            Some(TextureFilter::Nearest | TextureFilter::Bilinear) => 0.99,
            Some(TextureFilter::Trilinear) => 0.98,
        };
        Allowance { share }
    }

    pub(super) fn allows(&self, tally: &Tally) -> bool {
        tally.differing as f64 <= (1.0 - self.share) * tally.compared as f64
    }
}

impl Facts {
    /// Whether the drawing reproduces every fact: coverage exactly, depth and colour within
    /// `allowance`.
    pub fn agree(&self, allowance: Allowance) -> bool {
        self.coverage.differing == 0 && self.depth.differing == 0 && allowance.allows(&self.colour)
    }

    /// Whether the drawing reproduces every fact as an exact drawing would: coverage and depth
    /// everywhere, colours on all but 0.1 % of the pixels (the depth test's near ties).
    pub fn exact(&self) -> bool {
        self.agree(Allowance { share: 0.999 })
    }

    /// Every differing pixel: how far a drawing is from reproducing the trace.
    pub fn distance(&self) -> usize {
        self.coverage.differing + self.depth.differing + self.colour.differing
    }
}

/// The pixels whose centres lie within `tolerance` pixels of an edge of the trace's triangles:
/// their coverage is the snapping's choice, not a fact. Empty when the program says it snaps as
/// close2gl does (1/256 pixel or coarser: close2gl snaps to the same grid).
pub fn ties(input: &RasterFrame) -> Vec<bool> {
    let (width, height) = input.trace.window;
    let mut ties = vec![false; (width * height) as usize];
    if input.trace.subpixel.is_some_and(|bits| bits <= 8) {
        return ties;
    }
    let tolerance = 1.0 / 256.0 + 1e-6 * f64::from(width.max(height));
    let y = |y: f64| {
        if input.trace.y_up {
            f64::from(height) - y
        } else {
            y
        }
    };
    for triangle in &input.trace.triangles {
        let p = triangle.corners.map(|c| [c.window[0], y(c.window[1])]);
        for i in 0..3 {
            mark_near(&mut ties, (width, height), p[i], p[(i + 1) % 3], tolerance);
        }
    }
    ties
}

/// Marks the pixels whose centres lie within `tolerance` of the segment a → b.
fn mark_near(
    ties: &mut [bool],
    (width, height): (u32, u32),
    a: [f64; 2],
    b: [f64; 2],
    tolerance: f64,
) {
    let low = |k: usize| (a[k].min(b[k]) - 1.0).floor().max(0.0);
    let high = |k: usize, size: u32| (a[k].max(b[k]) + 1.0).ceil().min(f64::from(size) - 1.0);
    let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
    let length_squared = dx * dx + dy * dy;
    if length_squared.is_nan() || length_squared <= 0.0 || high(0, width) - low(0) > 1e6 {
        return;
    }
    for row in low(1) as u32..=high(1, height).max(0.0) as u32 {
        for column in low(0) as u32..=high(0, width).max(0.0) as u32 {
            let p = [f64::from(column) + 0.5, f64::from(row) + 0.5];
            let t = (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / length_squared).clamp(0.0, 1.0);
            let (ex, ey) = (a[0] + t * dx - p[0], a[1] + t * dy - p[1]);
            if ex * ex + ey * ey <= tolerance * tolerance {
                ties[(row * width + column) as usize] = true;
            }
        }
    }
}

/// Whether `colour` is one of the background's spellings (`backgrounds`), or within the colour
/// tolerance of the first.
pub(super) fn background_like(colour: [u8; 4], backgrounds: &[[u8; 4]]) -> (bool, bool) {
    let near = (0..3).all(|k| colour[k].abs_diff(backgrounds[0][k]) <= COLOUR_STEPS);
    let exact = backgrounds.iter().any(|b| colour[..3] == b[..3]);
    (exact, near && !exact)
}

/// The bytes a program may clear to for the background `rgb`: rounded from the f64 it wrote,
/// from that number read as f32 (a float program's own), or truncated.
pub fn backgrounds(rgb: [f64; 3]) -> Vec<[u8; 4]> {
    let bytes = |byte: &dyn Fn(f64) -> u8| {
        let [r, g, b] = rgb.map(|c| byte(c.clamp(0.0, 1.0)));
        [r, g, b, 255]
    };
    let mut all = vec![
        bytes(&|c| (c * 255.0 + 0.5) as u8),
        bytes(&|c| ((c as f32) * 255.0 + 0.5) as u8),
        bytes(&|c| (c * 255.0) as u8),
    ];
    all.dedup();
    all
}

/// The facts of `program` (the trace's buffers) against `drawn` in the picture's `rows` (from
/// the top), `ties` left out of coverage.
pub fn compare(
    input: &RasterFrame,
    drawn: &Buffers,
    ties: &[bool],
    background: &[[u8; 4]],
    rows: Range<u32>,
) -> Facts {
    let program: &Image = &input.framebuffer;
    let width = program.width;
    let mut facts = Facts::default();
    let pixels = (rows.start * width) as usize..(rows.end * width) as usize;
    for at in pixels {
        let (theirs, ours) = (program.pixels[at], drawn.image.pixels[at]);
        let (their_background, their_unsure) = background_like(theirs, background);
        let (our_background, our_unsure) = background_like(ours, background);
        let decided = !ties[at] && !their_unsure && !our_unsure;
        if decided {
            facts
                .coverage
                .count(their_background != our_background, at, width);
        }
        if !their_background && !our_background {
            let differs = (0..3).any(|k| theirs[k].abs_diff(ours[k]) > COLOUR_STEPS);
            facts.colour.count(differs, at, width);
            facts.inexact += usize::from(theirs[..3] != ours[..3]);
        }
        if let Some(depth) = &input.depth
            && !ties[at]
        {
            let differs = (depth.values[at] - drawn.depth[at]).abs() > DEPTH_TOLERANCE;
            facts
                .depth
                .count(differs || depth.values[at].is_nan(), at, width);
        }
    }
    facts
}

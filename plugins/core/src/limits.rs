//! Limits and defaults that more than one crate checks against, in one place so that the config,
//! the camera, the panel, the loaders and both views cannot disagree.

use std::ops::RangeInclusive;

/// Fields of view the camera takes, degrees: the config accepts them, zooming and the panel's
/// sliders keep to them. Narrower than 0.5° a small model's image is a few pixels of rounding;
/// wider than 170° the projection stretches the border past any use.
pub const FOV_RANGE: RangeInclusive<f32> = 0.5..=170.0;

/// How fast the camera may move, model radii per second (`camera.move_speed`, the panel's
/// slider), and turn, degrees per pixel of drag (`camera.rotate_speed`; held keys turn 360 times
/// that per second). Far above these the input's per-frame steps overflow f32 and turn the
/// camera's basis into NaN.
pub const MOVE_SPEED_RANGE: RangeInclusive<f32> = 0.01..=100.0;
pub const ROTATE_SPEED_RANGE: RangeInclusive<f32> = 0.01..=10.0;

/// Both fields of view of the assignment's initial camera, degrees.
pub const DEFAULT_FOV: f32 = 60.0;

/// The most subdivisions of a primitive along one direction: it keeps every mesh within 32-bit
/// indices and memory.
pub const MAX_SEGMENTS: u32 = 4096;

/// The widest and tallest window or image, pixels: the largest 2D texture common adapters
/// (lavapipe among them) allow.
pub const MAX_PIXELS: u32 = 16384;

/// Model files larger than this, bytes, load on a worker thread with progress while the last
/// model stays shown; smaller ones load within the frame that asks: a course model parses in a
/// frame or two, not worth a bar, and this size in well under a second even in a debug build
/// (measured: docs/performance.md#loading).
pub const BACKGROUND_LOAD_BYTES: u64 = 4 << 20;

/// The longest line a model file may have, bytes. A `.in` record is under a hundred bytes and
/// an OBJ face with a thousand corners some twenty thousand: anything longer is not a model,
/// and reading it whole would let one line take as much memory as the file.
pub const MAX_LINE_BYTES: usize = 1 << 20;

/// Twice a triangle's area over its longest edge squared, at or below which it counts as having
/// no area: it is at most 1e-5 as tall as it is long, a line for any rasteriser. A sliver (a UV
/// sphere's pole, where sin(π) in f32 leaves the pole's copies 1e-7 apart; a face seen exactly
/// edge-on) gets an area of random sign from rounding, and OpenGL counts a zero-area polygon as a
/// back face. Close2GL culls by this rule in window space and the reference renderer sorts the
/// mesh by it in world space; both must use this one number, or the views disagree on slivers.
pub const ZERO_AREA: f32 = 1e-5;

/// Whether a polygon with `twice_area` (either sign) and `longest_edge_squared` has no area to
/// speak of (see [`ZERO_AREA`]).
#[inline(always)]
pub fn has_no_area(twice_area: f32, longest_edge_squared: f32) -> bool {
    twice_area.abs() <= ZERO_AREA * longest_edge_squared
}

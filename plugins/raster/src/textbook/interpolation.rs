//! Attribute interpolation: a varying is not affine on screen, but it times 1/w is, and so is
//! 1/w; blend both with the barycentric weights, then divide (perspective-correct).

use close2gl_core::{RasterMistake as M, RasterMistakes};
use glam::{Vec2, Vec3};

use super::coverage::Setup;
use super::vertex::{EYE, UV, VARYINGS};

/// A pixel of a triangle with its varyings: what shading and texturing read.
pub(super) struct Pixel<'a> {
    triangle: &'a Setup,
    pub(super) mistakes: RasterMistakes,
    x: i32,
    y: i32,
    varyings: [f32; VARYINGS],
}

impl<'a> Pixel<'a> {
    pub(super) fn new(triangle: &'a Setup, x: i32, y: i32, mistakes: RasterMistakes) -> Self {
        let varyings = varyings(triangle, x, y, mistakes);
        Pixel {
            triangle,
            mistakes,
            x,
            y,
            varyings,
        }
    }

    /// The three varyings from `at`.
    pub(super) fn vec3(&self, at: usize) -> Vec3 {
        Vec3::from_slice(&self.varyings[at..at + 3])
    }

    /// The texture coordinates here.
    pub(super) fn uv(&self) -> Vec2 {
        Vec2::from_slice(&self.varyings[UV..])
    }

    /// The texture coordinates at the centre of pixel (x + dx, y + dy), covered or not (the level
    /// of detail takes them across a 2×2 quad).
    pub(super) fn uv_beside(&self, dx: i32, dy: i32) -> Vec2 {
        let here = varyings(self.triangle, self.x + dx, self.y + dy, self.mistakes);
        Vec2::from_slice(&here[UV..])
    }

    /// Where it is: column and row from the top.
    pub(super) fn at(&self) -> (i32, i32) {
        (self.x, self.y)
    }
}

/// Whether varying `k` is blended affinely on screen (the mistakes that forget 1/w).
fn affine(k: usize, mistakes: RasterMistakes) -> bool {
    match k {
        _ if k < EYE => mistakes.has(M::ColourAffine),
        _ if k < UV => mistakes.has(M::PhongAffine),
        _ => mistakes.has(M::UvAffine),
    }
}

/// The varyings at the centre of pixel (x, y) of `triangle`.
fn varyings(triangle: &Setup, x: i32, y: i32, mistakes: RasterMistakes) -> [f32; VARYINGS] {
    let v = &triangle.corners;
    if mistakes.has(M::NoInterpolation) {
        return v[0].varyings;
    }
    let weights = triangle.weights(x, y);
    // Corner i's weight goes to the values (q included) of `from(i)`: itself, or the next
    // corner's in the order the triangle was given.
    let next = if triangle.swapped { 2 } else { 1 };
    let from = |i: usize| match mistakes.has(M::WeightsRotated) {
        true => (i + next) % 3,
        false => i,
    };
    let over_w = |i: usize| weights[i] * v[from(i)].window[3] as f64;
    let sum_over_w: f64 = (0..3).map(over_w).sum();
    std::array::from_fn(|k| {
        let value = |i: usize| v[from(i)].varyings[k] as f64;
        let blend = match affine(k, mistakes) {
            true => (0..3).map(|i| weights[i] * value(i)).sum::<f64>(),
            false => (0..3).map(|i| over_w(i) * value(i)).sum::<f64>() / sum_over_w,
        };
        blend as f32
    })
}

//! What float32 rounding can make of a program's numbers: the error bounds that `close2gl check`'s
//! tolerances are derived from (docs/checking.md, "Tolerances"), so that a float32 program always
//! passes and nothing more does.
//!
//! A value that passes through k roundings of unit roundoff u carries a relative error of at
//! most about k·u of the sum of the magnitudes of its terms (not of the result: a dot product
//! whose terms cancel keeps the terms' error). The longest chain from the trace's camera to a
//! window coordinate is about 16 roundings: M's translation (a 3-term dot product), M·p (4
//! terms), P·(M·p) (2), the division by w, V (2), and tan and the degrees' conversion in P.
//! [`BOUND`] is twice that count, for the libm functions' last bits and the printing of the
//! trace's camera in nine digits.

use glam::{DMat4, DVec2, DVec3, DVec4};

/// float32's unit roundoff, 2⁻²⁴.
pub const UNIT_ROUNDOFF: f64 = 1.0 / 16_777_216.0;

/// The relative error bound of a float32 value that went through the pipeline's chain of
/// operations, relative to the magnitude of its terms: 32 u ≈ 1.9·10⁻⁶.
pub const BOUND: f64 = 32.0 * UNIT_ROUNDOFF;

/// A number written with six decimals (C's `%f`), in the 2D system's units: the last digit is
/// the program's printing, not its arithmetic.
pub const PRINTED: f64 = 1e-6;

/// The magnitude of the terms each row of clip coordinates sums, the largest over `world`'s
/// points: Σⱼ |Aᵣⱼ|·(|pⱼ| + |cⱼ|) + |Aᵣ₃|, with A = P·M and c the camera's position. The |cⱼ|
/// are M's translation's own terms (−c·u sums three), which a camera far from the origin makes
/// larger than the result.
pub fn clip_terms(a: DMat4, camera: DVec3, world: &[DVec3]) -> DVec4 {
    let row_terms = |p: DVec3, r: usize| {
        let row = a.row(r);
        row.truncate().abs().dot(p.abs() + camera.abs()) + row.w.abs()
    };
    let mut terms = DVec4::ZERO;
    for &p in world {
        let here = DVec4::new(
            row_terms(p, 0),
            row_terms(p, 1),
            row_terms(p, 2),
            row_terms(p, 3),
        );
        terms = terms.max(here);
    }
    terms
}

/// How far a clip coordinate of row `r` may be off: [`BOUND`] of its terms.
pub fn clip_error(terms: DVec4) -> DVec4 {
    terms * BOUND
}

/// Whether a corner lies on a plane of the view volume (or on the eye's plane, w = 0) within
/// rounding: whether it is inside is for the program's rounding to say.
pub fn near_a_plane(clip: &[DVec4; 3], terms: DVec4) -> bool {
    let e = clip_error(terms);
    clip.iter().any(|c| {
        let planes = [
            (c.w + c.x, e.w + e.x),
            (c.w - c.x, e.w + e.x),
            (c.w + c.y, e.w + e.y),
            (c.w - c.y, e.w + e.y),
            (c.w + c.z, e.w + e.z),
            (c.w - c.z, e.w + e.z),
            (c.w, e.w),
        ];
        planes
            .iter()
            .any(|(distance, error)| distance.abs() <= *error)
    })
}

/// How far a vertex of the 2D output may be off, in the 2D system's units: the error of its
/// clip coordinates through the division (x/w moves by (δx + |x/w|·δw)/|w|) and V's scale, the
/// rounding of the result itself, and the printing.
pub fn window_error(v: DMat4, terms: DVec4, clip: DVec4, system: DVec2) -> f64 {
    let e = clip_error(terms);
    let w = clip.w.abs();
    let ndc = clip.truncate().truncate() / clip.w;
    let scale = DVec2::new(v.col(0).x, v.col(1).y).abs();
    let through = scale * (DVec2::new(e.x, e.y) + ndc.abs() * e.w) / w;
    let offset = DVec2::new(v.col(3).x, v.col(3).y).abs();
    through.max_element() + BOUND * (system.abs() + offset + scale).max_element() + PRINTED
}

/// How far a vertex's NDC depth may be off.
pub fn depth_error(terms: DVec4, clip: DVec4) -> f64 {
    let e = clip_error(terms);
    (e.z + (clip.z / clip.w).abs() * e.w) / clip.w.abs() + BOUND + PRINTED
}

/// Twice a polygon's signed area (counter-clockwise positive with y up).
pub fn twice_area(polygon: &[DVec2]) -> f64 {
    let n = polygon.len();
    (0..n)
        .map(|i| polygon[i].perp_dot(polygon[(i + 1) % n]))
        .sum()
}

/// How far twice a polygon's signed area may be off when each vertex may be off by its error:
/// Σᵢ |pᵢ₊₁ − pᵢ₋₁|·eᵢ (twice the area is Σ pᵢ × pᵢ₊₁, whose gradient at pᵢ is that edge turned
/// by a right angle). A long spike with one uncertain far corner is uncertain only across its
/// short side.
pub fn twice_area_error(polygon: &[DVec2], errors: &[f64]) -> f64 {
    let n = polygon.len();
    (0..n)
        .map(|i| polygon[(i + 1) % n].distance(polygon[(i + n - 1) % n]) * errors[i])
        .sum()
}

/// How far the facing test of a world-space rule (a normal against a direction) may be off.
pub fn dot_error(a: DVec3, b: DVec3) -> f64 {
    BOUND * a.length() * b.length()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_far_camera_makes_the_terms_large_though_the_result_is_small() {
        let a = DMat4::from_translation(DVec3::new(-1e4, 0.0, 0.0));
        let near = clip_terms(a, DVec3::new(1e4, 0.0, 0.0), &[DVec3::new(1e4, 0.0, 0.0)]);
        assert!(near.x >= 2e4, "{near}");
        let origin = clip_terms(DMat4::IDENTITY, DVec3::ZERO, &[DVec3::new(1.0, 0.0, 0.0)]);
        assert_eq!(origin.x, 1.0);
    }

    #[test]
    fn a_spike_is_uncertain_across_its_short_side() {
        let spike = [
            DVec2::new(0.0, 0.0),
            DVec2::new(1.0, 0.0),
            DVec2::new(0.5, 1e6),
        ];
        let error = twice_area_error(&spike, &[1e-3, 1e-3, 10.0]);
        // The far corner's 10 units count along the 1-unit base only.
        assert!(error < 10.0 + 3e3, "{error}");
        assert!(error > 10.0);
    }

    #[test]
    fn a_corner_close_to_the_eye_is_known_only_roughly() {
        let v = DMat4::from_scale(DVec3::new(320.0, 240.0, 0.5));
        let terms = DVec4::splat(10.0);
        let far = window_error(v, terms, DVec4::new(1.0, 1.0, 1.0, 5.0), DVec2::ZERO);
        let close = window_error(v, terms, DVec4::new(1.0, 1.0, 1.0, 1e-3), DVec2::ZERO);
        assert!(close > 1000.0 * far, "{close} {far}");
    }
}

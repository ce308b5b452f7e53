//! Whether what a trace drew for one mesh triangle covers the same region as close2gl's polygon:
//! a fan, a polygon or several pieces of the same clipped shape all agree. The test is on the
//! shape, not the listing: every corner the trace drew lies on close2gl's polygon, every corner
//! of close2gl's polygon is one the trace drew, and the areas match (no piece twice, none
//! missing).

use close2gl_pipeline::rounding::{twice_area, twice_area_error};
use glam::DVec2;

/// How the trace's pieces differ from close2gl's polygon, if they do: the corner farthest from
/// where it should be, and the two areas.
#[derive(Clone, Debug, PartialEq)]
pub struct RegionDifference {
    /// A corner that is off: (expected, found) — found None when close2gl's corner has no
    /// counterpart in the trace, expected None when the trace's corner lies off the polygon.
    pub corner: (Option<DVec2>, Option<DVec2>),
    pub expected_area: f64,
    pub found_area: f64,
}

/// Whether the convex polygon (either winding, with an area) covers `p`, its border included.
pub fn covers(polygon: &[DVec2], p: DVec2) -> bool {
    let n = polygon.len();
    let sign = twice_area(polygon).signum();
    n >= 3
        && sign != 0.0
        && (0..n).all(|i| {
            let (a, b) = (polygon[i], polygon[(i + 1) % n]);
            (b - a).perp_dot(p - a) * sign >= 0.0
        })
}

/// The distance from `p` to a convex polygon (0 inside), whichever way it winds, and the
/// nearest edge (from vertex i to i + 1).
fn distance_to(polygon: &[DVec2], p: DVec2) -> (f64, usize) {
    let n = polygon.len();
    let to_edge = |i: usize| {
        let (a, b) = (polygon[i], polygon[(i + 1) % n]);
        let ab = b - a;
        let t = match ab.length_squared() {
            0.0 => 0.0,
            l => ((p - a).dot(ab) / l).clamp(0.0, 1.0),
        };
        p.distance(a + ab * t)
    };
    let nearest = (0..n)
        .map(|i| (to_edge(i), i))
        .min_by(|a, b| a.0.total_cmp(&b.0))
        .unwrap_or((f64::INFINITY, 0));
    match covers(polygon, p) {
        true => (0.0, nearest.1),
        false => nearest,
    }
}

/// Compares the trace's `pieces` with close2gl's convex `polygon` (both in the same 2D system),
/// each of whose vertices a float32 program may put `errors[i]` away.
pub fn compare(polygon: &[DVec2], errors: &[f64], pieces: &[&[DVec2]]) -> Option<RegionDifference> {
    let expected_area = twice_area(polygon).abs() / 2.0;
    let found_area: f64 = pieces.iter().map(|q| twice_area(q).abs() / 2.0).sum();
    let difference = |corner| RegionDifference {
        corner,
        expected_area,
        found_area,
    };
    let n = polygon.len();
    let found = pieces.iter().flat_map(|q| q.iter().copied());
    for q in found.clone() {
        let (distance, edge) = distance_to(polygon, q);
        if !q.is_finite() || distance > errors[edge].max(errors[(edge + 1) % n]) {
            return Some(difference((None, Some(q))));
        }
    }
    for (&p, &error) in polygon.iter().zip(errors) {
        let nearest = found
            .clone()
            .min_by(|a, b| a.distance(p).total_cmp(&b.distance(p)));
        match nearest {
            Some(q) if q.distance(p) <= error => {}
            q => return Some(difference((Some(p), q))),
        }
    }
    // Each side's area may be off by half the bound on twice it.
    if (expected_area - found_area).abs() > twice_area_error(polygon, errors) + 1e-12 {
        return Some(difference((None, None)));
    }
    None
}

/// Whether a region is too small to see: its area within what its vertices' errors allow (a
/// sliver a float32 program may draw or drop, or draw with no area).
pub fn negligible(polygon: &[DVec2], errors: &[f64]) -> bool {
    twice_area(polygon).abs() <= twice_area_error(polygon, errors)
}

#[cfg(test)]
mod tests {
    use super::*;

    const TIGHT: [f64; 4] = [1e-6; 4];

    fn square() -> Vec<DVec2> {
        [(0.0, 0.0), (4.0, 0.0), (4.0, 4.0), (0.0, 4.0)]
            .map(|(x, y)| DVec2::new(x, y))
            .to_vec()
    }

    #[test]
    fn a_fan_and_the_polygon_agree_whichever_way_they_wind() {
        let s = square();
        let fan = [[s[0], s[1], s[2]], [s[0], s[2], s[3]]];
        let reversed: Vec<DVec2> = s.iter().rev().copied().collect();
        assert_eq!(compare(&s, &TIGHT, &[&fan[0], &fan[1]]), None);
        assert_eq!(compare(&s, &TIGHT, &[&reversed]), None);
    }

    #[test]
    fn a_missing_piece_a_piece_twice_and_a_moved_corner_differ() {
        let s = square();
        let fan = [[s[0], s[1], s[2]], [s[0], s[2], s[3]]];
        assert!(compare(&s, &TIGHT, &[&fan[0]]).is_some(), "half of it");
        assert!(
            compare(&s, &TIGHT, &[&fan[0], &fan[1], &fan[1]]).is_some(),
            "a piece twice"
        );
        let mut moved = s.clone();
        moved[2] = DVec2::new(4.5, 4.0);
        let d = compare(&s, &TIGHT, &[&moved]).expect("moved");
        assert_eq!(d.corner.1, Some(DVec2::new(4.5, 4.0)));
    }

    #[test]
    fn a_whole_triangle_is_not_its_clipped_piece() {
        let triangle = [
            DVec2::new(0.0, 0.0),
            DVec2::new(8.0, 0.0),
            DVec2::new(0.0, 8.0),
        ];
        let clipped = [
            DVec2::new(0.0, 0.0),
            DVec2::new(4.0, 0.0),
            DVec2::new(4.0, 4.0),
            DVec2::new(0.0, 8.0),
        ];
        assert!(compare(&clipped, &TIGHT, &[&triangle]).is_some());
    }
}

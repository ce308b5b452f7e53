//! Whether what a trace drew for one mesh triangle covers the same region as close2gl's polygon:
//! a fan, a polygon or several pieces of the same clipped shape all agree. The test is on the
//! shape, not the listing: every corner the trace drew lies on close2gl's polygon, every corner
//! of close2gl's polygon is one the trace drew, and the areas match (no piece twice, none
//! missing).

use glam::DVec2;

/// How far a corner may be from where close2gl puts it: `absolute` in the 2D system's units,
/// plus `relative` times the corner's distance from the origin (a float32 program's error
/// grows with its numbers; corners near w = 0 land far away).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Tolerance {
    pub absolute: f64,
    pub relative: f64,
}

impl Tolerance {
    fn at(&self, p: DVec2) -> f64 {
        self.absolute + self.relative * p.length()
    }
}

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

/// Twice the signed area of a polygon (counter-clockwise positive in a y-up system).
pub fn twice_area(polygon: &[DVec2]) -> f64 {
    let n = polygon.len();
    (0..n)
        .map(|i| polygon[i].perp_dot(polygon[(i + 1) % n]))
        .sum()
}

fn perimeter(polygon: &[DVec2]) -> f64 {
    let n = polygon.len();
    (0..n)
        .map(|i| polygon[i].distance(polygon[(i + 1) % n]))
        .sum()
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

/// The distance from `p` to a convex polygon (0 inside), whichever way it winds.
fn distance_to(polygon: &[DVec2], p: DVec2) -> f64 {
    if covers(polygon, p) {
        return 0.0;
    }
    let n = polygon.len();
    (0..n)
        .map(|i| {
            let (a, b) = (polygon[i], polygon[(i + 1) % n]);
            let ab = b - a;
            let t = match ab.length_squared() {
                0.0 => 0.0,
                l => ((p - a).dot(ab) / l).clamp(0.0, 1.0),
            };
            p.distance(a + ab * t)
        })
        .fold(f64::INFINITY, f64::min)
}

/// Compares the trace's `pieces` with close2gl's convex `polygon` (both in the same 2D system).
pub fn compare(
    polygon: &[DVec2],
    pieces: &[&[DVec2]],
    tolerance: Tolerance,
) -> Option<RegionDifference> {
    let expected_area = twice_area(polygon).abs() / 2.0;
    let found_area: f64 = pieces.iter().map(|q| twice_area(q).abs() / 2.0).sum();
    let difference = |corner| RegionDifference {
        corner,
        expected_area,
        found_area,
    };
    let found = pieces.iter().flat_map(|q| q.iter().copied());
    for q in found.clone() {
        if !q.is_finite() || distance_to(polygon, q) > tolerance.at(q) {
            return Some(difference((None, Some(q))));
        }
    }
    for &p in polygon {
        let nearest = found
            .clone()
            .min_by(|a, b| a.distance(p).total_cmp(&b.distance(p)));
        match nearest {
            Some(q) if q.distance(p) <= tolerance.at(p) => {}
            q => return Some(difference((Some(p), q))),
        }
    }
    let slack = perimeter(polygon) * polygon.iter().map(|&p| tolerance.at(p)).fold(0.0, f64::max);
    if (expected_area - found_area).abs() > 2.0 * slack + 1e-12 {
        return Some(difference((None, None)));
    }
    None
}

/// Whether a region is too small to see: its area within what the tolerance allows for a
/// polygon of its size (a sliver a float32 program may draw or drop).
pub fn negligible(polygon: &[DVec2], tolerance: Tolerance) -> bool {
    let slack = perimeter(polygon) * polygon.iter().map(|&p| tolerance.at(p)).fold(0.0, f64::max);
    twice_area(polygon).abs() / 2.0 <= slack
}

#[cfg(test)]
mod tests {
    use super::*;

    const TIGHT: Tolerance = Tolerance {
        absolute: 1e-6,
        relative: 0.0,
    };

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
        assert_eq!(compare(&s, &[&fan[0], &fan[1]], TIGHT), None);
        assert_eq!(compare(&s, &[&reversed], TIGHT), None);
    }

    #[test]
    fn a_missing_piece_a_piece_twice_and_a_moved_corner_differ() {
        let s = square();
        let fan = [[s[0], s[1], s[2]], [s[0], s[2], s[3]]];
        assert!(compare(&s, &[&fan[0]], TIGHT).is_some(), "half of it");
        assert!(
            compare(&s, &[&fan[0], &fan[1], &fan[1]], TIGHT).is_some(),
            "a piece twice"
        );
        let mut moved = s.clone();
        moved[2] = DVec2::new(4.5, 4.0);
        let d = compare(&s, &[&moved], TIGHT).expect("moved");
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
        assert!(compare(&clipped, &[&triangle], TIGHT).is_some());
    }
}

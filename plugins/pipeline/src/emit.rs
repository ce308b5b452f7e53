//! What each mode draws of a clipped triangle, as OpenGL's polygon modes draw it: a fan of
//! triangles from its polygon's first corner (solid), the polygon's own edges as lines
//! (wireframe: the edges clipping added along a plane are not drawn), or its corners (points:
//! of the triangle cut by the near plane alone, see [`points`]). Every path emits through these:
//! the pipeline's triangles ([`crate::stage`]), a program's ([`crate::program::view`]) and a
//! shown trace's pieces, so no two can draw different dots or lines of the same polygon.

use close2gl_core::Topology;

use crate::clip::{NEAR, Outcode, Polygon, clip_polygon, outcode};

/// The corners of a polygon of `n` corners that `topology` sends on, in order: its fan
/// (`0 1 2, 0 2 3, ...`), the edges `i → i + 1` for which `own(i)` holds (the triangle's own,
/// not the clipping planes'), or every corner. For a point, the polygon is [`points`]'.
pub fn corners(
    topology: Topology,
    n: usize,
    own: impl Fn(usize) -> bool,
) -> impl Iterator<Item = usize> {
    let fan = (topology == Topology::Triangles).then(|| fan(n));
    let lines = (topology == Topology::Lines).then(|| edges(n, own));
    let points = (topology == Topology::Points).then_some(0..n);
    (fan.into_iter().flatten())
        .chain(lines.into_iter().flatten())
        .chain(points.into_iter().flatten())
}

/// [`corners`] of a whole triangle, every edge its own, as a table: a triangle inside the
/// view volume, by far the commonest, copies these rather than running the iterator.
pub fn whole(topology: Topology) -> &'static [usize] {
    match topology {
        Topology::Triangles | Topology::Points => &[0, 1, 2],
        Topology::Lines => &[0, 1, 1, 2, 2, 0],
    }
}

/// The fan of a polygon of `n` corners: `0 1 2, 0 2 3, ...`.
fn fan(n: usize) -> impl Iterator<Item = usize> {
    (1..n.saturating_sub(1)).flat_map(|i| [0, i, i + 1])
}

/// The edges `i → i + 1` of a polygon of `n` corners for which `drawn(i)` holds, as pairs of
/// corners.
fn edges(n: usize, drawn: impl Fn(usize) -> bool) -> impl Iterator<Item = usize> {
    (0..n)
        .filter(move |&i| drawn(i))
        .flat_map(move |i| [i, (i + 1) % n])
}

/// What point mode draws of `triangle` (clip coordinates), whose corners lie outside
/// `outside` and which is clipped against `planes`: the vertices that start one of its own
/// edges once the near plane has cut it (its corners, and the points where an edge comes back
/// in front of the near plane), each kept when it lies inside the other planes of `planes`.
/// A GPU applies every plane but the near one to each point alone (a point outside the
/// viewport or the depth range is dropped), so no vertex is made on them; the near plane it
/// must cut, since dividing by w needs w > 0.
pub fn points(triangle: &Polygon, outside: Outcode, planes: Outcode) -> Polygon {
    let near_cut = clip_polygon(triangle, outside & NEAR);
    let mut kept = Polygon { len: 0, ..near_cut };
    for i in 0..near_cut.len {
        let p = near_cut.points[i];
        // Points made on the near plane are inside it by construction, whatever the rounding.
        if near_cut.original[i] && outcode(p) & planes & !NEAR == 0 {
            kept.points[kept.len] = p;
            kept.original[kept.len] = true;
            kept.weights[kept.len] = near_cut.weights[i];
            kept.len += 1;
        }
    }
    kept
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec4;

    #[test]
    fn a_pentagon_fans_from_its_first_corner_and_keeps_its_own_edges() {
        assert_eq!(fan(5).collect::<Vec<_>>(), [0, 1, 2, 0, 2, 3, 0, 3, 4]);
        assert_eq!(fan(2).count(), 0);
        let own = [true, false, true, true, false];
        let lines: Vec<usize> = corners(Topology::Lines, 5, |i| own[i]).collect();
        assert_eq!(lines, [0, 1, 2, 3, 3, 4]);
        let points: Vec<usize> = corners(Topology::Points, 5, |i| own[i]).collect();
        assert_eq!(
            points,
            [0, 1, 2, 3, 4],
            "the points' polygon is already chosen"
        );
    }

    #[test]
    fn the_whole_triangles_table_is_what_the_emitter_gives() {
        for topology in [Topology::Triangles, Topology::Lines, Topology::Points] {
            let emitted: Vec<usize> = corners(topology, 3, |_| true).collect();
            assert_eq!(whole(topology), emitted, "{topology:?}");
        }
    }

    #[test]
    fn a_triangle_across_the_left_plane_shows_only_its_corners_inside() {
        // Two corners left of x = -w, one inside: the full clip has four corners, two of them
        // on the border; point mode draws the one corner inside, and nothing on the border.
        let triangle = Polygon::triangle(
            Vec4::new(-3.0, 0.0, 0.0, 1.0),
            Vec4::new(0.5, 0.2, 0.0, 1.0),
            Vec4::new(-3.0, 0.5, 0.0, 1.0),
        );
        let outside = outcode(triangle.points[0]) | outcode(triangle.points[2]);
        let kept = points(&triangle, outside, 0x3f);
        assert_eq!(kept.vertices(), [triangle.points[1]]);
        assert_eq!(kept.weights[0], glam::Vec3::Y);
    }
}

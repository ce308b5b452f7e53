//! Primitive assembly: a triangle is itself; a line is the rectangle one pixel wide around it
//! and a point the one-pixel square centred on it, the shapes Vulkan's rasterizer (the reference
//! view's) gives them, each as two triangles sharing a diagonal, which the top-left rule draws
//! each pixel of once.

use super::coverage::{STEPS, snap};
use super::vertex::Vertex;

/// A primitive's triangles. A primitive with a corner that cannot be snapped is not drawn.
pub(super) fn triangles(corners: &[Vertex]) -> Vec<[Vertex; 3]> {
    let Some(at) = corners
        .iter()
        .map(|v| snap(v.window))
        .collect::<Option<Vec<_>>>()
    else {
        return Vec::new();
    };
    match *corners {
        [a, b, c] => vec![[a, b, c]],
        [a, b] => line((&a, at[0]), (&b, at[1])),
        [v] => {
            let [x, y] = at[0].map(|p| p - 128);
            let square = [[x, y], [x + 256, y], [x + 256, y + 256], [x, y + 256]];
            rectangle(square.map(|c| moved(&v, c)))
        }
        _ => Vec::new(),
    }
}

/// The same vertex moved to the snapped position `to` (a corner of a line's or a point's
/// rectangle), keeping its depth, 1/w and varyings.
fn moved(v: &Vertex, to: [i64; 2]) -> Vertex {
    let mut moved = *v;
    moved.window[0] = to[0] as f32 / STEPS + 0.5;
    moved.window[1] = to[1] as f32 / STEPS + 0.5;
    moved.snapped = Some(to);
    moved
}

/// The rectangle one pixel wide around the line from `a` to `b`, each with where it snapped to.
fn line((a, at_a): (&Vertex, [i64; 2]), (b, at_b): (&Vertex, [i64; 2])) -> Vec<[Vertex; 3]> {
    let (dx, dy) = (a.window[0] - b.window[0], a.window[1] - b.window[1]);
    let length_squared = dx * dx + dy * dy;
    if length_squared == 0.0 || !length_squared.is_finite() {
        return Vec::new();
    }
    // Half a pixel across the line, snapped: the fast one's f32 operations, in its order, since
    // the corners decide coverage.
    let scale = 0.5 / length_squared.sqrt();
    let across = [-dy * scale * STEPS, dx * scale * STEPS].map(|d| d.round_ties_even() as i64);
    let side =
        |v: &Vertex, at: [i64; 2], sign: i64| moved(v, [0, 1].map(|k| at[k] + sign * across[k]));
    rectangle([
        side(a, at_a, -1),
        side(b, at_b, -1),
        side(b, at_b, 1),
        side(a, at_a, 1),
    ])
}

/// A rectangle as two triangles sharing the diagonal from its first corner to its third.
fn rectangle(c: [Vertex; 4]) -> Vec<[Vertex; 3]> {
    vec![[c[0], c[1], c[2]], [c[0], c[2], c[3]]]
}

//! Which corners of a drawn polygon each mode sends on, in order, as OpenGL's polygon modes
//! draw it: a fan of triangles from its first corner (solid), its own edges as lines
//! (wireframe: the edges clipping added along a plane are not drawn), or its corners (points).
//! The pipeline's clipped pieces, the textbook path and a shown trace all emit through these.

/// The fan of a polygon of `n` corners: `0 1 2, 0 2 3, ...`.
pub fn fan(n: usize) -> impl Iterator<Item = usize> {
    (1..n.saturating_sub(1)).flat_map(|i| [0, i, i + 1])
}

/// The edges `i → i + 1` of a polygon of `n` corners for which `drawn(i)` holds, as pairs of
/// corners.
pub fn edges(n: usize, drawn: impl Fn(usize) -> bool) -> impl Iterator<Item = usize> {
    (0..n)
        .filter(move |&i| drawn(i))
        .flat_map(move |i| [i, (i + 1) % n])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pentagon_fans_from_its_first_corner_and_keeps_its_own_edges() {
        assert_eq!(fan(5).collect::<Vec<_>>(), [0, 1, 2, 0, 2, 3, 0, 3, 4]);
        assert_eq!(fan(2).count(), 0);
        let own = [true, false, true, true, false];
        let lines: Vec<usize> = edges(5, |i| own[i]).collect();
        assert_eq!(lines, [0, 1, 2, 3, 3, 4]);
    }
}

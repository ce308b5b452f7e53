//! What the readers gather from an OBJ file: its `v`, `vt` and `vn` records, and its faces cut
//! into triangles of vertices, a vertex being a distinct `v/vt/vn` triple, numbered without
//! hashing in the common case (see [`Vertices`]).

use std::collections::HashMap;

use glam::{Vec2, Vec3};

use super::parse::NONE;

/// The records and triangles of a file, every object merged.
#[derive(Default, Debug)]
pub(super) struct Geometry {
    pub(super) positions: Vec<Vec3>,
    pub(super) texcoords: Vec<Vec2>,
    pub(super) normals: Vec<Vec3>,
    /// Each face's triangles, of [`Vertices`] ids, in file order.
    pub(super) triangles: Vec<[u32; 3]>,
    pub(super) vertices: Vertices,
}

impl Geometry {
    /// How many `v`, `vt` and `vn` records there are so far.
    pub(super) fn counts(&self) -> [usize; 3] {
        [
            self.positions.len(),
            self.texcoords.len(),
            self.normals.len(),
        ]
    }

    /// Adds a face whose `[v, vt, vn]` corners all exist: a fan from its first corner, in the
    /// file's winding, as tobj (which this loader replaced) and most readers cut polygons.
    pub(super) fn face(&mut self, corners: &[[u32; 3]]) {
        let [first, second, rest @ ..] = corners else {
            return;
        };
        let first = self.vertices.id(*first);
        let mut previous = self.vertices.id(*second);
        for &corner in rest {
            let id = self.vertices.id(corner);
            self.triangles.push([first, previous, id]);
            previous = id;
        }
    }
}

/// A position's first `[vt, vn]` before any corner has named it: no reference reaches it, the
/// readers refusing indices from `NONE - 1` on.
const UNSEEN: [u32; 2] = [NONE - 1, NONE - 1];

/// The distinct `[v, vt, vn]` triples of the faces, each an id. In most files a position is
/// named with one texture coordinate and normal (or none), so each triple's id is its `v`
/// index, checked against the first triple that named it; the others (a texture seam, a crease)
/// are numbered down from `u32::MAX` through a hash map.
#[derive(Default, Debug)]
pub(super) struct Vertices {
    /// The `[vt, vn]` each position was first named with ([`UNSEEN`] if it has not been); empty
    /// while no corner has named a texture coordinate or normal.
    first: Vec<[u32; 2]>,
    /// 1 + the largest `v` index named while `first` is empty.
    named: usize,
    /// Triples that differ from their position's first; `!id` indexes this.
    others: Vec<[u32; 3]>,
    index: HashMap<[u32; 3], u32>,
}

impl Vertices {
    /// The id of the corner `[v, vt, vn]`, whose references exist.
    fn id(&mut self, corner: [u32; 3]) -> u32 {
        let [v, vt, vn] = corner;
        if self.first.is_empty() {
            if vt == NONE && vn == NONE {
                self.named = self.named.max(v as usize + 1);
                return v;
            }
            // Every position named so far was named without a texture coordinate or normal.
            self.first = vec![[NONE, NONE]; self.named];
        }
        let at = v as usize;
        if self.first.len() <= at {
            self.first.resize(at + 1, UNSEEN);
        }
        let first = &mut self.first[at];
        if *first == UNSEEN {
            *first = [vt, vn];
        }
        if *first == [vt, vn] {
            return v;
        }
        let others = &mut self.others;
        *self.index.entry(corner).or_insert_with(|| {
            others.push(corner);
            !(others.len() as u32 - 1)
        })
    }

    /// Whether only positions were named: each vertex is then its `v` record.
    pub(super) fn positions_only(&self) -> bool {
        self.first.is_empty()
    }

    /// The `vn` index of each vertex ([`NONE`] for none), and of some that no corner uses.
    pub(super) fn named_normals(&self) -> impl Iterator<Item = u32> + '_ {
        let first = self.first.iter().filter(|&&f| f != UNSEEN).map(|f| f[1]);
        first.chain(self.others.iter().map(|c| c[2]))
    }

    /// How many ids there can be for `positions` positions: ids run below that once made
    /// [`Vertices::dense`]. `None` when they do not fit 32 bits.
    pub(super) fn count(&self, positions: usize) -> Option<usize> {
        let count = positions.checked_add(self.others.len())?;
        (count as u64 <= 1 << 32).then_some(count)
    }

    /// Vertex `id` as an index below [`Vertices::count`].
    pub(super) fn dense(&self, id: u32, positions: usize) -> usize {
        if (id as usize) < positions {
            id as usize
        } else {
            positions + !id as usize
        }
    }

    /// The `[v, vt, vn]` of vertex `id`.
    pub(super) fn corner(&self, id: u32) -> [u32; 3] {
        match self.first.get(id as usize) {
            Some(&[vt, vn]) => [id, vt, vn],
            None if self.first.is_empty() => [id, NONE, NONE],
            None => self
                .others
                .get(!id as usize)
                .copied()
                .unwrap_or([id, NONE, NONE]),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polygons_are_fans_from_their_first_corner() {
        let mut g = Geometry::default();
        let corners: Vec<[u32; 3]> = (0..5).map(|v| [v, NONE, NONE]).collect();
        g.face(&corners);
        assert_eq!(g.triangles, vec![[0, 1, 2], [0, 2, 3], [0, 3, 4]]);
        assert!(g.vertices.positions_only());
    }

    #[test]
    fn a_position_named_with_another_triple_is_another_vertex() {
        let mut g = Geometry::default();
        g.face(&[[0, NONE, NONE], [1, NONE, NONE], [2, NONE, NONE]]);
        g.face(&[[0, 0, NONE], [2, 1, 1], [3, 1, 1]]);
        g.face(&[[3, 1, 1], [2, 1, 1], [0, 0, NONE]]);
        let [a, b, c] = g.triangles[1];
        assert_eq!(g.triangles[2], [c, b, a], "the same triples, the same ids");
        assert_eq!(g.vertices.corner(a), [0, 0, NONE]);
        assert_eq!(g.vertices.corner(b), [2, 1, 1]);
        assert_eq!(g.vertices.corner(c), [3, 1, 1]);
        assert_eq!(g.vertices.corner(0), [0, NONE, NONE]);
        assert_eq!(c, 3, "a position's first triple is the position");
        assert_eq!(g.vertices.count(4), Some(6));
        let dense: Vec<usize> = [0, 1, 2, 3, a, b].map(|id| g.vertices.dense(id, 4)).into();
        assert_eq!(dense, [0, 1, 2, 3, 4, 5]);
    }
}

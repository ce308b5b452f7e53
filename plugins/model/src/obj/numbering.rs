//! The mesh's vertices, numbered: one per distinct (position, normal, texture coordinate) bits,
//! in the order the triangles first use them, which is how the mesh builder numbers corners
//! handed to it one by one. Without its hash of every vertex: a file vertex (a `v/vt/vn` id) is
//! looked at once, and compared only with the mesh vertices at its position, nearly always
//! none or one.

use super::faces::Vertices;
use super::parse::NONE;

pub(super) const TOO_MANY: &str = "more vertices than 32-bit indices can address";

/// The mesh's vertices, each as the first file vertex that made it.
pub(super) struct Numbering {
    pub(super) ids: Vec<u32>,
    /// Whether any corner has a texture coordinate.
    pub(super) textured: bool,
}

/// Numbers the vertices of `triangles` (of [`Vertices`] ids, made mesh vertex indices here).
/// `canonical` gives each of the `positions` `v` records its position's first record; `key`
/// gives the bits of an id's normal and texture coordinate as the mesh will hold them.
pub(super) fn number(
    triangles: &mut [[u32; 3]],
    vertices: &Vertices,
    canonical: &[u32],
    key: impl Fn(u32) -> [u32; 5],
) -> Result<Numbering, String> {
    let positions = canonical.len();
    let count = vertices.count(positions).ok_or(TOO_MANY)?;
    let mut vertex_of = vec![NONE; count];
    // The mesh vertices at each position, as a list through `next`.
    let mut first_at = vec![NONE; positions];
    let mut next = Vec::new();
    let mut numbering = Numbering {
        ids: Vec::new(),
        textured: false,
    };
    for id in triangles.as_flattened_mut() {
        let vertex = &mut vertex_of[vertices.dense(*id, positions)];
        if *vertex == NONE {
            let [v, vt, _] = vertices.corner(*id);
            numbering.textured |= vt != NONE;
            let at = &mut first_at[canonical[v as usize] as usize];
            let wanted = key(*id);
            let mut found = *at;
            while found != NONE && key(numbering.ids[found as usize]) != wanted {
                found = next[found as usize];
            }
            if found == NONE {
                found = u32::try_from(numbering.ids.len())
                    .ok()
                    .filter(|&i| i != NONE)
                    .ok_or(TOO_MANY)?;
                numbering.ids.push(*id);
                next.push(*at);
                *at = found;
            }
            *vertex = found;
        }
        *id = *vertex;
    }
    Ok(numbering)
}

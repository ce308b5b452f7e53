//! Which `v` records share a position: equal bits, -0.0 and 0.0 alike, as the mesh compares
//! vertices. A position written twice is one position to the smooth normals and to the mesh.

use glam::Vec3;

use crate::corner_index::CornerIndex;
use crate::mesh_builder::fingerprint;

/// Each record's first record with the same position (its own index if none came before). A
/// fingerprint index rather than a `HashMap` over the positions: half the memory and no SipHash,
/// and exact all the same, since a hit is confirmed bit for bit and the search goes on past a
/// fingerprint that only collides. `positions` holds fewer than 2^32 records.
pub(super) fn canonical(positions: &[Vec3]) -> Vec<u32> {
    let bits = |p: Vec3| (p + 0.0).to_array().map(f32::to_bits);
    let mut index = CornerIndex::with_capacity(positions.len());
    let mut canonical = Vec::with_capacity(positions.len());
    for (v, &p) in positions.iter().enumerate() {
        let key = bits(p);
        let fingerprint = fingerprint(&key);
        let same = |first: u32| bits(positions[first as usize]) == key;
        canonical.push(index.get(fingerprint, same).unwrap_or_else(|| {
            let v = v as u32;
            index.insert(fingerprint, v);
            v
        }));
    }
    canonical
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn equal_positions_point_to_the_first() {
        let positions = [
            Vec3::ZERO,
            Vec3::X,
            Vec3::new(-0.0, 0.0, 0.0),
            Vec3::X,
            Vec3::Y,
        ];
        assert_eq!(canonical(&positions), [0, 1, 0, 1, 4]);
    }
}

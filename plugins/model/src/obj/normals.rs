//! Smooth normals for the corners a file gives no (usable) normal: area-weighted, the
//! unnormalised cross product of each triangle being its normal times twice its area, so that
//! big faces weigh more. Summed per position (see `positions`), not per `v` record or vertex,
//! so that neither a texture seam nor a position written twice creases the shading.

use glam::Vec3;

/// The smooth normal at each `v` record: unit, +z where the faces cancel out or have no area.
pub(super) struct Smooth(Vec<Vec3>);

impl Smooth {
    /// The normals of `positions` (whose [`super::positions::canonical`] records are
    /// `canonical`) under `triangles` (of `v` indices, all in range), summed in triangle order.
    pub(super) fn new(
        positions: &[Vec3],
        canonical: &[u32],
        triangles: impl Iterator<Item = [u32; 3]>,
    ) -> Self {
        let mut normals = vec![Vec3::ZERO; positions.len()];
        for corners in triangles {
            let [a, b, c] = corners.map(|v| positions[v as usize]);
            let weighted = (b - a).cross(c - a);
            for v in corners {
                normals[canonical[v as usize] as usize] += weighted;
            }
        }
        // A record's canonical record comes first and is its own: it is final when reached.
        for v in 0..normals.len() {
            let first = canonical[v] as usize;
            normals[v] = if first == v {
                normals[v].try_normalize().unwrap_or(Vec3::Z)
            } else {
                normals[first]
            };
        }
        Self(normals)
    }

    /// The smooth normal at `v` record `v`.
    pub(super) fn at(&self, v: u32) -> Vec3 {
        self.0[v as usize]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::obj::positions::canonical;

    #[test]
    fn equal_positions_share_their_normal_and_no_area_gives_plus_z() {
        let positions = [
            Vec3::ZERO,
            Vec3::X,
            Vec3::Y,
            Vec3::new(-0.0, 0.0, 0.0),
            Vec3::Z,
            Vec3::splat(7.0),
        ];
        let canonical = canonical(&positions);
        let triangles = [[0, 1, 2], [3, 4, 1], [5, 5, 5]].into_iter();
        let smooth = Smooth::new(&positions, &canonical, triangles);
        // Areas 1/2 facing +z and 1/2 facing +y meet at the origin, written twice.
        let origin = Vec3::new(0.0, 1.0, 1.0).normalize();
        assert_eq!(smooth.at(0), origin);
        assert_eq!(smooth.at(3), origin);
        assert_eq!(smooth.at(2), Vec3::Z);
        assert_eq!(smooth.at(5), Vec3::Z, "no area");
    }
}

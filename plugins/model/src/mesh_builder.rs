use close2gl_core::Mesh;
use glam::{Vec2, Vec3};

use crate::corner_index::CornerIndex;

/// Builds an indexed mesh from triangle corners, giving identical (position, normal, texture
/// coordinate) corners one index so that a shared corner is transformed once per frame, not once
/// per triangle.
pub(crate) struct MeshBuilder {
    mesh: Mesh,
    /// A 64-bit fingerprint of each corner's bits → its index. Fingerprints rather than the 32
    /// bytes themselves keep the index small, the largest thing a big load holds besides the
    /// mesh; a hit is confirmed against the mesh, and a corner whose fingerprint is taken by
    /// another simply is not shared.
    index: CornerIndex,
    /// Whether any corner had a texture coordinate (the others get (0, 0)). Until one has,
    /// `mesh.uvs` stays empty rather than a zero for each vertex.
    textured: bool,
}

impl MeshBuilder {
    pub(crate) fn new(name: String) -> Self {
        Self::with_capacity(name, 0)
    }

    /// A builder with room for `triangles` triangles and about half as many vertices (a closed
    /// mesh has half as many and two; an open one a few more, along its border), so that a
    /// load whose header tells its size neither copies its vectors as they grow nor holds the
    /// old and the new at once: its peak memory stays near the mesh's.
    pub(crate) fn with_capacity(name: String, triangles: usize) -> Self {
        let vertices = triangles / 2 + triangles / 32 + 16;
        Self {
            mesh: Mesh {
                name,
                positions: Vec::with_capacity(vertices),
                normals: Vec::with_capacity(vertices),
                triangles: Vec::with_capacity(triangles),
                ..Mesh::default()
            },
            index: CornerIndex::with_capacity(vertices),
            textured: false,
        }
    }

    /// The index of the vertex `c`, added if it is new.
    pub(crate) fn corner(&mut self, c: &Corner) -> Result<u32, String> {
        if c.textured && !self.textured {
            self.textured = true;
            self.mesh.uvs.resize(self.mesh.positions.len(), Vec2::ZERO);
        }
        let found = self.index.get(c.fingerprint, |i| {
            let key = self.key_of(i as usize);
            key == c.key || fingerprint(&key) == c.fingerprint
        });
        if let Some(i) = found
            && self.key_of(i as usize) == c.key
        {
            return Ok(i);
        }
        let i = u32::try_from(self.mesh.positions.len())
            .map_err(|_| "more vertices than 32-bit indices can address".to_string())?;
        let number = |k: usize| f32::from_bits(c.key[k]);
        self.mesh
            .positions
            .push(Vec3::new(number(0), number(1), number(2)));
        self.mesh
            .normals
            .push(Vec3::new(number(3), number(4), number(5)));
        if self.textured {
            self.mesh.uvs.push(Vec2::new(number(6), number(7)));
        }
        if found.is_none() {
            self.index.insert(c.fingerprint, i);
        }
        Ok(i)
    }

    fn key_of(&self, i: usize) -> [u32; 8] {
        let uv = self.mesh.uvs.get(i).copied().unwrap_or_default();
        bits(self.mesh.positions[i], self.mesh.normals[i], uv)
    }

    pub(crate) fn triangle(&mut self, corners: [u32; 3]) {
        self.mesh.triangles.push(corners);
    }

    /// The face normal the file gives the triangle just added (a `.in` file does; an `.obj`
    /// does not, and its mesh has none).
    pub(crate) fn face_normal(&mut self, normal: Vec3) {
        self.mesh.face_normals.push(normal);
    }

    /// The mesh; without texture coordinates when no corner had one.
    pub(crate) fn finish(self) -> Mesh {
        self.mesh
    }
}

/// A corner as the builder compares corners, made apart from the builder (on any thread): the
/// bits of its eight numbers (-0.0 made 0.0, a missing texture coordinate (0, 0)) and their
/// fingerprint.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Corner {
    key: [u32; 8],
    fingerprint: u64,
    textured: bool,
}

impl Corner {
    pub(crate) fn new(position: Vec3, normal: Vec3, uv: Option<Vec2>) -> Self {
        let key = bits(position + 0.0, normal + 0.0, uv.unwrap_or_default() + 0.0);
        Self {
            key,
            fingerprint: fingerprint(&key),
            textured: uv.is_some(),
        }
    }
}

/// A 64-bit fingerprint of a corner's (or any key's) bits.
pub(crate) fn fingerprint(key: &[u32]) -> u64 {
    key.iter().fold(0u64, |h, &w| {
        (h ^ u64::from(w))
            .wrapping_mul(0x9e37_79b9_7f4a_7c15)
            .rotate_left(29)
    })
}

/// A corner as the builder compares corners: the bits of its eight numbers.
fn bits(p: Vec3, n: Vec3, uv: Vec2) -> [u32; 8] {
    [p.x, p.y, p.z, n.x, n.y, n.z, uv.x, uv.y].map(f32::to_bits)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn identical_corners_share_an_index_and_different_normals_do_not() {
        let mut b = MeshBuilder::new("t".into());
        let a = b.corner(&Corner::new(Vec3::ZERO, Vec3::Z, None)).unwrap();
        let again = b
            .corner(&Corner::new(Vec3::new(-0.0, 0.0, 0.0), Vec3::Z, None))
            .unwrap();
        let other_normal = b.corner(&Corner::new(Vec3::ZERO, Vec3::X, None)).unwrap();
        assert_eq!(a, again);
        assert_ne!(a, other_normal);
        let mesh = b.finish();
        assert_eq!(mesh.positions.len(), 2);
        assert!(mesh.uvs.is_empty(), "no corner had a texture coordinate");
    }

    #[test]
    fn different_texture_coordinates_make_different_vertices() {
        let mut b = MeshBuilder::new("t".into());
        let a = b
            .corner(&Corner::new(Vec3::ZERO, Vec3::Z, Some(Vec2::ZERO)))
            .unwrap();
        let seam = b
            .corner(&Corner::new(Vec3::ZERO, Vec3::Z, Some(Vec2::X)))
            .unwrap();
        assert_ne!(a, seam);
        assert_eq!(b.finish().uvs, vec![Vec2::ZERO, Vec2::X]);
    }
}

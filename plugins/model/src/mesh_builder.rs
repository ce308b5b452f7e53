use std::collections::HashMap;

use close2gl_core::Mesh;
use glam::{Vec2, Vec3};

/// Builds an indexed mesh from triangle corners, giving identical (position, normal, texture
/// coordinate) corners one index so that a shared corner is transformed once per frame, not once
/// per triangle.
pub(crate) struct MeshBuilder {
    mesh: Mesh,
    /// A 64-bit fingerprint of each corner's bits → its index. Fingerprints rather than the 32
    /// bytes themselves halve the map, the largest thing a big load holds besides the mesh; a
    /// hit is confirmed against the mesh, and a corner whose fingerprint is taken by another
    /// simply is not shared.
    index: HashMap<u64, u32>,
    /// Whether any corner had a texture coordinate (the others get (0, 0)).
    textured: bool,
}

impl MeshBuilder {
    pub(crate) fn new(name: String) -> Self {
        Self {
            mesh: Mesh {
                name,
                ..Mesh::default()
            },
            index: HashMap::new(),
            textured: false,
        }
    }

    /// The index of the vertex (`position`, `normal`, `uv`), added if it is new. Exact f32 bits
    /// are compared, except that -0.0 and 0.0 are the same corner.
    pub(crate) fn vertex(
        &mut self,
        position: Vec3,
        normal: Vec3,
        uv: Option<Vec2>,
    ) -> Result<u32, String> {
        self.textured |= uv.is_some();
        let (position, normal, uv) = (position + 0.0, normal + 0.0, uv.unwrap_or_default() + 0.0);
        let key = bits(position, normal, uv);
        let fingerprint = key.iter().fold(0u64, |h, &w| {
            (h ^ u64::from(w))
                .wrapping_mul(0x9e37_79b9_7f4a_7c15)
                .rotate_left(29)
        });
        if let Some(&i) = self.index.get(&fingerprint)
            && self.key_of(i as usize) == key
        {
            return Ok(i);
        }
        let i = u32::try_from(self.mesh.positions.len())
            .map_err(|_| "more vertices than 32-bit indices can address".to_string())?;
        self.mesh.positions.push(position);
        self.mesh.normals.push(normal);
        self.mesh.uvs.push(uv);
        self.index.entry(fingerprint).or_insert(i);
        Ok(i)
    }

    fn key_of(&self, i: usize) -> [u32; 8] {
        bits(
            self.mesh.positions[i],
            self.mesh.normals[i],
            self.mesh.uvs[i],
        )
    }

    pub(crate) fn triangle(&mut self, corners: [u32; 3]) {
        self.mesh.triangles.push(corners);
    }

    /// The mesh; without texture coordinates when no corner had one.
    pub(crate) fn finish(mut self) -> Mesh {
        if !self.textured {
            self.mesh.uvs.clear();
        }
        self.mesh
    }
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
        let a = b.vertex(Vec3::ZERO, Vec3::Z, None).unwrap();
        let again = b.vertex(Vec3::new(-0.0, 0.0, 0.0), Vec3::Z, None).unwrap();
        let other_normal = b.vertex(Vec3::ZERO, Vec3::X, None).unwrap();
        assert_eq!(a, again);
        assert_ne!(a, other_normal);
        let mesh = b.finish();
        assert_eq!(mesh.positions.len(), 2);
        assert!(mesh.uvs.is_empty(), "no corner had a texture coordinate");
    }

    #[test]
    fn different_texture_coordinates_make_different_vertices() {
        let mut b = MeshBuilder::new("t".into());
        let a = b.vertex(Vec3::ZERO, Vec3::Z, Some(Vec2::ZERO)).unwrap();
        let seam = b.vertex(Vec3::ZERO, Vec3::Z, Some(Vec2::X)).unwrap();
        assert_ne!(a, seam);
        assert_eq!(b.finish().uvs, vec![Vec2::ZERO, Vec2::X]);
    }
}

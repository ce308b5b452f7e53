use std::collections::HashMap;

use close2gl_core::Mesh;
use glam::{Vec2, Vec3};

/// Builds an indexed mesh from triangle corners, giving identical (position, normal, texture
/// coordinate) corners one index so that a shared corner is transformed once per frame, not once
/// per triangle.
pub(crate) struct MeshBuilder {
    mesh: Mesh,
    index: HashMap<[u32; 8], u32>,
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
        let key = [
            position.x.to_bits(),
            position.y.to_bits(),
            position.z.to_bits(),
            normal.x.to_bits(),
            normal.y.to_bits(),
            normal.z.to_bits(),
            uv.x.to_bits(),
            uv.y.to_bits(),
        ];
        if let Some(&i) = self.index.get(&key) {
            return Ok(i);
        }
        let i = u32::try_from(self.mesh.positions.len())
            .map_err(|_| "more vertices than 32-bit indices can address".to_string())?;
        self.mesh.positions.push(position);
        self.mesh.normals.push(normal);
        self.mesh.uvs.push(uv);
        self.index.insert(key, i);
        Ok(i)
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

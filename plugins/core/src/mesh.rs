//! The model as Close2GL and the reference both read it: an indexed triangle mesh.

use bevy_ecs::prelude::*;
use glam::{Vec2, Vec3};

/// An indexed triangle mesh in world coordinates (the file's own coordinates: framing moves the
/// camera, never the model). `normals[i]` and `uvs[i]` belong to `positions[i]`; each triangle
/// lists three vertex indices in the file's winding.
#[derive(Component, Clone, Debug, Default, PartialEq)]
pub struct Mesh {
    pub name: String,
    pub positions: Vec<Vec3>,
    pub normals: Vec<Vec3>,
    /// Texture coordinates (s, t), one per position, or none for a model without them. t grows
    /// upwards in the image, as in OpenGL: (0, 0) is the image's bottom-left corner.
    pub uvs: Vec<Vec2>,
    pub triangles: Vec<[u32; 3]>,
    /// The file's face normal of each triangle, as written (a `.in` file gives them), or none.
    /// Only the mistake `culling_by_file_normals` reads them: the pipeline culls by winding.
    pub face_normals: Vec<Vec3>,
}

impl Mesh {
    /// Checks the invariants every consumer relies on: at least one triangle, indices in range,
    /// one normal (and none or one texture coordinate) per position, every number finite.
    pub fn validate(&self) -> Result<(), String> {
        if self.triangles.is_empty() {
            return Err("the mesh has no triangles".into());
        }
        if self.normals.len() != self.positions.len() {
            return Err(format!(
                "{} normals for {} positions",
                self.normals.len(),
                self.positions.len()
            ));
        }
        if let Some(p) = self.positions.iter().position(|p| !p.is_finite()) {
            return Err(format!("vertex {p} is not finite"));
        }
        if let Some(p) = self.normals.iter().position(|n| !n.is_finite()) {
            return Err(format!("normal {p} is not finite"));
        }
        if !self.uvs.is_empty() && self.uvs.len() != self.positions.len() {
            return Err(format!(
                "{} texture coordinates for {} positions",
                self.uvs.len(),
                self.positions.len()
            ));
        }
        if !self.face_normals.is_empty() && self.face_normals.len() != self.triangles.len() {
            return Err(format!(
                "{} face normals for {} triangles",
                self.face_normals.len(),
                self.triangles.len()
            ));
        }
        if let Some(p) = self.uvs.iter().position(|uv| !uv.is_finite()) {
            return Err(format!("texture coordinate {p} is not finite"));
        }
        let count = self.positions.len() as u32;
        if let Some(t) = self
            .triangles
            .iter()
            .position(|t| t.iter().any(|&i| i >= count))
        {
            return Err(format!("triangle {t} indexes a vertex that does not exist"));
        }
        Ok(())
    }

    /// Axis-aligned bounds `(min, max)` of the vertices the triangles use.
    pub fn bounds(&self) -> (Vec3, Vec3) {
        self.triangles
            .iter()
            .flatten()
            .map(|&i| self.positions[i as usize])
            .fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p), hi.max(p))
            })
    }

    /// Centre and radius of the sphere around the bounding box.
    pub fn bounding_sphere(&self) -> (Vec3, f32) {
        let (lo, hi) = self.bounds();
        ((lo + hi) * 0.5, (hi - lo).length() * 0.5)
    }
}

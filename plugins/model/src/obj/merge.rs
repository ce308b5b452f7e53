//! The mesh tobj's objects make: all merged, in file order, through the mesh builder (one vertex
//! per distinct position, normal and texture coordinate bits). A corner's normal is the file's,
//! normalised, else the smooth one at its position; tobj gives an object normals (and texture
//! coordinates) only when every one of its corners names one, so an object with a corner
//! without is smooth (and untextured) throughout. Normals are used as the file points them: an
//! OBJ face has no normal of its own to flip them against (a `.in` file's has).

use std::collections::HashMap;

use close2gl_core::Mesh;
use glam::{Vec2, Vec3};

use crate::mesh_builder::{Corner, MeshBuilder};

/// One tobj object's corners by its (single) index.
struct Object<'m> {
    mesh: &'m tobj::Mesh,
    normals: bool,
    uvs: bool,
}

impl<'m> Object<'m> {
    fn new(mesh: &'m tobj::Mesh) -> Self {
        let vertices = mesh.positions.len() / 3;
        Self {
            mesh,
            normals: mesh.normals.len() / 3 == vertices,
            uvs: mesh.texcoords.len() / 2 == vertices,
        }
    }

    fn vertices(&self) -> usize {
        self.mesh.positions.len() / 3
    }

    fn triangles(&self) -> impl Iterator<Item = [u32; 3]> + '_ {
        let indices = self.mesh.indices.chunks_exact(3);
        indices.map(|t| [t[0], t[1], t[2]])
    }

    fn position(&self, i: u32) -> Vec3 {
        Vec3::from_slice(&self.mesh.positions[3 * i as usize..])
    }

    /// The file's normal, normalised, if the object has normals and this one has a direction.
    fn normal(&self, i: u32) -> Option<Vec3> {
        let normal = || Vec3::from_slice(&self.mesh.normals[3 * i as usize..]);
        self.normals.then(normal)?.try_normalize()
    }

    fn uv(&self, i: u32) -> Option<Vec2> {
        let uv = || Vec2::from_slice(&self.mesh.texcoords[2 * i as usize..]);
        self.uvs.then(uv)
    }
}

/// The mesh, named `name`; the error is the message without the file.
pub(super) fn build(models: &[tobj::Model], name: String) -> Result<Mesh, String> {
    let objects: Vec<Object> = models.iter().map(|m| Object::new(&m.mesh)).collect();
    let triangles = objects.iter().map(|o| o.mesh.indices.len() / 3).sum();
    if triangles == 0 {
        return Err("no triangles (faces need at least 3 vertices)".into());
    }
    let smooth = smooth_normals(&objects);
    let mut builder = MeshBuilder::with_capacity(name, triangles);
    for object in &objects {
        // tobj made a vertex of each distinct `v/vt/vn` of the object, and each makes one
        // corner: the mesh builder is asked once per vertex, not once per triangle corner.
        let mut mesh_index: Vec<Option<u32>> = vec![None; object.vertices()];
        for triangle in object.triangles() {
            let mut corners = [0; 3];
            for (corner, i) in corners.iter_mut().zip(triangle) {
                *corner = match mesh_index[i as usize] {
                    Some(index) => index,
                    None => {
                        let position = object.position(i);
                        let normal = object
                            .normal(i)
                            .or_else(|| smooth.get(&key(position)).copied())
                            .unwrap_or(Vec3::Z);
                        let uv = object.uv(i);
                        let index = builder.corner(&Corner::new(position, normal, uv))?;
                        *mesh_index[i as usize].insert(index)
                    }
                };
            }
            builder.triangle(corners);
        }
    }
    Ok(builder.finish())
}

/// A position's bits, -0.0 and 0.0 alike, as the mesh builder compares vertices.
fn key(p: Vec3) -> [u32; 3] {
    (p + 0.0).to_array().map(f32::to_bits)
}

/// Area-weighted normals per position, if some corner has no usable normal of its own: the
/// unnormalised cross product of each triangle is its normal times twice its area, so big faces
/// weigh more. Summed per position, over all the tobj vertices there, so that neither a texture
/// seam nor a position written twice creases the shading. Where the faces cancel out or have no
/// area, +z.
fn smooth_normals(objects: &[Object]) -> HashMap<[u32; 3], Vec3> {
    let mut sums: HashMap<[u32; 3], Vec3> = HashMap::new();
    let lacking = |o: &Object| o.triangles().flatten().any(|i| o.normal(i).is_none());
    if !objects.iter().any(lacking) {
        return sums;
    }
    for object in objects {
        // Per tobj vertex first: a position is hashed once per vertex, not once per corner.
        let mut at_vertex = vec![Vec3::ZERO; object.vertices()];
        for triangle in object.triangles() {
            let [a, b, c] = triangle.map(|i| object.position(i));
            let weighted = (b - a).cross(c - a);
            for i in triangle {
                at_vertex[i as usize] += weighted;
            }
        }
        for (i, sum) in at_vertex.into_iter().enumerate() {
            *sums.entry(key(object.position(i as u32))).or_default() += sum;
        }
    }
    for sum in sums.values_mut() {
        *sum = sum.try_normalize().unwrap_or(Vec3::Z);
    }
    sums
}

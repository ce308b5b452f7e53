//! The mesh an OBJ file's [`Geometry`] makes: its vertices numbered (see `numbering`), then
//! filled in one array at a time, each of the file's arrays dropped once used, so that memory
//! stays near the mesh's own. What it holds is what the mesh builder makes of the same corners:
//! -0.0 made 0.0, a missing texture coordinate (0, 0), none at all when no corner has one.

use close2gl_core::Mesh;
use glam::{Vec2, Vec3};

use super::faces::{Geometry, Vertices};
use super::normals::Smooth;
use super::numbering::{self, TOO_MANY};
use super::parse::MAX_INDEX;
use super::positions::canonical;

/// The mesh, named `name`; the error is the message without the file.
pub(super) fn build(geometry: Geometry, name: String) -> Result<Mesh, String> {
    let Geometry {
        positions,
        texcoords,
        normals,
        mut triangles,
        vertices,
    } = geometry;
    if triangles.is_empty() {
        return Err("no triangles (faces need at least 3 vertices)".into());
    }
    if positions.len() > MAX_INDEX as usize {
        return Err(TOO_MANY.into());
    }
    let canonical = canonical(&positions);
    let smooth = needs_smooth(&vertices, &normals).then(|| {
        let triangles = triangles.iter();
        let corners = triangles.map(|t| t.map(|id| vertices.corner(id)[0]));
        Smooth::new(&positions, &canonical, corners)
    });
    let normal = |id| normal(&vertices, &normals, smooth.as_ref(), id) + 0.0;
    let uv = |id| uv(&vertices, &texcoords, id) + 0.0;
    let key = |id| {
        let (n, uv) = (normal(id), uv(id));
        [n.x, n.y, n.z, uv.x, uv.y].map(f32::to_bits)
    };
    let numbering = numbering::number(&mut triangles, &vertices, &canonical, key)?;
    drop(canonical);
    let ids = numbering.ids;
    let mut mesh = Mesh {
        name,
        triangles,
        ..Mesh::default()
    };
    mesh.positions = ids
        .iter()
        .map(|&id| positions[vertices.corner(id)[0] as usize] + 0.0)
        .collect();
    drop(positions);
    if numbering.textured {
        mesh.uvs = ids.iter().map(|&id| uv(id)).collect();
    }
    drop(texcoords);
    mesh.normals = ids.iter().map(|&id| normal(id)).collect();
    Ok(mesh)
}

/// Whether some vertex has no file normal to use.
fn needs_smooth(vertices: &Vertices, normals: &[Vec3]) -> bool {
    vertices.positions_only()
        || vertices
            .named_normals()
            .any(|vn| file_normal(normals, vn).is_none())
}

/// The file's normal `vn`, normalised, if it has one with a direction.
fn file_normal(normals: &[Vec3], vn: u32) -> Option<Vec3> {
    normals.get(vn as usize)?.try_normalize()
}

/// The normal of vertex `id`: the file's, else the smooth one.
fn normal(vertices: &Vertices, normals: &[Vec3], smooth: Option<&Smooth>, id: u32) -> Vec3 {
    let [v, _, vn] = vertices.corner(id);
    file_normal(normals, vn)
        .or_else(|| smooth.map(|s| s.at(v)))
        .unwrap_or(Vec3::Z)
}

/// The texture coordinate of vertex `id`, (0, 0) if it has none.
fn uv(vertices: &Vertices, texcoords: &[Vec2], id: u32) -> Vec2 {
    let [_, vt, _] = vertices.corner(id);
    texcoords.get(vt as usize).copied().unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use std::collections::HashMap;

    use proptest::prelude::*;

    use super::*;
    use crate::mesh_builder::{Corner, MeshBuilder};
    use crate::obj::parse::NONE;

    /// The mesh as the loader made it before: every corner handed to the mesh builder, smooth
    /// normals in a map keyed by position bits.
    fn one_corner_at_a_time(g: &Geometry) -> Mesh {
        let key = |p: Vec3| (p + 0.0).to_array().map(f32::to_bits);
        let corners = |t: &[u32; 3]| t.map(|id| g.vertices.corner(id));
        let mut sums: HashMap<[u32; 3], Vec3> = HashMap::new();
        for t in &g.triangles {
            let [a, b, c] = corners(t).map(|[v, ..]| g.positions[v as usize]);
            for p in [a, b, c] {
                *sums.entry(key(p)).or_default() += (b - a).cross(c - a);
            }
        }
        let mut builder = MeshBuilder::new("m".into());
        for t in &g.triangles {
            let mut triangle = [0; 3];
            for (k, [v, vt, vn]) in corners(t).into_iter().enumerate() {
                let p = g.positions[v as usize];
                let normal = file_normal(&g.normals, vn)
                    .or_else(|| sums[&key(p)].try_normalize())
                    .unwrap_or(Vec3::Z);
                let uv = g.texcoords.get(vt as usize).copied();
                triangle[k] = builder.corner(&Corner::new(p, normal, uv)).unwrap();
            }
            builder.triangle(triangle);
        }
        builder.finish()
    }

    /// Few distinct numbers, so that positions, normals and texture coordinates repeat.
    fn number() -> impl Strategy<Value = f32> {
        prop::sample::select(vec![0.0, -0.0, 1.0, -1.0, 0.5])
    }

    fn geometry() -> impl Strategy<Value = Geometry> {
        let vec3 = || (number(), number(), number()).prop_map(|(x, y, z)| Vec3::new(x, y, z));
        let positions = prop::collection::vec(vec3(), 1..12);
        let texcoords = prop::collection::vec((number(), number()), 0..4);
        let normals = prop::collection::vec(vec3(), 0..4);
        let picks = prop::collection::vec(prop::collection::vec(any::<[u16; 3]>(), 3..5), 1..20);
        (positions, texcoords, normals, picks).prop_map(|(positions, texcoords, normals, faces)| {
            let mut g = Geometry {
                texcoords: texcoords.into_iter().map(Vec2::from).collect(),
                positions,
                normals,
                ..Geometry::default()
            };
            let pick = |n: u16, count: usize| match count {
                0 => NONE,
                // One pick in four names none.
                _ if n.is_multiple_of(4) => NONE,
                _ => u32::from(n) % count as u32,
            };
            for face in faces {
                let corners: Vec<[u32; 3]> = face
                    .iter()
                    .map(|&[v, vt, vn]| {
                        let v = u32::from(v) % g.positions.len() as u32;
                        [v, pick(vt, g.texcoords.len()), pick(vn, g.normals.len())]
                    })
                    .collect();
                g.face(&corners);
            }
            g
        })
    }

    proptest! {
        #[test]
        fn the_mesh_is_the_one_the_mesh_builder_makes_corner_by_corner(g in geometry()) {
            let before = format!("{:?}", one_corner_at_a_time(&g));
            let mesh = build(g, "m".into()).unwrap();
            prop_assert_eq!(format!("{mesh:?}"), before);
        }
    }
}

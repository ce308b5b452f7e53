//! Meshes built by hand, with exact normals, counter-clockwise seen from outside.

use std::f32::consts::PI;

use close2gl_core::Mesh;
use close2gl_core::glam::Vec3;

/// A closed 2-unit cube centred on the origin.
pub fn cube() -> Mesh {
    let positions: Vec<Vec3> = (0..8)
        .map(|i| {
            Vec3::new(
                [-1.0, 1.0][i & 1],
                [-1.0, 1.0][(i >> 1) & 1],
                [-1.0, 1.0][i >> 2],
            )
        })
        .collect();
    let quads = [
        [0, 2, 3, 1],
        [4, 5, 7, 6],
        [0, 1, 5, 4],
        [2, 6, 7, 3],
        [0, 4, 6, 2],
        [1, 3, 7, 5],
    ];
    let triangles = quads
        .iter()
        .flat_map(|[a, b, c, d]| [[*a, *b, *c], [*a, *c, *d]])
        .collect();
    Mesh {
        face_normals: Vec::new(),
        name: "cube".into(),
        normals: positions.clone(),
        positions,
        uvs: Vec::new(),
        triangles,
    }
}

/// A UV sphere: `stacks` from pole to pole, `slices` around, the seam's and the poles' vertices
/// repeated (so the poles' triangles have no area, as in the model crate's sphere).
pub fn sphere(center: Vec3, radius: f32, stacks: u32, slices: u32) -> Mesh {
    let mut mesh = Mesh {
        name: "sphere".into(),
        ..Default::default()
    };
    for i in 0..=stacks {
        let theta = PI * i as f32 / stacks as f32;
        for j in 0..=slices {
            let phi = 2.0 * PI * j as f32 / slices as f32;
            let n = Vec3::new(
                theta.sin() * phi.cos(),
                theta.cos(),
                -theta.sin() * phi.sin(),
            );
            mesh.positions.push(center + radius * n);
            mesh.normals.push(n);
        }
    }
    let row = slices + 1;
    for i in 0..stacks {
        for j in 0..slices {
            let (a, b) = (i * row + j, (i + 1) * row + j);
            mesh.triangles.push([a, b, b + 1]);
            mesh.triangles.push([a, b + 1, a + 1]);
        }
    }
    mesh
}

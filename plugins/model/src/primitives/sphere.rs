use close2gl_core::Mesh;
use glam::Vec3;

use super::{angle, around_y, quad, vertex};

/// The lecture's sphere: `stacks` bands from pole to pole (subh), `slices` around (suba),
/// normals p/r. Poles are single vertices, so the degenerate triangles the slides skip at
/// i = 0 and i = subh never exist.
pub(super) fn sphere(radius: f32, stacks: u32, slices: u32) -> Mesh {
    let mut mesh = Mesh::default();
    let top = vertex(&mut mesh, Vec3::Y * radius, Vec3::Y);
    // Rings 1..stacks, from the top down: polar angle φ = π·ring/stacks.
    let first = top + 1;
    for ring in 1..stacks {
        let phi = std::f32::consts::PI * ring as f32 / stacks as f32;
        for i in 0..slices {
            let n = around_y(angle(i, slices)) * phi.sin() + Vec3::Y * phi.cos();
            vertex(&mut mesh, n * radius, n);
        }
    }
    let bottom = vertex(&mut mesh, Vec3::NEG_Y * radius, Vec3::NEG_Y);
    let at = |ring: u32, i: u32| first + (ring - 1) * slices + i % slices;
    // Southwards × eastwards points outwards, so (north-west, south-west, south-east, north-east)
    // goes CCW seen from outside.
    for i in 0..slices {
        mesh.triangles.push([top, at(1, i), at(1, i + 1)]);
        mesh.triangles
            .push([at(stacks - 1, i), bottom, at(stacks - 1, i + 1)]);
    }
    for ring in 1..stacks - 1 {
        for i in 0..slices {
            quad(
                &mut mesh,
                [
                    at(ring, i),
                    at(ring + 1, i),
                    at(ring + 1, i + 1),
                    at(ring, i + 1),
                ],
            );
        }
    }
    mesh
}

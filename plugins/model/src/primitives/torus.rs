use close2gl_core::Mesh;
use glam::Vec3;

use super::{angle, around_y, quad, vertex};

/// The lecture's torus around y: `n0` segments around the ring (θ), `n1` around the tube (φ),
/// normals N = (Δx, y, Δz) / r1 as on the slide. `r0` is measured from the centre to the
/// tube's centre (close2gl's config convention; the slide puts the tube's centre at r0 + r1).
pub(super) fn torus(r0: f32, r1: f32, n0: u32, n1: u32) -> Mesh {
    let mut mesh = Mesh::default();
    for i in 0..n0 {
        let out = around_y(angle(i, n0));
        for j in 0..n1 {
            let phi = angle(j, n1);
            let normal = out * phi.cos() + Vec3::Y * phi.sin();
            vertex(&mut mesh, out * r0 + normal * r1, normal);
        }
    }
    let at = |i: u32, j: u32| (i % n0) * n1 + j % n1;
    // Along the ring × up the tube points outwards, so (i, j), (i+1, j), (i+1, j+1), (i, j+1)
    // goes CCW seen from outside.
    for i in 0..n0 {
        for j in 0..n1 {
            quad(
                &mut mesh,
                [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)],
            );
        }
    }
    mesh
}

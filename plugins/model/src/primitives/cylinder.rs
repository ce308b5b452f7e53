use close2gl_core::Mesh;
use glam::Vec3;

use super::{angle, around_y, disc, quad, vertex};

/// The lecture's cylinder around y from -height/2 to +height/2: radial side normals, caps
/// facing ±y with their own vertices.
pub(super) fn cylinder(radius: f32, height: f32, slices: u32) -> Mesh {
    let mut mesh = Mesh::default();
    let half = Vec3::Y * (height / 2.0);
    for i in 0..slices {
        let out = around_y(angle(i, slices));
        vertex(&mut mesh, out * radius - half, out);
        vertex(&mut mesh, out * radius + half, out);
    }
    // Bottom and top of each slice are neighbours: 2i and 2i + 1.
    let bottom = |i: u32| 2 * (i % slices);
    // Eastwards × up points outwards.
    for i in 0..slices {
        quad(
            &mut mesh,
            [bottom(i), bottom(i + 1), bottom(i + 1) + 1, bottom(i) + 1],
        );
    }
    disc(&mut mesh, radius, height / 2.0, true, slices);
    disc(&mut mesh, radius, -height / 2.0, false, slices);
    mesh
}

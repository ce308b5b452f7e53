use close2gl_core::Mesh;
use glam::Vec3;

use super::{angle, around_y, disc, vertex};

/// The lecture's cone around y, base at -height/2, apex at +height/2, with a bottom cap. The
/// side normals are the cone's exact ones, tilted up by the slope: (h·sinθ, r, h·cosθ)/√(h²+r²).
/// The apex has no normal of its own ("why? any better way?"): each side triangle gets its own
/// apex vertex with the normal at the middle of its slice, so the shading does not fold there.
pub(super) fn cone(radius: f32, height: f32, slices: u32) -> Mesh {
    let mut mesh = Mesh::default();
    let slope = |theta: f32| (around_y(theta) * height + Vec3::Y * radius).normalize();
    let base_y = -height / 2.0;
    // The base ring is vertices 0..slices.
    for i in 0..slices {
        let theta = angle(i, slices);
        let p = around_y(theta) * radius + Vec3::Y * base_y;
        vertex(&mut mesh, p, slope(theta));
    }
    let apex = Vec3::Y * (height / 2.0);
    for i in 0..slices {
        let middle = (angle(i, slices) + angle(i + 1, slices)) / 2.0;
        let top = vertex(&mut mesh, apex, slope(middle));
        // Eastwards × up the slope points outwards.
        mesh.triangles.push([i, (i + 1) % slices, top]);
    }
    disc(&mut mesh, radius, base_y, false, slices);
    mesh
}

use close2gl_core::Mesh;
use glam::{Vec2, Vec3};

use super::{quad, vertex};

/// The lecture's box: edges `size` along x, y, z, centred on the origin, 12 triangles, each side
/// with its own four vertices so the normals are the sides' normals, and the whole texture on
/// every side (s along the side's u, t along its v).
pub(super) fn cuboid(size: Vec3) -> Mesh {
    // (normal, u, v) with u × v = normal, so corners listed −u−v, +u−v, +u+v, −u+v go CCW
    // seen from outside.
    const SIDES: [(Vec3, Vec3, Vec3); 6] = [
        (Vec3::X, Vec3::Y, Vec3::Z),
        (Vec3::NEG_X, Vec3::Z, Vec3::Y),
        (Vec3::Y, Vec3::Z, Vec3::X),
        (Vec3::NEG_Y, Vec3::X, Vec3::Z),
        (Vec3::Z, Vec3::X, Vec3::Y),
        (Vec3::NEG_Z, Vec3::Y, Vec3::X),
    ];
    let mut mesh = Mesh::default();
    for (normal, u, v) in SIDES {
        let corners = [(-0.5, -0.5), (0.5, -0.5), (0.5, 0.5), (-0.5, 0.5)].map(|(su, sv)| {
            mesh.uvs.push(Vec2::new(su + 0.5, sv + 0.5));
            vertex(&mut mesh, (normal * 0.5 + u * su + v * sv) * size, normal)
        });
        quad(&mut mesh, corners);
    }
    mesh
}

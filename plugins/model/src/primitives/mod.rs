//! The procedural primitives of the shading lecture (002) with exact normals: box, sphere,
//! torus, cone, cylinder. Each is closed and wound counter-clockwise seen from outside (front
//! faces CCW). y is up; angles θ go around y with x = r·sinθ, z = r·cosθ, as on the slides.

mod cone;
mod cuboid;
mod cylinder;
mod sphere;
mod torus;

use close2gl_core::limits::MAX_SEGMENTS;
use close2gl_core::{Mesh, PrimitiveKind, PrimitiveParams};
use glam::Vec3;

/// Builds `kind` from `params`. Parameters out of range (the config rejects them too) are an
/// error naming the config key, never a panic or a runaway allocation.
pub fn primitive(kind: PrimitiveKind, p: &PrimitiveParams) -> Result<Mesh, String> {
    let mut mesh = match kind {
        PrimitiveKind::Box => cuboid::cuboid(Vec3::new(
            size("box_size[0]", p.box_size.x)?,
            size("box_size[1]", p.box_size.y)?,
            size("box_size[2]", p.box_size.z)?,
        )),
        PrimitiveKind::Sphere => sphere::sphere(
            size("sphere_radius", p.sphere_radius)?,
            segments("sphere_stacks", p.sphere_stacks, 2)?,
            segments("sphere_slices", p.sphere_slices, 3)?,
        ),
        PrimitiveKind::Torus => torus::torus(
            size("torus_r0", p.torus_r0)?,
            size("torus_r1", p.torus_r1)?,
            segments("torus_n0", p.torus_n0, 3)?,
            segments("torus_n1", p.torus_n1, 3)?,
        ),
        PrimitiveKind::Cone => cone::cone(
            size("cone_radius", p.cone_radius)?,
            size("cone_height", p.cone_height)?,
            segments("cone_slices", p.cone_slices, 3)?,
        ),
        PrimitiveKind::Cylinder => cylinder::cylinder(
            size("cylinder_radius", p.cylinder_radius)?,
            size("cylinder_height", p.cylinder_height)?,
            segments("cylinder_slices", p.cylinder_slices, 3)?,
        ),
    };
    mesh.name = kind.name().to_string();
    Ok(mesh)
}

fn size(key: &str, value: f32) -> Result<f32, String> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(format!(
            "primitives.{key}: expected a finite number > 0, found {value}"
        ))
    }
}

fn segments(key: &str, value: u32, minimum: u32) -> Result<u32, String> {
    if (minimum..=MAX_SEGMENTS).contains(&value) {
        Ok(value)
    } else {
        Err(format!(
            "primitives.{key}: expected {minimum}..={MAX_SEGMENTS}, found {value}"
        ))
    }
}

/// Adds a vertex and returns its index (segment counts are capped, so it fits in u32).
fn vertex(mesh: &mut Mesh, position: Vec3, normal: Vec3) -> u32 {
    mesh.positions.push(position);
    mesh.normals.push(normal);
    (mesh.positions.len() - 1) as u32
}

/// Adds the quad a, b, c, d (in that order around it) as two triangles with the same winding.
fn quad(mesh: &mut Mesh, [a, b, c, d]: [u32; 4]) {
    mesh.triangles.push([a, b, c]);
    mesh.triangles.push([a, c, d]);
}

/// The unit direction at angle `theta` around y, on the slides' convention.
fn around_y(theta: f32) -> Vec3 {
    Vec3::new(theta.sin(), 0.0, theta.cos())
}

/// θ_i = 2π·i/n.
fn angle(i: u32, n: u32) -> f32 {
    std::f32::consts::TAU * i as f32 / n as f32
}

/// A flat disc of `radius` at height `y` facing +y (`up`) or -y, wound CCW seen from the side
/// it faces: the caps of the cone and the cylinder.
fn disc(mesh: &mut Mesh, radius: f32, y: f32, up: bool, slices: u32) {
    let normal = if up { Vec3::Y } else { Vec3::NEG_Y };
    let centre = vertex(mesh, Vec3::new(0.0, y, 0.0), normal);
    let first = centre + 1;
    for i in 0..slices {
        let p = around_y(angle(i, slices)) * radius + Vec3::new(0.0, y, 0.0);
        vertex(mesh, p, normal);
    }
    for i in 0..slices {
        let (a, b) = (first + i, first + (i + 1) % slices);
        // θ turns from +z towards +x: counter-clockwise seen from above.
        mesh.triangles
            .push(if up { [centre, a, b] } else { [centre, b, a] });
    }
}

#[cfg(test)]
mod tests;

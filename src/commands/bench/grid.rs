//! The big-model scene: a flat grid of about a million triangles, generated (no file ships), each
//! smaller than a pixel once framed at 1920×1080: what a scanned or subdivided model gives the
//! rasterizer, one triangle after another with nothing to hide the per-triangle costs.

use close2gl_core::{App, Mesh};
use glam::Vec3;

/// The grid nearest `triangles` (rounded up to whole rows): 2 · side² triangles over the unit
/// squares of [0, side]², corners shared, counter-clockwise seen from +z, as a course file lists
/// them.
pub fn grid(triangles: usize) -> Mesh {
    let side = ((triangles as f64 / 2.0).sqrt().ceil() as u32).max(1);
    let mut mesh = Mesh {
        name: format!("grid of {} triangles", 2 * side as usize * side as usize),
        ..Mesh::default()
    };
    for y in 0..=side {
        for x in 0..=side {
            mesh.positions.push(Vec3::new(x as f32, y as f32, 0.0));
            mesh.normals.push(Vec3::Z);
        }
    }
    let index = |x: u32, y: u32| y * (side + 1) + x;
    for y in 0..side {
        for x in 0..side {
            let (a, b, c, d) = (
                index(x, y),
                index(x + 1, y),
                index(x + 1, y + 1),
                index(x, y + 1),
            );
            mesh.triangles.push([a, b, c]);
            mesh.triangles.push([a, c, d]);
        }
    }
    mesh
}

/// Puts `mesh` in place of the app's model, framed as a model the user opens is framed.
pub fn replace_model(app: &mut App, mesh: Mesh) -> Result<(), String> {
    let world = app.world_mut();
    let mut model = world
        .query::<&mut Mesh>()
        .single_mut(world)
        .map_err(|e| format!("the scene has no model to replace: {e}"))?;
    *model = mesh;
    app.update();
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_grid_has_the_asked_size_and_faces_the_viewer() {
        let mesh = grid(1_000_000);
        assert_eq!(mesh.triangles.len(), 1_002_528);
        assert_eq!(mesh.positions.len(), 709 * 709);
        assert!(mesh.validate().is_ok());
        for t in mesh.triangles.iter().step_by(9973) {
            let [a, b, c] = t.map(|i| mesh.positions[i as usize]);
            assert!((b - a).cross(c - a).z > 0.0, "{t:?}");
        }
    }
}

//! The straightforward Close2GL frame that the fast path is measured against: the algorithm of
//! the seed report (000), kept here in the benchmark code only. It copies the mesh into a list of
//! triangles, transforms all three vertices of every triangle, clips into a new list, divides into
//! another, culls into another, and copies the survivors into a float array: every stage
//! allocates, and every shared vertex is transformed once per triangle that uses it.

use close2gl_core::glam::{Vec3, Vec4};
use close2gl_core::{Camera, FrontFace, Mesh, RenderSettings, Viewport};
use close2gl_pipeline::matrices::{projection_modelview, viewport as viewport_matrix};

/// One frame; returns the window positions as a flat `[x0, y0, x1, y1, ...]` array.
pub fn frame(
    mesh: &Mesh,
    camera: &Camera,
    settings: &RenderSettings,
    viewport: Viewport,
) -> Vec<f32> {
    let triangles: Vec<[Vec3; 3]> = mesh
        .triangles
        .iter()
        .map(|t| t.map(|i| mesh.positions[i as usize]))
        .collect();

    let pm = projection_modelview(camera);
    let transformed: Vec<[Vec4; 3]> = triangles
        .iter()
        .map(|t| t.map(|p| pm * p.extend(1.0)))
        .collect();

    let clipped: Vec<[Vec4; 3]> = transformed
        .into_iter()
        .filter(|t| {
            t.iter()
                .all(|p| p.w > 0.0 && p.x.abs() <= p.w && p.y.abs() <= p.w && p.z.abs() <= p.w)
        })
        .collect();

    let divided: Vec<[Vec3; 3]> = clipped
        .iter()
        .map(|t| t.map(|p| p.truncate() / p.w))
        .collect();

    let culled: Vec<[Vec3; 3]> = divided
        .into_iter()
        .filter(|t| {
            if !settings.backface_culling {
                return true;
            }
            let z = (t[1] - t[0]).cross(t[2] - t[0]).z;
            match settings.front_face {
                FrontFace::Ccw => z > 0.0,
                FrontFace::Cw => z < 0.0,
            }
        })
        .collect();

    let v = viewport_matrix(viewport.width as f32, viewport.height as f32);
    let mut floats = Vec::new();
    for t in &culled {
        for p in t {
            let w = v * p.extend(1.0);
            floats.push(w.x);
            floats.push(w.y);
        }
    }
    floats
}

//! The straightforward Close2GL frame that the fast path is measured against: the algorithm of
//! the seed report (000), kept here in the benchmark code only. It copies the mesh into a list of
//! triangles, transforms all three vertices of every triangle, clips into a new list, divides into
//! another, culls into another, and copies the survivors into a float array: every stage
//! allocates, and every shared vertex is transformed once per triangle that uses it. It clips as
//! the fast path does (full clipping, with the pipeline's own clipper), so that the two are timed
//! on the same work; only the structure differs.

use close2gl_core::glam::{Vec3, Vec4};
use close2gl_core::{Camera, FrontFace, Mesh, PipelineSettings, Viewport};
use close2gl_pipeline::clip::{Polygon, clip_polygon, outcode};
use close2gl_pipeline::matrices::{projection_modelview, viewport as viewport_matrix};

/// One frame; returns the window positions as a flat `[x0, y0, x1, y1, ...]` array.
pub fn frame(
    mesh: &Mesh,
    camera: &Camera,
    settings: &PipelineSettings,
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

    let mut clipped: Vec<[Vec4; 3]> = Vec::new();
    for triangle in transformed {
        clip_into(triangle, &mut clipped);
    }

    let divided: Vec<[Vec3; 3]> = clipped
        .iter()
        .map(|t| t.map(|p| p.truncate() / p.w))
        .collect();

    let culled: Vec<[Vec3; 3]> = divided
        .into_iter()
        .filter(|t| !settings.backface_culling || faces_front(t, settings.front_face))
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

/// The sign of the area in normalised device coordinates (y up).
fn faces_front(t: &[Vec3; 3], front: FrontFace) -> bool {
    let z = (t[1] - t[0]).cross(t[2] - t[0]).z;
    match front {
        FrontFace::Ccw => z > 0.0,
        FrontFace::Cw => z < 0.0,
    }
}

/// Full clipping: a triangle inside the view volume is copied, one outside a plane is dropped,
/// and one across the border is cut by the pipeline's clipper and fanned back into triangles.
fn clip_into(triangle: [Vec4; 3], out: &mut Vec<[Vec4; 3]>) {
    let codes = triangle.map(outcode);
    let outside_any = codes[0] | codes[1] | codes[2];
    if outside_any == 0 {
        out.push(triangle);
        return;
    }
    if codes[0] & codes[1] & codes[2] != 0 {
        return;
    }
    let [a, b, c] = triangle;
    let piece = clip_polygon(&Polygon::triangle(a, b, c), outside_any);
    let corners = piece.vertices();
    for i in 1..corners.len().saturating_sub(1) {
        out.push([corners[0], corners[i], corners[i + 1]]);
    }
}

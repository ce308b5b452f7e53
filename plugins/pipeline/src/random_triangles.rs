//! Random single triangles around a camera at the origin's side, for the tests that hold two
//! paths of the pipeline to the same answer: many straddle the near and side planes.

use close2gl_core::{Camera, Mesh, Viewport};
use glam::Vec3;

/// A xorshift stream in [0, 1).
fn random(mut seed: u64) -> impl FnMut() -> f32 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        (seed >> 40) as f32 / (1u64 << 24) as f32
    }
}

/// `count` one-triangle meshes with corners in a 24-unit cube about the origin, from `seed`.
pub fn triangles(seed: u64, count: usize) -> impl Iterator<Item = Mesh> {
    let mut r = random(seed);
    (0..count).map(move |_| {
        let mut point = || Vec3::new(r() - 0.5, r() - 0.5, r() - 0.5) * 24.0;
        Mesh {
            name: "one".into(),
            positions: vec![point(), point(), point()],
            normals: vec![Vec3::Z; 3],
            uvs: Vec::new(),
            triangles: vec![[0, 1, 2]],
            face_normals: Vec::new(),
        }
    })
}

/// A camera 6 units from the origin looking at it (near 1, far 20), from `eye`'s side.
pub fn camera(eye: Vec3) -> Camera {
    Camera {
        near: 1.0,
        far: 20.0,
        ..Camera::default()
    }
    .looking_at(eye, Vec3::ZERO, Vec3::Y)
    .expect("a valid pose")
}

/// A 320 × 200 view.
pub const VIEWPORT: Viewport = Viewport {
    width: 320,
    height: 200,
};

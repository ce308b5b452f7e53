//! The reference probe on a real adapter: the ID pass names the triangle the GPU drew at a pixel.

use close2gl_core::glam::Vec3;
use close2gl_core::{Camera, Mesh, PipelineSettings, Scene, Viewport};
use close2gl_gpu::{ReferenceHit, probe_reference};
use close2gl_testkit::gpu;

/// Two squares facing the camera (which looks down -z from the origin): triangles 0 and 1 are a
/// big one at z = -10, triangles 2 and 3 a small one at z = -5 in front of its middle, wound
/// clockwise (a back face) when `near_is_back`.
fn two_squares(near_is_back: bool) -> Mesh {
    let square = |z: f32, half: f32| {
        [(-half, -half), (half, -half), (half, half), (-half, half)]
            .map(|(x, y)| Vec3::new(x, y, z))
    };
    let positions: Vec<Vec3> = square(-10.0, 2.0)
        .into_iter()
        .chain(square(-5.0, 0.5))
        .collect();
    let near = if near_is_back {
        [[4, 6, 5], [4, 7, 6]]
    } else {
        [[4, 5, 6], [4, 6, 7]]
    };
    Mesh {
        face_normals: Vec::new(),
        name: "two squares".into(),
        normals: vec![Vec3::Z; positions.len()],
        positions,
        uvs: Vec::new(),
        triangles: [[0, 1, 2], [0, 2, 3]].into_iter().chain(near).collect(),
    }
}

fn probe(mesh: &Mesh, settings: &PipelineSettings, pixel: (u32, u32)) -> Option<ReferenceHit> {
    let scene = Scene {
        mesh,
        camera: &Camera::default(),
        pipeline: settings,
        viewport: Viewport {
            width: 64,
            height: 64,
        },
    };
    probe_reference(&gpu(), scene, pixel).expect("the probe reads back")
}

#[test]
fn the_probe_names_the_triangle_that_won_the_depth_test_and_none_on_the_background() {
    let settings = PipelineSettings::default();
    let mesh = two_squares(false);
    // The middle: the near square covers the far one. Left of the middle only the far one.
    let near = probe(&mesh, &settings, (30, 29)).expect("the near square is drawn there");
    let far = probe(&mesh, &settings, (24, 29)).expect("the far square is drawn there");
    assert!(matches!(near.triangle, 2 | 3), "{near:?}");
    assert!(matches!(far.triangle, 0 | 1), "{far:?}");
    assert!(near.depth < far.depth && near.depth > 0.0 && far.depth < 1.0);
    assert_eq!(probe(&mesh, &settings, (1, 1)), None, "the background");
}

#[test]
fn the_probe_culls_as_the_reference_does_and_refuses_a_pixel_outside_the_viewport() {
    let settings = PipelineSettings {
        backface_culling: true,
        ..Default::default()
    };
    let hit = probe(&two_squares(true), &settings, (30, 29)).expect("the far square");
    assert!(
        matches!(hit.triangle, 0 | 1),
        "the back face is culled: {hit:?}"
    );
    let scene = Scene {
        mesh: &two_squares(false),
        camera: &Camera::default(),
        pipeline: &settings,
        viewport: Viewport {
            width: 64,
            height: 64,
        },
    };
    let error = probe_reference(&gpu(), scene, (64, 3)).unwrap_err();
    assert_eq!(error, "pixel 64,3 is outside the 64x64 viewport");
}

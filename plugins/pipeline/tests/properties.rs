//! Properties of the Close2GL pipeline on random cameras and meshes: full clipping keeps every
//! output finite and inside the viewport, nothing behind the camera is drawn, and the fast path
//! writes exactly the textbook path's 2D buffer.

use close2gl_core::glam::Vec3;
use close2gl_core::{
    Camera, Clipping, Close2glFrame, FateCounts, Fates, FrontFace, Mesh, PipelineSettings,
    RenderMode, Viewport,
};
use close2gl_pipeline::{FastPipeline, textbook};
use proptest::prelude::*;

fn vec3(range: f32) -> impl Strategy<Value = Vec3> {
    (-range..range, -range..range, -range..range).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

/// A triangle soup around the origin, indexed so that corners are shared between triangles.
fn mesh(max_triangles: usize) -> impl Strategy<Value = Mesh> {
    (4usize..64).prop_flat_map(move |vertices| {
        (
            prop::collection::vec(vec3(10.0), vertices),
            prop::collection::vec(
                (0..vertices as u32, 0..vertices as u32, 0..vertices as u32)
                    .prop_map(|(a, b, c)| [a, b, c]),
                1..max_triangles,
            ),
        )
            .prop_map(|(positions, triangles)| Mesh {
                face_normals: Vec::new(),
                name: "random".into(),
                normals: vec![Vec3::Z; positions.len()],
                positions,
                uvs: Vec::new(),
                triangles,
            })
    })
}

fn camera() -> impl Strategy<Value = Camera> {
    (
        vec3(15.0),
        vec3(5.0),
        vec3(1.0),
        5.0f32..170.0,
        5.0f32..170.0,
        0.01f32..2.0,
        2.0f32..100.0,
    )
        .prop_filter_map(
            "degenerate pose",
            |(position, target, up, hfov, vfov, near, far_factor)| {
                Camera {
                    hfov,
                    vfov,
                    near,
                    far: near * far_factor,
                    ..Camera::default()
                }
                .looking_at(position, target, up + Vec3::Y * 0.1)
            },
        )
}

fn settings() -> impl Strategy<Value = PipelineSettings> {
    (0usize..3, any::<bool>(), any::<bool>()).prop_map(|(mode, cw, culling)| PipelineSettings {
        mode: [RenderMode::Points, RenderMode::Wireframe, RenderMode::Solid][mode],
        front_face: if cw { FrontFace::Cw } else { FrontFace::Ccw },
        backface_culling: culling,
        clipping: Clipping::Full,
        ..PipelineSettings::default()
    })
}

fn viewport() -> impl Strategy<Value = Viewport> {
    (1u32..2000, 1u32..2000).prop_map(|(width, height)| Viewport { width, height })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn full_clipping_output_is_finite_and_inside_the_viewport(
        mesh in mesh(60), camera in camera(), settings in settings(), viewport in viewport(),
    ) {
        let frame = textbook::run(&mesh, &camera, &settings, viewport);
        let slack = 1e-3 * viewport.width.max(viewport.height) as f32;
        for [x, y] in &frame.vertices {
            prop_assert!(x.is_finite() && y.is_finite());
            prop_assert!(*x >= -slack && *x <= viewport.width as f32 + slack, "x = {x}");
            prop_assert!(*y >= -slack && *y <= viewport.height as f32 + slack, "y = {y}");
        }
        let c = frame.counts;
        prop_assert_eq!(c.triangles_in, mesh.triangles.len());
        prop_assert_eq!(c.clipped + c.culled + c.drawn, c.triangles_in);
    }

    #[test]
    fn nothing_behind_the_camera_is_drawn(
        mesh in mesh(60), camera in camera(), settings in settings(), viewport in viewport(),
    ) {
        // Move every vertex behind the centre of projection (positive distance along n).
        let mut behind = mesh.clone();
        for p in &mut behind.positions {
            let local = *p - camera.position;
            let depth = local.dot(camera.n).abs() + 1e-3;
            *p = camera.position + camera.u * local.dot(camera.u) + camera.v * local.dot(camera.v) + camera.n * depth;
        }
        for clipping in [Clipping::Full, Clipping::Simple] {
            let frame = textbook::run(&behind, &camera, &PipelineSettings { clipping, ..settings }, viewport);
            prop_assert!(frame.vertices.is_empty(), "{:?} drew {} vertices", clipping, frame.vertices.len());
            prop_assert_eq!(frame.counts.clipped, behind.triangles.len());
        }
    }

    #[test]
    fn the_fast_path_writes_the_textbook_buffer_and_fates(
        mesh in mesh(200), camera in camera(), settings in settings(), viewport in viewport(), simple in any::<bool>(),
    ) {
        let settings = PipelineSettings {
            clipping: if simple { Clipping::Simple } else { Clipping::Full },
            ..settings
        };
        let (slow, slow_fates) = textbook::run_recording(&mesh, &camera, &settings, viewport);
        let mut fast = Close2glFrame::default();
        let mut fates = Fates { record: true, ..Fates::default() };
        FastPipeline::default().run(&mesh, &camera, &settings, viewport, &mut fast, &mut fates);
        prop_assert_eq!(&slow, &fast);
        prop_assert_eq!(slow_fates.counts, fates.counts);
        // Debug text, so that the NaN areas of clipped triangles compare equal.
        prop_assert_eq!(format!("{:?}", slow_fates.triangles), format!("{:?}", fates.triangles));
        // Without recording: the same buffer and stage counts, and no fates at all.
        let mut unrecorded = Fates::default();
        FastPipeline::default().run(&mesh, &camera, &settings, viewport, &mut fast, &mut unrecorded);
        prop_assert_eq!(&slow, &fast);
        prop_assert!(unrecorded.triangles.is_empty());
        prop_assert_eq!(unrecorded.counts, FateCounts::default());
    }
}

//! The fate view on a real adapter: Close2GL's view colours each triangle by the fate recorded in
//! `Fates` and outlines what clipping removed where it would project; the reference view gets
//! the GPU's own facing and depth-test answers.

use close2gl_core::glam::Vec3;
use close2gl_core::{
    App, Appearance, Camera, Close2glFrame, FateKind, Fates, FrontFace, Mesh, Overlay,
    PipelineSettings, RecordFates, RenderMode, SelectedTriangle, Shading, TriangleFate, Viewport,
};
use close2gl_gpu::{Gpu, OffscreenPlugin, Snapshot, render_offscreen};
use close2gl_testkit::gpu;

const SIZE: u32 = 64;

/// Seen from the origin down -z on a 64x64 viewport: triangle 0 in the middle at z = -5; 1
/// reaching out over the left border; 2 bigger, behind 0 at z = -10.
fn scene() -> Mesh {
    let positions = vec![
        Vec3::new(-1.0, -1.0, -5.0),
        Vec3::new(1.0, -1.0, -5.0),
        Vec3::new(0.0, 1.0, -5.0),
        Vec3::new(-5.0, -1.0, -5.0),
        Vec3::new(-2.0, 0.0, -5.0),
        Vec3::new(-5.0, 1.0, -5.0),
        Vec3::new(-3.0, -3.0, -10.0),
        Vec3::new(3.0, -3.0, -10.0),
        Vec3::new(0.0, 3.0, -10.0),
    ];
    Mesh {
        face_normals: Vec::new(),
        name: "fates".into(),
        normals: vec![Vec3::Z; positions.len()],
        positions,
        uvs: Vec::new(),
        triangles: vec![[0, 1, 2], [3, 4, 5], [6, 7, 8]],
    }
}

/// How the model looks under the fate view here: flat colour.
fn flat() -> Appearance {
    Appearance {
        shading: Shading::None,
        ..Default::default()
    }
}

/// Renders the scene with the fate view on, the fates recorded as `kinds` (what Close2GL's
/// pipeline records; set here so that the view is tested on its own).
fn render(kinds: [FateKind; 3]) -> (App, Snapshot) {
    render_on(gpu(), PipelineSettings::default(), scene(), kinds)
}

/// [`render`] of `mesh` on `device` with the pipeline's switches `pipeline`.
fn render_on(
    device: Gpu,
    pipeline: PipelineSettings,
    mesh: Mesh,
    kinds: [FateKind; 3],
) -> (App, Snapshot) {
    let viewport = Viewport {
        width: SIZE,
        height: SIZE,
    };
    let mut app = close2gl_testkit::world_with(mesh, Camera::default(), viewport);
    let fates = Fates {
        triangles: kinds
            .map(|kind| TriangleFate {
                kind,
                ..Default::default()
            })
            .to_vec(),
        ..Default::default()
    };
    app.insert_resource(pipeline)
        .insert_resource(flat())
        .insert_resource(Overlay::FateView)
        .insert_resource(fates)
        .init_resource::<Close2glFrame>()
        .add_plugins(OffscreenPlugin(device));
    let snapshot = render_offscreen(&mut app).expect("both views render");
    (app, snapshot)
}

fn rgb(pixel: [u8; 4]) -> [f32; 3] {
    [pixel[0], pixel[1], pixel[2]].map(f32::from)
}

/// `over` blended over `under` with `alpha`, as the GPU's alpha blending does.
fn blend(under: [f32; 3], over: [u8; 3], alpha: f32) -> [f32; 3] {
    [0, 1, 2].map(|i| under[i] * (1.0 - alpha) + f32::from(over[i]) * alpha)
}

fn near(a: [f32; 3], b: [f32; 3]) -> bool {
    a.iter().zip(&b).all(|(a, b)| (a - b).abs() <= 2.0)
}

#[test]
fn close2gl_fills_each_triangle_in_its_fate_colour_and_outlines_what_clipping_removed() {
    let (app, snapshot) = render([FateKind::Drawn, FateKind::Clipped, FateKind::Hidden]);
    assert!(
        app.world().resource::<RecordFates>().0,
        "the view asks for fates"
    );
    let close2gl = &snapshot.close2gl;
    let [r, g, b] = FateKind::Drawn.color();
    // The middle: triangle 0 over the hidden triangle 2 (painted far to near).
    assert_eq!(close2gl.pixel(32, 36), [r, g, b, 255]);
    let [r, g, b] = FateKind::Hidden.color();
    assert_eq!(
        close2gl.pixel(21, 40),
        [r, g, b, 255],
        "triangle 2 left of 0"
    );
    // Triangle 1's outline where it reaches into the view: its corner at x ≈ 9.8, y = 32.
    let [r, g, b] = FateKind::Clipped.color();
    let outlined = (28..37).any(|y| (0..12).any(|x| close2gl.pixel(x, y) == [r, g, b, 255]));
    assert!(
        outlined,
        "the clipped triangle's outline shows at the border"
    );
    assert_ne!(
        close2gl.pixel(3, 32),
        [r, g, b, 255],
        "an outline, not a fill"
    );
}

#[test]
fn the_reference_shows_the_gpus_facing_and_its_depth_test_failures() {
    let (_, snapshot) = render([FateKind::Drawn; 3]);
    let shaded = Appearance::default().color.to_array().map(|c| c * 255.0);
    let front = blend(shaded, FateKind::Drawn.color(), 0.6);
    let reference = &snapshot.reference;
    // Triangle 2 left of triangle 0: a front face that won the depth test.
    assert!(
        near(rgb(reference.pixel(21, 40)), front),
        "{:?}",
        reference.pixel(21, 40)
    );
    // The middle: triangle 0 won, triangle 2 behind it failed the test there.
    let failed = blend(front, FateKind::Hidden.color(), 0.35);
    assert!(
        near(rgb(reference.pixel(32, 36)), failed),
        "{:?}",
        reference.pixel(32, 36)
    );
}

/// Without the polygon modes lines and points are drawn as rectangles and squares of two
/// triangles, which face the way their corners' order makes them, whatever the face's facing:
/// the overlay takes the face's, as the shader found it. The scene is wound so that every face
/// is a front face for the front face set, and none is culled.
#[test]
fn without_polygon_modes_the_facing_overlay_takes_each_faces_own_facing() {
    let bare = close2gl_testkit::gpu_without_polygon_modes();
    let shaded = flat().color.to_array().map(|c| c * 255.0);
    let [front, back] =
        [FateKind::Drawn, FateKind::Culled].map(|kind| blend(shaded, kind.color(), 0.6));
    for mode in [RenderMode::Wireframe, RenderMode::Points] {
        for front_face in [FrontFace::Ccw, FrontFace::Cw] {
            let mut mesh = scene();
            if front_face == FrontFace::Cw {
                mesh.triangles.iter_mut().for_each(|t| t.swap(1, 2));
            }
            let pipeline = PipelineSettings {
                mode,
                front_face,
                ..Default::default()
            };
            let (_, snapshot) = render_on(bare.clone(), pipeline, mesh, [FateKind::Drawn; 3]);
            let pixels = &snapshot.reference.pixels;
            let count = |colour| pixels.iter().filter(|p| near(rgb(**p), colour)).count();
            let (front, back) = (count(front), count(back));
            assert!(
                front > 5 && back == 0,
                "{mode:?}, {front_face:?}: {front} pixels in the front colour, {back} in the back"
            );
        }
    }
}

#[test]
fn the_selected_triangle_is_highlighted_in_both_views_even_where_it_is_hidden() {
    let (mut app, plain) = render([FateKind::Drawn, FateKind::Clipped, FateKind::Hidden]);
    // Triangle 2 lies behind triangle 0: its highlight shows over 0 all the same.
    app.insert_resource(SelectedTriangle(Some(2)));
    let selected = render_offscreen(&mut app).expect("both views render");
    for (view, before, after) in [
        ("reference", &plain.reference, &selected.reference),
        ("close2gl", &plain.close2gl, &selected.close2gl),
    ] {
        assert_ne!(
            before.pixel(32, 36),
            after.pixel(32, 36),
            "{view}: over triangle 0"
        );
        assert_ne!(
            before.pixel(21, 40),
            after.pixel(21, 40),
            "{view}: inside triangle 2"
        );
        assert_eq!(before.pixel(2, 2), after.pixel(2, 2), "{view}: outside it");
        // The marker: strokes 6 to 16 pixels from the centre of triangle 2, which projects to
        // (32, 37.5), so that a triangle smaller than a pixel is found at a glance. (Checked
        // where the triangle's own outline does not pass: its right edge crosses row 37 at
        // x = 43, and its sides are over 2 pixels from column 32 below row 23.)
        let orange = [255, 128, 0, 255];
        let stroke = |xs: std::ops::Range<u32>, ys: std::ops::Range<u32>| {
            xs.flat_map(|x| ys.clone().map(move |y| (x, y)))
                .any(|(x, y)| after.pixel(x, y) == orange)
        };
        assert!(stroke(38..42, 36..39), "{view}: the marker's right stroke");
        assert!(stroke(31..33, 24..31), "{view}: the marker's upper stroke");
    }
    // A triangle the mesh does not have highlights nothing.
    app.insert_resource(SelectedTriangle(Some(3)));
    let missing = render_offscreen(&mut app).expect("both views render");
    assert!(missing.reference.pixels == plain.reference.pixels);
    assert!(missing.close2gl.pixels == plain.close2gl.pixels);
}

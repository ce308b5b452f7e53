//! The outside view on a real adapter: a known scene drawn, and the pixels where the outside
//! camera's own matrices project the near plane and the model must show them.

use close2gl_core::glam::Vec3;
use close2gl_core::{App, Appearance, Camera, OutsideView, Viewport};
use close2gl_gpu::outside::{OutsideRenderer, render_outside};
use close2gl_gpu::{Image, OffscreenPlugin, render_offscreen};
use close2gl_pipeline::Close2glPlugin;
use close2gl_pipeline::morph::OutsideFraming;
use close2gl_testkit::{gpu, sphere};

const SIZE: Viewport = Viewport {
    width: 320,
    height: 240,
};
const MODEL: Vec3 = Vec3::new(0.2, 0.9, 0.3);

/// A unit sphere at the origin seen from (0, 0, 5) through a narrow horizontal field of view
/// (10°: the side planes cut the sphere) with the near plane at z = 3 and the far at z = -3.
fn scene() -> (App, Camera) {
    let camera = Camera {
        hfov: 10.0,
        vfov: 60.0,
        near: 2.0,
        far: 8.0,
        ..Camera::default()
    }
    .looking_at(Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y)
    .expect("a valid pose");
    let mesh = sphere(Vec3::ZERO, 1.0, 48, 96);
    let mut app = close2gl_testkit::world_with(mesh, camera, SIZE);
    app.insert_resource(Appearance {
        color: MODEL,
        ..Appearance::default()
    })
    .insert_resource(OutsideView {
        show: true,
        stage: 0.0,
    })
    .add_plugins(close2gl_core::SettingsPlugin)
    .add_plugins(Close2glPlugin)
    .add_plugins(OffscreenPlugin(gpu()));
    (app, camera)
}

/// The pixel the outside camera projects world point `p` onto.
fn pixel_of(app: &App, camera: &Camera, p: Vec3) -> (u32, u32) {
    let frame = OutsideFraming::new(camera, (Vec3::splat(-1.0), Vec3::splat(1.0)));
    let outside = app
        .world()
        .resource::<OutsideRenderer>()
        .camera()
        .expect("the outside view was drawn");
    let clip = outside.view_projection() * (p - frame.origin).extend(1.0);
    let ndc = clip / clip.w;
    let x = (ndc.x + 1.0) * 0.5 * SIZE.width as f32;
    let y = (1.0 - ndc.y) * 0.5 * SIZE.height as f32;
    (x as u32, y as u32)
}

fn rgb(image: &Image, (x, y): (u32, u32)) -> Vec3 {
    let [r, g, b, _] = image.pixel(x, y);
    Vec3::new(r.into(), g.into(), b.into())
}

/// The model's colour as the outside view lights it at the sphere's point `p` (flat shading
/// from the facet, lit from the outside camera), within the tolerance a 96-slice facet allows.
fn lit(app: &App, camera: &Camera, p: Vec3) -> Vec3 {
    let eye = app
        .world()
        .resource::<OutsideRenderer>()
        .camera()
        .expect("drawn")
        .eye;
    let frame = OutsideFraming::new(camera, (Vec3::splat(-1.0), Vec3::splat(1.0)));
    let to_eye = (eye + frame.origin - p).normalize();
    MODEL * 255.0 * (0.35 + 0.65 * p.dot(to_eye).abs())
}

fn close(actual: Vec3, expected: Vec3, tolerance: f32) -> bool {
    (actual - expected).abs().max_element() <= tolerance * expected.max_element().max(30.0)
}

#[test]
fn the_near_plane_and_the_model_land_where_the_outside_camera_projects_them() {
    let (mut app, camera) = scene();
    render_offscreen(&mut app).expect("the two views");
    let image = render_outside(&mut app).expect("the outside view");
    let dir = std::path::PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../target/outside");
    std::fs::create_dir_all(&dir).expect("the image directory");
    image
        .write_png(&dir.join("known_scene.png"))
        .expect("write");
    let background = Vec3::new(20.0, 20.0, 26.0);

    // The near face's centre: the translucent near colour (255, 210, 60, alpha 60) over the
    // background; three of its half-widths beside it, the background.
    let near_centre = camera.position - camera.n * camera.near;
    let alpha = 60.0 / 255.0;
    let expected = background * (1.0 - alpha) + Vec3::new(255.0, 210.0, 60.0) * alpha;
    let at = pixel_of(&app, &camera, near_centre);
    assert!(
        close(rgb(&image, at), expected, 0.06),
        "near plane at {at:?}: {}",
        rgb(&image, at)
    );
    let half_width = camera.near * 5f32.to_radians().tan();
    let beside = pixel_of(&app, &camera, near_centre + camera.u * 3.0 * half_width);
    assert!(
        close(rgb(&image, beside), background, 0.06),
        "beside the near plane at {beside:?}"
    );

    // Two points of the sphere that face the outside camera: one inside the 10° volume, lit;
    // one beyond its right plane, dimmed to 0.3 of that.
    let inside = Vec3::new(0.1, 0.3, 0.95).normalize();
    let outside = Vec3::new(0.9, 0.3, 0.3).normalize();
    let (at_in, at_out) = (
        pixel_of(&app, &camera, inside),
        pixel_of(&app, &camera, outside),
    );
    let (seen_in, seen_out) = (rgb(&image, at_in), rgb(&image, at_out));
    assert!(
        close(seen_in, lit(&app, &camera, inside), 0.1),
        "inside at {at_in:?}: {seen_in}"
    );
    let dimmed = lit(&app, &camera, outside) * 0.3;
    assert!(
        close(seen_out, dimmed, 0.12),
        "outside at {at_out:?}: {seen_out} vs {dimmed}"
    );
}

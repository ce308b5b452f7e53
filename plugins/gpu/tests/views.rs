//! Both views on a real adapter, on worlds built by hand: the Close2GL pipeline fills the 2D
//! buffer, the GPU crate draws both views offscreen, and the coverage must agree.

use std::path::PathBuf;

use close2gl_core::glam::Vec3;
use close2gl_core::{
    App, Camera, FrontFace, Mesh, ModelStatus, RenderMode, RenderSettings, Shading, Viewport,
};
use close2gl_gpu::parity::{Comparison, coverage, diff_image, to_rgb8};
use close2gl_gpu::{Gpu, OffscreenPlugin, Snapshot, render_offscreen};
use close2gl_pipeline::Close2glPlugin;
use close2gl_testkit::{gpu, sphere};

fn app(mesh: Mesh, camera: Camera, settings: RenderSettings, viewport: Viewport) -> App {
    app_on(gpu(), mesh, camera, settings, viewport)
}

/// The Close2GL pipeline and both views offscreen on `gpu`, over a world built by hand.
fn app_on(
    gpu: Gpu,
    mesh: Mesh,
    camera: Camera,
    settings: RenderSettings,
    viewport: Viewport,
) -> App {
    let mut app = close2gl_testkit::world_with(mesh, camera, settings, viewport);
    app.insert_resource(ModelStatus {
        generation: 1,
        ..Default::default()
    })
    .add_plugins(Close2glPlugin)
    .add_plugins(OffscreenPlugin(gpu));
    app
}

fn camera_at(position: Vec3, target: Vec3) -> Camera {
    Camera {
        near: 0.1,
        far: 100.0,
        ..Camera::default()
    }
    .looking_at(position, target, Vec3::Y)
    .expect("a valid pose")
}

/// Compares both views; on failure writes them and the diff under target/gpu-views/<case>/.
fn check(case: &str, snapshot: &Snapshot, threshold: f64) -> Comparison {
    let comparison =
        Comparison::of_images(&snapshot.reference, &snapshot.close2gl, snapshot.background);
    if comparison.coverage_agreement < threshold {
        let dir = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("../../target/gpu-views")
            .join(case);
        std::fs::create_dir_all(&dir).expect("create the image directory");
        snapshot
            .reference
            .write_png(&dir.join("reference.png"))
            .unwrap();
        snapshot
            .close2gl
            .write_png(&dir.join("close2gl.png"))
            .unwrap();
        diff_image(&snapshot.reference, &snapshot.close2gl, snapshot.background)
            .write_png(&dir.join("diff.png"))
            .unwrap();
        panic!(
            "{case}: coverage agreement {:.5} < {threshold} ({comparison:?}); see {}",
            comparison.coverage_agreement,
            dir.join("diff.png").display()
        );
    }
    comparison
}

#[test]
fn a_framed_sphere_agrees_in_every_mode_and_front_face() {
    for mode in [RenderMode::Solid, RenderMode::Wireframe, RenderMode::Points] {
        for front_face in [FrontFace::Ccw, FrontFace::Cw] {
            let settings = RenderSettings {
                mode,
                front_face,
                ..Default::default()
            };
            let mut app = app(
                sphere(Vec3::ZERO, 1.0, 16, 32),
                camera_at(Vec3::new(0.3, 0.5, 3.0), Vec3::ZERO),
                settings,
                Viewport {
                    width: 160,
                    height: 120,
                },
            );
            let snapshot = render_offscreen(&mut app).expect("render");
            let threshold = if mode == RenderMode::Solid {
                0.999
            } else {
                0.99
            };
            let case = format!("sphere_{}_{}", mode.name(), front_face.name());
            let comparison = check(&case, &snapshot, threshold);
            assert!(comparison.covered_pixels > 100, "{case}: {comparison:?}");
        }
    }
}

fn framed_sphere(settings: RenderSettings, viewport: Viewport) -> App {
    app(
        sphere(Vec3::ZERO, 1.0, 16, 32),
        camera_at(Vec3::new(0.3, 0.5, 3.0), Vec3::ZERO),
        settings,
        viewport,
    )
}

const SMALL: Viewport = Viewport {
    width: 160,
    height: 120,
};

#[test]
fn a_model_behind_the_camera_leaves_both_views_background_and_scores_zero() {
    let mut app = app(
        sphere(Vec3::new(0.0, 0.0, 10.0), 1.0, 8, 16),
        camera_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0)),
        RenderSettings::default(),
        SMALL,
    );
    let snapshot = render_offscreen(&mut app).expect("render");
    let background = to_rgb8(RenderSettings::default().background);
    assert_eq!(snapshot.background, background);
    for image in [&snapshot.reference, &snapshot.close2gl] {
        assert_eq!((image.width, image.height), (160, 120));
        assert!(image.pixels.iter().all(|p| p[..3] == background));
    }
    let comparison =
        Comparison::of_images(&snapshot.reference, &snapshot.close2gl, snapshot.background);
    assert_eq!(comparison.covered_pixels, 0);
    assert_eq!(comparison.coverage_agreement, 0.0);
    assert_eq!(snapshot.counts.drawn, 0);
}

/// The covered pixels' colours, in a fixed order.
fn colors(snapshot: &Snapshot) -> Vec<[u8; 4]> {
    let covered = coverage(&snapshot.reference, snapshot.background);
    snapshot
        .reference
        .pixels
        .iter()
        .zip(covered)
        .filter(|(_, c)| *c)
        .map(|(p, _)| *p)
        .collect()
}

#[test]
fn shading_changes_colours_but_not_coverage() {
    let shot = |shading| {
        let settings = RenderSettings {
            shading,
            ..Default::default()
        };
        let snapshot = render_offscreen(&mut framed_sphere(settings, SMALL)).expect("render");
        check(&format!("shading_{}", shading.name()), &snapshot, 0.999);
        snapshot
    };
    let flat = shot(Shading::None);
    let ad = shot(Shading::GouraudAd);
    let ads = shot(Shading::GouraudAds);
    let phong = shot(Shading::Phong);
    // Flat colour is exactly the user's colour.
    let color = to_rgb8(RenderSettings::default().color);
    assert!(colors(&flat).iter().all(|p| p[..3] == color));
    // Same pixels covered in every mode, different colours.
    let (flat, ad, ads, phong) = (colors(&flat), colors(&ad), colors(&ads), colors(&phong));
    assert!(flat.len() == ad.len() && ad.len() == ads.len() && ads.len() == phong.len());
    assert_ne!(ad, flat);
    // The specular term only adds light.
    assert!(
        ad.iter()
            .zip(&ads)
            .all(|(a, s)| (0..3).all(|i| s[i] >= a[i]))
    );
    assert!(ad.iter().zip(&ads).any(|(a, s)| s != a));
    // Per-fragment lighting differs from interpolated lighting somewhere, not everywhere.
    let differing = ads.iter().zip(&phong).filter(|(g, p)| g != p).count();
    assert!(
        differing > 0 && differing < ads.len(),
        "{differing} of {}",
        ads.len()
    );
    // Lit colours vary across the sphere (the light is not ignored).
    let distinct: std::collections::BTreeSet<_> = phong.iter().collect();
    assert!(distinct.len() > 20, "{} distinct colours", distinct.len());
}

#[test]
fn the_mesh_is_uploaded_again_only_when_the_generation_changes() {
    let mut app = framed_sphere(RenderSettings::default(), SMALL);
    let first = render_offscreen(&mut app).expect("render");
    // Move the model without telling the renderers: the reference keeps the mesh it has.
    let moved = sphere(Vec3::new(0.5, 0.0, 0.0), 1.0, 16, 32);
    let mut mesh = app
        .world_mut()
        .query::<&mut Mesh>()
        .single_mut(app.world_mut())
        .unwrap();
    *mesh = moved;
    let stale = render_offscreen(&mut app).expect("render");
    assert_eq!(stale.reference, first.reference);
    assert_ne!(stale.close2gl, first.close2gl);
    app.world_mut().resource_mut::<ModelStatus>().generation += 1;
    let fresh = render_offscreen(&mut app).expect("render");
    assert_ne!(fresh.reference, first.reference);
    check("after_reload", &fresh, 0.999);
}

#[test]
fn a_resize_changes_both_views_and_they_still_agree() {
    let mut app = framed_sphere(RenderSettings::default(), SMALL);
    render_offscreen(&mut app).expect("render");
    *app.world_mut().resource_mut::<Viewport>() = Viewport {
        width: 97,
        height: 203,
    };
    let snapshot = render_offscreen(&mut app).expect("render");
    for image in [&snapshot.reference, &snapshot.close2gl] {
        assert_eq!((image.width, image.height), (97, 203));
    }
    check("resized", &snapshot, 0.999);
}

#[test]
fn the_2d_buffer_grows_when_the_model_gets_bigger() {
    let settings = RenderSettings {
        mode: RenderMode::Wireframe,
        ..Default::default()
    };
    let mut app = framed_sphere(settings, SMALL);
    render_offscreen(&mut app).expect("render");
    let mut mesh = app
        .world_mut()
        .query::<&mut Mesh>()
        .single_mut(app.world_mut())
        .unwrap();
    *mesh = sphere(Vec3::ZERO, 1.0, 64, 128);
    app.world_mut().resource_mut::<ModelStatus>().generation += 1;
    let snapshot = render_offscreen(&mut app).expect("render");
    assert!(snapshot.counts.output_primitives > 3 * 1024);
    check("grown", &snapshot, 0.99);
}

#[test]
fn a_viewport_larger_than_the_adapter_allows_is_an_error_not_a_panic() {
    let mut app = framed_sphere(RenderSettings::default(), SMALL);
    let max = gpu().device.limits().max_texture_dimension_2d;
    *app.world_mut().resource_mut::<Viewport>() = Viewport {
        width: max + 1,
        height: 8,
    };
    let error = render_offscreen(&mut app).expect_err("too large");
    assert!(error.contains(&format!("{}x8", max + 1)), "{error}");
}

/// A device without the polygon-mode features still draws every mode, and says what it draws
/// instead.
#[test]
fn without_polygon_modes_the_views_say_what_they_draw_instead() {
    let full = gpu();
    let instance = full.instance.clone();
    let adapter = pollster::block_on(instance.request_adapter(&Default::default()))
        .expect("the adapter found before");
    let (device, queue) = pollster::block_on(adapter.request_device(&Default::default()))
        .expect("a device without optional features");
    let bare = Gpu {
        instance,
        adapter,
        device,
        queue,
    };
    assert!(
        close2gl_gpu::Views::new(&full, close2gl_gpu::OFFSCREEN_FORMAT)
            .limitations()
            .is_none()
    );
    let limitations = close2gl_gpu::Views::new(&bare, close2gl_gpu::OFFSCREEN_FORMAT)
        .limitations()
        .expect("limitations named");
    assert!(limitations.contains("POLYGON_MODE_LINE"), "{limitations}");
    assert!(limitations.contains("POLYGON_MODE_POINT"), "{limitations}");
    for mode in [RenderMode::Wireframe, RenderMode::Points] {
        let settings = RenderSettings {
            mode,
            ..Default::default()
        };
        let camera = camera_at(Vec3::new(0.3, 0.5, 3.0), Vec3::ZERO);
        let sphere = sphere(Vec3::ZERO, 1.0, 16, 32);
        let mut app = app_on(bare.clone(), sphere, camera, settings, SMALL);
        let snapshot = render_offscreen(&mut app).expect("render");
        let covered = coverage(&snapshot.reference, snapshot.background)
            .into_iter()
            .filter(|c| *c)
            .count();
        assert!(
            covered > 100,
            "{mode:?}: the fallback drew {covered} pixels"
        );
    }
}

//! Both views on a real adapter, on worlds built by hand: the Close2GL pipeline fills the 2D
//! buffer, the GPU crate draws both views offscreen, and the coverage must agree.

use std::path::PathBuf;

use close2gl_core::bevy_ecs::change_detection::DetectChangesMut;
use close2gl_core::glam::{Vec2, Vec3};
use close2gl_core::parity::{
    CoverageComparison, ONLY_CLOSE2GL, ONLY_REFERENCE, coverage, diff_image, is_covered, to_rgb8,
};
use close2gl_core::{
    App, Appearance, Camera, Clipping, FrontFace, Image, Mesh, Overlay, PipelineSettings,
    Rasterizer, RenderMode, Scene, Shading, Texture, TextureFilter, Viewport,
};
use close2gl_gpu::attachments::{READABLE_TARGET, texture_2d};
use close2gl_gpu::{
    DEPTH_FORMAT, Gpu, OFFSCREEN_FORMAT, OffscreenPlugin, Readback, ReferenceSkew, Snapshot, Views,
    probe_reference, render_offscreen, submit_pass, wgpu,
};
use close2gl_pipeline::Close2glPlugin;
use close2gl_testkit::{gpu, sphere};

fn app(mesh: Mesh, camera: Camera, viewport: Viewport) -> App {
    app_on(gpu(), mesh, camera, viewport)
}

/// The Close2GL pipeline and both views offscreen on `gpu`, over a world built by hand with the
/// default settings (a test inserts the ones it changes).
fn app_on(gpu: Gpu, mesh: Mesh, camera: Camera, viewport: Viewport) -> App {
    let mut app = close2gl_testkit::world_with(mesh, camera, viewport);
    app.add_plugins(Close2glPlugin)
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
fn check(case: &str, snapshot: &Snapshot, threshold: f64) -> CoverageComparison {
    let comparison = CoverageComparison::of_images(&snapshot.reference, &snapshot.close2gl);
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
        diff_image(&snapshot.reference, &snapshot.close2gl)
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
            let mut app = app(
                sphere(Vec3::ZERO, 1.0, 16, 32),
                camera_at(Vec3::new(0.3, 0.5, 3.0), Vec3::ZERO),
                Viewport {
                    width: 160,
                    height: 120,
                },
            );
            app.insert_resource(PipelineSettings {
                mode,
                front_face,
                ..Default::default()
            });
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

fn framed_sphere(viewport: Viewport) -> App {
    app(
        sphere(Vec3::ZERO, 1.0, 16, 32),
        camera_at(Vec3::new(0.3, 0.5, 3.0), Vec3::ZERO),
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
        SMALL,
    );
    let snapshot = render_offscreen(&mut app).expect("render");
    let background = to_rgb8(Appearance::default().background);
    for image in [&snapshot.reference, &snapshot.close2gl] {
        assert_eq!((image.width, image.height), (160, 120));
        let uncovered = [background[0], background[1], background[2], 0];
        assert!(image.pixels.iter().all(|p| *p == uncovered));
    }
    let comparison = CoverageComparison::of_images(&snapshot.reference, &snapshot.close2gl);
    assert_eq!(comparison.covered_pixels, 0);
    assert_eq!(comparison.coverage_agreement, 0.0);
    assert_eq!(snapshot.counts.drawn, 0);
}

/// The covered pixels' colours, in a fixed order.
fn colors(snapshot: &Snapshot) -> Vec<[u8; 4]> {
    let covered = coverage(&snapshot.reference);
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
        let mut app = framed_sphere(SMALL);
        app.insert_resource(Appearance {
            shading,
            ..Default::default()
        });
        let snapshot = render_offscreen(&mut app).expect("render");
        check(&format!("shading_{}", shading.name()), &snapshot, 0.999);
        snapshot
    };
    let flat = shot(Shading::None);
    let ad = shot(Shading::GouraudAd);
    let ads = shot(Shading::GouraudAds);
    let phong = shot(Shading::Phong);
    // Flat colour is exactly the user's colour.
    let color = to_rgb8(Appearance::default().color);
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
fn the_mesh_is_uploaded_again_only_when_it_changes() {
    let mut app = framed_sphere(SMALL);
    let first = render_offscreen(&mut app).expect("render");
    // Move the model behind change detection's back: the reference keeps the mesh it has (it
    // uploads on the mesh's change tick, not every frame).
    let moved = sphere(Vec3::new(0.5, 0.0, 0.0), 1.0, 16, 32);
    let mut mesh = app
        .world_mut()
        .query::<&mut Mesh>()
        .single_mut(app.world_mut())
        .unwrap();
    *mesh.bypass_change_detection() = moved;
    let stale = render_offscreen(&mut app).expect("render");
    assert_eq!(stale.reference, first.reference);
    // Marked changed, as any write through the world marks it: both views follow.
    let mut mesh = app
        .world_mut()
        .query::<&mut Mesh>()
        .single_mut(app.world_mut())
        .unwrap();
    mesh.set_changed();
    let fresh = render_offscreen(&mut app).expect("render");
    assert_ne!(fresh.reference, first.reference);
    check("after_reload", &fresh, 0.999);
}

#[test]
fn a_resize_changes_both_views_and_they_still_agree() {
    let mut app = framed_sphere(SMALL);
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
    let mut app = framed_sphere(SMALL);
    app.insert_resource(PipelineSettings {
        mode: RenderMode::Wireframe,
        ..Default::default()
    });
    render_offscreen(&mut app).expect("render");
    let mut mesh = app
        .world_mut()
        .query::<&mut Mesh>()
        .single_mut(app.world_mut())
        .unwrap();
    *mesh = sphere(Vec3::ZERO, 1.0, 64, 128);
    let snapshot = render_offscreen(&mut app).expect("render");
    assert!(snapshot.counts.output_primitives > 3 * 1024);
    check("grown", &snapshot, 0.99);
}

#[test]
fn a_viewport_larger_than_the_adapter_allows_is_an_error_not_a_panic() {
    let mut app = framed_sphere(SMALL);
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
    let bare = Gpu::from_device(instance, adapter, device, queue);
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
        let camera = camera_at(Vec3::new(0.3, 0.5, 3.0), Vec3::ZERO);
        let sphere = sphere(Vec3::ZERO, 1.0, 16, 32);
        let mut app = app_on(bare.clone(), sphere, camera, SMALL);
        app.insert_resource(PipelineSettings {
            mode,
            ..Default::default()
        });
        let snapshot = render_offscreen(&mut app).expect("render");
        let covered = coverage(&snapshot.reference)
            .into_iter()
            .filter(|c| *c)
            .count();
        assert!(
            covered > 100,
            "{mode:?}: the fallback drew {covered} pixels"
        );
    }
}

/// Without the polygon modes the probe's ID pass draws lines and points face by face as the
/// reference does: a sample of the pixels the reference covers are hit, on a triangle facing
/// the camera (culling is on), and a sample of those it leaves are not.
#[test]
fn without_polygon_modes_the_probe_hits_what_the_reference_draws() {
    let bare = close2gl_testkit::gpu_without_polygon_modes();
    let viewport = Viewport {
        width: 48,
        height: 36,
    };
    let camera = camera_at(Vec3::new(0.3, 0.5, 3.0), Vec3::ZERO);
    let mesh = sphere(Vec3::ZERO, 1.0, 8, 16);
    for mode in [RenderMode::Wireframe, RenderMode::Points] {
        let pipeline = PipelineSettings {
            mode,
            backface_culling: true,
            ..Default::default()
        };
        let mut app = app_on(bare.clone(), mesh.clone(), camera, viewport);
        app.insert_resource(pipeline);
        let snapshot = render_offscreen(&mut app).expect("render");
        let covered = coverage(&snapshot.reference);
        let scene = Scene {
            mesh: &mesh,
            camera: &camera,
            pipeline: &pipeline,
            viewport,
        };
        let (mut hits, mut misses) = (0, 0);
        for (i, &on) in covered.iter().enumerate().filter(|(i, _)| i % 7 == 0) {
            let pixel = (i as u32 % viewport.width, i as u32 / viewport.width);
            let hit = probe_reference(&bare, scene, pixel).expect("the probe reads back");
            assert_eq!(hit.is_some(), on, "{mode:?} at {pixel:?}: {hit:?}");
            let Some(hit) = hit else {
                misses += 1;
                continue;
            };
            let [a, b, c] =
                mesh.triangles[hit.triangle as usize].map(|i| mesh.positions[i as usize]);
            let facing = (b - a).cross(c - a).dot(camera.position - a);
            assert!(facing > 0.0, "{mode:?}: a culled triangle hit at {pixel:?}");
            hits += 1;
        }
        assert!(
            hits > 3 && misses > 3,
            "{mode:?}: {hits} hits, {misses} misses"
        );
    }
}

/// A view's pixels (the reference's with its depth buffer, or Close2GL's) when the pass draws it
/// into the rectangle at `origin` of a larger target, as the windows and the page draw each view:
/// the rectangle's part, rows from the top.
fn drawn_at(app: &App, origin: (u32, u32), reference: bool) -> Vec<[u8; 4]> {
    let gpu = app.world().resource::<Gpu>();
    let views = app.world().resource::<Views>();
    let Viewport { width, height } = *app.world().resource::<Viewport>();
    let size = (origin.0 + width, origin.1 + height);
    let texture = |format, usage| texture_2d(&gpu.device, "placed view", size, format, usage);
    let color = texture(OFFSCREEN_FORMAT, READABLE_TARGET);
    let depth = texture(DEPTH_FORMAT, wgpu::TextureUsages::RENDER_ATTACHMENT);
    let depth_view = depth.create_view(&Default::default());
    let color_view = color.create_view(&Default::default());
    let clear = wgpu::LoadOp::Clear(views.clear_color());
    let depth = reference.then_some(&depth_view);
    submit_pass(gpu, &color_view, depth, clear, |pass| {
        let (x, y) = (origin.0 as f32, origin.1 as f32);
        pass.set_viewport(x, y, width as f32, height as f32, 0.0, 1.0);
        match reference {
            true => views.draw_reference(pass),
            false => views.draw_close2gl(pass),
        }
    });
    let pixels = Readback::new(&gpu.device, size, 1)
        .read(gpu, &[&color])
        .expect("read back");
    let rows = pixels[0].chunks(size.0 as usize).skip(origin.1 as usize);
    rows.flat_map(|row| row[origin.0 as usize..].to_vec())
        .collect()
}

/// Without the polygon modes a line's fragments are kept by their position in the view, not in
/// the target: both GPU views draw the same pixels wherever the pass places them.
#[test]
fn without_polygon_modes_lines_are_the_same_wherever_the_view_is_placed() {
    let bare = close2gl_testkit::gpu_without_polygon_modes();
    let camera = camera_at(Vec3::new(0.3, 0.5, 3.0), Vec3::ZERO);
    let mut app = app_on(bare, sphere(Vec3::ZERO, 1.0, 8, 16), camera, SMALL);
    app.insert_resource(PipelineSettings {
        mode: RenderMode::Wireframe,
        ..Default::default()
    });
    render_offscreen(&mut app).expect("render");
    for reference in [true, false] {
        let at_corner = drawn_at(&app, (0, 0), reference);
        let background = at_corner[0];
        let drawn = at_corner.iter().filter(|p| **p != background).count();
        assert!(drawn > 100, "reference {reference}: {drawn} pixels drawn");
        let placed = drawn_at(&app, (13, 7), reference);
        assert!(at_corner == placed, "reference {reference}: moved");
    }
}

/// A rectangle from `corners` (counter-clockwise seen from its front), textured `repeat` times
/// each way.
fn quad(corners: [Vec3; 4], repeat: f32) -> Mesh {
    let normal = (corners[1] - corners[0])
        .cross(corners[2] - corners[0])
        .normalize();
    Mesh {
        face_normals: Vec::new(),
        name: "quad".into(),
        positions: corners.to_vec(),
        normals: vec![normal; 4],
        uvs: [(0.0, 0.0), (1.0, 0.0), (1.0, 1.0), (0.0, 1.0)]
            .map(|(s, t)| Vec2::new(s, t) * repeat)
            .to_vec(),
        triangles: vec![[0, 1, 2], [0, 2, 3]],
    }
}

/// White, unlit, textured with the course's checkerboard through `filter`.
fn textured_app(mesh: Mesh, camera: Camera, filter: TextureFilter, viewport: Viewport) -> App {
    let mut app = app(mesh, camera, viewport);
    app.insert_resource(Appearance {
        color: Vec3::ONE,
        shading: Shading::None,
        texture_filter: filter,
        ..Default::default()
    })
    .init_resource::<Texture>();
    app
}

fn head_on_quad() -> App {
    let corners =
        [(-1.0, -1.0), (1.0, -1.0), (1.0, 1.0), (-1.0, 1.0)].map(|(x, y)| Vec3::new(x, y, 0.0));
    textured_app(
        quad(corners, 1.0),
        camera_at(Vec3::new(0.0, 0.0, 2.5), Vec3::ZERO),
        TextureFilter::Nearest,
        Viewport {
            width: 64,
            height: 64,
        },
    )
}

/// How many covered pixels of the reference view are within 2 of grey level `level`.
fn share_of(snapshot: &Snapshot, level: u8) -> f64 {
    let colors = colors(snapshot);
    let near = |p: &&[u8; 4]| p[..3].iter().all(|c| c.abs_diff(level) <= 2);
    colors.iter().filter(near).count() as f64 / colors.len() as f64
}

/// The red level of the leftmost covered pixel in the bottom or the top covered row.
fn left_corner(snapshot: &Snapshot, bottom: bool) -> u8 {
    let image = &snapshot.reference;
    let width = image.width as usize;
    let covered = coverage(image);
    let mut indices = (0..covered.len()).filter(|i| covered[*i]);
    let index = if bottom {
        indices.next_back()
    } else {
        indices.next()
    };
    let row = index.expect("the quad is drawn") / width;
    let column = (0..width).find(|x| covered[row * width + x]);
    image.pixels[row * width + column.expect("a covered pixel")][0]
}

#[test]
fn a_checkerboard_quad_shows_both_squares_and_none_with_texturing_off() {
    let mut app = head_on_quad();
    let textured = render_offscreen(&mut app).expect("render");
    let (white, grey) = (share_of(&textured, 255), share_of(&textured, 48));
    // (s, t) = (0, 0) is the image's bottom-left corner, whose square is white; the top-left
    // one is grey. A flipped s or t would swap them.
    assert_eq!(
        (left_corner(&textured, true), left_corner(&textured, false)),
        (255, 48)
    );
    assert!(white + grey > 0.99, "white {white}, grey {grey}");
    assert!((0.4..0.6).contains(&white), "white {white}, grey {grey}");
    app.world_mut().resource_mut::<Appearance>().texture = false;
    let plain = render_offscreen(&mut app).expect("render");
    assert_eq!(share_of(&plain, 255), 1.0);
    assert_eq!(colors(&plain).len(), colors(&textured).len());
}

#[test]
fn the_texture_is_uploaded_again_only_when_it_changes() {
    let mut app = head_on_quad();
    let first = render_offscreen(&mut app).expect("render");
    let black = Image {
        width: 2,
        height: 2,
        pixels: vec![[0, 0, 0, 255]; 4],
    };
    app.world_mut()
        .resource_mut::<Texture>()
        .bypass_change_detection()
        .image = black;
    let stale = render_offscreen(&mut app).expect("render");
    assert_eq!(stale.reference, first.reference);
    app.world_mut().resource_mut::<Texture>().set_changed();
    let fresh = render_offscreen(&mut app).expect("render");
    let black = [0, 0, 0, 255];
    assert!(
        fresh
            .reference
            .pixels
            .iter()
            .all(|p| *p == black || !is_covered(p))
    );
}

/// A floor 8 wide and 40 deep, its checker squares a quarter unit, seen from half a unit above
/// it: far away the squares get much smaller than a pixel.
fn grazing_floor(filter: TextureFilter) -> Snapshot {
    let corners =
        [(-4.0, 0.0), (4.0, 0.0), (4.0, -40.0), (-4.0, -40.0)].map(|(x, z)| Vec3::new(x, 0.0, z));
    let mut app = textured_app(
        quad(corners, 4.0),
        camera_at(Vec3::new(0.0, 0.5, 1.0), Vec3::new(0.0, 0.0, -10.0)),
        filter,
        Viewport {
            width: 96,
            height: 72,
        },
    );
    render_offscreen(&mut app).expect("render")
}

/// The mean |p(x+1) - p(x)| (red channel) between horizontal neighbours in the far half of the
/// floor (the upper half of the rows it covers).
fn far_half_energy(snapshot: &Snapshot) -> f64 {
    let image = &snapshot.reference;
    let covered = coverage(image);
    let width = image.width as usize;
    let rows: Vec<usize> = (0..image.height as usize)
        .filter(|y| covered[y * width..(y + 1) * width].iter().any(|c| *c))
        .collect();
    let (mut sum, mut pairs) = (0u64, 0u64);
    for y in &rows[..rows.len() / 2] {
        for x in 0..width - 1 {
            let (a, b) = (y * width + x, y * width + x + 1);
            if covered[a] && covered[b] {
                sum += image.pixels[a][0].abs_diff(image.pixels[b][0]) as u64;
                pairs += 1;
            }
        }
    }
    sum as f64 / pairs.max(1) as f64
}

#[test]
fn the_filters_differ_on_a_grazing_floor_and_trilinear_calms_the_far_half() {
    let [nearest, bilinear, trilinear] = [
        TextureFilter::Nearest,
        TextureFilter::Bilinear,
        TextureFilter::Trilinear,
    ]
    .map(grazing_floor);
    assert_ne!(nearest.reference, bilinear.reference);
    assert_ne!(bilinear.reference, trilinear.reference);
    assert_ne!(nearest.reference, trilinear.reference);
    let (near, tri) = (far_half_energy(&nearest), far_half_energy(&trilinear));
    assert!(tri < 0.5 * near, "trilinear {tri}, nearest {near}");
}

#[test]
fn the_live_difference_is_the_render_commands_diff_image() {
    // Close enough that the sphere crosses the border, where simple clipping drops whole
    // triangles that the GPU still draws.
    let mut app = app(
        sphere(Vec3::ZERO, 1.0, 16, 32),
        camera_at(Vec3::new(0.3, 0.5, 1.6), Vec3::ZERO),
        SMALL,
    );
    app.insert_resource(PipelineSettings {
        clipping: Clipping::Simple,
        ..Default::default()
    })
    .insert_resource(Appearance {
        shading: Shading::Phong,
        ..Default::default()
    });
    let plain = render_offscreen(&mut app).expect("both views render");
    *app.world_mut().resource_mut::<Overlay>() = Overlay::Difference;
    let live = render_offscreen(&mut app).expect("the difference renders");

    let expected = diff_image(&plain.reference, &plain.close2gl);
    let missing = expected
        .pixels
        .iter()
        .filter(|&&p| p == ONLY_REFERENCE)
        .count();
    assert!(
        missing > 50,
        "simple clipping drops border triangles: {missing} pixels"
    );
    assert!(
        live.close2gl.pixels == expected.pixels,
        "the live difference is diff.png"
    );
    assert!(
        live.reference.pixels == plain.reference.pixels,
        "the reference is left alone"
    );
}

/// The pixels the live difference paints as covered by one view only.
fn painted(live: &Snapshot) -> usize {
    let one_view_only = |p: &&[u8; 4]| **p == ONLY_REFERENCE || **p == ONLY_CLOSE2GL;
    live.close2gl.pixels.iter().filter(one_view_only).count()
}

/// The framed sphere, solid, with both rasterizers, its reference's colours moved by `skew` as
/// another GPU's rounding moves them: coverage agrees exactly, as without the skew, and the live
/// difference paints nothing. `check_skew` says the skew took: it gets the reference's pixel and
/// Close2GL's at a covered `(true)` or uncovered `(false)` place.
fn assert_a_skew_changes_no_coverage(
    look: Appearance,
    skew: ReferenceSkew,
    check_skew: impl Fn(bool, [u8; 4], [u8; 4]),
) {
    for rasterizer in Rasterizer::ALL.iter().copied() {
        let mut app = framed_sphere(SMALL);
        app.add_plugins(close2gl_raster::RasterPlugin)
            .insert_resource(PipelineSettings {
                close2gl_raster: rasterizer,
                ..Default::default()
            })
            .insert_resource(look)
            .insert_resource(skew);
        let snapshot = render_offscreen(&mut app).expect("render");
        let covered = coverage(&snapshot.close2gl);
        for place in [true, false] {
            let i = covered
                .iter()
                .position(|&c| c == place)
                .expect("both kinds");
            check_skew(
                place,
                snapshot.reference.pixels[i],
                snapshot.close2gl.pixels[i],
            );
        }
        let case = format!("skew_{}_{}", skew.background, rasterizer.name());
        let comparison = check(&case, &snapshot, 1.0);
        assert!(comparison.covered_pixels > 1000, "{case}: {comparison:?}");
        *app.world_mut().resource_mut::<Overlay>() = Overlay::Difference;
        let live = render_offscreen(&mut app).expect("the difference renders");
        assert_eq!(
            painted(&live),
            0,
            "{case}: the live difference paints pixels"
        );
    }
}

/// NVIDIA clears to 0.1 as 25/255 where lavapipe and the software rasterizer store 26: here the
/// reference's background is moved one step on lavapipe, in each direction.
#[test]
fn a_reference_background_one_step_away_changes_no_coverage() {
    for steps in [1, -1] {
        let skew = ReferenceSkew {
            background: steps,
            color: 0,
        };
        assert_a_skew_changes_no_coverage(Appearance::default(), skew, |covered, r, c| {
            if !covered {
                let moved = [0, 1, 2].map(|k| i32::from(r[k]) - i32::from(c[k]));
                assert_eq!(moved, [steps; 3], "the reference's background moved");
            }
        });
    }
}

/// A model drawn in the background's colour is covered all the same: Close2GL's model one step
/// above the background, the reference's moved one step down onto it.
#[test]
fn a_model_in_the_backgrounds_colour_is_covered() {
    let background = Vec3::new(20.0, 20.0, 26.0) / 255.0;
    let look = Appearance {
        color: background + Vec3::splat(1.0 / 255.0),
        background,
        ..Default::default()
    };
    let skew = ReferenceSkew {
        background: 0,
        color: -1,
    };
    assert_a_skew_changes_no_coverage(look, skew, |covered, r, c| {
        if covered {
            assert_eq!(
                r[..3],
                [20, 20, 26],
                "the reference's model in the background's colour"
            );
            assert_eq!(c[..3], [21, 21, 27], "Close2GL's one step above");
        }
    });
}

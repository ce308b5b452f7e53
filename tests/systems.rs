//! The ECS systems on a headless World: a test inserts resources, sends input, runs the
//! schedules and asserts. No window, no GPU.

use close2gl::camera::{
    CameraPlugin, apply_camera_actions, apply_camera_edit, apply_camera_replacement,
    frame_new_model,
};
use close2gl::config::Config;
use close2gl::watch::WatchPlugin;
use std::any::TypeId;
use std::sync::Arc;

use close2gl::core::bevy_ecs::change_detection::DetectChanges;
use close2gl::core::bevy_ecs::schedule::{ApplyDeferred, IntoSystemSet, Schedules, SystemSet};
use close2gl::core::bevy_ecs::system::SystemAccess;
use close2gl::core::glam::{Vec2, Vec3};
use close2gl::core::{
    App, Appearance, Camera, CameraAction, CameraActions, CameraHome, CameraMode, Clipping,
    Close2glFrame, FrameSet, FrontFace, Image, InputState, Lighting, Mesh, ModelSource,
    ModelStatus, Overlay, PipelineSettings, RasterMistake, Rasterizer, RenderMode, SettingsPlugin,
    Shading, SoftwareFrame, Texture, Topology, Update, Viewport,
};
use close2gl::input::InputPlugin;
use close2gl::pipeline::Close2glPlugin;
use close2gl::raster::RasterPlugin;
use close2gl_testkit::{camera, camera_mut, cube, mesh, world_with};

fn app_with(mesh: Mesh, pipeline: PipelineSettings) -> App {
    let viewport = Viewport {
        width: 640,
        height: 480,
    };
    let mut app = world_with(mesh, Camera::default(), viewport);
    app.insert_resource(pipeline)
        .add_plugins(CameraPlugin)
        .add_plugins(InputPlugin)
        .add_plugins(Close2glPlugin);
    app.update();
    app
}

fn frame(app: &App) -> &Close2glFrame {
    app.world().resource::<Close2glFrame>()
}

/// Holds `keys` for one frame of `dt` seconds.
fn hold(app: &mut App, keys: &[&str], dt: f32) {
    let mut input = app.world_mut().resource_mut::<InputState>();
    input.held = keys.iter().map(|k| k.to_string()).collect();
    input.dt = dt;
    app.update();
    let mut input = app.world_mut().resource_mut::<InputState>();
    input.held.clear();
    input.end_frame();
}

fn press(app: &mut App, key: &str) {
    app.world_mut()
        .resource_mut::<InputState>()
        .pressed
        .push(key.into());
    app.update();
    app.world_mut().resource_mut::<InputState>().end_frame();
}

fn close(a: Vec3, b: Vec3) -> bool {
    (a - b).length() < 1e-4 * (1.0 + b.length())
}

#[test]
fn loading_frames_the_model_from_plus_z() {
    let mut app = app_with(cube(), PipelineSettings::default());
    let c = camera(&mut app);
    assert_eq!((c.u, c.v, c.n), (Vec3::X, Vec3::Y, Vec3::Z));
    assert_eq!(c.target, Vec3::ZERO);
    // The bounding sphere (radius √3) fits the 60° fields of view exactly.
    assert!((c.position.z - 3f32.sqrt() / 30f32.to_radians().sin()).abs() < 1e-4);
    let bounds = frame(&app).bounds_px().expect("the cube is drawn");
    assert!(bounds[0] > 0.0 && bounds[2] < 640.0 && bounds[1] > 0.0 && bounds[3] < 480.0);
}

#[test]
fn w_moves_along_minus_n() {
    let mut app = app_with(cube(), PipelineSettings::default());
    let before = camera(&mut app);
    hold(&mut app, &["w"], 0.05);
    let after = camera(&mut app);
    let moved = after.position - before.position;
    assert!(moved.length() > 0.0);
    assert!(close(moved.normalize(), -before.n), "moved along {moved}");
    assert_eq!((after.u, after.v, after.n), (before.u, before.v, before.n));
}

#[test]
fn after_a_yaw_w_follows_the_new_n() {
    let mut app = app_with(cube(), PipelineSettings::default());
    app.world_mut().resource_mut::<InputState>().drag = Vec2::new(120.0, 0.0);
    app.update();
    app.world_mut().resource_mut::<InputState>().end_frame();
    let turned = camera(&mut app);
    assert!(!close(turned.n, Vec3::Z), "the drag turned the camera");
    assert!(
        (turned.u.dot(turned.n)).abs() < 1e-5
            && (turned.u.cross(turned.v) - turned.n).length() < 1e-5
    );
    hold(&mut app, &["w"], 0.05);
    let moved = camera(&mut app).position - turned.position;
    assert!(
        close(moved.normalize(), -turned.n),
        "moved along {moved}, n = {}",
        turned.n
    );
}

#[test]
fn orbiting_keeps_the_look_at_point_and_the_distance() {
    let mut app = app_with(cube(), PipelineSettings::default());
    press(&mut app, "tab");
    let start = camera(&mut app);
    assert_eq!(start.mode, CameraMode::LookAt);
    for keys in [["d"], ["r"], ["a"], ["f"]] {
        hold(&mut app, &keys, 0.05);
    }
    app.world_mut()
        .resource_mut::<CameraActions>()
        .0
        .push(CameraAction::Orbit {
            yaw: 0.7,
            pitch: -0.3,
        });
    app.update();
    let end = camera(&mut app);
    assert!(!close(end.position, start.position));
    assert_eq!(end.target, start.target);
    assert!((end.distance() - start.distance()).abs() < 1e-4 * start.distance());
    assert!(
        close(end.n, (end.position - end.target).normalize()),
        "still looking at the target"
    );
}

#[test]
fn reset_returns_to_the_framed_pose() {
    let mut app = app_with(cube(), PipelineSettings::default());
    let home = app
        .world_mut()
        .query::<&CameraHome>()
        .single(app.world())
        .expect("framed")
        .0;
    hold(&mut app, &["w", "d", "z"], 0.05);
    app.world_mut().resource_mut::<InputState>().drag = Vec2::new(-40.0, 25.0);
    app.update();
    assert_ne!(camera(&mut app).position, home.position);
    press(&mut app, "space");
    let c = camera(&mut app);
    assert_eq!(
        (c.position, c.u, c.v, c.n, c.target),
        (home.position, home.u, home.v, home.n, home.target)
    );
}

#[test]
fn scroll_zooms_both_fields_of_view_keeping_their_ratio() {
    let mut app = app_with(cube(), PipelineSettings::default());
    let wide = Camera {
        hfov: 90.0,
        vfov: 50.0,
        ..camera(&mut app)
    };
    *camera_mut(&mut app) = wide;
    app.world_mut().resource_mut::<InputState>().scroll = 3.0;
    app.update();
    let zoomed = camera(&mut app);
    assert!(zoomed.hfov < wide.hfov && zoomed.vfov < wide.vfov);
    // The ratio a zoom keeps is the image's aspect: tan(hfov/2) / tan(vfov/2).
    let aspect = |c: &Camera| (c.hfov.to_radians() / 2.0).tan() / (c.vfov.to_radians() / 2.0).tan();
    assert!(
        (aspect(&zoomed) / aspect(&wide) - 1.0).abs() < 1e-5,
        "aspect {} became {}",
        aspect(&wide),
        aspect(&zoomed)
    );
}

#[test]
fn the_lecture_keys_switch_shading() {
    let mut app = app_with(cube(), PipelineSettings::default());
    let shading = |app: &App| app.world().resource::<Appearance>().shading;
    press(&mut app, "shift+p");
    assert_eq!(shading(&app), Shading::Phong);
    press(&mut app, "shift+g");
    assert_eq!(shading(&app), Shading::GouraudAds);
    press(&mut app, "shift+d");
    assert_eq!(shading(&app), Shading::None);
}

#[test]
fn cw_and_ccw_partition_a_closed_cube() {
    let pose = |app: &mut App| {
        let mut q = app.world_mut().query::<&mut Camera>();
        let mut c = q.single_mut(app.world_mut()).expect("camera");
        *c = c
            .looking_at(Vec3::new(3.0, 2.5, 4.0), Vec3::ZERO, Vec3::Y)
            .expect("pose");
    };
    let mut drawn = Vec::new();
    for front_face in [FrontFace::Ccw, FrontFace::Cw] {
        let mut app = app_with(
            cube(),
            PipelineSettings {
                front_face,
                ..PipelineSettings::default()
            },
        );
        pose(&mut app);
        app.update();
        let counts = frame(&app).counts;
        assert_eq!(counts.clipped, 0);
        assert_eq!(counts.drawn + counts.culled, 12);
        drawn.push(counts.drawn);
    }
    assert_eq!(
        drawn,
        [6, 6],
        "three faces face the camera, three face away"
    );
}

/// One triangle crossing the near plane: two corners in front of the camera, one behind it.
fn triangle_through_the_near_plane(clipping: Clipping) -> Close2glFrame {
    let mesh = Mesh {
        face_normals: Vec::new(),
        name: "one".into(),
        positions: vec![
            Vec3::new(-0.3, -0.3, -2.0),
            Vec3::new(0.3, -0.3, -2.0),
            Vec3::new(0.0, 0.1, 5.0),
        ],
        normals: vec![Vec3::Y; 3],
        uvs: Vec::new(),
        triangles: vec![[0, 1, 2]],
    };
    let settings = PipelineSettings {
        clipping,
        backface_culling: false,
        ..PipelineSettings::default()
    };
    let mut app = app_with(mesh, settings);
    let mut q = app.world_mut().query::<&mut Camera>();
    *q.single_mut(app.world_mut()).expect("camera") = Camera {
        near: 0.5,
        far: 50.0,
        ..Camera::default()
    };
    app.update();
    frame(&app).clone()
}

#[test]
fn the_near_plane_cuts_a_triangle_in_full_mode_and_drops_it_in_simple_mode() {
    let full = triangle_through_the_near_plane(Clipping::Full);
    assert_eq!((full.counts.clipped, full.counts.drawn), (0, 1));
    // The cut leaves a quad (two triangles): the near plane crosses two edges, and the narrow
    // triangle stays within the side planes.
    assert_eq!(full.counts.output_primitives, 2);
    assert_eq!(full.vertices.len(), 6);
    for [x, y] in &full.vertices {
        assert!(
            (0.0..=640.0).contains(x) && (0.0..=480.0).contains(y),
            "({x}, {y})"
        );
    }
    let simple = triangle_through_the_near_plane(Clipping::Simple);
    assert_eq!((simple.counts.clipped, simple.counts.drawn), (1, 0));
    assert!(simple.vertices.is_empty());
}

#[test]
fn a_resize_changes_the_viewport_mapping() {
    let mut app = app_with(cube(), PipelineSettings::default());
    let big = frame(&app).bounds_px().expect("drawn");
    *app.world_mut().resource_mut::<Viewport>() = Viewport {
        width: 320,
        height: 240,
    };
    app.update();
    let small = frame(&app).bounds_px().expect("drawn");
    for (b, s) in big.iter().zip(&small) {
        assert!((b / 2.0 - s).abs() < 1e-3, "{big:?} vs {small:?}");
    }
}

#[test]
fn each_mode_emits_its_primitives() {
    for (mode, per_triangle) in [
        (RenderMode::Solid, 3),
        (RenderMode::Wireframe, 6),
        (RenderMode::Points, 3),
    ] {
        let app = app_with(
            cube(),
            PipelineSettings {
                mode,
                ..PipelineSettings::default()
            },
        );
        let f = frame(&app);
        assert_eq!(f.vertices.len(), f.counts.drawn * per_triangle, "{mode:?}");
    }
}

/// The software rasterizer follows the model's texture: set, replaced, removed.
#[test]
fn the_software_view_follows_the_texture_as_it_changes_and_goes() {
    let mut mesh = cube();
    mesh.uvs = vec![Vec2::splat(0.5); mesh.positions.len()];
    let settings = PipelineSettings {
        close2gl_raster: Rasterizer::Software,
        ..PipelineSettings::default()
    };
    let mut app = app_with(mesh, settings);
    app.init_resource::<Lighting>().add_plugins(RasterPlugin);
    camera_mut(&mut app).position = Vec3::new(0.0, 0.0, 6.0);
    let centre = |app: &App| {
        app.world()
            .resource::<SoftwareFrame>()
            .image
            .pixel(320, 240)
    };
    let texture = |rgba| Texture {
        source: None,
        image: Image::filled(1, 1, rgba),
    };

    app.insert_resource(texture([255, 0, 0, 255]));
    app.update();
    let red = centre(&app);
    assert!(red[0] > 100 && red[1] == 0 && red[2] == 0, "{red:?}");
    app.insert_resource(texture([0, 0, 255, 255]));
    app.update();
    let blue = centre(&app);
    assert!(blue[0] == 0 && blue[1] == 0 && blue[2] > 30, "{blue:?}");
    app.world_mut().remove_resource::<Texture>();
    app.update();
    assert_eq!(
        centre(&app)[..3],
        [217, 166, 64],
        "the flat colour, untextured"
    );
}

/// The software rasterizer on a headless world: it draws only when asked for, only when
/// something changed, and its image has the viewport's size with the cube in the middle.
#[test]
fn the_raster_system_draws_when_asked_and_when_something_changed() {
    let mut app = app_with(cube(), PipelineSettings::default());
    app.init_resource::<Lighting>().add_plugins(RasterPlugin);
    camera_mut(&mut app).position = Vec3::new(0.0, 0.0, 6.0);
    let drawn = |app: &App| app.world().resource_ref::<SoftwareFrame>().last_changed();
    let inserted = drawn(&app);
    app.update();
    assert_eq!(drawn(&app), inserted, "gpu: nothing drawn");

    app.world_mut()
        .resource_mut::<PipelineSettings>()
        .close2gl_raster = Rasterizer::Software;
    app.update();
    let first = drawn(&app);
    assert_ne!(first, inserted, "software: drawn");
    let frame = app.world().resource::<SoftwareFrame>().clone();
    let image = &frame.image;
    assert_eq!((image.width, image.height), (640, 480));
    let at = |x: u32, y: u32| image.pixel(x, y);
    assert_eq!(
        at(320, 240)[..3],
        [217, 166, 64],
        "the cube's flat colour in the middle"
    );
    assert_eq!(at(2, 2)[..3], [20, 20, 26], "the background in a corner");

    app.update();
    assert_eq!(drawn(&app), first, "nothing changed");
    app.world_mut().resource_mut::<Lighting>().kd = 0.5;
    app.world_mut().resource_mut::<Appearance>().shading = Shading::Phong;
    app.update();
    assert_ne!(drawn(&app), first, "lit: drawn again");
    let lit = app.world().resource::<SoftwareFrame>();
    assert_ne!(
        lit.image.pixel(320, 240),
        image.pixels[240 * 640 + 320],
        "now lit"
    );
}

/// The render settings are three resources, each read by whom it concerns: switching the overlay
/// or the background recomputes nothing of the pipeline's (the Close2GL frame keeps its change
/// tick; the background redraws the software image alone), and switching the mode recomputes
/// the frame in that same frame.
/// The cube in front of the camera, Close2GL rasterizing in software; and those settings.
fn software_cube() -> (App, PipelineSettings) {
    let software = PipelineSettings {
        close2gl_raster: Rasterizer::Software,
        ..PipelineSettings::default()
    };
    let mut app = app_with(cube(), software);
    app.init_resource::<Lighting>().add_plugins(RasterPlugin);
    camera_mut(&mut app).position = Vec3::new(0.0, 0.0, 6.0);
    (app, software)
}

#[test]
fn a_raster_mistake_shows_in_the_software_view_without_recomputing_the_geometry() {
    let (mut app, _) = software_cube();
    app.update();
    let right = app.world().resource::<SoftwareFrame>().image.clone();
    let geometry = app.world().resource_ref::<Close2glFrame>().last_changed();
    let mut look = *app.world().resource::<Appearance>();
    look.raster_mistake = RasterMistake::ChannelsSwapped;
    app.insert_resource(look);
    app.update();
    let swapped = app.world().resource::<SoftwareFrame>().image.clone();
    let covered: Vec<usize> = (0..right.pixels.len())
        .filter(|&i| right.pixels[i][3] == 255)
        .collect();
    assert!(!covered.is_empty(), "the cube is drawn");
    for i in covered {
        let [r, g, b, a] = right.pixels[i];
        assert_eq!(swapped.pixels[i], [b, g, r, a], "pixel {i}");
    }
    let computed = app.world().resource_ref::<Close2glFrame>().last_changed();
    assert_eq!(
        computed, geometry,
        "a raster mistake recomputes no geometry"
    );
}

#[test]
fn a_reload_that_changes_only_the_background_recomputes_no_geometry() {
    let (mut app, software) = software_cube();
    let mut config = Config::default();
    config.render.pipeline = software;
    close2gl::apply_settings(app.world_mut(), &config);
    app.update();
    let computed = |app: &App| app.world().resource_ref::<Close2glFrame>().last_changed();
    let drawn = |app: &App| app.world().resource_ref::<SoftwareFrame>().last_changed();
    let (geometry, image) = (computed(&app), drawn(&app));
    // The same file again (--watch saw it saved unchanged): nothing runs again.
    close2gl::apply_settings(app.world_mut(), &config);
    app.update();
    assert_eq!(computed(&app), geometry, "an unchanged reload: the frame");
    assert_eq!(drawn(&app), image, "an unchanged reload: the image");
    config.render.appearance.background = Vec3::ONE;
    close2gl::apply_settings(app.world_mut(), &config);
    app.update();
    assert_eq!(
        computed(&app),
        geometry,
        "the background: the frame is left alone"
    );
    assert_ne!(
        drawn(&app),
        image,
        "the background: the image is drawn again"
    );
}

#[test]
fn only_the_pipelines_switches_recompute_the_close2gl_frame() {
    let (mut app, _) = software_cube();
    app.update();
    let computed = |app: &App| app.world().resource_ref::<Close2glFrame>().last_changed();
    let drawn = |app: &App| app.world().resource_ref::<SoftwareFrame>().last_changed();
    let (geometry, image) = (computed(&app), drawn(&app));

    *app.world_mut().resource_mut::<Overlay>() = Overlay::Difference;
    app.update();
    assert_eq!(
        computed(&app),
        geometry,
        "the overlay: the frame is left alone"
    );
    assert_eq!(drawn(&app), image, "the overlay: the image is left alone");

    app.world_mut().resource_mut::<Appearance>().background = Vec3::ONE;
    app.update();
    assert_eq!(
        computed(&app),
        geometry,
        "the background: the frame is left alone"
    );
    assert_ne!(
        drawn(&app),
        image,
        "the background: the image is drawn again"
    );
    let corner = app.world().resource::<SoftwareFrame>().image.pixel(2, 2);
    assert_eq!(corner[..3], [255, 255, 255], "in the new background");

    app.world_mut().resource_mut::<PipelineSettings>().mode = RenderMode::Wireframe;
    app.update();
    assert_ne!(
        computed(&app),
        geometry,
        "the mode: the frame is computed again"
    );
    assert_eq!(frame(&app).topology, Topology::Lines);
}

#[test]
fn a_requested_model_is_loaded_and_framed_in_the_same_frame() {
    let config = Config {
        model: ModelSource::parse("assets/cube.in"),
        ..Config::default()
    };
    let viewport = Viewport {
        width: 640,
        height: 480,
    };
    let mut app = close2gl::build_app(&config, viewport).expect("the cube loads");
    let (centre, _) = mesh(&mut app).bounding_sphere();
    assert_eq!(
        camera(&mut app).target,
        centre,
        "framed in the load's frame"
    );
    assert!(frame(&app).counts.drawn > 0, "and drawn by Close2GL");
    let status = app.world().resource::<ModelStatus>();
    assert_eq!((status.generation, status.error.as_ref()), (1, None));
}

#[test]
fn a_model_that_does_not_load_is_an_error_before_anything_is_shown() {
    let config = Config {
        model: ModelSource::parse("no/such/model.in"),
        ..Config::default()
    };
    let viewport = Viewport::default();
    match close2gl::build_app(&config, viewport) {
        Ok(_) => panic!("a missing file built an app"),
        Err(error) => assert!(
            error.starts_with("no/such/model.in: cannot read"),
            "{error}"
        ),
    }
}

#[test]
fn a_plugin_without_the_resources_it_needs_names_the_plugin_that_provides_them() {
    let mut app = App::new();
    app.add_plugins(SettingsPlugin).add_plugins(InputPlugin);
    let error = app
        .check_requirements()
        .expect_err("the camera plugin is missing");
    assert_eq!(
        error,
        "InputPlugin needs the CameraActions resource: add CameraPlugin (or insert \
         CameraActions yourself)"
    );
    app.add_plugins(CameraPlugin);
    assert_eq!(app.check_requirements(), Ok(()));
}

/// The app the viewer runs, headless: the default plugins, the GPU's uploads, the outside view,
/// the panel, the viewer's own systems and the file watch.
fn viewer_app() -> App {
    let mut app = close2gl::build_app(&Config::default(), Viewport::default()).expect("loads");
    app.add_plugins(close2gl_gpu::GpuPlugin)
        .add_plugins(close2gl_gpu::outside::OutsidePlugin)
        .add_plugins(close2gl_ui::UiPlugin)
        .add_plugins(close2gl_viewer::ViewerSystemsPlugin)
        .add_plugins(WatchPlugin {
            config_file: None,
            reload: Arc::new(|| Ok(Config::default())),
        });
    app.update();
    app
}

#[test]
fn every_system_sits_in_one_frame_set_of_the_one_schedule() {
    let app = viewer_app();
    let schedules = app.world().resource::<Schedules>();
    let labels: Vec<String> = schedules
        .iter()
        .map(|(label, _)| format!("{label:?}"))
        .collect();
    assert_eq!(labels, ["Update"], "the frame has one schedule");
    let schedule = schedules.get(Update).expect("the frame schedule");
    let mut per_set = [0; FrameSet::ALL.len()];
    for (key, system) in schedule.systems().expect("the schedule has run") {
        // The sync points bevy inserts between sets are not a plugin's.
        if system.system_type() == TypeId::of::<ApplyDeferred>() {
            continue;
        }
        let sets: Vec<usize> = (0..FrameSet::ALL.len())
            .filter(|&i| {
                schedule
                    .graph()
                    .systems_in_set(FrameSet::ALL[i].intern())
                    .is_ok_and(|systems| systems.contains(&key))
            })
            .collect();
        assert_eq!(
            sets.len(),
            1,
            "{} is in {} FrameSets",
            system.name(),
            sets.len()
        );
        per_set[sets[0]] += 1;
    }
    // Every set has a system of the viewer's, so the walk above saw each of them.
    assert!(!per_set.contains(&0), "systems per FrameSet: {per_set:?}");
}

/// The camera plugin is the one system of the viewer's app that writes the `Camera`: the others
/// read it and ask through `CameraRequest`. Exclusive systems (the panel's, the watch's) could
/// write anything; they are held to asking by their own tests (`plugins/ui/tests/panel.rs`,
/// `tests/watch.rs`), and only they are let through here.
#[test]
fn the_camera_plugin_is_the_one_system_that_writes_the_camera() {
    let mut app = viewer_app();
    let camera = app.world_mut().register_component::<Camera>();
    let schedules = app.world().resource::<Schedules>();
    let schedule = schedules.get(Update).expect("the frame schedule");
    let camera_plugins = [
        apply_camera_edit.into_system_set().intern(),
        frame_new_model.into_system_set().intern(),
        apply_camera_actions.into_system_set().intern(),
        apply_camera_replacement.into_system_set().intern(),
    ];
    let of_the_camera_plugin = |key| {
        camera_plugins.iter().any(|&set| {
            (schedule.graph().systems_in_set(set)).is_ok_and(|systems| systems.contains(&key))
        })
    };
    let mut writers = 0;
    for (key, system) in schedule
        .systems_with_access()
        .expect("the schedule has run")
    {
        if let SystemAccess::Shared(access) = system.access()
            && access.combined_access().has_write(camera)
        {
            writers += 1;
            let name = system.system().name();
            assert!(of_the_camera_plugin(key), "{name} writes the Camera");
        }
    }
    assert_eq!(
        writers,
        camera_plugins.len(),
        "each of the camera plugin's systems writes it"
    );
}

/// The cube, just loaded, and a trace from (0, 0, 5) looking down −z asked for: one frame run.
fn app_showing_one_trace(name: &str) -> App {
    let dir = close2gl_testkit::TempDir::new(name);
    let path = dir.join("one.trace");
    let trace = "close2gl-trace 1\nwindow 640 480\ncamera position 0 0 5\ncamera u 1 0 0\n\
                 camera v 0 1 0\ncamera n 0 0 1\ncamera hfov 60\ncamera vfov 60\ncamera near 1\n\
                 camera far 10\ntri 0 10 10 100 10 10 100\n";
    std::fs::write(&path, trace).expect("write the trace");
    let viewport = Viewport {
        width: 640,
        height: 480,
    };
    let mut app = world_with(cube(), Camera::default(), viewport);
    app.add_plugins(CameraPlugin)
        .add_plugins(Close2glPlugin)
        .add_plugins(close2gl_trace::TracePlugin);
    app.world_mut()
        .resource_mut::<close2gl_trace::view::TraceRequest>()
        .0 = Some(path);
    app.update();
    app
}

/// A trace loaded in the frame a model arrives is drawn from the trace's camera in that frame:
/// the camera plugin frames the new model, then sets the camera the trace asked for, before
/// the pipeline runs.
#[test]
fn a_trace_loaded_with_a_new_model_is_drawn_from_its_camera_in_that_frame() {
    let mut app = app_showing_one_trace("systems_trace_camera");
    let shown = camera(&mut app);
    assert_eq!(
        (shown.position, shown.n, shown.hfov, shown.near, shown.far),
        (Vec3::new(0.0, 0.0, 5.0), Vec3::Z, 60.0, 1.0, 10.0)
    );
    let switches = *app.world().resource::<PipelineSettings>();
    let viewport = *app.world().resource::<Viewport>();
    let expected = close2gl::pipeline::textbook::run(&cube(), &shown, &switches, viewport);
    assert_eq!(frame(&app).vertices, expected.vertices);
}

/// A shown trace has an output of its own: the pipeline's frame stays what the pipeline drew
/// (its counts describe it), the trace's 2D output goes to `TraceOutput` in the view's pixels,
/// and once no trace is shown there is none.
#[test]
fn a_shown_trace_writes_its_own_output_and_leaves_the_pipelines_frame_alone() {
    use close2gl::core::TraceOutput;
    use close2gl_trace::view::TraceView;
    let mut app = app_showing_one_trace("systems_trace_output");
    let shown = app.world().resource::<TraceOutput>().0.clone();
    // ortho2d 0 640 0 480 is y up; the view's pixels are y down.
    let expected = vec![[10.0, 470.0], [100.0, 470.0], [10.0, 380.0]];
    assert_eq!(shown, Some(expected.clone()));
    let pipeline = &frame(&app).vertices;
    assert!(
        !pipeline.is_empty() && *pipeline != expected,
        "the pipeline's frame is its own: {pipeline:?}"
    );
    app.world_mut().resource_mut::<TraceView>().shown = None;
    app.update();
    assert_eq!(app.world().resource::<TraceOutput>().0, None);
}

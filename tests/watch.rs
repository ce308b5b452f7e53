//! `--watch` on a headless app: the real config and model files in a temporary directory,
//! changed on disk while the app runs frames, as an editor would save them.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::{Duration, Instant};

use close2gl::config;
use close2gl::core::glam::Vec3;
use close2gl::core::{App, Camera, ModelStatus, PipelineSettings, RenderMode, Viewport};
use close2gl::watch::WatchPlugin;
use close2gl_testkit::{TempDir, camera};

/// How long a change may take to be seen (the watch polls four times a second and waits for
/// one quiet poll).
const NOTICED_WITHIN: Duration = Duration::from_secs(10);

const TETRA: &str = include_str!("../plugins/model/tests/data/tetra.in");

struct Files {
    /// Kept for its lifetime: the directory goes when the files do.
    _dir: TempDir,
    config: PathBuf,
    model: PathBuf,
}

impl Files {
    fn new(name: &str) -> Files {
        let dir = TempDir::new(&format!("watch_{name}"));
        let files = Files {
            config: dir.join("config.toml"),
            model: dir.join("tetra.in"),
            _dir: dir,
        };
        std::fs::write(&files.model, TETRA).expect("the model");
        files.write_config("solid");
        files
    }

    fn write_config(&self, mode: &str) {
        let text = format!("[model]\npath = \"tetra.in\"\n[render]\nmode = \"{mode}\"\n");
        std::fs::write(&self.config, text).expect("the config");
    }

    /// The app as `close2gl --config DIR/config.toml --watch` builds it, without the windows.
    fn app(&self) -> App {
        let file = self.config.clone();
        let load = move || config::load(Some(&file), &[]);
        let config = load().expect("the config loads");
        let viewport = Viewport {
            width: 320,
            height: 240,
        };
        let mut app = close2gl::build_app(&config, viewport).expect("the app");
        app.add_plugins(WatchPlugin {
            config_file: Some(self.config.clone()),
            reload: Arc::new(load),
        });
        app.update();
        app
    }
}

/// Runs frames until `done` holds; panics naming `what` when it does not in time.
fn frames_until(app: &mut App, what: &str, done: impl Fn(&App) -> bool) {
    let started = Instant::now();
    while !done(app) {
        assert!(
            started.elapsed() < NOTICED_WITHIN,
            "not seen in time: {what}"
        );
        std::thread::sleep(Duration::from_millis(50));
        app.update();
    }
}

fn mesh_positions(app: &mut App) -> Vec<Vec3> {
    close2gl_testkit::mesh(app).positions.clone()
}

fn error(app: &App) -> Option<String> {
    app.world().resource::<ModelStatus>().error.clone()
}

/// The tetrahedron moved by `dx` along x: another valid save of the same file.
fn moved_tetra(dx: f32) -> String {
    TETRA
        .lines()
        .map(
            |line| match line.split_whitespace().collect::<Vec<_>>()[..] {
                [tag @ ("v0" | "v1" | "v2"), x, ref rest @ ..] => {
                    let x: f32 = x.parse().expect("a number");
                    format!("{tag} {} {}", x + dx, rest.join(" "))
                }
                _ => line.to_string(),
            },
        )
        .collect::<Vec<_>>()
        .join("\n")
}

fn write(path: &Path, text: &str) {
    std::fs::write(path, text).expect("the file is written");
}

#[test]
fn a_saved_model_is_reloaded_and_the_camera_stays_where_it_is() {
    let files = Files::new("model");
    let mut app = files.app();
    let before = mesh_positions(&mut app);
    // The user has flown somewhere: that pose must survive the reload.
    let flown = Camera {
        position: Vec3::new(0.3, 2.0, 4.0),
        ..camera(&mut app)
    };
    let mut cameras = app.world_mut().query::<&mut Camera>();
    *cameras.single_mut(app.world_mut()).expect("one camera") = flown;

    write(&files.model, &moved_tetra(0.5));
    frames_until(&mut app, "the model reloaded", |app| {
        app.world().resource::<ModelStatus>().generation > 1
    });

    let after = mesh_positions(&mut app);
    assert_eq!(after.len(), before.len());
    assert!((after[0].x - before[0].x - 0.5).abs() < 1e-6, "{after:?}");
    assert_eq!(camera(&mut app), flown, "the camera did not move");
    assert_eq!(error(&app), None);
}

#[test]
fn a_broken_save_shows_its_error_and_the_last_good_model_stays() {
    let files = Files::new("broken");
    let mut app = files.app();
    let before = mesh_positions(&mut app);

    write(&files.model, "Object name = TETRA\n# triangles = oops\n");
    frames_until(&mut app, "the error", |app| error(app).is_some());

    let message = error(&app).unwrap_or_default();
    assert!(
        message.contains("tetra.in:2"),
        "names file and line: {message}"
    );
    assert_eq!(
        mesh_positions(&mut app),
        before,
        "the last good model stays"
    );

    // Fixed again: reloaded, and the error is gone.
    write(&files.model, &moved_tetra(1.0));
    frames_until(&mut app, "the fixed model", |app| {
        app.world().resource::<ModelStatus>().generation > 1
    });
    assert_eq!(error(&app), None);
}

#[test]
fn a_saved_config_applies_its_settings_and_a_broken_one_changes_nothing() {
    let files = Files::new("config");
    let mut app = files.app();
    let pose = camera(&mut app);
    assert_eq!(
        app.world().resource::<PipelineSettings>().mode,
        RenderMode::Solid
    );

    files.write_config("wireframe");
    frames_until(&mut app, "wireframe from the config", |app| {
        app.world().resource::<PipelineSettings>().mode == RenderMode::Wireframe
    });
    assert_eq!(camera(&mut app).position, pose.position, "the pose stays");

    files.write_config("no_such_mode");
    frames_until(&mut app, "the config's error", |app| error(app).is_some());
    let message = error(&app).unwrap_or_default();
    assert!(
        message.contains("config.toml") && message.contains("render.mode"),
        "{message}"
    );
    assert_eq!(
        app.world().resource::<PipelineSettings>().mode,
        RenderMode::Wireframe,
        "nothing half-applied"
    );
}

/// A saved config's lens reaches the camera by the mapping the app starts with
/// (`CameraConfig::set_lens`): both fields of view, and a pinned near beyond the camera's far
/// moves far past it; the pose stays.
#[test]
fn a_saved_configs_lens_reaches_the_camera_and_its_pose_stays() {
    let files = Files::new("lens");
    let mut app = files.app();
    let before = camera(&mut app);
    let near = before.far * 2.0;
    let text = format!(
        "[model]\npath = \"tetra.in\"\n[render]\nmode = \"wireframe\"\n\
         [camera]\nhfov = 45.0\nvfov = 30.0\nnear = {near:?}\n"
    );
    write(&files.config, &text);
    frames_until(&mut app, "the saved config", |app| {
        app.world().resource::<PipelineSettings>().mode == RenderMode::Wireframe
    });
    let after = camera(&mut app);
    assert_eq!((after.hfov, after.vfov, after.near), (45.0, 30.0, near));
    assert!(after.far > after.near, "far {} before near", after.far);
    assert_eq!(after.position, before.position, "the pose stays");
}

/// A trace shown with --watch is read again when the program writes it again: its new camera
/// and check's new report replace the old; a half-written or broken trace shows its error and
/// the last good one stays.
#[test]
fn a_shown_trace_is_read_again_when_the_program_writes_it_again() {
    use close2gl_trace::view::{TraceRequest, TraceView};
    let files = Files::new("trace");
    let trace = files.model.with_file_name("frame.trace");
    let write = |x: f32| {
        let text = format!(
            "close2gl-trace 1\nwindow 320 240\ncamera position {x} 0 5\ncamera u 1 0 0\n\
             camera v 0 1 0\ncamera n 0 0 1\ncamera hfov 60\ncamera vfov 60\ncamera near 1\n\
             camera far 20\nend\n"
        );
        std::fs::write(&trace, text).expect("the trace");
    };
    write(0.0);
    let mut app = files.app();
    app.world_mut().resource_mut::<TraceRequest>().0 = Some(trace.clone());
    app.update();
    assert_eq!(camera(&mut app).position, Vec3::new(0.0, 0.0, 5.0));
    // The watch takes up the shown trace's file on the frame after it is shown.
    app.update();
    write(1.5);
    frames_until(&mut app, "the trace written again", |app| {
        app.world()
            .resource::<TraceView>()
            .shown
            .as_ref()
            .is_some_and(|s| s.trace.camera.position.x == 1.5)
    });
    assert_eq!(camera(&mut app).position, Vec3::new(1.5, 0.0, 5.0));
    std::fs::write(&trace, "close2gl-trace 1\nwindow 320\n").expect("a broken trace");
    frames_until(&mut app, "the broken trace's error", |app| {
        app.world().resource::<TraceView>().error.is_some()
    });
    let view = app.world().resource::<TraceView>();
    assert!(
        view.error
            .as_deref()
            .is_some_and(|e| e.contains("frame.trace:2:")),
        "{:?}",
        view.error
    );
    assert!(
        view.shown
            .as_ref()
            .is_some_and(|s| s.trace.camera.position.x == 1.5),
        "the last good one stays"
    );
}

/// A raster trace shown with --watch is read again when the program writes its framebuffer
/// after the trace: the buffers are watched with it.
#[test]
fn a_shown_raster_trace_is_read_again_when_its_framebuffer_is_written_again() {
    use close2gl_trace::view::{TraceRequest, TraceView};
    let files = Files::new("raster");
    let trace = files.model.with_file_name("frame.raster");
    let framebuffer = files.model.with_file_name("frame.ppm");
    let write_framebuffer = |red: u8| {
        let text = format!("P3\n2 1\n255\n{red} 0 0 {red} 0 0\n");
        std::fs::write(&framebuffer, text).expect("the framebuffer");
    };
    write_framebuffer(10);
    let text = "close2gl-raster 1\nwindow 2 1\nframebuffer frame.ppm\nattributes window\nend\n";
    std::fs::write(&trace, text).expect("the trace");
    let mut app = files.app();
    app.world_mut().resource_mut::<TraceRequest>().0 = Some(trace.clone());
    app.update();
    let red = |app: &App| {
        let view = app.world().resource::<TraceView>();
        (view.raster.as_ref()).map(|r| r.frame.framebuffer.pixels[0][0])
    };
    assert_eq!(
        red(&app),
        Some(10),
        "{:?}",
        app.world().resource::<TraceView>().error
    );
    // The watch takes up the shown trace's files on the frame after it is shown.
    app.update();
    write_framebuffer(200);
    frames_until(&mut app, "the framebuffer written again", |app| {
        red(app) == Some(200)
    });
}

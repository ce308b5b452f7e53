//! A model file too big to load within a frame loads on a worker thread, on the headless app the
//! commands and the viewer run: the last model stays shown (and framed) while `ModelStatus`
//! says how far the load is; the frame that finds it done swaps the mesh in and frames it; a
//! newer request cancels it. A replay holds it to the frames the recording saw.

use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};

use close2gl::config::Config;
use close2gl_core::limits::BACKGROUND_LOAD_BYTES;
use close2gl_core::{
    App, Camera, LoadPace, Loading, Mesh, ModelRequest, ModelSource, ModelStatus, PrimitiveKind,
    Viewport,
};
use close2gl_testkit::{GridFile, TempDir, write_grid_in};

/// A grid file in `dir` just big enough to load in the background.
fn big(dir: &TempDir, name: &str) -> (PathBuf, GridFile) {
    let path = dir.0.join(format!("{name}.in"));
    let grid = write_grid_in(&path, name, 170).expect("write the grid");
    assert!(grid.bytes > BACKGROUND_LOAD_BYTES, "{} B", grid.bytes);
    (path, grid)
}

/// The headless app with the bundled cube loaded and framed.
fn app_with_the_cube() -> App {
    let config = Config {
        model: ModelSource::parse("assets/cube.in"),
        ..Config::default()
    };
    close2gl::build_app(&config, Viewport::default()).expect("the cube loads")
}

fn request(app: &mut App, path: &Path) {
    app.world_mut().resource_mut::<ModelRequest>().0 = Some(ModelSource::File(path.into()));
    app.update();
}

fn status(app: &App) -> ModelStatus {
    app.world().resource::<ModelStatus>().clone()
}

fn mesh(app: &mut App) -> Mesh {
    let world = app.world_mut();
    world
        .query::<&Mesh>()
        .single(world)
        .expect("one mesh")
        .clone()
}

fn camera(app: &mut App) -> Camera {
    close2gl_testkit::camera(app)
}

/// Runs frames until no load is in flight, and returns the fractions seen on the way.
fn until_loaded(app: &mut App) -> Vec<f32> {
    let started = Instant::now();
    let mut fractions = Vec::new();
    while let Some(Loading { fraction, .. }) = status(app).loading {
        fractions.push(fraction);
        assert!(
            started.elapsed() < Duration::from_secs(120),
            "still loading after 2 minutes"
        );
        std::thread::sleep(Duration::from_millis(5));
        app.update();
    }
    fractions
}

#[test]
fn a_big_file_loads_in_the_background_while_the_last_model_stays() {
    let dir = TempDir::new("background_load");
    let (path, grid) = big(&dir, "grid");
    let mut app = app_with_the_cube();
    let cube = mesh(&mut app);
    let cube_camera = camera(&mut app);

    request(&mut app, &path);
    let loading = status(&app).loading.expect("loading in the background");
    assert_eq!(loading.source, ModelSource::File(path.clone()));
    assert!((0.0..=1.0).contains(&loading.fraction));
    assert_eq!(mesh(&mut app), cube, "the last model stays");
    assert_eq!(camera(&mut app), cube_camera, "and so does its framing");
    assert_eq!(status(&app).generation, 1);

    let fractions = until_loaded(&mut app);
    assert!(
        fractions.windows(2).all(|w| w[0] <= w[1] && w[1] <= 1.0),
        "{fractions:?}"
    );
    let loaded = mesh(&mut app);
    assert_eq!(loaded.name, "grid");
    assert_eq!(loaded.triangles.len(), grid.triangles);
    assert_eq!(loaded.positions.len(), grid.vertices);
    let after = status(&app);
    assert_eq!(
        (after.generation, after.error, after.loading),
        (2, None, None)
    );
    let (centre, _) = loaded.bounding_sphere();
    assert_eq!(camera(&mut app).target, centre, "framed when it came in");
}

#[test]
fn a_replay_shows_the_recorded_progress_and_brings_the_model_in_on_the_recorded_frame() {
    let dir = TempDir::new("replay_pace");
    let (path, grid) = big(&dir, "grid");
    let mut app = app_with_the_cube();
    let cube = mesh(&mut app);
    app.insert_resource(LoadPace::Replay(Some(0.0)));
    request(&mut app, &path);
    // The worker is done long before this (about 0.1 s), but the recording says the load went on.
    std::thread::sleep(Duration::from_secs(1));
    for fraction in [0.25, 0.75] {
        app.insert_resource(LoadPace::Replay(Some(fraction)));
        app.update();
        assert_eq!(status(&app).loading.map(|l| l.fraction), Some(fraction));
        assert_eq!(mesh(&mut app), cube, "not in before its recorded frame");
    }
    // Its frame: it comes in, waited for if need be, and is framed.
    app.insert_resource(LoadPace::Replay(None));
    app.update();
    let after = status(&app);
    assert_eq!((after.generation, after.loading), (2, None));
    let loaded = mesh(&mut app);
    assert_eq!(loaded.triangles.len(), grid.triangles);
    assert_eq!(camera(&mut app).target, loaded.bounding_sphere().0);
}

#[test]
fn a_newer_request_supersedes_a_load_in_flight() {
    let dir = TempDir::new("supersede");
    let (first, _) = big(&dir, "first");
    let (second, _) = big(&dir, "second");
    let mut app = app_with_the_cube();

    request(&mut app, &first);
    request(&mut app, &second);
    assert_eq!(
        status(&app).loading.map(|l| l.source),
        Some(ModelSource::File(second.clone()))
    );
    until_loaded(&mut app);
    assert_eq!(mesh(&mut app).name, "second");
    assert_eq!(status(&app).generation, 2, "the first never came in");

    // A primitive (instant) supersedes a big file: the file's result is dropped.
    request(&mut app, &first);
    app.world_mut().resource_mut::<ModelRequest>().0 =
        Some(ModelSource::Primitive(PrimitiveKind::Box));
    app.update();
    assert_eq!(status(&app).loading, None);
    assert_eq!(mesh(&mut app).name, "box");
    for _ in 0..40 {
        std::thread::sleep(Duration::from_millis(10));
        app.update();
    }
    assert_eq!(mesh(&mut app).name, "box");
    assert_eq!(status(&app).generation, 3);
}

#[test]
fn a_big_file_that_fails_keeps_the_last_model_and_says_where() {
    let dir = TempDir::new("background_error");
    let (path, _) = big(&dir, "broken");
    let mut text = std::fs::read_to_string(&path).expect("read");
    text.push_str("v0 1 2\n");
    std::fs::write(&path, text).expect("write");
    let mut app = app_with_the_cube();
    let cube = mesh(&mut app);
    request(&mut app, &path);
    until_loaded(&mut app);
    let error = status(&app).error.expect("an error");
    assert!(
        error.starts_with(&format!("{}:", path.display())),
        "{error}"
    );
    assert!(
        error.contains("expected 'v0 x y z nx ny nz material'"),
        "{error}"
    );
    assert_eq!(mesh(&mut app), cube);
    assert_eq!(status(&app).generation, 1);
}

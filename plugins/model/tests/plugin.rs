//! The model plugin on a headless world: a request replaces the mesh or reports an error and
//! keeps the old one.

use bevy_ecs::prelude::*;
use close2gl_core::{
    App, FrameSet, Mesh, ModelRequest, ModelSource, ModelStatus, PrimitiveKind, PrimitiveParams,
    Texture, TextureRequest, Update,
};
use close2gl_model::ModelPlugin;

/// How many frames saw a changed mesh (what the camera plugin's framing reacts to).
#[derive(Resource, Default)]
struct MeshChanges(usize);

fn count_mesh_changes(meshes: Query<(), Changed<Mesh>>, mut changes: ResMut<MeshChanges>) {
    changes.0 += meshes.iter().count();
}

fn app() -> App {
    let mut app = App::new();
    app.add_plugins(ModelPlugin)
        .init_resource::<MeshChanges>()
        .add_systems(Update, count_mesh_changes.in_set(FrameSet::Output));
    app
}

fn request(app: &mut App, source: ModelSource) {
    app.world_mut().resource_mut::<ModelRequest>().0 = Some(source);
    app.update();
}

fn meshes(app: &mut App) -> Vec<Mesh> {
    let world = app.world_mut();
    world.query::<&Mesh>().iter(world).cloned().collect()
}

fn status(app: &App) -> ModelStatus {
    app.world().resource::<ModelStatus>().clone()
}

#[test]
fn a_request_replaces_the_one_mesh_and_bumps_the_generation() {
    let mut app = app();
    app.world_mut().spawn(Mesh {
        name: "old".into(),
        ..Mesh::default()
    });
    app.update();
    let before = app.world().resource::<MeshChanges>().0;

    let torus = ModelSource::Primitive(PrimitiveKind::Torus);
    request(&mut app, torus.clone());
    let meshes = meshes(&mut app);
    assert_eq!(meshes.len(), 1);
    assert_eq!(meshes[0].name, "torus");
    assert_eq!(app.world().resource::<MeshChanges>().0, before + 1);
    assert_eq!(
        status(&app),
        ModelStatus {
            source: Some(torus),
            warnings: Vec::new(),
            error: None,
            generation: 1,
            loading: None,
        }
    );
    assert_eq!(
        app.world().resource::<ModelRequest>().0,
        None,
        "the request is taken"
    );

    request(&mut app, ModelSource::Primitive(PrimitiveKind::Cone));
    assert_eq!(status(&app).generation, 2);
}

#[test]
fn a_failed_load_keeps_the_previous_mesh_and_only_sets_the_error() {
    let mut app = app();
    request(&mut app, ModelSource::Primitive(PrimitiveKind::Box));
    let loaded = status(&app);
    let changes = app.world().resource::<MeshChanges>().0;

    request(&mut app, ModelSource::File("/nonexistent/cow.in".into()));
    let failed = status(&app);
    assert_eq!(meshes(&mut app)[0].name, "box");
    assert_eq!(
        app.world().resource::<MeshChanges>().0,
        changes,
        "no change"
    );
    assert_eq!(failed.source, loaded.source);
    assert_eq!(failed.generation, loaded.generation);
    assert!(
        failed
            .error
            .as_deref()
            .is_some_and(|e| e.starts_with("/nonexistent/cow.in: cannot read")),
        "{failed:?}"
    );

    // A good load afterwards clears the error.
    request(&mut app, ModelSource::Primitive(PrimitiveKind::Sphere));
    assert_eq!(status(&app).error, None);
    assert_eq!(meshes(&mut app)[0].name, "sphere");
}

#[test]
fn a_world_without_a_mesh_gets_one() {
    let mut app = app();
    assert!(meshes(&mut app).is_empty());
    request(&mut app, ModelSource::Primitive(PrimitiveKind::Cylinder));
    assert_eq!(meshes(&mut app).len(), 1);
}

#[test]
fn the_primitive_params_resource_is_used() {
    let mut app = app();
    app.insert_resource(PrimitiveParams {
        cone_slices: 5,
        ..PrimitiveParams::default()
    });
    request(&mut app, ModelSource::Primitive(PrimitiveKind::Cone));
    assert_eq!(meshes(&mut app)[0].triangles.len(), 10);
}

#[test]
fn frames_without_a_request_do_nothing() {
    let mut app = app();
    app.update();
    app.update();
    assert_eq!(status(&app), ModelStatus::default());
    assert!(meshes(&mut app).is_empty());
}

fn texture_request(app: &mut App, path: &std::path::Path) {
    app.world_mut().resource_mut::<TextureRequest>().0 = Some(path.to_path_buf());
    app.update();
}

/// The checkerboard until an image is asked for; a PNG replaces it (a new generation, the file's
/// texels); a file that is missing or not an image removes it (the model shows untextured) and
/// the error names the file.
#[test]
fn a_texture_request_loads_the_image_or_leaves_the_model_untextured() {
    let dir = std::env::temp_dir().join(format!("close2gl-texture-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("a temp dir");
    let mut app = app();
    app.update();
    let texture = app.world().resource::<Texture>().clone();
    assert_eq!(
        (texture.source, texture.image.width),
        (None, 256),
        "the checkerboard"
    );

    let png = dir.join("two.png");
    let mut image = image::RgbaImage::new(2, 1);
    image.put_pixel(1, 0, image::Rgba([10, 20, 30, 255]));
    image.save(&png).expect("write a PNG");
    texture_request(&mut app, &png);
    let texture = app.world().resource::<Texture>().clone();
    assert_eq!(texture.source.as_deref(), Some(png.as_path()));
    assert_eq!(texture.image.pixels, vec![[0, 0, 0, 0], [10, 20, 30, 255]]);

    let not_an_image = dir.join("notes.png");
    std::fs::write(&not_an_image, "not a picture").expect("write");
    for bad in [dir.join("missing.png"), not_an_image] {
        texture_request(&mut app, &bad);
        assert!(
            app.world().get_resource::<Texture>().is_none(),
            "untextured"
        );
        let error = status(&app).error.expect("an error");
        assert!(error.starts_with(&bad.display().to_string()), "{error}");
        assert_eq!(error.lines().count(), 1, "{error}");
    }
}

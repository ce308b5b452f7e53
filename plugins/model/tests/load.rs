//! `load`: choosing the loader by extension, reading files, and reporting what cannot be read.

use std::path::{Path, PathBuf};

use close2gl_core::{ModelSource, PrimitiveKind, PrimitiveParams};
use close2gl_model::load;

fn data(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data")
        .join(name)
}

/// A file of this test run's own, removed when dropped.
struct TempFile(PathBuf);

impl TempFile {
    fn new(name: &str, contents: &[u8]) -> Self {
        let path =
            std::env::temp_dir().join(format!("close2gl_model_{}_{name}", std::process::id()));
        std::fs::write(&path, contents).unwrap();
        Self(path)
    }

    fn source(&self) -> ModelSource {
        ModelSource::File(self.0.clone())
    }
}

impl Drop for TempFile {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

fn load_file(path: &Path) -> Result<close2gl_model::LoadedModel, String> {
    load(
        &ModelSource::File(path.to_path_buf()),
        &PrimitiveParams::default(),
    )
}

#[test]
fn the_samples_load_from_disk() {
    let tetra = load_file(&data("tetra.in")).unwrap();
    assert_eq!(tetra.mesh.triangles.len(), 4);
    let quad = load_file(&data("quad_two_materials.in")).unwrap();
    assert_eq!(quad.mesh.triangles.len(), 2);
}

#[test]
fn extensions_are_matched_whatever_their_case() {
    let obj = TempFile::new("tri.OBJ", b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    let model = load(&obj.source(), &PrimitiveParams::default()).unwrap();
    assert_eq!(model.mesh.triangles.len(), 1);
    assert!(model.mesh.name.ends_with("tri"));

    let tetra = std::fs::read(data("tetra.in")).unwrap();
    let upper = TempFile::new("tetra.IN", &tetra);
    let model = load(&upper.source(), &PrimitiveParams::default()).unwrap();
    assert_eq!(model.mesh.name, "TETRA");
}

#[test]
fn other_extensions_are_an_error_naming_the_file_and_the_accepted_ones() {
    let error = load_file(Path::new("models/cow.stl")).unwrap_err();
    assert_eq!(
        error,
        "models/cow.stl: unsupported model file: expected a .in or .obj file \
         (or a primitive: box, sphere, torus, cone, cylinder)"
    );
    assert!(
        load_file(Path::new("models/cow"))
            .unwrap_err()
            .starts_with("models/cow: unsupported")
    );
}

#[test]
fn an_unreadable_path_is_an_error_naming_it() {
    let error = load_file(Path::new("/nonexistent/cow.in")).unwrap_err();
    assert!(
        error.starts_with("/nonexistent/cow.in: cannot read: "),
        "{error}"
    );
    assert!(!error.contains('\n'));
}

#[test]
fn invalid_utf8_is_an_error_at_its_line() {
    let mut bytes = std::fs::read(data("tetra.in")).unwrap();
    let at = bytes.windows(2).position(|w| w == b"v1").unwrap();
    bytes[at + 1] = 0xff;
    let file = TempFile::new("broken.in", &bytes);
    let error = load(&file.source(), &PrimitiveParams::default()).unwrap_err();
    let label = file.0.display().to_string();
    assert!(
        error.starts_with(&format!(
            "{label}:10: expected 'v1 x y z nx ny nz material', found 'v\u{fffd} "
        )),
        "{error}"
    );
}

#[test]
fn primitives_are_built_from_the_params() {
    for &kind in PrimitiveKind::ALL {
        let model = load(&ModelSource::Primitive(kind), &PrimitiveParams::default()).unwrap();
        model.mesh.validate().unwrap();
        assert!(model.warnings.is_empty());
    }
    let params = PrimitiveParams {
        sphere_stacks: 0,
        ..PrimitiveParams::default()
    };
    let error = load(&ModelSource::Primitive(PrimitiveKind::Sphere), &params).unwrap_err();
    assert_eq!(
        error,
        "primitives.sphere_stacks: expected 2..=4096, found 0"
    );
}

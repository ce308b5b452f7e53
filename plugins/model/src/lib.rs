//! The model plugin. It owns turning a `ModelSource` into a `Mesh`: the course's `.in` triangle
//! files (every variant the README's Models section lists), Wavefront `.obj` files (through tobj),
//! and the shading lecture's primitives (box, sphere, torus, cone, cylinder) with exact normals.
//! Its system reads and takes the `ModelRequest` resource, reads `PrimitiveParams`, replaces the
//! one `Mesh` component (spawning it if there is none) and writes `ModelStatus`. A load that
//! fails leaves the previous mesh untouched and only sets `ModelStatus::error`. A file too big
//! to load within a frame loads on a worker thread (its own `BackgroundLoad` resource), with
//! `ModelStatus::loading` saying how far it is, and is swapped in by the frame that finds it
//! done (in a replay, the frame the recording says: `LoadPace`, which the viewer sets). It owns
//! `ModelRequest`, `ModelStatus`, `PrimitiveParams`, `BackgroundLoad` and `LoadPace`, and runs
//! in `FrameSet::Load`'s first step (`LoadStep::Files`). It owns the model's `Texture` too (the course's checkerboard until a
//! `TextureRequest` names a PNG or JPEG file; a file that does not load removes it, so the
//! model shows untextured, and sets the error). Framing the camera on the new mesh is the
//! camera plugin's job (it watches `Changed<Mesh>`, in `FrameSet::Camera`).

mod background;
mod corner_index;
#[cfg(test)]
mod damage;
mod decimal;
mod diagnostics;
mod image_file;
mod in_format;
mod in_parallel;
mod in_triangles;
mod line_reader;
mod mesh_builder;
mod obj;
mod primitives;
mod progress;
mod words;

use std::path::Path;

use bevy_ecs::prelude::*;
use close2gl_core::{
    App, LoadPace, LoadStep, Mesh, ModelRequest, ModelSource, ModelStatus, Plugin, PrimitiveParams,
    Texture, TextureRequest, Update,
};

pub use background::BackgroundLoad;
pub use image_file::load_texture;
pub use in_format::parse_in;
pub use obj::parse_obj;
pub use primitives::primitive;

use background::Poll;
use progress::{Counted, LoadProgress};

/// A mesh ready to show, and what the loader noticed but forgave (e.g. a header that lies about
/// its triangle count).
#[derive(Clone, Debug, PartialEq)]
pub struct LoadedModel {
    pub mesh: Mesh,
    pub warnings: Vec<String>,
}

/// Loads a `.in` or `.obj` file (chosen by extension, case-insensitive) or builds a primitive.
/// Every error is one line naming the file (and the line, where the format allows).
pub fn load(source: &ModelSource, params: &PrimitiveParams) -> Result<LoadedModel, String> {
    match source {
        ModelSource::Primitive(kind) => primitive(*kind, params).map(|mesh| LoadedModel {
            mesh,
            warnings: Vec::new(),
        }),
        ModelSource::File(path) => load_file(path, &LoadProgress::default()),
    }
}

/// Loads a `.in` or `.obj` file, counting what it reads into `progress`. Both stream, so memory
/// follows the mesh, not the file.
pub(crate) fn load_file(path: &Path, progress: &LoadProgress) -> Result<LoadedModel, String> {
    let label = path.display().to_string();
    let extension = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let obj = match extension.as_deref() {
        Some("in") => false,
        Some("obj") => true,
        _ => {
            return Err(format!(
                "{label}: unsupported model file: expected a .in or .obj file \
                 (or a primitive: box, sphere, torus, cone, cylinder)"
            ));
        }
    };
    let cannot_read = |e: std::io::Error| format!("{label}: cannot read: {e}");
    let open_file = || {
        close2gl_core::files::open(path).map_err(|e| match e.kind() {
            std::io::ErrorKind::InvalidInput => {
                format!("{label}: expected a .in or .obj file, found a directory or device")
            }
            _ => cannot_read(e),
        })
    };
    let size = open_file()?.len().map_err(cannot_read)?;
    // An OBJ file is read once; a `.in` file too (its header twice), one with an error again,
    // line by line (see `in_format::read_in`), which the bar does not foresee.
    progress.set_total(size);
    let label = label.as_str();
    // Opened again for each read: a `.in` file with an error is read a second time.
    let open = || {
        Ok(Counted {
            inner: open_file()?,
            progress,
        })
    };
    if obj {
        obj::read_obj(open()?, label)
    } else {
        in_format::read_in(open, size, label)
    }
}

/// The name a mesh gets when its file does not give one: the file's stem.
fn file_stem(label: &str) -> String {
    Path::new(label)
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default()
}

/// Adds the model-loading system; see the crate docs.
pub struct ModelPlugin;

impl Plugin for ModelPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<ModelRequest>()
            .init_resource::<ModelStatus>()
            .init_resource::<PrimitiveParams>()
            .init_resource::<TextureRequest>()
            .init_resource::<Texture>()
            .init_resource::<BackgroundLoad>()
            .init_resource::<LoadPace>()
            .add_systems(
                Update,
                (load_requested_model, load_requested_texture).in_set(LoadStep::Files),
            );
    }
}

/// Serves a pending `ModelRequest`: on success the mesh is replaced in place (so `Changed<Mesh>`
/// fires) and the status moves to the new source; on failure only the error is recorded. A file
/// too big to load within a frame goes to a worker thread instead (`ModelStatus::loading` says
/// how far it is) and is served like this in the frame that finds it done (or, in a replay,
/// the frame `LoadPace` names); a newer request cancels it.
pub fn load_requested_model(
    mut commands: Commands,
    mut request: ResMut<ModelRequest>,
    params: Res<PrimitiveParams>,
    mut status: ResMut<ModelStatus>,
    mut meshes: Query<&mut Mesh>,
    mut background: ResMut<BackgroundLoad>,
    pace: Res<LoadPace>,
) {
    if let Some(source) = request.0.take() {
        background.cancel();
        status.loading = None;
        if let Some(path) = background::big_file(&source) {
            status.loading = background.start(source.clone(), path);
            if status.loading.is_some() {
                return;
            }
        }
        let loaded = load(&source, &params);
        show(&mut commands, &mut status, &mut meshes, source, loaded);
        return;
    }
    match background.poll(*pace) {
        Some(Poll::Done(source, loaded)) => {
            status.loading = None;
            show(&mut commands, &mut status, &mut meshes, source, loaded);
        }
        Some(Poll::Running(fraction)) => {
            // Only a real change marks the status changed.
            if status
                .loading
                .as_ref()
                .is_some_and(|l| l.fraction != fraction)
                && let Some(loading) = status.loading.as_mut()
            {
                loading.fraction = fraction;
            }
        }
        None => {}
    }
}

/// Puts a loaded model in place of the one mesh, or records why it did not load.
fn show(
    commands: &mut Commands,
    status: &mut ModelStatus,
    meshes: &mut Query<&mut Mesh>,
    source: ModelSource,
    loaded: Result<LoadedModel, String>,
) {
    match loaded {
        Ok(loaded) => {
            match meshes.iter_mut().next() {
                Some(mut mesh) => *mesh = loaded.mesh,
                None => {
                    commands.spawn(loaded.mesh);
                }
            }
            *status = ModelStatus {
                source: Some(source),
                warnings: loaded.warnings,
                error: None,
                generation: status.generation + 1,
                loading: None,
            };
        }
        Err(message) => status.error = Some(message),
    }
}

/// Serves a pending `TextureRequest`: on success the texture is replaced; on
/// failure it is removed, so that the model shows untextured, and the error is recorded.
pub fn load_requested_texture(
    mut commands: Commands,
    mut request: ResMut<TextureRequest>,
    mut status: ResMut<ModelStatus>,
) {
    let Some(path) = request.0.take() else {
        return;
    };
    match load_texture(&path) {
        Ok(image) => {
            commands.insert_resource(Texture {
                source: Some(path),
                image,
            });
        }
        Err(message) => {
            commands.remove_resource::<Texture>();
            status.error = Some(message);
        }
    }
}

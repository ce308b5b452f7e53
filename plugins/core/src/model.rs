//! Which model is shown and how it is being loaded: the file or primitive asked for, the
//! texture asked for, and the loading's progress.

use std::path::PathBuf;

use bevy_ecs::prelude::*;
use glam::Vec3;

named_enum!(
    /// The procedural primitives of the shading lecture (002), with exact normals.
    PrimitiveKind {
        Box = "box", Sphere = "sphere", Torus = "torus", Cone = "cone", Cylinder = "cylinder"
    }
);

/// The primitives' parameters (the `[primitives]` config section).
#[derive(Resource, Clone, Copy, Debug, PartialEq)]
pub struct PrimitiveParams {
    /// Box edge lengths along x, y, z.
    pub box_size: Vec3,
    pub sphere_radius: f32,
    /// Sphere subdivisions from pole to pole (the lecture's subh) and around (suba).
    pub sphere_stacks: u32,
    pub sphere_slices: u32,
    /// Torus: r0 from the centre to the tube's centre, r1 the tube's radius; n0 segments around
    /// the ring, n1 around the tube.
    pub torus_r0: f32,
    pub torus_r1: f32,
    pub torus_n0: u32,
    pub torus_n1: u32,
    pub cone_radius: f32,
    pub cone_height: f32,
    pub cone_slices: u32,
    pub cylinder_radius: f32,
    pub cylinder_height: f32,
    pub cylinder_slices: u32,
}

impl Default for PrimitiveParams {
    fn default() -> Self {
        Self {
            box_size: Vec3::ONE,
            sphere_radius: 1.0,
            sphere_stacks: 32,
            sphere_slices: 64,
            torus_r0: 1.0,
            torus_r1: 0.35,
            torus_n0: 64,
            torus_n1: 32,
            cone_radius: 1.0,
            cone_height: 2.0,
            cone_slices: 64,
            cylinder_radius: 1.0,
            cylinder_height: 2.0,
            cylinder_slices: 64,
        }
    }
}

/// Where a model comes from.
#[derive(Clone, Debug, PartialEq)]
pub enum ModelSource {
    /// A `.in` or `.obj` file.
    File(PathBuf),
    Primitive(PrimitiveKind),
}

impl ModelSource {
    /// A primitive's name, or else a path.
    pub fn parse(text: &str) -> Self {
        match PrimitiveKind::from_name(text) {
            Some(kind) => ModelSource::Primitive(kind),
            None => ModelSource::File(PathBuf::from(text)),
        }
    }
}

/// Set it to ask the model plugin for a texture image (a PNG or JPEG file); the plugin takes it
/// and replaces [`crate::Texture`], or reports the error in [`ModelStatus`] and leaves the model
/// untextured.
#[derive(Resource, Clone, Debug, Default, PartialEq)]
pub struct TextureRequest(pub Option<PathBuf>);

/// Set it to ask the model plugin for a (re)load; the plugin takes it and reports in
/// [`ModelStatus`]. A failed load keeps the previous model.
#[derive(Resource, Clone, Debug, Default, PartialEq)]
pub struct ModelRequest(pub Option<ModelSource>);

/// What the model plugin last did: the source shown, its warnings, or the last error.
#[derive(Resource, Clone, Debug, Default, PartialEq)]
pub struct ModelStatus {
    pub source: Option<ModelSource>,
    pub warnings: Vec<String>,
    pub error: Option<String>,
    /// Bumped on every successful load, so renderers know to upload the mesh again.
    pub generation: u64,
    /// A big file being read on a worker thread while `source`'s mesh stays shown.
    pub loading: Option<Loading>,
}

/// A model file loading in the background (see
/// [`crate::limits::BACKGROUND_LOAD_BYTES`]).
#[derive(Clone, Debug, PartialEq)]
pub struct Loading {
    pub source: ModelSource,
    /// How much of the file has been parsed, 0..=1.
    pub fraction: f32,
}

/// When a model loading on a worker thread shows its progress and arrives. Live, as the worker
/// goes. A replay makes every frame show what the recording's frame showed, so that the mesh
/// arrives on the same frame (which frames the camera on it) whatever the machine's speed.
/// The viewer sets it each frame; the model plugin owns it.
#[derive(Resource, Clone, Copy, Debug, Default, PartialEq)]
pub enum LoadPace {
    #[default]
    Live,
    /// The recording's [`Loading::fraction`] at the end of this frame: `Some` shows it and
    /// keeps the load in flight, even if it is done; `None` waits for a load in flight to end.
    Replay(Option<f32>),
}

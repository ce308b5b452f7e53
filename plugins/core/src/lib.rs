//! The shared ECS vocabulary of close2gl. This crate owns the small `App`/`Plugin` pair (a World
//! with its one frame schedule, and the [`FrameSet`]s that order every plugin's systems in it),
//! every component and resource that more than one plugin touches (the camera and the requests
//! that edit it, the mesh, the render settings split by who reads them (the pipeline's
//! switches, the appearance, the overlay) and lighting, the outside view's settings and orbit, the raw input and the camera actions it becomes, the viewport,
//! and the Close2GL frame: the 2D vertex buffer and its stage counts, the fates and the selected
//! triangle), the files the app opens by path ([`files`]: the disk, or the bytes a web page handed it), the one RGBA8 [`Image`] and how two are compared ([`parity`]), and the limits and
//! names they share ([`limits`], [`NamedEnum`]). Its one plugin, [`SettingsPlugin`], owns the settings
//! both views follow. It reads and writes nothing itself; every other crate depends on it, so
//! that plugins can talk to each other without depending on each other.

#[macro_use]
mod named;

mod app;
mod camera;
pub mod declaration;
mod excerpt;
mod fates;
pub mod files;
mod frame;
pub mod image;
mod input;
mod layout;
pub mod limits;
mod mesh;
mod model;
mod outside;
pub mod parity;
mod raster_mistake;
mod reference_camera;
mod schedule;
mod settings;
mod settings_plugin;
mod texture;
mod tools;
mod wake;

pub use app::{App, Owner, Plugin};
pub use camera::{
    Camera, CameraAction, CameraActions, CameraHome, CameraMode, CameraRequest, CameraSpeeds,
    Framing, KeepPose, LookAtPose,
};
pub use excerpt::{EXCERPT_CHARS, excerpt};
pub use fates::{
    ClipPlane, FateCounts, FateKind, Fates, RecordFates, SelectedTriangle, TriangleFate,
};
pub use frame::{
    Close2glFrame, CutVertex, FixedFrame, Letterbox, RasterGeometry, RasterVertex, Scene,
    SoftwareFrame, StageCounts, Topology, TraceFindings, TraceOutput, ViewImages, Viewport,
};
pub use image::Image;
pub use input::{Action, InputBindings, InputState, ProbeClick};
pub use layout::{Layout, View};
pub use mesh::Mesh;
pub use model::{
    LoadPace, Loading, ModelRequest, ModelSource, ModelStatus, PrimitiveKind, PrimitiveParams,
    TextureRequest,
};
pub use named::NamedEnum;
pub use outside::{OutsideOrbit, OutsideView, STAGE_NAMES};
pub use raster_mistake::{
    ByteConversion, DepthFunction, RasterMistake, RasterMistakes, RasterRules, RasterStage, TieRule,
};
pub use reference_camera::camera_matrices;
pub use schedule::{Close2glStep, FrameSet, LoadStep, OutputStep, Update};
pub use settings::{
    Appearance, Clipping, FrontFace, Lighting, Mistake, Overlay, PipelineSettings, Rasterizer,
    RenderMode, Shading, TextureFilter, insert_if_changed,
};
pub use settings_plugin::SettingsPlugin;
pub use texture::{Texture, checkerboard};
pub use tools::{CommandLine, PageLink, ToolRequests};
pub use wake::Wake;

/// Re-exported so that plugin authors need only this crate to write systems.
pub use bevy_ecs;
pub use glam;

//! The shared ECS vocabulary of close2gl. This crate owns the small `App`/`Plugin` pair (a World
//! with named frame schedules), the schedule labels, and every component and resource that more
//! than one plugin touches: the camera, the mesh, the render settings and lighting, the raw input
//! and the camera actions it becomes, the viewport, and the Close2GL frame (the 2D vertex buffer and
//! its stage counts). It reads and writes nothing itself; every other crate depends on it, so that
//! plugins can talk to each other without depending on each other.

mod app;
mod camera;
mod frame;
mod input;
mod mesh;
mod model;
mod settings;

pub use app::{App, Plugin, PostUpdate, PreUpdate, Render, Startup, Update, frame_schedules};
pub use camera::{
    Camera, CameraAction, CameraActions, CameraHome, CameraMode, CameraSpeeds, Framing,
};
pub use frame::{
    Close2glFrame, CutVertex, RasterGeometry, RasterVertex, SoftwareFrame, StageCounts, Topology,
    Viewport,
};
pub use input::{InputBindings, InputState};
pub use mesh::Mesh;
pub use model::{ModelRequest, ModelSource, ModelStatus, PrimitiveKind, PrimitiveParams};
pub use settings::{
    Clipping, FrontFace, Lighting, Rasterizer, RenderMode, RenderSettings, Shading,
};

/// Re-exported so that plugin authors need only this crate to write systems.
pub use bevy_ecs;
pub use glam;

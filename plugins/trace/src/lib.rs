//! close2gl's scene and trace files (`trace-format.md`, version 1), which let any program, in
//! any language, be checked against close2gl's pipeline: a scene is what a grader hands a
//! program to say which frame to draw, a trace is what the program wrote about that frame of its
//! own Close2GL (its camera, its matrices, the 2D triangles it drew). This crate owns reading
//! both into plain values, with every fault a one-line [`FormatError`] naming the file and line,
//! and writing them back as text that reads back the same; [`check`] compares a trace with the
//! pipeline, and [`rubric`] makes the assignment's rubric into scenes and judges a program's
//! traces of them, for `close2gl grade`. Its plugin, [`TracePlugin`], shows a trace in the viewer
//! ([`view`]) and owns the two resources that hold it.

pub mod check;
pub mod format;
pub mod rubric;
pub mod view;

use bevy_ecs::prelude::*;
use close2gl_core::{
    App, CameraRequest, Close2glStep, LoadStep, Owner, PipelineSettings, Plugin, TraceOutput,
    Update, Viewport,
};
use view::{TraceRequest, TraceView, load_requested_trace, show_trace};

pub use format::{
    Axis, CameraLines, ClipLine, Culling, FormatError, Motion, Piece, SceneCamera, SceneFile,
    System2d, Trace, TraceClipping, parse_scene, parse_trace, read_scene, read_trace,
};

/// Reads requested traces (in `FrameSet::Load`, against the mesh loaded there: its camera asked
/// of the camera plugin through `CameraRequest`, which sets it over the framing of a new model,
/// its switches written into `PipelineSettings`) and shows the current one's 2D output (after
/// the pipeline's own frame, into `TraceOutput`). Owns `TraceRequest`, `TraceView` and
/// `TraceOutput`; reads the mesh, the `Camera`, `Close2glFrame` and `Viewport`.
pub struct TracePlugin;

impl Plugin for TracePlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<TraceRequest>()
            .init_resource::<TraceView>()
            .init_resource::<TraceOutput>()
            .requires::<PipelineSettings>(Owner::Settings)
            .requires::<CameraRequest>(Owner::Camera)
            .requires::<Viewport>(Owner::Settings)
            .add_systems(
                Update,
                (
                    load_requested_trace.in_set(LoadStep::AgainstMesh),
                    show_trace.in_set(Close2glStep::Raster),
                ),
            );
    }
}

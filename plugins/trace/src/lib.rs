//! close2gl's viewer plugin for a program's trace: [`TracePlugin`] reads the trace the command
//! line, a dropped file or the watch asks for (its format is `close2gl_trace_format`'s), checks
//! it against the shown mesh (`close2gl_check`), takes its camera and settings, and puts its 2D
//! output in the Close2GL view ([`view`]); a raster trace (a student's own rasterizer, no camera)
//! it shows as two fixed images, the program's framebuffer and close2gl's drawing of its
//! triangles ([`view::raster`]). It owns the resources that hold the trace (`TraceRequest`,
//! `TraceView`, `TraceOutput`, `ViewImages`, and `TraceFindings`, check's findings in the
//! panel's words); it reads the mesh and `Viewport`, asks the camera plugin for the trace's
//! camera (`CameraRequest`) and writes `PipelineSettings` when a trace is taken.

pub mod view;

use bevy_ecs::prelude::*;
use close2gl_core::{
    App, CameraRequest, Close2glStep, LoadStep, Owner, PipelineSettings, Plugin, TraceFindings,
    TraceOutput, Update, ViewImages, Viewport,
};
use view::{
    TraceRequest, TraceView, load_requested_raster_trace, load_requested_trace,
    raster_images_system, trace_output_system, word_findings,
};

/// Reads requested traces (in `FrameSet::Load`, against the mesh loaded there: its camera asked
/// of the camera plugin through `CameraRequest`, which sets it over the framing of a new model,
/// its switches written into `PipelineSettings`) and shows the current one's 2D output (after
/// the pipeline's own frame, into `TraceOutput`); a raster trace, read without waiting for a
/// mesh, puts its two images into `ViewImages`. Owns `TraceRequest`, `TraceView`,
/// `TraceOutput`, `ViewImages` and `TraceFindings`; reads the mesh, the `Camera`, `Close2glFrame` and
/// `Viewport`.
pub struct TracePlugin;

impl Plugin for TracePlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<TraceRequest>()
            .init_resource::<TraceView>()
            .init_resource::<TraceOutput>()
            .init_resource::<TraceFindings>()
            .init_resource::<ViewImages>()
            .requires::<PipelineSettings>(Owner::Settings)
            .requires::<CameraRequest>(Owner::Camera)
            .requires::<Viewport>(Owner::Settings)
            .add_systems(
                Update,
                (
                    (
                        load_requested_raster_trace,
                        load_requested_trace,
                        word_findings,
                        raster_images_system,
                    )
                        .chain()
                        .in_set(LoadStep::AgainstMesh),
                    trace_output_system.in_set(Close2glStep::Raster),
                ),
            );
    }
}

//! close2gl's viewer plugin for a program's trace: [`TracePlugin`] reads the trace the command
//! line, a dropped file or the watch asks for (its format is `close2gl_trace_format`'s), checks
//! it against the shown mesh (`close2gl_check`), takes its camera and settings, and puts its 2D
//! output in the Close2GL view ([`view`]). It owns the resources that hold the trace
//! (`TraceRequest`, `TraceView`, `TraceOutput`, and `TraceFindings`, check's findings in the
//! panel's words); it reads the mesh and `Viewport`, and writes the `Camera` and
//! `RenderSettings` when a trace is taken.

pub mod view;

use bevy_ecs::prelude::*;
use close2gl_core::{
    App, Close2glStep, Owner, Plugin, RenderSettings, TraceFindings, TraceOutput, Update, Viewport,
};
use view::{TraceRequest, TraceView, load_requested_trace, show_trace, word_findings};

/// Reads requested traces (in `FrameSet::Close2gl`, before the pipeline: after the framing of a
/// new model, whose camera the trace's replaces) and shows the current one's 2D output (after
/// the pipeline's own frame). Owns `TraceRequest` and `TraceView`;
/// reads the mesh and `Viewport`, writes the `Camera`, `RenderSettings` and `Close2glFrame`.
pub struct TracePlugin;

impl Plugin for TracePlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<TraceRequest>()
            .init_resource::<TraceView>()
            .init_resource::<TraceOutput>()
            .init_resource::<TraceFindings>()
            .requires::<RenderSettings>(Owner::Settings)
            .requires::<Viewport>(Owner::Settings)
            .add_systems(
                Update,
                (
                    (load_requested_trace, word_findings)
                        .chain()
                        .in_set(Close2glStep::Prepare),
                    show_trace.in_set(Close2glStep::Raster),
                ),
            );
    }
}

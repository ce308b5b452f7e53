//! A trace in the viewer: `close2gl MODEL --trace FILE`, a trace file dropped on the window, and
//! with `--watch` the same file written again. [`crate::TracePlugin`] reads the requested trace, checks
//! it against the shown mesh, asks the camera plugin for its camera and takes its pipeline
//! switches (so that the reference shows the frame the program drew), and puts the trace's own 2D output in the Close2GL view in place of
//! close2gl's, for the GPU to draw as the assignment's 2D output is drawn. The live difference
//! and the probe then work on it; [`probe`] answers a probe from the trace's side. A raster
//! trace (a student's own rasterizer) is shown as two fixed images instead ([`raster`]).

mod findings;
mod open;
pub mod probe;
pub mod raster;
mod show;

use std::path::PathBuf;

use bevy_ecs::prelude::*;

use close2gl_check::Report;
use close2gl_trace_format::Trace;

pub use findings::word_findings;
pub use open::{load_requested_trace, trace_camera, trace_settings};
pub use raster::{RasterShown, load_requested_raster_trace, raster_images_system};
pub use show::trace_output_system;

/// A trace file to read (replacing the one shown), set by the command line, a dropped file or
/// the watch; taken by [`load_requested_trace`].
#[derive(Resource, Clone, Debug, Default, PartialEq)]
pub struct TraceRequest(pub Option<PathBuf>);

/// The trace shown, if any (a geometry trace in `shown`, or a raster trace in `raster`, never
/// both), with check's report on it; or why the last request was refused (the trace shown
/// before stays).
#[derive(Resource, Debug, Default)]
pub struct TraceView {
    pub path: Option<PathBuf>,
    pub shown: Option<Shown>,
    pub raster: Option<RasterShown>,
    pub error: Option<String>,
    /// Bumped on every trace taken, so that what draws it knows to redraw.
    pub generation: u64,
}

impl TraceView {
    /// `path` taken in place of what was shown (its caller puts it in `shown` or `raster`),
    /// the last refusal forgotten.
    fn taken(&mut self, path: PathBuf) {
        self.shown = None;
        self.raster = None;
        self.path = Some(path);
        self.error = None;
        self.generation += 1;
    }

    /// The files the shown trace was read from: the trace, and a raster trace's buffers and
    /// texture beside it (a program may write them after the trace: `--watch` reads the trace
    /// again when any of them changes).
    pub fn files(&self) -> Vec<PathBuf> {
        let Some(path) = &self.path else {
            return Vec::new();
        };
        let mut files = vec![path.clone()];
        if let Some(raster) = &self.raster {
            let trace = &raster.frame.trace;
            let folder = path.parent().unwrap_or(std::path::Path::new(""));
            let beside = [Some(&trace.framebuffer), trace.depthbuffer.as_ref()]
                .into_iter()
                .chain([trace.texture.as_ref().map(|(name, _)| name)]);
            files.extend(beside.flatten().map(|name| folder.join(name)));
        }
        files
    }
}

/// A trace that was read and checked.
#[derive(Debug)]
pub struct Shown {
    pub trace: Trace,
    pub report: Report,
}

//! The frame's one schedule and the named system sets that order the plugins within it.

use bevy_ecs::prelude::*;
use bevy_ecs::schedule::ScheduleLabel;

/// The one schedule [`crate::App::update`] runs every frame: every plugin's systems are in it,
/// each in a [`FrameSet`], and the sets run in order. There is no second axis to pick: where a
/// system runs in the frame is its set.
#[derive(ScheduleLabel, Clone, Debug, PartialEq, Eq, Hash)]
pub struct Update;

/// Where a plugin's systems sit in a frame. [`crate::App::new`] chains the sets in this order,
/// so two systems in different sets never race: a model loaded in `Load` is framed by `Camera`
/// in the same frame, whatever the scheduler does.
#[derive(SystemSet, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FrameSet {
    /// What came from outside the world becomes actions and requests: keys and the mouse
    /// become camera actions and render switches, a watched file changed becomes a reload.
    Input,
    /// The control panel (an exclusive system): what it changes lands in this same frame.
    Panel,
    /// A requested model is loaded and replaces the mesh, then what is read against it (a
    /// requested trace).
    Load,
    /// The camera's one writer: the edits asked for, framing a new mesh, the camera actions, then
    /// a replacement asked for (a trace's camera).
    Camera,
    /// The Close2GL pipeline turns camera, mesh and settings into the 2D buffer, then the
    /// software rasterizer into pixels; what asks them to record more (the fates) runs first.
    Close2gl,
    /// The frame's results go out of the world: what changed is uploaded to the GPU views
    /// (systems a headless app does not add), and anything that reports on the frame reads it.
    Output,
}

impl FrameSet {
    /// Every set, in the order it runs.
    pub const ALL: [FrameSet; 6] = [
        FrameSet::Input,
        FrameSet::Panel,
        FrameSet::Load,
        FrameSet::Camera,
        FrameSet::Close2gl,
        FrameSet::Output,
    ];
}

/// The steps inside [`FrameSet::Load`], chained in this order, so that what is read against the
/// mesh reads the one loaded this frame.
#[derive(SystemSet, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum LoadStep {
    /// A requested model or texture is read; the model replaces the mesh.
    Files,
    /// What is checked against the mesh now shown: a requested trace, whose camera and switches
    /// are asked for.
    AgainstMesh,
}

impl LoadStep {
    /// Every step, in the order it runs.
    pub const ALL: [LoadStep; 2] = [LoadStep::Files, LoadStep::AgainstMesh];
}

/// The steps inside [`FrameSet::Close2gl`], chained in this order, so that no plugin orders
/// itself by another crate's system.
#[derive(SystemSet, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Close2glStep {
    /// What asks the pipeline for more: recording the fates while they are shown.
    Prepare,
    /// The pipeline: camera, mesh and settings into the 2D buffer.
    Geometry,
    /// What reads the 2D buffer: the software rasterizer, a shown trace's output in its place.
    Raster,
}

impl Close2glStep {
    /// Every step, in the order it runs.
    pub const ALL: [Close2glStep; 3] = [
        Close2glStep::Prepare,
        Close2glStep::Geometry,
        Close2glStep::Raster,
    ];
}

/// The steps inside [`FrameSet::Output`], chained in this order, so that what reports on the
/// frame sees it as uploaded without naming the uploads.
#[derive(SystemSet, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OutputStep {
    /// What changed goes to the GPU views.
    Upload,
    /// What answers a question about the frame as it is drawn: the viewer's pixel probe.
    Report,
}

impl OutputStep {
    /// Every step, in the order it runs.
    pub const ALL: [OutputStep; 2] = [OutputStep::Upload, OutputStep::Report];
}

/// The frame's schedule with the sets chained in [`FrameSet::ALL`]'s order, the steps of
/// [`FrameSet::Load`] in [`LoadStep::ALL`]'s, those of [`FrameSet::Close2gl`] in
/// [`Close2glStep::ALL`]'s and those of [`FrameSet::Output`] in [`OutputStep::ALL`]'s.
pub(crate) fn frame_schedule() -> Schedule {
    let mut schedule = Schedule::new(Update);
    let [input, panel, load, camera, close2gl, output] = FrameSet::ALL;
    schedule.configure_sets((input, panel, load, camera, close2gl, output).chain());
    let [files, against_mesh] = LoadStep::ALL;
    schedule.configure_sets((files, against_mesh).chain().in_set(load));
    let [prepare, geometry, raster] = Close2glStep::ALL;
    schedule.configure_sets((prepare, geometry, raster).chain().in_set(close2gl));
    let [upload, report] = OutputStep::ALL;
    schedule.configure_sets((upload, report).chain().in_set(output));
    schedule
}

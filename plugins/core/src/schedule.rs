//! The frame's schedules and the named system sets that order the plugins within them.

use bevy_ecs::prelude::*;
use bevy_ecs::schedule::{InternedScheduleLabel, ScheduleLabel};

/// Runs once, before the first frame.
#[derive(ScheduleLabel, Clone, Debug, PartialEq, Eq, Hash)]
pub struct Startup;
/// Turns raw input into actions.
#[derive(ScheduleLabel, Clone, Debug, PartialEq, Eq, Hash)]
pub struct PreUpdate;
/// Applies actions: camera moves, model loads, settings change.
#[derive(ScheduleLabel, Clone, Debug, PartialEq, Eq, Hash)]
pub struct Update;
/// Derives per-frame data from the updated state (the Close2GL pipeline runs here).
#[derive(ScheduleLabel, Clone, Debug, PartialEq, Eq, Hash)]
pub struct PostUpdate;
/// Draws: GPU systems only, so a headless world may leave it empty.
#[derive(ScheduleLabel, Clone, Debug, PartialEq, Eq, Hash)]
pub struct Render;

/// The schedules `App::update` runs every frame, in order.
pub fn frame_schedules() -> [InternedScheduleLabel; 4] {
    [
        PreUpdate.intern(),
        Update.intern(),
        PostUpdate.intern(),
        Render.intern(),
    ]
}

/// Where a plugin's systems sit in a frame. [`crate::App::new`] orders the sets the same way in
/// every schedule, so two systems in different sets of one schedule never race: a model loaded
/// in `Load` is framed by `Camera` in the same frame, whatever the scheduler does.
#[derive(SystemSet, Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FrameSet {
    /// Raw input becomes camera actions and render switches.
    Input,
    /// The control panel (an exclusive system): what it changes lands in this same frame.
    Panel,
    /// A requested model is loaded and replaces the mesh.
    Load,
    /// Framing a new mesh, then the camera actions applied.
    Camera,
    /// The Close2GL pipeline turns camera, mesh and settings into the 2D buffer.
    Close2gl,
    /// The frame's results go out of the world: what changed is uploaded to the GPU views,
    /// and anything that reports on the frame reads it here. (Not `Render`, which is the
    /// schedule the GPU's uploads run in.)
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

/// A schedule with the sets configured in [`FrameSet::ALL`]'s order.
pub(crate) fn ordered_schedule(label: impl ScheduleLabel) -> Schedule {
    let mut schedule = Schedule::new(label);
    let [input, panel, load, camera, close2gl, output] = FrameSet::ALL;
    schedule.configure_sets((input, panel, load, camera, close2gl, output).chain());
    schedule
}

//! What the panel remembers between frames that belongs to no other resource.

use bevy_ecs::prelude::*;

#[derive(Resource, Debug, Default)]
pub struct PanelState {
    /// The model path being typed.
    pub path: String,
    /// The `ModelStatus::generation` the path field was last filled from.
    pub path_generation: u64,
    /// Change hfov and vfov together.
    pub lock_fov: bool,
    /// The texture path being typed.
    pub texture_path: String,
    /// The key cheat sheet is shown.
    pub help: bool,
    /// The legends in the views' corners are hidden.
    pub hide_legends: bool,
    /// The probe's window asked for the selected triangle's journey: the panel opens it and
    /// scrolls to it once.
    pub show_journey: bool,
    /// No panel: the views take the whole window (a page embedded in a course's page).
    pub hidden: bool,
}

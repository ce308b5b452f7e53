//! The control panel: an egui side panel over the ECS world, in nine sections, and what it paints
//! over the views. Model reads `ModelStatus` and `Mesh` and writes `ModelRequest` (a path, a
//! primitive, a reload). Render reads and writes `PipelineSettings` and `Appearance`; Texture
//! `Appearance` too, and writes `TextureRequest`. Camera reads the `Camera` component and asks
//! for its edits through `CameraRequest` (the camera plugin applies them in this frame), writes
//! `CameraSpeeds`, and pushes `CameraAction::Reset` into `CameraActions`. Outside view reads and writes `OutsideView` (shown,
//! stage) and `OutsideOrbit` (a reset, the whole volume framed). Stats reads `Close2glFrame` and
//! [`ViewStats`] (frame times, the adapter's name and limitations, which the viewer fills). Tools
//! sets `ToolRequests` (the input plugin's), carries out copy as command (clipboard and terminal,
//! the command from the app's `CommandLine`) and the key cheat sheet (from `InputBindings`), and
//! shows the [`Notice`] a tool leaves. Trace, shown while the Close2GL view shows a program's
//! trace, reads `TraceFindings` (the file, check's findings in words, why a trace was refused). Inspector reads `Fates`, `Mesh`, `Camera` and `Viewport`
//! (the legend's counts, the picked triangle's fate, the matrices) and writes
//! the `Overlay` and `SelectedTriangle` (reading `PipelineSettings` for the journey). Over the views it names them, shows the
//! legend of the overlay each shows, and opens the probe's [`ProbeAnswer`] beside the clicked
//! pixel (Esc, from egui or `InputState`, closes it; its button selects the triangle). It owns
//! [`PanelState`], `ViewStats` and `Notice`; the other plugins provide what it reads.
//!
//! Each section is a system of its own file, its parameters saying what it touches; `panel_layout.rs`
//! places them, and [`panel_system`] (`system.rs`, in `FrameSet::Panel`), the one function over
//! the whole world, runs the layout with the frame's [`PanelInput`], which the viewer gives, and
//! leaves egui's [`PanelOutput`] for it to paint. It knows no window system or GPU.

mod camera_panel;
mod inspector;
mod legend;
mod model_panel;
mod outside_panel;
mod panel_layout;
mod parts;
mod path_entry;
mod render_panel;
mod state;
mod stats_panel;
mod system;
mod texture_panel;
mod tools_panel;
mod trace_panel;
mod view_areas;

use close2gl_core::{
    App, Appearance, CameraActions, CameraRequest, CameraSpeeds, Close2glFrame, FrameSet,
    ModelRequest, ModelStatus, Overlay, Owner, PipelineSettings, Plugin, TextureRequest,
    ToolRequests, Update,
};

pub use inspector::ProbeAnswer;
pub use panel_layout::{PANEL_WIDTH, views_area};
pub use state::PanelState;
pub use stats_panel::{FrameTimer, ViewStats};
pub use system::{PanelInput, PanelOutput, panel_system};
pub use tools_panel::{Notice, REPRO_OUT};

use bevy_ecs::prelude::*;

pub struct UiPlugin;

impl Plugin for UiPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<PanelState>()
            .init_resource::<ViewStats>()
            .init_resource::<Notice>()
            .requires::<ModelStatus>(Owner::Model)
            .requires::<ModelRequest>(Owner::Model)
            .requires::<TextureRequest>(Owner::Model)
            .requires::<PipelineSettings>(Owner::Settings)
            .requires::<Appearance>(Owner::Settings)
            .requires::<Overlay>(Owner::Settings)
            .requires::<CameraActions>(Owner::Camera)
            .requires::<CameraRequest>(Owner::Camera)
            .requires::<CameraSpeeds>(Owner::Camera)
            .requires::<Close2glFrame>(Owner::Close2gl)
            .requires::<ToolRequests>(Owner::Input)
            .add_systems(Update, panel_system.in_set(FrameSet::Panel));
    }
}

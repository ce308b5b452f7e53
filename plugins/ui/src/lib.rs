//! The control panel: an egui side panel over the ECS world, in eight sections. Model reads
//! `ModelStatus` and `Mesh` and writes `ModelRequest` (a path, a primitive, a reload). Render reads
//! and writes `RenderSettings`. Camera reads and writes the `Camera` component and `CameraSpeeds`,
//! and pushes `CameraAction::Reset` into `CameraActions`. Outside view reads and writes
//! `OutsideView` (shown, stage) and `OutsideOrbit` (a reset, the whole volume framed). Stats reads
//! `Close2glFrame` and [`ViewStats`] (frame times, the adapter's name and limitations, which the
//! viewer fills). Tools sets `ToolRequests` (the input plugin's), carries out copy as command
//! (clipboard and terminal) and the key cheat sheet (from `InputBindings`), and shows the
//! [`Notice`] a tool leaves. Inspector reads `Fates`, `Mesh`, `Camera` and `Viewport` (the legend's
//! counts, the picked triangle's fate, the matrices) and writes `RenderSettings::overlay` and
//! `SelectedTriangle`. Over the views ([`over_views`]) it names them, shows the legend of the
//! overlay each shows, and opens the probe's [`ProbeAnswer`] beside the clicked pixel (Esc, from
//! egui or `InputState`, closes it; its button selects the triangle). It owns `PanelState`,
//! `ViewStats` and `Notice`; the other plugins provide what it reads. Its one system
//! ([`panel_system`], in `FrameSet::Panel`) runs the panel over the world with the frame's
//! [`PanelInput`], which the viewer gives, and leaves egui's [`PanelOutput`] for it to paint. It
//! knows no window system or GPU; a test can call [`show`] with an `egui::Ui` and the world.

mod camera;
mod inspector;
mod legend;
mod model;
mod outside;
mod render;
mod stats;
mod system;
mod texture;
mod tools;
mod trace;

use bevy_ecs::prelude::*;
use close2gl_core::{
    App, CameraActions, CameraSpeeds, Close2glFrame, FrameSet, ModelRequest, ModelStatus,
    OutsideView, Owner, Plugin, RenderSettings, Update,
};

pub use inspector::ProbeAnswer;
pub use stats::{FrameTimer, ViewStats};
pub use system::{PanelInput, PanelOutput, panel_system};
pub use tools::{Notice, REPRO_OUT};

/// Width of the side panel, its margins included, in points.
pub const PANEL_WIDTH: f32 = 290.0;

pub struct UiPlugin;

impl Plugin for UiPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<PanelState>()
            .init_resource::<ViewStats>()
            .init_resource::<Notice>()
            .requires::<ModelStatus>(Owner::Model)
            .requires::<ModelRequest>(Owner::Model)
            .requires::<RenderSettings>(Owner::Settings)
            .requires::<CameraActions>(Owner::Camera)
            .requires::<CameraSpeeds>(Owner::Camera)
            .requires::<Close2glFrame>(Owner::Close2gl)
            .add_systems(Update, panel_system.in_set(FrameSet::Panel));
    }
}

/// What the panel remembers between frames that belongs to no other resource.
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
}

/// What the panel leaves of `screen` for the views: all but its fixed width at the right. Not
/// the rectangle egui reports for the panel, which grows by a few points when its scroll bar
/// appears: the views, their viewport and a replay's pixels must not depend on whether the panel
/// scrolls, nor on what it shows.
pub fn views_area(screen: egui::Rect) -> egui::Rect {
    let mut views = screen;
    views.max.x = (views.max.x - PANEL_WIDTH).max(views.min.x);
    views
}

/// Shows the panel at the right of `ui` and returns the rectangle left for the views, in points.
pub fn show(ui: &mut egui::Ui, world: &mut World) -> egui::Rect {
    world.init_resource::<PanelState>();
    world.init_resource::<ViewStats>();
    egui::Panel::right("close2gl_panel")
        .resizable(false)
        .exact_size(PANEL_WIDTH)
        .show(ui, |ui| {
            egui::ScrollArea::vertical()
                .auto_shrink([false, false])
                .show(ui, |ui| sections(ui, world));
        });
    let views = views_area(ui.max_rect());
    // After the panel, so that its buttons take effect in the frame they are clicked in.
    tools::carry_out(ui.ctx(), world);
    tools::show_notice(ui, views, world);
    tools::cheat_sheet(ui.ctx(), world);
    views
}

/// What the panel paints over the views of `area` (`shared`: the split layout shows them all
/// there): their names, the legends of the overlays they show, and the probe's answer.
pub fn over_views(ui: &egui::Ui, world: &mut World, area: egui::Rect, shared: bool) {
    let outside = world.get_resource::<OutsideView>().is_some_and(|o| o.show);
    label_views(ui, area, shared, outside);
    legend::show(ui, world, area, shared);
    inspector::probe_window(ui.ctx(), world, area);
}

/// Names the views in their top-left corners.
fn label_views(ui: &egui::Ui, area: egui::Rect, shared: bool, outside: bool) {
    let painter = ui.painter();
    for (view, rect) in legend::view_rects(area, shared, outside) {
        let text = match view {
            legend::View::Reference => "Reference (wgpu)",
            legend::View::Close2gl => "Close2GL",
            legend::View::Outside => "Outside (drag, scroll)",
        };
        painter.text(
            rect.left_top() + egui::vec2(10.0, 8.0),
            egui::Align2::LEFT_TOP,
            text,
            egui::FontId::proportional(14.0),
            ui.visuals().weak_text_color(),
        );
    }
}

fn sections(ui: &mut egui::Ui, world: &mut World) {
    egui::CollapsingHeader::new("Model")
        .default_open(true)
        .show(ui, |ui| model::section(ui, world));
    if trace::shown(world) {
        egui::CollapsingHeader::new("Trace")
            .default_open(true)
            .show(ui, |ui| trace::section(ui, world));
    }
    egui::CollapsingHeader::new("Render")
        .default_open(true)
        .show(ui, |ui| render::section(ui, world));
    egui::CollapsingHeader::new("Texture")
        .default_open(true)
        .show(ui, |ui| texture::section(ui, world));
    egui::CollapsingHeader::new("Camera")
        .default_open(true)
        .show(ui, |ui| camera::section(ui, world));
    egui::CollapsingHeader::new("Outside view")
        .default_open(true)
        .show(ui, |ui| outside::section(ui, world));
    egui::CollapsingHeader::new("Tools")
        .default_open(true)
        .show(ui, |ui| tools::section(ui, world));
    egui::CollapsingHeader::new("Inspector")
        .default_open(true)
        .show(ui, |ui| inspector::section(ui, world));
    egui::CollapsingHeader::new("Stats")
        .default_open(true)
        .show(ui, |ui| stats::section(ui, world));
}

/// Writes `edited` back to the resource only when it differs, so that an idle panel does not
/// mark the resource changed every frame.
fn write_if_changed<R: Resource + PartialEq + Clone>(world: &mut World, edited: &R) {
    if world.get_resource::<R>() != Some(edited) {
        world.insert_resource(edited.clone());
    }
}

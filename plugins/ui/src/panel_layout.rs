//! The panel's layout: the side panel at the right with its sections top to bottom, then what
//! it paints over the views (the tools' notice and cheat sheet, the views' names, the legends,
//! the probe's answer). Each part is a system of its own module, run here through [`Parts`].

use bevy_ecs::prelude::*;

use crate::parts::Parts;
use crate::state::PanelState;
use crate::view_areas::{self, ViewArea};
use crate::{
    camera_panel, inspector, legend, model_panel, outside_panel, render_panel, stats_panel,
    texture_panel, tools_panel, trace_panel,
};

/// Width of the side panel, its margins included, in points.
pub const PANEL_WIDTH: f32 = 290.0;

/// What the panel leaves of `screen` for the views: all but its fixed width at the right. Not
/// the rectangle egui reports for the panel, which grows by a few points when its scroll bar
/// appears: the views, their viewport and a replay's pixels must not depend on whether the panel
/// scrolls, nor on what it shows.
/// Everything when the panel is `hidden`.
pub fn views_area(screen: egui::Rect, hidden: bool) -> egui::Rect {
    let mut views = screen;
    if !hidden {
        views.max.x = (views.max.x - PANEL_WIDTH).max(views.min.x);
    }
    views
}

/// The panel at the right of `ui` (unless it is hidden), then what it paints over the views
/// (`shared`: the split layout shows them all beside the panel).
pub fn show(ui: &mut egui::Ui, parts: &mut Parts, shared: bool) {
    let hidden = parts.run(|state: Res<PanelState>| state.hidden, ()) == Some(true);
    if !hidden {
        egui::Panel::right("close2gl_panel")
            .resizable(false)
            .exact_size(PANEL_WIDTH)
            .show(ui, |ui| {
                egui::ScrollArea::vertical()
                    .auto_shrink([false, false])
                    .show(ui, |ui| sections(ui, parts));
            });
    }
    let views = ViewArea {
        area: views_area(ui.max_rect(), hidden),
        shared,
    };
    // After the panel, so that its buttons take effect in the frame they are clicked in.
    if parts.run(tools_panel::take_requests, ()) == Some(true) {
        let command = parts.command(tools_panel::REPRO_OUT);
        parts.run(tools_panel::copied, (ui.ctx().clone(), command));
    }
    parts.run(tools_panel::show_notice, (ui, views));
    parts.run(tools_panel::cheat_sheet, ui);
    parts.run(view_areas::labels, (ui, views));
    parts.run(legend::show, (ui, views));
    parts.run(inspector::probe_window, (ui, views));
}

fn sections(ui: &mut egui::Ui, parts: &mut Parts) {
    section(ui, parts, "Model", model_panel::section);
    if parts.run(trace_panel::shown, ()) == Some(true) {
        section(ui, parts, "Trace", trace_panel::section);
    }
    section(ui, parts, "Render", render_panel::section);
    section(ui, parts, "Texture", texture_panel::section);
    section(ui, parts, "Camera", camera_panel::section);
    section(ui, parts, "Outside view", outside_panel::section);
    section(ui, parts, "Tools", tools_panel::section);
    section(ui, parts, "Inspector", inspector::section);
    section(ui, parts, "Stats", stats_panel::section);
}

/// One section under its title, open at first.
fn section<M>(
    ui: &mut egui::Ui,
    parts: &mut Parts,
    title: &str,
    part: impl IntoSystem<InMut<'static, egui::Ui>, (), M> + 'static,
) {
    egui::CollapsingHeader::new(title)
        .default_open(true)
        .show(ui, |ui| parts.run(part, ui));
}

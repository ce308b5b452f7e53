//! The user's tools in the panel: buttons for copy as command, screenshot, the key cheat sheet
//! and comparing the views (the same `ToolRequests` their keys set; in a browser also the page's
//! file chooser and its link), carrying out the two that need no GPU, the cheat sheet overlay
//! itself, and a short notice of what a tool did.

use bevy_ecs::prelude::*;
use close2gl_core::{Action, InputBindings, PageLink, ToolRequests};

use crate::ViewStats;
use crate::state::PanelState;
use crate::view_areas::ViewArea;

/// How long a notice stays, in seconds.
const NOTICE_SECONDS: f64 = 6.0;

/// Where the copied command writes its images.
pub const REPRO_OUT: &str = "repro";

/// A line telling the user what a tool just did (files saved, a command copied); the viewer
/// writes one too. Shown at the top of the views for a few seconds.
#[derive(Resource, Clone, Debug, Default, PartialEq)]
pub struct Notice {
    pub text: String,
    /// When it was first shown (egui's clock); `None` until then.
    pub shown_at: Option<f64>,
}

impl Notice {
    pub fn new(text: impl Into<String>) -> Self {
        Notice {
            text: text.into(),
            shown_at: None,
        }
    }
}

/// The buttons, each naming its key as bound, and what the views' last comparison found.
pub fn section(
    InMut(ui): InMut<egui::Ui>,
    bindings: Option<Res<InputBindings>>,
    mut tools: ResMut<ToolRequests>,
    (link, stats): (Option<Res<PageLink>>, Res<ViewStats>),
    mut commands: Commands,
) {
    let key = |action: Action| {
        let keys = bindings
            .as_ref()
            .map(|b| shown(b, action))
            .unwrap_or_default();
        match keys.is_empty() {
            true => keys,
            false => format!(" ({keys})"),
        }
    };
    let mut asked = ToolRequests::default();
    ui.horizontal_wrapped(|ui| {
        asked.copy_command = ui
            .button(format!("Copy as command{}", key(Action::CopyCommand)))
            .clicked();
        asked.screenshot = ui
            .button(format!("Screenshot{}", key(Action::Screenshot)))
            .clicked();
        asked.toggle_help = ui.button(format!("Keys{}", key(Action::Help))).clicked();
        asked.compare_views = ui
            .button("Compare views")
            .on_hover_text("The views' coverage agreement, as close2gl render computes it")
            .clicked();
        // In a browser: the page's own file chooser, and its link to this view.
        asked.open_file = cfg!(target_arch = "wasm32") && ui.button("Open a file…").clicked();
        if let Some(PageLink(link)) = link.as_deref()
            && ui.button("Copy link").clicked()
        {
            ui.ctx().copy_text(link.clone());
            commands.insert_resource(Notice::new("Copied the link to this view"));
        }
    });
    if let Some(agreement) = stats.coverage_agreement {
        ui.weak(format!(
            "The views cover the same pixels: {:.3} % (last compared)",
            100.0 * agreement
        ));
    }
    if asked.any() {
        tools.copy_command |= asked.copy_command;
        tools.screenshot |= asked.screenshot;
        tools.toggle_help |= asked.toggle_help;
        tools.compare_views |= asked.compare_views;
        tools.open_file |= asked.open_file;
    }
}

/// Takes the requests the panel carries out: toggles the cheat sheet, and answers whether the
/// command is to be copied ([`copied`] then says what was).
pub fn take_requests(mut tools: ResMut<ToolRequests>, mut state: ResMut<PanelState>) -> bool {
    let ToolRequests {
        copy_command,
        toggle_help,
        ..
    } = *tools;
    if !copy_command && !toggle_help {
        return false;
    }
    (tools.copy_command, tools.toggle_help) = (false, false);
    state.help ^= toggle_help;
    copy_command
}

/// Puts the copied `command` on the clipboard and the terminal, and says so; `None`: nothing
/// shows yet to copy.
pub fn copied(In((ctx, command)): In<(egui::Context, Option<String>)>, mut notice: ResMut<Notice>) {
    let text = match command {
        Some(command) => {
            println!("{command}");
            ctx.copy_text(command);
            "Copied the command that renders this view (also printed on the terminal)"
        }
        None => "Nothing to copy yet: no model is shown",
    };
    *notice = Notice::new(text);
}

/// The notice, at the top of the views, until it has been shown long enough.
pub fn show_notice(
    (InRef(ui), In(views)): (InRef<egui::Ui>, In<ViewArea>),
    mut notice: ResMut<Notice>,
) {
    if notice.text.is_empty() {
        return;
    }
    let now = ui.input(|i| i.time);
    let shown_at = *notice.shown_at.get_or_insert(now);
    if now - shown_at > NOTICE_SECONDS {
        notice.text.clear();
        return;
    }
    ui.ctx()
        .request_repaint_after(std::time::Duration::from_secs_f64(NOTICE_SECONDS));
    let painter = ui.painter();
    let at = views.area.center_bottom() - egui::vec2(0.0, 16.0);
    let galley = painter.layout_no_wrap(
        notice.text.clone(),
        egui::FontId::proportional(15.0),
        ui.visuals().strong_text_color(),
    );
    let rect = egui::Align2::CENTER_BOTTOM.anchor_size(at, galley.size());
    painter.rect_filled(rect.expand(6.0), 4.0, ui.visuals().extreme_bg_color);
    painter.galley(rect.min, galley, ui.visuals().strong_text_color());
}

/// What each action does, in the cheat sheet's words.
const DESCRIPTIONS: [(Action, &str); 24] = [
    (Action::Forward, "move forward (along -n)"),
    (Action::Back, "move back (along n)"),
    (Action::Left, "move left (along -u)"),
    (Action::Right, "move right (along u)"),
    (Action::Up, "move up (along v)"),
    (Action::Down, "move down (along -v)"),
    (Action::RollLeft, "roll left (about n)"),
    (Action::RollRight, "roll right (about n)"),
    (Action::PitchUp, "pitch up (about u)"),
    (Action::PitchDown, "pitch down (about u)"),
    (Action::YawLeft, "yaw left (about v)"),
    (Action::YawRight, "yaw right (about v)"),
    (Action::Reset, "reset the camera"),
    (Action::ToggleMode, "free / look-at camera"),
    (Action::OriginalColor, "original colour (no shading)"),
    (Action::Phong, "Phong shading"),
    (Action::Gouraud, "Gouraud shading"),
    (Action::Help, "show or hide these keys"),
    (Action::Screenshot, "save both views as PNGs"),
    (Action::CopyCommand, "copy the command for this view"),
    (Action::FateView, "inspector: the fate view on / off"),
    (
        Action::DifferenceView,
        "inspector: where the two views differ, on / off",
    ),
    (
        Action::OutsideView,
        "the outside view on / off (a third column)",
    ),
    (
        Action::OutsideWholeVolume,
        "the outside view frames the whole volume / the model and the near plane",
    ),
];

/// `action`'s keys as the user reads them: "f1 or ?".
fn shown(bindings: &InputBindings, action: Action) -> String {
    bindings.keys(action).collect::<Vec<_>>().join(" or ")
}

/// The key cheat sheet over the views, from the bindings as configured.
pub fn cheat_sheet(
    InRef(ui): InRef<egui::Ui>,
    bindings: Option<Res<InputBindings>>,
    mut state: ResMut<PanelState>,
) {
    let Some(bindings) = bindings.filter(|_| state.help) else {
        return;
    };
    let rows: Vec<(String, &str)> = DESCRIPTIONS
        .iter()
        .map(|(action, what)| (shown(&bindings, *action), *what))
        .filter(|(keys, _)| !keys.is_empty())
        .collect();
    let mut open = true;
    egui::Window::new("Keys")
        .open(&mut open)
        .collapsible(false)
        .resizable(false)
        .anchor(egui::Align2::LEFT_TOP, egui::vec2(16.0, 32.0))
        .show(ui.ctx(), |ui| {
            egui::Grid::new("keys").striped(true).show(ui, |ui| {
                for (key, what) in &rows {
                    ui.monospace(key);
                    ui.label(*what);
                    ui.end_row();
                }
                ui.monospace("drag");
                ui.label("yaw and pitch");
                ui.end_row();
                ui.monospace("wheel");
                ui.label("zoom (field of view)");
                ui.end_row();
                ui.monospace("ctrl+click");
                ui.label("probe the pixel (Inspector)");
                ui.end_row();
            });
        });
    if !open {
        state.help = false;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_bindable_action_is_described() {
        let described: Vec<Action> = DESCRIPTIONS.iter().map(|(a, _)| *a).collect();
        let bindable: Vec<Action> = InputBindings::DEFAULTS.iter().map(|(a, _)| *a).collect();
        assert_eq!(described, bindable);
        assert_eq!(bindable, Action::ALL, "every action has a default key");
    }
}

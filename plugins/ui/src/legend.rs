//! What the overlays' colours mean, in one place: the panel's legend and the small legends in the
//! corner of each view read the same rows. A view's legend shows only while that view shows an
//! overlay (the fate view, the live difference, the outside view in fate colours), so that a
//! first-time user reads the colours where they look at them; its close button and the
//! Inspector's checkbox hide them all (`PanelState::hide_legends`).

use bevy_ecs::prelude::*;
use close2gl_core::parity::{ONLY_CLOSE2GL, ONLY_REFERENCE};
use close2gl_core::{FateKind, OutsideView, Overlay, View};

use crate::state::PanelState;
use crate::view_areas::{ViewArea, view_rects};

/// What the GPU paints over the reference in the fate view: its own answers.
pub const REFERENCE: [(FateKind, &str); 3] = [
    (FateKind::Drawn, "front facing, won the depth test"),
    (FateKind::Culled, "back facing, won the depth test"),
    (FateKind::Hidden, "failed the depth test"),
];

/// A colour and what it means.
type Row = ([u8; 3], &'static str);

/// The live difference's colours, as `close2gl render` paints diff.png.
pub fn difference() -> [Row; 3] {
    let rgb = |[r, g, b, _]: [u8; 4]| [r, g, b];
    [
        (rgb(ONLY_REFERENCE), "covered in the reference only"),
        (rgb(ONLY_CLOSE2GL), "covered in Close2GL only"),
        ([230, 230, 230], "the same in both (the reference, faded)"),
    ]
}

/// The outside view's own colours beside the fates': the shader dims what lies outside the view
/// volume to 0.3 of its colour, and paints what the division throws behind the eye magenta.
const OUTSIDE: [Row; 2] = [
    ([27, 57, 27], "dimmed: outside the view volume"),
    ([255, 0, 255], "thrown by the division (w <= 0)"),
];

pub fn swatch(ui: &mut egui::Ui, [r, g, b]: [u8; 3]) {
    let (rect, _) = ui.allocate_exact_size(egui::vec2(12.0, 12.0), egui::Sense::hover());
    ui.painter()
        .rect_filled(rect, 2.0, egui::Color32::from_rgb(r, g, b));
}

/// A legend's title and rows, for `view` as the settings show it; None when it shows no overlay.
fn rows(view: View, overlay: Overlay) -> Option<(&'static str, Vec<Row>)> {
    let fates = || FateKind::ALL.iter().map(|k| (k.color(), k.name()));
    match (view, overlay) {
        (View::Reference, Overlay::FateView) => Some((
            "The GPU's answers",
            REFERENCE.iter().map(|(k, m)| (k.color(), *m)).collect(),
        )),
        (View::Close2gl, Overlay::FateView) => Some(("Close2GL's fates", fates().collect())),
        (View::Close2gl, Overlay::Difference) => {
            Some(("Where the views differ", difference().to_vec()))
        }
        (View::Outside, Overlay::FateView) => {
            Some(("Outside view: fates", fates().chain(OUTSIDE).collect()))
        }
        _ => None,
    }
}

/// The legends in the corners of the views that show an overlay, unless hidden.
pub fn show(
    (InRef(ui), In(views)): (InRef<egui::Ui>, In<ViewArea>),
    overlay: Res<Overlay>,
    outside: Option<Res<OutsideView>>,
    mut state: ResMut<PanelState>,
) {
    if state.hide_legends || *overlay == Overlay::Off {
        return;
    }
    let outside = outside.is_some_and(|o| o.show);
    let mut hide = false;
    for (view, rect) in view_rects(views, outside) {
        if let Some((title, rows)) = rows(view, *overlay) {
            hide |= legend(ui.ctx(), view, rect, title, &rows);
        }
    }
    if hide {
        state.hide_legends = true;
    }
}

/// One legend in the bottom-left corner of `rect`; returns whether its close button was clicked.
fn legend(ctx: &egui::Context, view: View, rect: egui::Rect, title: &str, rows: &[Row]) -> bool {
    egui::Area::new(egui::Id::unique(("legend", view)))
        .fixed_pos(rect.left_bottom() + egui::vec2(8.0, -8.0))
        .pivot(egui::Align2::LEFT_BOTTOM)
        .show(ctx, |ui| {
            egui::Frame::popup(ui.style())
                .show(ui, |ui| {
                    ui.style_mut().override_text_style = Some(egui::TextStyle::Small);
                    let close = ui
                        .horizontal(|ui| {
                            ui.label(egui::RichText::new(title).strong());
                            ui.small_button("×")
                                .on_hover_text("Hide the legends (Inspector: Legends in the views)")
                                .clicked()
                        })
                        .inner;
                    for (color, meaning) in rows {
                        ui.horizontal(|ui| {
                            swatch(ui, *color);
                            ui.label(*meaning);
                        });
                    }
                    close
                })
                .inner
        })
        .inner
}

use bevy_ecs::prelude::*;
use close2gl_core::{OutsideOrbit, OutsideView, STAGE_NAMES};

/// The pipeline seen from outside: shown or not, the stage slider (world, eye, NDC, and every
/// stage between), the orbit camera's reset and what it frames.
pub fn section(
    InMut(ui): InMut<egui::Ui>,
    mut current: ResMut<OutsideView>,
    mut orbit: Option<ResMut<OutsideOrbit>>,
) {
    let mut outside = *current;
    ui.checkbox(&mut outside.show, "Show the outside view")
        .on_hover_text("The camera, its view volume and the model, seen from outside");
    ui.add_enabled_ui(outside.show, |ui| {
        ui.add(
            egui::Slider::new(&mut outside.stage, 0.0..=OutsideView::MAX_STAGE)
                .text("stage")
                .custom_formatter(|stage, _| stage_label(stage as f32)),
        )
        .on_hover_text("0 world, 1 eye (M applied), 2 NDC (P applied and divided)");
        ui.horizontal(|ui| {
            for (name, stage) in STAGE_NAMES {
                if ui.button(name).clicked() {
                    outside.stage = stage;
                }
            }
            if ui.button("Reset orbit").clicked()
                && let Some(orbit) = orbit.as_mut()
            {
                orbit.set_if_neq(OutsideOrbit::default());
            }
        });
        if let Some(orbit) = orbit.as_mut() {
            let mut edited = **orbit;
            ui.checkbox(&mut edited.whole_volume, "Frame the whole volume")
                .on_hover_text(
                    "Off: the model, the eye and the near plane fill the view. On: the far plane \
                     too, however far beyond the model",
                );
            orbit.set_if_neq(edited);
        }
    });
    current.set_if_neq(outside);
}

/// The stage's number, with the stop's name when it is on one.
fn stage_label(stage: f32) -> String {
    match STAGE_NAMES.iter().find(|(_, at)| *at == stage) {
        Some((name, _)) => format!("{stage:.2} {name}"),
        None => format!("{stage:.2}"),
    }
}

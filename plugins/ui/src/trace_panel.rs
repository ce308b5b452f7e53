//! The Trace section, shown while the Close2GL view shows a program's trace: which file, check's
//! verdict, the first difference with its details, the mistakes named, every stage's status,
//! and why the last trace requested was refused. Reads `TraceView`; writes nothing.

use bevy_ecs::prelude::*;
use close2gl_check::compare::Status;
use close2gl_trace::view::TraceView;

/// Whether there is a trace (or a refused one) to show.
pub fn shown(view: Option<Res<TraceView>>) -> bool {
    view.is_some_and(|v| v.shown.is_some() || v.error.is_some())
}

pub fn section(InMut(ui): InMut<egui::Ui>, view: Res<TraceView>) {
    if let Some(error) = &view.error {
        ui.colored_label(ui.visuals().error_fg_color, error);
    }
    let (Some(shown), Some(path)) = (&view.shown, &view.path) else {
        return;
    };
    ui.label(format!("Close2GL shows {}", path.display()));
    let report = &shown.report;
    match report.agrees() {
        true => ui.colored_label(
            egui::Color32::from_rgb(90, 190, 90),
            "It agrees with close2gl's pipeline.",
        ),
        false => ui.colored_label(
            ui.visuals().warn_fg_color,
            "It differs from close2gl's pipeline.",
        ),
    };
    if let Some(first) = report.comparison.first_difference() {
        ui.label(format!("First difference: {}", first.stage.name()));
        for detail in first.details.iter().take(5) {
            ui.add(egui::Label::new(egui::RichText::new(detail).small()).wrap());
        }
    }
    let mistakes = report.mistakes();
    if !mistakes.is_empty() {
        ui.strong(format!("Mistake: {}", mistakes.join(", ")));
    }
    if let Some(unexplained) = &report.unexplained {
        ui.add(egui::Label::new(unexplained).wrap());
    }
    egui::Grid::new("trace_stages")
        .striped(true)
        .show(ui, |ui| {
            for stage in &report.comparison.stages {
                ui.label(stage.stage.name());
                let text = match stage.status {
                    Status::NotChecked => "not checked".to_string(),
                    Status::Agree => format!("agrees ({})", stage.checked),
                    Status::Differs => format!("{} of {} differ", stage.differing, stage.checked),
                };
                ui.label(text);
                ui.end_row();
            }
        });
}

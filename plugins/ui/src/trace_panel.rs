//! The Trace section, shown while the Close2GL view shows a program's trace: which file, check's
//! verdict, the first difference with its details, the mistakes named, every stage's status
//! (for a raster trace, check's raster report as it is), and why the last trace requested was
//! refused. Reads `TraceFindings` (the trace plugin's, in
//! words); writes nothing.

use bevy_ecs::prelude::*;
use close2gl_core::TraceFindings;

/// Whether there is a trace (or a refused one) to show.
pub fn shown(findings: Option<Res<TraceFindings>>) -> bool {
    findings.is_some_and(|f| f.path.is_some() || f.error.is_some())
}

pub fn section(InMut(ui): InMut<egui::Ui>, findings: Res<TraceFindings>) {
    if let Some(error) = &findings.error {
        ui.colored_label(ui.visuals().error_fg_color, error);
    }
    let Some(path) = &findings.path else {
        return;
    };
    ui.label(format!("Close2GL shows {}", path.display()));
    if let Some(report) = &findings.raster_report {
        return raster_section(ui, findings.agrees, report);
    }
    verdict(ui, findings.agrees, "close2gl's pipeline");
    if let Some((stage, details)) = &findings.first_difference {
        ui.label(format!("First difference: {stage}"));
        for detail in details.iter().take(5) {
            ui.add(egui::Label::new(egui::RichText::new(detail).small()).wrap());
        }
    }
    if !findings.mistakes.is_empty() {
        ui.strong(format!("Mistake: {}", findings.mistakes.join(", ")));
    }
    if let Some(unexplained) = &findings.unexplained {
        ui.add(egui::Label::new(unexplained).wrap());
    }
    egui::Grid::new("trace_stages")
        .striped(true)
        .show(ui, |ui| {
            for (stage, status) in &findings.stages {
                ui.label(*stage);
                ui.label(status);
                ui.end_row();
            }
        });
}

/// A raster trace: check's verdict, that its frame is fixed, and check's report as it is (the
/// facts, the legal rules, the mistakes named and what each does).
fn raster_section(ui: &mut egui::Ui, agrees: bool, report: &[String]) {
    verdict(ui, agrees, "close2gl's textbook rasterizer");
    ui.label("A raster trace's frame is fixed: the camera moves nothing in these views.");
    for line in report {
        ui.add(egui::Label::new(egui::RichText::new(line).monospace().small()).wrap());
    }
}

/// Check's verdict against `judge`, green when it agrees.
fn verdict(ui: &mut egui::Ui, agrees: bool, judge: &str) {
    match agrees {
        true => ui.colored_label(
            egui::Color32::from_rgb(90, 190, 90),
            format!("It agrees with {judge}."),
        ),
        false => ui.colored_label(
            ui.visuals().warn_fg_color,
            format!("It differs from {judge}."),
        ),
    };
}

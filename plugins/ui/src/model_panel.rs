use std::time::Duration;

use bevy_ecs::prelude::*;
use close2gl_core::{Loading, Mesh, ModelRequest, ModelSource, ModelStatus, PrimitiveKind};

use crate::path_entry::path_entry;
use crate::state::PanelState;

/// The path being typed and its Load button; a new model (dropped, picked, reloaded) shows its
/// path in the field. Returns the model asked for, if any.
fn path_field(
    ui: &mut egui::Ui,
    state: &mut PanelState,
    status: &ModelStatus,
) -> Option<ModelSource> {
    if state.path_generation != status.generation {
        state.path_generation = status.generation;
        if let Some(ModelSource::File(path)) = &status.source {
            state.path = path.display().to_string();
        }
    }
    let hint = ".in or .obj file, or drop one here";
    path_entry(ui, &mut state.path, hint, "Load", 50.0).map(ModelSource::parse)
}

/// How often the panel asks to be drawn while a model loads: the viewer otherwise sleeps until
/// input comes, and the bar would not move.
const LOADING_REPAINT: Duration = Duration::from_millis(100);

/// The bar of a model loading in the background, named and in percent.
fn loading_bar(ui: &mut egui::Ui, loading: &Loading) {
    let name = match &loading.source {
        ModelSource::File(path) => path.file_name().map_or_else(
            || path.display().to_string(),
            |n| n.to_string_lossy().into(),
        ),
        ModelSource::Primitive(kind) => kind.name().to_string(),
    };
    let percent = (loading.fraction * 100.0).floor();
    ui.add(egui::ProgressBar::new(loading.fraction).text(format!("loading {name}: {percent}%")));
    ui.ctx().request_repaint_after(LOADING_REPAINT);
}

/// A path field with Load, a button per primitive, Reload, and what the last load said.
pub fn section(
    InMut(ui): InMut<egui::Ui>,
    status: Res<ModelStatus>,
    mut requested: ResMut<ModelRequest>,
    meshes: Query<&Mesh>,
    mut state: ResMut<PanelState>,
) {
    let mut request = path_field(ui, &mut state, &status);
    ui.horizontal_wrapped(|ui| {
        for &kind in PrimitiveKind::ALL {
            if ui.button(kind.name()).clicked() {
                request = Some(ModelSource::Primitive(kind));
            }
        }
        if ui
            .add_enabled(status.source.is_some(), egui::Button::new("Reload"))
            .clicked()
        {
            request = status.source.clone();
        }
    });
    if let Ok(mesh) = meshes.single() {
        ui.weak(format!(
            "{}: {} triangles, {} vertices",
            mesh.name,
            mesh.triangles.len(),
            mesh.positions.len()
        ));
    }
    if let Some(loading) = &status.loading {
        loading_bar(ui, loading);
    }
    if let Some(error) = &status.error {
        ui.colored_label(ui.visuals().error_fg_color, error);
    }
    for warning in &status.warnings {
        ui.colored_label(ui.visuals().warn_fg_color, warning);
    }
    if request.is_some() {
        requested.0 = request;
    }
}

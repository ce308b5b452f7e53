use std::path::PathBuf;

use bevy_ecs::prelude::*;
use close2gl_core::{Appearance, Mesh, Texture, TextureFilter, TextureRequest};

use crate::path_entry::path_entry;
use crate::state::PanelState;

/// Texturing on or off, the filter, and the image: a path field with Load (or drop a PNG or JPEG
/// on the window); the built-in checkerboard until one is loaded. A model without texture
/// coordinates says so, since nothing then shows.
pub fn section(
    InMut(ui): InMut<egui::Ui>,
    mut current: ResMut<Appearance>,
    mut requested: ResMut<TextureRequest>,
    texture: Option<Res<Texture>>,
    meshes: Query<&Mesh>,
    mut state: ResMut<PanelState>,
) {
    let mut settings = *current;
    ui.checkbox(&mut settings.texture, "Texture");
    ui.horizontal(|ui| {
        ui.label("Filter");
        for &filter in TextureFilter::ALL {
            ui.selectable_value(&mut settings.texture_filter, filter, filter.name());
        }
    });
    current.set_if_neq(settings);

    let hint = "PNG or JPEG image, or drop one here";
    let request =
        path_entry(ui, &mut state.texture_path, hint, "Load image", 100.0).map(PathBuf::from);
    let shown = match texture.as_deref() {
        Some(Texture {
            source: Some(path), ..
        }) => path.display().to_string(),
        Some(_) => "the built-in checkerboard".to_string(),
        None => "none (the image did not load)".to_string(),
    };
    let textured = meshes.single().is_ok_and(|m| !m.uvs.is_empty());
    ui.weak(if textured {
        format!("Image: {shown}")
    } else {
        format!("Image: {shown}; this model has no texture coordinates")
    });
    if request.is_some() {
        requested.0 = request;
    }
}

use bevy_ecs::prelude::*;
use close2gl_core::{Mesh, RenderSettings, Texture, TextureFilter, TextureRequest};

use crate::state::PanelState;

/// Texturing on or off, the filter, and the image: a path field with Load (or drop a PNG or JPEG
/// on the window); the built-in checkerboard until one is loaded. A model without texture
/// coordinates says so, since nothing then shows.
pub fn section(
    InMut(ui): InMut<egui::Ui>,
    mut current: ResMut<RenderSettings>,
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

    let mut request = None;
    ui.horizontal(|ui| {
        let field = egui::TextEdit::singleline(&mut state.texture_path)
            .hint_text("PNG or JPEG image, or drop one here")
            .desired_width(ui.available_width() - 100.0);
        let entered = ui.add(field).lost_focus() && ui.input(|i| i.key_pressed(egui::Key::Enter));
        let path = state.texture_path.trim();
        if (ui.button("Load image").clicked() || entered) && !path.is_empty() {
            request = Some(path.into());
        }
    });
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

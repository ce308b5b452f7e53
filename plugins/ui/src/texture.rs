use bevy_ecs::prelude::*;
use close2gl_core::{Mesh, RenderSettings, Texture, TextureFilter, TextureRequest};

use crate::PanelState;

/// Texturing on or off, the filter, and the image: a path field with Load (or drop a PNG or JPEG
/// on the window); the built-in checkerboard until one is loaded. A model without texture
/// coordinates says so, since nothing then shows.
pub fn section(ui: &mut egui::Ui, world: &mut World) {
    let Some(mut settings) = world.get_resource::<RenderSettings>().copied() else {
        return;
    };
    ui.checkbox(&mut settings.texture, "Texture");
    ui.horizontal(|ui| {
        ui.label("Filter");
        for &filter in TextureFilter::ALL {
            ui.selectable_value(&mut settings.texture_filter, filter, filter.name());
        }
    });
    crate::write_if_changed(world, &settings);

    let mut request = None;
    let mut state = world.resource_mut::<PanelState>();
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
    let shown = match world.get_resource::<Texture>() {
        Some(Texture {
            source: Some(path), ..
        }) => path.display().to_string(),
        Some(_) => "the built-in checkerboard".to_string(),
        None => "none (the image did not load)".to_string(),
    };
    let mut meshes = world.query::<&Mesh>();
    let textured = meshes.single(world).is_ok_and(|m| !m.uvs.is_empty());
    ui.weak(if textured {
        format!("Image: {shown}")
    } else {
        format!("Image: {shown}; this model has no texture coordinates")
    });
    if request.is_some() {
        world.insert_resource(TextureRequest(request));
    }
}

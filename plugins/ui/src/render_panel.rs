use bevy_ecs::prelude::*;
use close2gl_core::glam::Vec3;
use close2gl_core::{
    Appearance, Clipping, FrontFace, Mistake, PipelineSettings, RasterMistake, Rasterizer,
    RenderMode, Shading,
};

/// Mode, front face, culling, clipping, shading, who rasterizes Close2GL and the model's colour:
/// the pipeline's switches and the appearance, for both views.
pub fn section(
    InMut(ui): InMut<egui::Ui>,
    mut current: ResMut<PipelineSettings>,
    mut current_look: ResMut<Appearance>,
) {
    let (mut settings, mut look) = (*current, *current_look);
    ui.horizontal(|ui| {
        ui.label("Mode");
        choice(ui, &mut settings.mode, RenderMode::ALL, RenderMode::name);
    });
    ui.horizontal(|ui| {
        ui.label("Front face");
        choice(
            ui,
            &mut settings.front_face,
            FrontFace::ALL,
            FrontFace::name,
        );
    });
    ui.checkbox(&mut settings.backface_culling, "Backface culling");
    ui.horizontal(|ui| {
        ui.label("Clipping");
        choice(ui, &mut settings.clipping, Clipping::ALL, Clipping::name);
    });
    mistake(ui, &mut settings.mistake);
    shading(ui, &mut look.shading);
    raster_mistake(ui, &mut look.raster_mistake);
    rasterizer(ui, &mut settings.close2gl_raster);
    ui.horizontal(|ui| {
        ui.label("Colour");
        color(ui, &mut look.color);
        ui.label("Background");
        color(ui, &mut look.background);
    });
    // Unchanged, it stays so: an idle panel must not mark the settings changed every frame.
    current.set_if_neq(settings);
    current_look.set_if_neq(look);
}

/// A classic mistake for Close2GL to make, from a list: its symptom shows beside the reference.
fn mistake(ui: &mut egui::Ui, mistake: &mut Mistake) {
    let hover = "Close2GL makes a classic mistake of the assignment on purpose, so that its \
                 symptom shows beside the reference (docs/checking.md).";
    listed(ui, "Mistake", mistake, Mistake::ALL, Mistake::name, hover);
}

/// A classic mistake of the rasterizer assignment for Close2GL's own rasterizer to make.
fn raster_mistake(ui: &mut egui::Ui, mistake: &mut RasterMistake) {
    let hover = "Close2GL's own rasterizer (Close2GL: software) makes a classic mistake of the \
                 rasterizer assignment on purpose, drawn by the textbook rasterizer: its symptom \
                 shows beside the reference (docs/checking.md).";
    let name = RasterMistake::name;
    listed(
        ui,
        "Raster mistake",
        mistake,
        RasterMistake::ALL,
        name,
        hover,
    );
}

/// The shading, from a list: it names what the two views' lighting is.
fn shading(ui: &mut egui::Ui, shading: &mut Shading) {
    let hover = "Both views' lighting when Close2GL rasterizes in software; with the GPU \
                 rasterizer, Close2GL draws flat colour.";
    listed(ui, "Shading", shading, Shading::ALL, Shading::name, hover);
}

/// A labelled drop-down list of every value of a named setting.
fn listed<T: Copy + PartialEq>(
    ui: &mut egui::Ui,
    label: &str,
    value: &mut T,
    all: &[T],
    name: fn(T) -> &'static str,
    hover: &str,
) {
    ui.horizontal(|ui| {
        ui.label(label);
        egui::ComboBox::from_id_salt(label)
            .selected_text(name(*value))
            .show_ui(ui, |ui| {
                for &option in all {
                    ui.selectable_value(value, option, name(option));
                }
            })
            .response
            .on_hover_text(hover);
    });
}

/// Who rasterizes Close2GL's output: the GPU, as the assignment asks, or Close2GL itself.
fn rasterizer(ui: &mut egui::Ui, rasterizer: &mut Rasterizer) {
    ui.horizontal(|ui| {
        ui.label("Close2GL");
        let name = |r: Rasterizer| match r {
            Rasterizer::Gpu => "GPU (assignment)",
            Rasterizer::Software => "software",
        };
        choice(ui, rasterizer, Rasterizer::ALL, name);
    })
    .response
    .on_hover_text(
        "GPU (assignment): the GPU only draws Close2GL's 2D primitives, in flat colour (the \
         assignment's rule; render.close2gl_raster = \"gpu\"). software: Close2GL's own \
         rasterizer, z-buffer and shading.",
    );
}

/// One selectable button per option.
fn choice<T: Copy + PartialEq>(
    ui: &mut egui::Ui,
    value: &mut T,
    options: &[T],
    name: fn(T) -> &'static str,
) {
    for &option in options {
        ui.selectable_value(value, option, name(option));
    }
}

/// The colour's bytes are what the views write to the screen, so the swatch shows them as they
/// are (egui's RGB button would take them for linear values and show them brighter).
fn color(ui: &mut egui::Ui, value: &mut Vec3) {
    let mut srgb = value.to_array().map(|c| (c * 255.0).round() as u8);
    if ui.color_edit_button_srgb(&mut srgb).changed() {
        *value = Vec3::from(srgb.map(|c| c as f32 / 255.0));
    }
}

//! The control panel as a system: an exclusive system in `FrameSet::Panel`, after
//! the keys were mapped and before a model loads, the camera moves and the pipeline runs, so that
//! what the panel changes (and the tools the keys asked for) lands in this same frame. The window's
//! owner hands it the frame's input ([`PanelInput`]) and takes what egui painted ([`PanelOutput`]);
//! without input (a headless app) it does nothing. It is the panel's one function over the whole
//! world, which it lends to the layout as [`Parts`]: every section is a system of its own.

use bevy_ecs::prelude::*;

use crate::panel_layout;
use crate::parts::Parts;

/// This frame's input for the panel, from the window's owner.
#[derive(Resource)]
pub struct PanelInput {
    pub ctx: egui::Context,
    /// Taken by the panel when it runs.
    pub raw: Option<egui::RawInput>,
    /// The window shows both views (the split layout), which the labels name.
    pub both_views: bool,
}

/// What egui made of the frame, for the window's owner to paint.
#[derive(Resource)]
pub struct PanelOutput(pub egui::FullOutput);

pub fn panel_system(world: &mut World) {
    let Some(mut input) = world.get_resource_mut::<PanelInput>() else {
        return;
    };
    let Some(raw) = input.raw.take() else {
        return;
    };
    let (ctx, both_views) = (input.ctx.clone(), input.both_views);
    let output = ctx.run_ui(raw, |ui| {
        panel_layout::show(ui, &mut Parts(&mut *world), both_views);
    });
    world.insert_resource(PanelOutput(output));
}

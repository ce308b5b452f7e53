//! The owner of the settings both views follow.

use crate::{
    App, Appearance, Lighting, OutsideOrbit, OutsideView, Overlay, PipelineSettings, Plugin,
    RecordFates, SelectedTriangle, Viewport, Wake,
};

/// Owns the render settings, one resource per kind of reader: [`PipelineSettings`] (the
/// pipeline's switches), [`Appearance`] (how both views colour the model) and [`Overlay`] (the
/// inspector's display), and [`Lighting`] (both views light
/// the model with it) and [`Viewport`] (the size both views share): neither view owns what the
/// other must follow too. The input plugin, the panel
/// and the viewer write them; the Close2GL pipeline and the GPU views read them. Values inserted
/// before the plugin is added (the configuration's) are kept. [`OutsideView`] (shown or not, and
/// its stage) and [`OutsideOrbit`] (its own camera) are settings of the same kind: the config,
/// the panel and the keys write them, the GPU's outside renderer reads them. It owns [`Wake`] too, which the
/// viewer fills and any plugin's background work clones, [`SelectedTriangle`], which the
/// panel and the probe write and both views highlight, and [`RecordFates`], the request the
/// fate view and the headless commands make and the pipeline reads.
pub struct SettingsPlugin;

impl Plugin for SettingsPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<PipelineSettings>()
            .init_resource::<Appearance>()
            .init_resource::<Overlay>()
            .init_resource::<Lighting>()
            .init_resource::<Viewport>()
            .init_resource::<OutsideView>()
            .init_resource::<OutsideOrbit>()
            .init_resource::<Wake>()
            .init_resource::<SelectedTriangle>()
            .init_resource::<RecordFates>();
    }
}

//! The `Render` systems: upload what changed from the ECS world into [`Views`].

use bevy_ecs::prelude::*;
use close2gl_core::Owner;
use close2gl_core::{
    App, Camera, Close2glFrame, Fates, FrameSet, Lighting, Mesh, Overlay, Plugin, PostUpdate,
    Render, RenderSettings, SelectedTriangle, SoftwareFrame, Texture, Viewport,
};

use crate::fate_view::record_fates_while_shown;
use crate::reference::clear_color;
use crate::{Gpu, Views};
use close2gl_core::parity::to_rgb8;

/// Adds the `Render` systems that upload what changed, by bevy's change ticks as the pipeline
/// watches its inputs: the `Mesh` again only when it changed, the `Texture` likewise; the
/// reference uniforms from `Camera`, `RenderSettings` and `Lighting`; the Close2GL 2D buffer
/// from `Close2glFrame`, or the software rasterizer's image from `SoftwareFrame`; in the fate
/// view (`RenderSettings::overlay`), each triangle in its colour from `Fates`, which it asks
/// Close2GL to record (`Fates::record`) while that view is shown (it inserts `Fates` if no one
/// has); the selected triangle's highlight (`SelectedTriangle`); in the live difference, both
/// views drawn again into textures of the `Viewport`'s size and compared. They run once
/// the `Gpu` and `Views` resources exist (inserted by whoever owns the target), so a window may
/// arrive late. It owns no resource: the model, settings and Close2GL plugins provide what it
/// reads, the model plugin the texture (without one the reference draws untextured), and the
/// raster plugin, when there is one, the software image.
pub struct GpuPlugin;

impl Plugin for GpuPlugin {
    fn build(&self, app: &mut App) {
        app.requires::<RenderSettings>(Owner::Settings)
            .requires::<Lighting>(Owner::Settings)
            .requires::<Close2glFrame>(Owner::Close2gl)
            .requires::<Viewport>(Owner::Settings)
            .requires::<SelectedTriangle>(Owner::Settings)
            .init_resource::<Fates>()
            .add_systems(
                PostUpdate,
                record_fates_while_shown.in_set(FrameSet::Camera),
            )
            .add_systems(
                Render,
                (
                    upload_mesh,
                    upload_texture,
                    upload_reference,
                    upload_close2gl,
                    upload_software,
                    upload_fates,
                    upload_highlight,
                    render_difference,
                )
                    .chain()
                    .in_set(FrameSet::Output)
                    .run_if(resource_exists::<Gpu>.and_then(resource_exists::<Views>)),
            );
    }
}

/// The mesh again when it changed (bevy's change ticks, as the pipeline watches it), or when
/// the views are new.
fn upload_mesh(gpu: Res<Gpu>, mesh: Single<Ref<Mesh>>, mut views: ResMut<Views>) {
    if mesh.is_changed() || views.is_added() {
        views.reference.upload_mesh(&gpu.device, &mesh);
    }
}

/// The texture again when it changed, appeared or went, or when the views are new.
fn upload_texture(gpu: Res<Gpu>, texture: Option<Res<Texture>>, mut views: ResMut<Views>) {
    let changed = texture.as_ref().is_some_and(|t| t.is_changed());
    let gone = texture.is_none() && views.reference.is_textured();
    if changed || gone || views.is_added() {
        views
            .reference
            .upload_texture(&gpu.device, &gpu.queue, texture.as_deref());
    }
}

/// Every frame: the uniforms are a few hundred bytes, cheaper than tracking what moved.
fn upload_reference(
    gpu: Res<Gpu>,
    camera: Single<&Camera>,
    settings: Res<RenderSettings>,
    lighting: Res<Lighting>,
    mut views: ResMut<Views>,
) {
    views.background = clear_color(settings.background);
    views
        .reference
        .update(&gpu.device, &gpu.queue, &camera, &settings, &lighting);
}

/// Only when the frame, the colour or the views changed: the 2D buffer can be megabytes.
fn upload_close2gl(
    gpu: Res<Gpu>,
    frame: Res<Close2glFrame>,
    settings: Res<RenderSettings>,
    mut views: ResMut<Views>,
) {
    if frame.is_changed() || settings.is_changed() || views.is_added() {
        views
            .close2gl
            .update(&gpu.device, &gpu.queue, &frame, settings.color);
    }
}

/// The software rasterizer's image, when it is the one shown and it is new. Without the raster
/// plugin there is no image, and the view stays empty.
fn upload_software(
    gpu: Res<Gpu>,
    image: Option<Res<SoftwareFrame>>,
    settings: Res<RenderSettings>,
    mut views: ResMut<Views>,
) {
    views.rasterizer = settings.close2gl_raster;
    if let Some(image) = image
        && (image.is_changed() || views.is_added())
    {
        views.software.update(&gpu.device, &gpu.queue, &image.image);
    }
}

/// The fate view, every frame while it is shown: the fates change with every Close2GL frame.
fn upload_fates(
    gpu: Res<Gpu>,
    mesh: Single<&Mesh>,
    camera: Single<&Camera>,
    fates: Res<Fates>,
    settings: Res<RenderSettings>,
    mut views: ResMut<Views>,
) {
    views.overlay = settings.overlay;
    if settings.overlay == Overlay::Fates {
        views
            .fates
            .update(&gpu.device, &gpu.queue, &mesh, &camera, &fates);
    }
}

/// The selected triangle's corners and marker in both views, every frame: seventeen vertices.
fn upload_highlight(
    gpu: Res<Gpu>,
    mesh: Single<&Mesh>,
    camera: Single<&Camera>,
    selected: Res<SelectedTriangle>,
    viewport: Res<Viewport>,
    mut views: ResMut<Views>,
) {
    let scene = (&**mesh, &**camera);
    views
        .highlight
        .update(&gpu.queue, scene, selected.0, *viewport);
}

/// The live difference, every frame while it is shown: both views drawn again, after every
/// upload, into the textures it compares.
fn render_difference(
    gpu: Res<Gpu>,
    viewport: Res<Viewport>,
    settings: Res<RenderSettings>,
    mut views: ResMut<Views>,
) {
    if settings.overlay == Overlay::Difference {
        let size = (viewport.width, viewport.height);
        views.render_difference(&gpu, size, to_rgb8(settings.background));
    }
}

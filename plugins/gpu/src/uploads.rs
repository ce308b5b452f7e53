//! The [`crate::GpuPlugin`]'s systems (in `FrameSet::Output`): upload what changed from the ECS
//! world into [`Views`].

use bevy_ecs::prelude::*;
use bevy_ecs::system::SystemParam;
use close2gl_core::Letterbox;
use close2gl_core::parity::to_rgb8;
use close2gl_core::{
    Appearance, Camera, Close2glFrame, Fates, Lighting, Mesh, Overlay, PipelineSettings,
    SelectedTriangle, SoftwareFrame, Texture, TraceOutput, ViewImages, Viewport,
};

use crate::gpu::Gpu;
use crate::reference_skew::ReferenceSkew;
use crate::views::Views;

/// The mesh again when it changed (bevy's change ticks, as the pipeline watches it), or when
/// the views are new.
pub(crate) fn upload_mesh(gpu: Res<Gpu>, mesh: Single<Ref<Mesh>>, mut views: ResMut<Views>) {
    if mesh.is_changed() || views.is_added() {
        views.reference.upload_mesh(&gpu.device, &mesh);
    }
}

/// The texture again when it changed, appeared or went, or when the views are new.
pub(crate) fn upload_texture(
    gpu: Res<Gpu>,
    texture: Option<Res<Texture>>,
    mut views: ResMut<Views>,
) {
    let changed = texture.as_ref().is_some_and(|t| t.is_changed());
    let gone = texture.is_none() && views.reference.is_textured();
    if changed || gone || views.is_added() {
        views
            .reference
            .upload_texture(&gpu.device, &gpu.queue, texture.as_deref());
    }
}

/// Every frame: the uniforms are a few hundred bytes, cheaper than tracking what moved. The
/// reference draws with its colours moved by the [`ReferenceSkew`] (none unless one is set).
pub(crate) fn upload_reference(
    gpu: Res<Gpu>,
    camera: Single<&Camera>,
    (pipeline, look, overlay): (Res<PipelineSettings>, Res<Appearance>, Res<Overlay>),
    (lighting, skew): (Res<Lighting>, Res<ReferenceSkew>),
    viewport: Res<Viewport>,
    mut views: ResMut<Views>,
) {
    let skewed = skew.apply(*look);
    views.background = look.background;
    views.reference_background = skewed.background;
    views.reference.update(
        &gpu.device,
        &gpu.queue,
        (&camera, *viewport),
        (&pipeline, &skewed, *overlay),
        &lighting,
    );
}

/// Only when the frame, a shown trace, the colour or the views changed: the 2D buffer can be
/// megabytes. A shown trace's output is drawn in place of the pipeline's.
pub(crate) fn upload_close2gl(
    gpu: Res<Gpu>,
    frame: Res<Close2glFrame>,
    trace: Option<Res<TraceOutput>>,
    look: Res<Appearance>,
    mut views: ResMut<Views>,
) {
    let trace_changed = trace.as_ref().is_some_and(|t| t.is_changed());
    if frame.is_changed() || trace_changed || look.is_changed() || views.is_added() {
        let shown = trace.as_ref().and_then(|t| t.0.as_deref());
        let vertices = shown.unwrap_or(&frame.vertices);
        views
            .close2gl
            .update(&gpu.device, &gpu.queue, &frame, vertices, look.color);
    }
}

/// The software rasterizer's image, when it is the one shown and it is new. Without the raster
/// plugin there is no image, and the view stays empty.
pub(crate) fn upload_software(
    gpu: Res<Gpu>,
    image: Option<Res<SoftwareFrame>>,
    pipeline: Res<PipelineSettings>,
    mut views: ResMut<Views>,
) {
    views.rasterizer = pipeline.close2gl_raster;
    if let Some(image) = image
        && (image.is_changed() || views.is_added())
    {
        views.software.update(&gpu.device, &gpu.queue, &image.image);
    }
}

/// A raster trace's fixed frame, when it came, changed or went: both views show its images in
/// place of their own drawing meanwhile. Without the trace plugin there is none.
pub(crate) fn upload_view_images(
    gpu: Res<Gpu>,
    images: Option<Res<ViewImages>>,
    viewport: Res<Viewport>,
    mut views: ResMut<Views>,
) {
    let changed = |i: &Res<ViewImages>| i.is_changed() || viewport.is_changed();
    let Some(images) = images.filter(|i| changed(i) || views.is_added()) else {
        return;
    };
    views.fixed = images.0.is_some();
    if let Some(frame) = &images.0 {
        // Each on a canvas of the view's shape, so that stretched over it the frame keeps its
        // own; the bars are the view's background, uncovered.
        let size = (frame.reference.width, frame.reference.height);
        let letterbox = Letterbox::new(size, *viewport);
        let [r, g, b] = to_rgb8(views.background);
        let views = &mut *views;
        for (view, image) in
            (views.fixed_images.iter_mut()).zip([&frame.reference, &frame.close2gl])
        {
            let canvas = letterbox.place(image, [r, g, b, 0]);
            view.update(&gpu.device, &gpu.queue, &canvas);
        }
    }
}

/// The mesh and the camera the overlays draw their lines over.
#[derive(SystemParam)]
pub(crate) struct MeshAndCamera<'w, 's> {
    mesh: Single<'w, 's, &'static Mesh>,
    camera: Single<'w, 's, &'static Camera>,
}

impl MeshAndCamera<'_, '_> {
    fn get(&self) -> (&Mesh, &Camera) {
        (&self.mesh, &self.camera)
    }
}

/// The fate view, every frame while it is shown: the fates change with every Close2GL frame.
pub(crate) fn upload_fates(
    gpu: Res<Gpu>,
    scene: MeshAndCamera,
    fates: Res<Fates>,
    overlay: Res<Overlay>,
    mut views: ResMut<Views>,
) {
    views.overlay = *overlay;
    if *overlay == Overlay::FateView {
        views
            .fates
            .update(&gpu.device, &gpu.queue, scene.get(), &fates);
    }
}

/// The selected triangle's corners and marker in both views, every frame: seventeen vertices.
pub(crate) fn upload_highlight(
    gpu: Res<Gpu>,
    scene: MeshAndCamera,
    selected: Res<SelectedTriangle>,
    viewport: Res<Viewport>,
    mut views: ResMut<Views>,
) {
    views
        .highlight
        .update(&gpu.queue, scene.get(), selected.0, *viewport);
}

/// The live difference, every frame while it is shown: both views drawn again, after every
/// upload, into the textures it compares.
pub(crate) fn render_difference(
    gpu: Res<Gpu>,
    viewport: Res<Viewport>,
    overlay: Res<Overlay>,
    mut views: ResMut<Views>,
) {
    if *overlay == Overlay::Difference {
        views.render_difference(&gpu, (viewport.width, viewport.height));
    }
}

//! The GPU side of close2gl, on wgpu: the shared device ([`Gpu`], which says when it is lost),
//! the reference renderer (the mesh drawn from glam's own camera matrices, standing in for OpenGL;
//! its lines and points drawn face by face where the device lacks the polygon-mode features, or
//! when the environment's `CLOSE2GL_NO_POLYGON_MODE` is 1, read as each device opens)
//! and the Close2GL view (the 2D buffer drawn through a pass-through pipeline, or the software
//! rasterizer's image drawn as one textured triangle, or in the fate view each triangle in its
//! fate's colour, or in the live difference where the two views differ), both held in [`Views`],
//! with the selected triangle's highlight. [`GpuPlugin`] adds
//! the systems (in `FrameSet::Output`'s `OutputStep::Upload`) that read `Camera`, `Mesh`,
//! `PipelineSettings` (mode, culling, who rasterizes), `Appearance`, `Overlay`, `Lighting`,
//! `Texture`, `Close2glFrame`, `SoftwareFrame`, `SelectedTriangle`, `Viewport`, `ViewImages` (a raster
//! trace's fixed frame, shown in place of both views' drawing) and `Fates` (asking
//! for it to be recorded while the fate view is shown) and upload what changed into `Views`; whoever
//! owns the target (a window, or [`render_offscreen`]) records the draws.
//! Offscreen rendering, reading textures back ([`Readback`]), the texture and attachment
//! descriptions every target shares ([`attachments`]), the reference probe (an ID pass that says which
//! mesh triangle the GPU drew at a pixel, [`probe_reference`]), the pixel probe's one home
//! ([`ProbedFrame::answer`]: both views' answers for a pixel, the reference's beside Close2GL's
//! from the raster crate, for the viewer's Ctrl+click and `close2gl inspect`) and the timed submission every
//! view is drawn with ([`submit_pass_timed`]) live here too (images and their comparison are the
//! core's: `close2gl_core::Image`, `close2gl_core::parity`). [`outside`] is the
//! third view, the pipeline seen from outside: its [`outside::OutsidePlugin`] reads the camera,
//! the mesh, the `Appearance`, the `Overlay`, `OutsideView`, `OutsideOrbit` and `Fates`, and fills
//! [`outside::OutsideRenderer`]. No window or UI crate is a dependency.

pub mod attachments;
mod close2gl_view;
mod corners;
mod difference_view;
mod fate_view;
mod fullscreen;
mod gpu;
mod grow_buffer;
mod highlight;
mod id_pass;
mod image_view;
mod offscreen;
pub mod outside;
mod pass;
mod pixel_answer;
mod readback;
mod reference;
mod reference_skew;
mod reference_texture;
mod uniforms;
mod uploads;
mod vertex_pipeline;
mod views;

use bevy_ecs::prelude::*;
use close2gl_core::{
    App, Appearance, Close2glFrame, Close2glStep, Fates, Lighting, OutputStep, Overlay, Owner,
    PipelineSettings, Plugin, RecordFates, SelectedTriangle, Update, Viewport,
};

use fate_view::record_fates_while_shown;
use uploads::{
    render_difference, upload_close2gl, upload_fates, upload_highlight, upload_mesh,
    upload_reference, upload_software, upload_texture, upload_view_images,
};

pub use attachments::DEPTH_FORMAT;
pub use close2gl_core::Image;
pub use close2gl_core::camera_matrices;
pub use gpu::{Gpu, NO_POLYGON_MODE_VAR, parse_backends};
pub use id_pass::{ReferenceHit, ReferenceProbe, probe_reference, start_probe};
pub use offscreen::{OFFSCREEN_FORMAT, OffscreenPlugin, Snapshot, render_offscreen};
pub use pass::{submit_pass, submit_pass_timed};
pub use pixel_answer::{PixelAnswer, ProbedFrame};
pub use readback::{Pending, Readback};
pub use reference::clear_color;
pub use reference_skew::ReferenceSkew;
pub use views::Views;
/// Re-exported so that users of this crate name the same wgpu types.
pub use wgpu;

/// Adds the systems that upload what changed, by bevy's change ticks as the pipeline
/// watches its inputs: the `Mesh` again only when it changed, the `Texture` likewise; the
/// reference uniforms from `Camera`, `PipelineSettings`, `Appearance` and `Lighting`; the Close2GL 2D buffer
/// from `Close2glFrame`, or the software rasterizer's image from `SoftwareFrame`; a raster
/// trace's two fixed images from `ViewImages`, shown in place of both views' drawing; in the fate
/// view (the `Overlay`), each triangle in its colour from `Fates`, which it asks
/// Close2GL to record (`RecordFates`) while that view is shown; the selected triangle's highlight (`SelectedTriangle`); in the live difference, both
/// views drawn again into textures of the `Viewport`'s size and compared. They run once
/// the `Gpu` and `Views` resources exist (inserted by whoever owns the target), so a window may
/// arrive late. It owns one resource, [`ReferenceSkew`] (none by default: the reference's
/// colours moved a few steps, as another GPU's rounding would move them); the model, settings
/// and Close2GL plugins provide what it reads, the model plugin the texture (without one the
/// reference draws untextured), and the raster plugin, when there is one, the software image.
pub struct GpuPlugin;

impl Plugin for GpuPlugin {
    fn build(&self, app: &mut App) {
        app.requires::<PipelineSettings>(Owner::Settings)
            .requires::<Appearance>(Owner::Settings)
            .requires::<Overlay>(Owner::Settings)
            .requires::<Lighting>(Owner::Settings)
            .requires::<Close2glFrame>(Owner::Close2gl)
            .requires::<Viewport>(Owner::Settings)
            .requires::<SelectedTriangle>(Owner::Settings)
            .requires::<Fates>(Owner::Close2gl)
            .requires::<RecordFates>(Owner::Settings)
            .init_resource::<ReferenceSkew>()
            .add_systems(
                Update,
                record_fates_while_shown.in_set(Close2glStep::Prepare),
            )
            .add_systems(
                Update,
                (
                    upload_mesh,
                    upload_texture,
                    upload_reference,
                    upload_close2gl,
                    upload_software,
                    upload_view_images,
                    upload_fates,
                    upload_highlight,
                    render_difference,
                )
                    .chain()
                    .in_set(OutputStep::Upload)
                    .run_if(resource_exists::<Gpu>.and_then(resource_exists::<Views>)),
            );
    }
}

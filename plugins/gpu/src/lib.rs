//! The GPU side of close2gl, on wgpu: the shared device ([`Gpu`], which says when it is lost),
//! the reference renderer (the mesh drawn from glam's own camera matrices, standing in for OpenGL)
//! and the Close2GL view (the 2D buffer drawn through a pass-through pipeline, or the software
//! rasterizer's image drawn as one textured triangle, or in the fate view each triangle in its
//! fate's colour, or in the live difference where the two views differ), both held in [`Views`],
//! with the selected triangle's highlight. [`GpuPlugin`] adds
//! the `Render` systems that read `Camera`, `Mesh`, `RenderSettings`, `Lighting`,
//! `Texture`, `Close2glFrame`, `SoftwareFrame`, `SelectedTriangle`, `Viewport` and `Fates` (asking
//! for it to be recorded while the fate view is shown) and upload what changed into `Views`; whoever
//! owns the target (a window, or [`render_offscreen`]) records the draws.
//! Offscreen rendering, reading textures back ([`Readback`]), the texture and attachment
//! descriptions every target shares ([`texture`]), the reference probe (an ID pass that says which
//! mesh triangle the GPU drew at a pixel, [`probe_reference`]) and the timed submission every
//! view is drawn with ([`submit_pass_timed`]) live here too (images and their comparison are the
//! core's: `close2gl_core::Image`, `close2gl_core::parity`). [`outside`] is the
//! third view, the pipeline seen from outside: its [`outside::OutsidePlugin`] reads the camera,
//! the mesh, the settings, `OutsideView`, `OutsideOrbit` and `Fates`, and fills
//! [`outside::OutsideRenderer`]. No window or UI crate is a dependency.

mod close2gl_view;
mod corners;
mod difference_view;
mod fate_view;
mod fullscreen;
mod gpu;
mod grow_buffer;
mod highlight;
mod id_pass;
mod offscreen;
pub mod outside;
mod readback;
mod reference;
mod reference_texture;
mod software_view;
mod systems;
pub mod texture;
mod vertex_pipeline;
mod views;

pub use close2gl_core::Image;
pub use close2gl_core::camera_matrices;
pub use gpu::{Gpu, parse_backends};
pub use id_pass::{ReferenceHit, ReferenceProbe, probe_reference, start_probe};
pub use offscreen::{OFFSCREEN_FORMAT, OffscreenPlugin, Snapshot, render_offscreen};
pub use readback::{Pending, Readback};
pub use reference::clear_color;
pub use systems::GpuPlugin;
pub use views::Views;
/// Re-exported so that users of this crate name the same wgpu types.
pub use wgpu;

/// The depth attachment format the reference view's pass must use.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// Records one pass into `target` (its depth, when given, cleared to the far plane) and submits
/// it. The windows and the offscreen target draw every view through this, so they draw alike.
pub fn submit_pass(
    gpu: &Gpu,
    target: &wgpu::TextureView,
    depth: Option<&wgpu::TextureView>,
    load: wgpu::LoadOp<wgpu::Color>,
    record: impl FnOnce(&mut wgpu::RenderPass<'_>),
) {
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("view"),
            color_attachments: &[Some(texture::color_attachment(target, load))],
            depth_stencil_attachment: depth.map(texture::depth_attachment),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        record(&mut pass);
    }
    gpu.queue.submit([encoder.finish()]);
}

/// [`submit_pass`], then waits for the GPU to finish it: a view's time is its own recording and
/// the GPU's work on it. Returns the milliseconds it took. The windows and the offscreen target
/// time every view this way.
pub fn submit_pass_timed(
    gpu: &Gpu,
    target: &wgpu::TextureView,
    depth: Option<&wgpu::TextureView>,
    load: wgpu::LoadOp<wgpu::Color>,
    record: impl FnOnce(&mut wgpu::RenderPass<'_>),
) -> f64 {
    let start = web_time::Instant::now();
    submit_pass(gpu, target, depth, load, record);
    // A failed wait means a lost device; the next acquire or readback reports it.
    let _ = gpu.device.poll(wgpu::PollType::Wait {
        submission_index: None,
        timeout: Some(std::time::Duration::from_secs(30)),
    });
    start.elapsed().as_secs_f64() * 1e3
}

/// A view's uniform buffer (binding 0 of group 0, seen by both shader stages), its bind group
/// and the pipeline layout every one of the view's pipelines shares.
/// A uniform buffer at `binding`, seen by the `visibility` stages.
fn uniform_entry(binding: u32, visibility: wgpu::ShaderStages) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty: wgpu::BindingType::Buffer {
            ty: wgpu::BufferBindingType::Uniform,
            has_dynamic_offset: false,
            min_binding_size: None,
        },
        count: None,
    }
}

struct UniformSetup {
    buffer: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    layout: wgpu::PipelineLayout,
}

impl UniformSetup {
    fn new(device: &wgpu::Device, label: &str, size: usize) -> Self {
        let buffer = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some(label),
            size: size as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind_group_layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some(label),
            entries: &[uniform_entry(0, wgpu::ShaderStages::VERTEX_FRAGMENT)],
        });
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some(label),
            layout: &bind_group_layout,
            entries: &[wgpu::BindGroupEntry {
                binding: 0,
                resource: buffer.as_entire_binding(),
            }],
        });
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(label),
            bind_group_layouts: &[Some(&bind_group_layout)],
            immediate_size: 0,
        });
        Self {
            buffer,
            bind_group,
            layout,
        }
    }
}

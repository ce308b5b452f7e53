//! The GPU side of close2gl, on wgpu: the shared device ([`Gpu`]), the reference renderer (the
//! mesh drawn from glam's own camera matrices, standing in for OpenGL) and the Close2GL view (the
//! 2D buffer drawn through a pass-through pipeline), both held in [`Views`]. [`GpuPlugin`] adds
//! the `Render` systems that read `Camera`, `Mesh`, `ModelStatus`, `RenderSettings`, `Lighting` and
//! `Close2glFrame` and upload what changed into `Views`; whoever owns the target (a window, or
//! [`render_offscreen`]) records the draws. Offscreen rendering, PNG images and the coverage
//! comparison behind `close2gl render` and the parity tests live here too. No window or UI crate
//! is a dependency.

mod close2gl_view;
mod gpu;
pub mod image;
mod offscreen;
pub mod parity;
mod reference;
mod systems;
mod views;

pub use gpu::{Gpu, parse_backends};
pub use image::Image;
pub use offscreen::{OFFSCREEN_FORMAT, OffscreenPlugin, Snapshot, render_offscreen};
pub use reference::{camera_matrices, clear_color};
pub use systems::GpuPlugin;
pub use views::Views;
/// Re-exported so that users of this crate name the same wgpu types.
pub use wgpu;

/// The depth attachment format the reference view's pass must use.
pub const DEPTH_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Depth32Float;

/// One uniform buffer at binding 0 of group 0: its layout and bind group.
fn uniform_binding(
    device: &wgpu::Device,
    label: &str,
    buffer: &wgpu::Buffer,
    visibility: wgpu::ShaderStages,
) -> (wgpu::BindGroupLayout, wgpu::BindGroup) {
    let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some(label),
        entries: &[wgpu::BindGroupLayoutEntry {
            binding: 0,
            visibility,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Uniform,
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        }],
    });
    let group = device.create_bind_group(&wgpu::BindGroupDescriptor {
        label: Some(label),
        layout: &layout,
        entries: &[wgpu::BindGroupEntry {
            binding: 0,
            resource: buffer.as_entire_binding(),
        }],
    });
    (layout, group)
}

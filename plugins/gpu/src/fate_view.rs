//! The fate view (`Overlay::Fates`): Close2GL's view with every mesh triangle in its fate's
//! colour (`FateKind::color`, the one legend), from the fates Close2GL itself recorded
//! (`Fates`). Triangles that reach the screen (drawn, cut, no pixels, hidden) are filled; those
//! clipping or culling removed (clipped, culled, zero area) are outlined where they would
//! project, so that a student switching to simple clipping sees what vanished at the border.
//!
//! The corners are Close2GL's own clip coordinates P·M·p (its matrices, not glam's). The GPU
//! clips the filled triangles as full clipping would; the outlines get a depth inside the volume
//! so that the near and far planes do not hide them. Corners with w <= 0 are at or behind the eye
//! and project nowhere: the GPU clips every outline to w > 0, so a triangle wholly behind the
//! eye shows nothing and one reaching behind it shows the part in front.

use bevy_ecs::prelude::*;
use bytemuck::{Pod, Zeroable};
use close2gl_core::{Camera, FateKind, Fates, Mesh, Overlay, RenderSettings, TriangleFate};
use close2gl_pipeline::matrices::ClipTransform;
use glam::Vec4;

use crate::grow_buffer::GrowBuffer;

/// One corner: Close2GL's clip coordinates (z remapped from OpenGL's -w..w to wgpu's 0..w) and
/// its fate's colour.
#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct FateVertex {
    clip: [f32; 4],
    color: [u8; 4],
}

pub(crate) struct FateView {
    fill: wgpu::RenderPipeline,
    outline: wgpu::RenderPipeline,
    fills: GrowBuffer,
    outlines: GrowBuffer,
    fill_count: u32,
    outline_count: u32,
    /// Kept between frames: the triangles to fill, far to near, and the vertices.
    order: Vec<(f32, u32)>,
    fill_vertices: Vec<FateVertex>,
    outline_vertices: Vec<FateVertex>,
}

/// Whether a fate reaches the screen (filled) or was removed before it (outlined).
fn is_filled(kind: FateKind) -> bool {
    !matches!(
        kind,
        FateKind::Clipped | FateKind::Culled | FateKind::ZeroArea
    )
}

impl FateView {
    pub(crate) fn new(device: &wgpu::Device, color_format: wgpu::TextureFormat) -> Self {
        let shader = device.create_shader_module(wgpu::include_wgsl!("fate_view.wgsl"));
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("fate view"),
            bind_group_layouts: &[],
            immediate_size: 0,
        });
        let pipeline = |topology| create_pipeline(device, &shader, &layout, color_format, topology);
        Self {
            fill: pipeline(wgpu::PrimitiveTopology::TriangleList),
            outline: pipeline(wgpu::PrimitiveTopology::LineList),
            fills: GrowBuffer::new(device, "fate fills", wgpu::BufferUsages::VERTEX),
            outlines: GrowBuffer::new(device, "fate outlines", wgpu::BufferUsages::VERTEX),
            fill_count: 0,
            outline_count: 0,
            order: Vec::new(),
            fill_vertices: Vec::new(),
            outline_vertices: Vec::new(),
        }
    }

    /// Rebuilds both vertex lists from the mesh, the camera and the recorded fates (nothing when
    /// the last frame recorded none) and uploads them.
    pub(crate) fn update(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        mesh: &Mesh,
        camera: &Camera,
        fates: &Fates,
    ) {
        let transform = ClipTransform::new(camera);
        let clip =
            |t: &[u32; 3]| t.map(|i| gl_to_wgpu_depth(transform.apply(mesh.positions[i as usize])));
        let recorded = mesh.triangles.iter().zip(&fates.triangles);
        self.order.clear();
        self.outline_vertices.clear();
        for (index, (triangle, fate)) in recorded.enumerate() {
            let corners = clip(triangle);
            if is_filled(fate.kind) {
                self.order.push((mean_depth(corners), index as u32));
            } else {
                push_outline(&mut self.outline_vertices, corners, fate);
            }
        }
        // The painter's order, far to near: no depth buffer in Close2GL's view pass.
        self.order.sort_by(|a, b| b.0.total_cmp(&a.0));
        self.fill_vertices.clear();
        for &(_, index) in &self.order {
            let color = rgba(fates.triangles[index as usize].kind);
            let corners = clip(&mesh.triangles[index as usize]);
            self.fill_vertices.extend(corners.map(|c| FateVertex {
                clip: c.to_array(),
                color,
            }));
        }
        self.fills
            .write(device, queue, bytemuck::cast_slice(&self.fill_vertices));
        self.outlines
            .write(device, queue, bytemuck::cast_slice(&self.outline_vertices));
        self.fill_count = self.fill_vertices.len() as u32;
        self.outline_count = self.outline_vertices.len() as u32;
    }

    /// Fills first, outlines over them: what was removed stays visible where it would be.
    pub(crate) fn draw(&self, pass: &mut wgpu::RenderPass<'_>) {
        for (pipeline, buffer, count) in [
            (&self.fill, &self.fills, self.fill_count),
            (&self.outline, &self.outlines, self.outline_count),
        ] {
            if count > 0 {
                pass.set_pipeline(pipeline);
                pass.set_vertex_buffer(0, buffer.slice());
                pass.draw(0..count, 0..1);
            }
        }
    }
}

/// OpenGL's clip depth (-w..w) as wgpu's (0..w): the same planes, so the GPU clips where
/// Close2GL's full clipping does.
fn gl_to_wgpu_depth(clip: Vec4) -> Vec4 {
    Vec4::new(clip.x, clip.y, 0.5 * (clip.z + clip.w), clip.w)
}

/// The mean NDC depth of the corners in front of the eye (triangles reaching behind it sort by
/// the corners that are in front).
fn mean_depth(corners: [Vec4; 3]) -> f32 {
    let (sum, n) = corners
        .iter()
        .filter(|c| c.w > 0.0)
        .fold((0.0, 0.0), |(sum, n), c| (sum + c.z / c.w, n + 1.0));
    if n > 0.0 { sum / n } else { f32::MAX }
}

/// The three edges as lines, at a depth inside the volume (w/2) so that only the side planes and
/// w > 0 clip them.
fn push_outline(out: &mut Vec<FateVertex>, corners: [Vec4; 3], fate: &TriangleFate) {
    let color = rgba(fate.kind);
    let vertex = |c: Vec4| FateVertex {
        clip: [c.x, c.y, 0.5 * c.w, c.w],
        color,
    };
    for (a, b) in [(0, 1), (1, 2), (2, 0)] {
        out.extend([vertex(corners[a]), vertex(corners[b])]);
    }
}

fn rgba(kind: FateKind) -> [u8; 4] {
    let [r, g, b] = kind.color();
    [r, g, b, 255]
}

fn create_pipeline(
    device: &wgpu::Device,
    shader: &wgpu::ShaderModule,
    layout: &wgpu::PipelineLayout,
    color_format: wgpu::TextureFormat,
    topology: wgpu::PrimitiveTopology,
) -> wgpu::RenderPipeline {
    let attributes = wgpu::vertex_attr_array![0 => Float32x4, 1 => Unorm8x4];
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("fate view"),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module: shader,
            entry_point: Some("vs_main"),
            compilation_options: Default::default(),
            buffers: &[Some(wgpu::VertexBufferLayout {
                array_stride: size_of::<FateVertex>() as u64,
                step_mode: wgpu::VertexStepMode::Vertex,
                attributes: &attributes,
            })],
        },
        primitive: wgpu::PrimitiveState {
            topology,
            cull_mode: None,
            ..Default::default()
        },
        depth_stencil: None,
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module: shader,
            entry_point: Some("fs_main"),
            compilation_options: Default::default(),
            targets: &[Some(color_format.into())],
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// Asks Close2GL to record fates while the fate view is shown: on when the overlay becomes
/// `Fates`, off when it leaves it (so that another reader's request, made while the view was
/// off, is left alone).
pub(crate) fn record_fates_while_shown(
    settings: Res<RenderSettings>,
    mut fates: ResMut<Fates>,
    mut shown: Local<bool>,
) {
    let now = settings.overlay == Overlay::Fates;
    if now != *shown {
        fates.record = now;
        *shown = now;
    }
}

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
    /// Drawn in this order: culled outlines (mostly behind what is filled, so under it), the
    /// fills, then clipped outlines (over everything: what vanished at the border).
    layers: [Layer; 3],
    /// Kept between frames: the triangles to fill, far to near.
    order: Vec<(f32, u32)>,
}

/// One draw of the fate view: its vertices on the CPU (kept between frames) and the GPU.
struct Layer {
    vertices: Vec<FateVertex>,
    buffer: GrowBuffer,
    count: u32,
}

impl Layer {
    fn new(device: &wgpu::Device, label: &'static str) -> Self {
        Self {
            vertices: Vec::new(),
            buffer: GrowBuffer::new(device, label, wgpu::BufferUsages::VERTEX),
            count: 0,
        }
    }

    fn upload(&mut self, device: &wgpu::Device, queue: &wgpu::Queue) {
        self.buffer
            .write(device, queue, bytemuck::cast_slice(&self.vertices));
        self.count = self.vertices.len() as u32;
    }
}

const UNDER: usize = 0;
const FILLS: usize = 1;
const OVER: usize = 2;

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
            layers: ["fate outlines under", "fate fills", "fate outlines over"]
                .map(|label| Layer::new(device, label)),
            order: Vec::new(),
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
        for layer in &mut self.layers {
            layer.vertices.clear();
        }
        for (index, (triangle, fate)) in recorded.enumerate() {
            let corners = clip(triangle);
            match fate.kind {
                FateKind::Clipped => push_outline(&mut self.layers[OVER].vertices, corners, fate),
                FateKind::Culled | FateKind::ZeroArea => {
                    push_outline(&mut self.layers[UNDER].vertices, corners, fate);
                }
                _ => self.order.push((mean_depth(corners), index as u32)),
            }
        }
        // The painter's order, far to near: no depth buffer in Close2GL's view pass.
        self.order.sort_by(|a, b| b.0.total_cmp(&a.0));
        for &(_, index) in &self.order {
            let color = rgba(fates.triangles[index as usize].kind);
            let corners = clip(&mesh.triangles[index as usize]);
            let vertex = |c: Vec4| FateVertex {
                clip: c.to_array(),
                color,
            };
            self.layers[FILLS].vertices.extend(corners.map(vertex));
        }
        for layer in &mut self.layers {
            layer.upload(device, queue);
        }
    }

    pub(crate) fn draw(&self, pass: &mut wgpu::RenderPass<'_>) {
        let pipelines = [&self.outline, &self.fill, &self.outline];
        for (pipeline, layer) in pipelines.into_iter().zip(&self.layers) {
            if layer.count > 0 {
                pass.set_pipeline(pipeline);
                pass.set_vertex_buffer(0, layer.buffer.slice());
                pass.draw(0..layer.count, 0..1);
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

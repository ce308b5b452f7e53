//! The fate view (`Overlay::FateView`): Close2GL's view with every mesh triangle in its fate's
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
use close2gl_core::{Camera, FateKind, Fates, Mesh, Overlay, RecordFates, TriangleFate};
use close2gl_pipeline::matrices::ClipTransform;
use glam::Vec4;

use crate::corners::{Corner, CornerPipelines, gl_to_wgpu_depth, outline};
use crate::grow_buffer::GrowBuffer;

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
    vertices: Vec<Corner>,
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
        let pipelines = CornerPipelines::new(device, "fate view", color_format, false);
        Self {
            fill: pipelines.fill,
            outline: pipelines.outline,
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
        (mesh, camera): (&Mesh, &Camera),
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
            let vertex = |c: Vec4| Corner {
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

/// The mean NDC depth of the corners in front of the eye (triangles reaching behind it sort by
/// the corners that are in front).
fn mean_depth(corners: [Vec4; 3]) -> f32 {
    let (sum, n) = corners
        .iter()
        .filter(|c| c.w > 0.0)
        .fold((0.0, 0.0), |(sum, n), c| (sum + c.z / c.w, n + 1.0));
    if n > 0.0 { sum / n } else { f32::MAX }
}

fn push_outline(out: &mut Vec<Corner>, corners: [Vec4; 3], fate: &TriangleFate) {
    out.extend(outline(corners, rgba(fate.kind)));
}

fn rgba(kind: FateKind) -> [u8; 4] {
    let [r, g, b] = kind.color();
    [r, g, b, 255]
}

/// Asks Close2GL to record fates while the fate view is shown: on when the overlay becomes
/// `Fates`, off when it leaves it (so that another reader's request, made while the view was
/// off, is left alone).
pub(crate) fn record_fates_while_shown(
    overlay: Res<Overlay>,
    mut request: ResMut<RecordFates>,
    mut shown: Local<bool>,
) {
    let now = *overlay == Overlay::FateView;
    if now != *shown {
        request.0 = now;
        *shown = now;
    }
}

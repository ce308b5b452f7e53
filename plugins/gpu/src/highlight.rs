//! The selected triangle (`SelectedTriangle`) highlighted in both views: its inside tinted and
//! its edges outlined, over everything (no depth test), so that a hidden, culled or clipped
//! triangle shows where it would be. Each view places it with its own matrices (the reference
//! with glam's view and projection, Close2GL with its own P·M), so where the two pipelines
//! disagree on a triangle, so do its highlights.

use close2gl_core::{Camera, Mesh};
use close2gl_pipeline::matrices::ClipTransform;
use glam::Vec4;
use wgpu::util::DeviceExt;

use crate::corners::{Corner, CornerPipelines, gl_to_wgpu_depth, outline};
use crate::reference::relative_matrices;

const FILL: [u8; 4] = [255, 255, 255, 110];
const OUTLINE: [u8; 4] = [255, 128, 0, 255];
/// Three corners to fill, then three edges as six line ends.
const CORNERS: usize = 9;

pub(crate) struct Highlight {
    /// For the reference's pass, which has a depth attachment.
    reference_pipelines: CornerPipelines,
    close2gl_pipelines: CornerPipelines,
    reference: wgpu::Buffer,
    close2gl: wgpu::Buffer,
    shown: bool,
}

impl Highlight {
    pub(crate) fn new(device: &wgpu::Device, color_format: wgpu::TextureFormat) -> Self {
        let buffer = |label| {
            device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents: bytemuck::cast_slice(&[Corner::default(); CORNERS]),
                usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
            })
        };
        Self {
            reference_pipelines: CornerPipelines::new(device, "highlight", color_format, true),
            close2gl_pipelines: CornerPipelines::new(device, "highlight", color_format, false),
            reference: buffer("highlight: reference"),
            close2gl: buffer("highlight: close2gl"),
            shown: false,
        }
    }

    /// Places `selected` (a mesh triangle, if any and in range) in both views.
    pub(crate) fn update(
        &mut self,
        queue: &wgpu::Queue,
        mesh: &Mesh,
        camera: &Camera,
        selected: Option<u32>,
    ) {
        let triangle = selected.and_then(|t| mesh.triangles.get(t as usize));
        self.shown = triangle.is_some();
        let Some(triangle) = triangle else {
            return;
        };
        let world = triangle.map(|i| mesh.positions[i as usize]);
        // As the reference draws its mesh: relative to a nearby origin, for precision.
        let (view, projection) = relative_matrices(camera, world[0]);
        let reference = world.map(|p| projection * view * (p - world[0]).extend(1.0));
        let transform = ClipTransform::new(camera);
        let close2gl = world.map(|p| gl_to_wgpu_depth(transform.apply(p)));
        queue.write_buffer(
            &self.reference,
            0,
            bytemuck::cast_slice(&corners(reference)),
        );
        queue.write_buffer(&self.close2gl, 0, bytemuck::cast_slice(&corners(close2gl)));
    }

    pub(crate) fn draw_reference(&self, pass: &mut wgpu::RenderPass<'_>) {
        self.draw(pass, &self.reference_pipelines, &self.reference);
    }

    pub(crate) fn draw_close2gl(&self, pass: &mut wgpu::RenderPass<'_>) {
        self.draw(pass, &self.close2gl_pipelines, &self.close2gl);
    }

    fn draw(
        &self,
        pass: &mut wgpu::RenderPass<'_>,
        pipelines: &CornerPipelines,
        corners: &wgpu::Buffer,
    ) {
        if !self.shown {
            return;
        }
        pass.set_vertex_buffer(0, corners.slice(..));
        pass.set_pipeline(&pipelines.fill);
        pass.draw(0..3, 0..1);
        pass.set_pipeline(&pipelines.outline);
        pass.draw(3..CORNERS as u32, 0..1);
    }
}

/// The fill's corners (inside the volume's depth, as the outline's), then the outline's edges.
fn corners(clip: [Vec4; 3]) -> [Corner; CORNERS] {
    let edges = outline(clip, OUTLINE);
    let fill = [edges[0], edges[2], edges[4]].map(|c| Corner { color: FILL, ..c });
    let mut all = [Corner::default(); CORNERS];
    all[..3].copy_from_slice(&fill);
    all[3..].copy_from_slice(&edges);
    all
}

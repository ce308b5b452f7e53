//! The selected triangle (`SelectedTriangle`) highlighted in both views: its inside tinted and
//! its edges outlined, over everything (no depth test), so that a hidden, culled or clipped
//! triangle shows where it would be. Each view places it with its own matrices (the reference
//! with glam's view and projection, Close2GL with its own P·M), so where the two pipelines
//! disagree on a triangle, so do its highlights.

use close2gl_core::{Camera, Mesh, Viewport};
use close2gl_pipeline::matrices::ClipTransform;
use glam::Vec4;
use wgpu::util::DeviceExt;

use crate::corners::{Corner, CornerPipelines, gl_to_wgpu_depth, outline};
use crate::reference::relative_matrices;

const FILL: [u8; 4] = [255, 255, 255, 110];
const OUTLINE: [u8; 4] = [255, 128, 0, 255];
/// Three corners to fill, three edges as six line ends, then the marker's four strokes.
const CORNERS: usize = 17;
/// The marker around the triangle's centre, in pixels: a cross with a gap, so that a triangle
/// smaller than a pixel (a dense mesh's) is still found at a glance.
const MARK_GAP: f32 = 6.0;
const MARK_REACH: f32 = 16.0;

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

    /// Places `selected` (a mesh triangle, if any and in range) in both views of `viewport`'s
    /// size.
    pub(crate) fn update(
        &mut self,
        queue: &wgpu::Queue,
        (mesh, camera): (&Mesh, &Camera),
        selected: Option<u32>,
        viewport: Viewport,
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
        for (buffer, clip) in [(&self.reference, reference), (&self.close2gl, close2gl)] {
            queue.write_buffer(buffer, 0, bytemuck::cast_slice(&corners(clip, viewport)));
        }
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

/// The fill's corners (inside the volume's depth, as the outline's), the outline's edges, and
/// the marker around the centre (off the screen when the centre is not in front of the eye).
fn corners(clip: [Vec4; 3], viewport: Viewport) -> [Corner; CORNERS] {
    let edges = outline(clip, OUTLINE);
    let fill = [edges[0], edges[2], edges[4]].map(|c| Corner { color: FILL, ..c });
    let mut all = [Corner::default(); CORNERS];
    all[..3].copy_from_slice(&fill);
    all[3..9].copy_from_slice(&edges);
    all[9..].copy_from_slice(&marker(clip, viewport));
    all
}

/// Four strokes around the triangle's centre on screen, `MARK_GAP` to `MARK_REACH` pixels out.
fn marker(clip: [Vec4; 3], viewport: Viewport) -> [Corner; 8] {
    let centre = (clip[0] + clip[1] + clip[2]) / 3.0;
    if centre.w <= 0.0 {
        // Outside the volume, where clipping drops the strokes whole.
        let away = Corner {
            clip: [2.0, 2.0, 0.5, 1.0],
            color: OUTLINE,
        };
        return [away; 8];
    }
    let (x, y) = (centre.x / centre.w, centre.y / centre.w);
    // Pixels to NDC: the viewport spans 2 in each direction.
    let px = 2.0 / viewport.width.max(1) as f32;
    let py = 2.0 / viewport.height.max(1) as f32;
    let at = |dx: f32, dy: f32| Corner {
        clip: [x + dx * px, y + dy * py, 0.5, 1.0],
        color: OUTLINE,
    };
    let (g, r) = (MARK_GAP, MARK_REACH);
    [
        at(-r, 0.0),
        at(-g, 0.0),
        at(g, 0.0),
        at(r, 0.0),
        at(0.0, -r),
        at(0.0, -g),
        at(0.0, g),
        at(0.0, r),
    ]
}

//! Corners the CPU has already put in clip coordinates, each with a colour, and the pipelines
//! that fill or outline them: the fate view (Close2GL's own P·M·p) and the selected triangle's
//! highlight (each view's own matrices). The GPU only clips and rasterizes them.

use bytemuck::{Pod, Zeroable};
use glam::Vec4;

use crate::attachments::depth_untouched;
use crate::vertex_pipeline::VertexPipeline;

/// One corner: clip coordinates in wgpu's depth convention (z in 0..w) and a colour.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
pub(crate) struct Corner {
    pub(crate) clip: [f32; 4],
    pub(crate) color: [u8; 4],
}

/// OpenGL's clip depth (-w..w) as wgpu's (0..w): the same planes, so the GPU clips where
/// Close2GL's full clipping does.
pub(crate) fn gl_to_wgpu_depth(clip: Vec4) -> Vec4 {
    Vec4::new(clip.x, clip.y, 0.5 * (clip.z + clip.w), clip.w)
}

/// A triangle's three edges as six line ends in `color`, at a depth inside the volume (w/2) so
/// that only the side planes and w > 0 clip them: a triangle beyond the far plane or in front of
/// the near plane still shows where it would project.
pub(crate) fn outline(corners: [Vec4; 3], color: [u8; 4]) -> [Corner; 6] {
    let [a, b, c] = corners.map(|p| Corner {
        clip: [p.x, p.y, 0.5 * p.w, p.w],
        color,
    });
    [a, b, b, c, c, a]
}

/// The fill (triangle list) and outline (line list) pipelines, alpha-blended, for a pass with
/// a [`crate::DEPTH_FORMAT`] attachment when `with_depth` says so (tested `Always`, never written: drawn over
/// everything) or without one.
pub(crate) struct CornerPipelines {
    pub(crate) fill: wgpu::RenderPipeline,
    pub(crate) outline: wgpu::RenderPipeline,
}

impl CornerPipelines {
    pub(crate) fn new(
        device: &wgpu::Device,
        label: &str,
        color_format: wgpu::TextureFormat,
        with_depth: bool,
    ) -> Self {
        let shader = device.create_shader_module(wgpu::include_wgsl!("corners.wgsl"));
        let layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some(label),
            bind_group_layouts: &[],
            immediate_size: 0,
        });
        let depth_stencil = with_depth.then(depth_untouched);
        let pipeline = |topology| {
            create_pipeline(
                device,
                (label, &shader, &layout),
                color_format,
                topology,
                depth_stencil.clone(),
            )
        };
        Self {
            fill: pipeline(wgpu::PrimitiveTopology::TriangleList),
            outline: pipeline(wgpu::PrimitiveTopology::LineList),
        }
    }
}

fn create_pipeline(
    device: &wgpu::Device,
    (label, shader, layout): (&str, &wgpu::ShaderModule, &wgpu::PipelineLayout),
    color_format: wgpu::TextureFormat,
    topology: wgpu::PrimitiveTopology,
    depth_stencil: Option<wgpu::DepthStencilState>,
) -> wgpu::RenderPipeline {
    let attributes = wgpu::vertex_attr_array![0 => Float32x4, 1 => Unorm8x4];
    VertexPipeline {
        label,
        shader,
        layout,
        fragment: "fs_main",
        vertex: wgpu::VertexBufferLayout {
            array_stride: size_of::<Corner>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &attributes,
        },
        topology,
        depth_stencil,
        color_format,
        blend: Some(wgpu::BlendState::ALPHA_BLENDING),
    }
    .create(device)
}

//! The outside view on the GPU: one shader, three pipelines (the model, the lines, the
//! translucent planes), three vertex buffers refilled from [`OutsideScene`] each frame it shows.

use bevy_ecs::prelude::*;
use bytemuck::{Pod, Zeroable};

use super::outside_camera::OutsideCamera;
use super::outside_scene::{OutsideScene, OutsideVertex};
use crate::attachments::DEPTH_FORMAT;
use crate::gpu::Gpu;
use crate::uniforms::UniformSetup;
use crate::vertex_pipeline::VertexPipeline;

/// The uniform block of outside.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct FrameUniforms {
    view_projection: [[f32; 4]; 4],
    eye: [f32; 4],
}

/// A vertex buffer that grows by doubling, so a steady frame allocates nothing.
struct Vertices {
    buffer: wgpu::Buffer,
    count: u32,
}

impl Vertices {
    fn new(device: &wgpu::Device) -> Self {
        Self {
            buffer: vertex_buffer(device, 4096),
            count: 0,
        }
    }

    fn upload(&mut self, gpu: &Gpu, vertices: &[OutsideVertex]) {
        let bytes: &[u8] = bytemuck::cast_slice(vertices);
        let needed = bytes.len() as u64;
        if needed > self.buffer.size() {
            self.buffer = vertex_buffer(&gpu.device, needed.next_power_of_two());
        }
        if !bytes.is_empty() {
            gpu.queue.write_buffer(&self.buffer, 0, bytes);
        }
        self.count = vertices.len() as u32;
    }

    fn draw(&self, pass: &mut wgpu::RenderPass<'_>, pipeline: &wgpu::RenderPipeline) {
        if self.count > 0 {
            pass.set_pipeline(pipeline);
            pass.set_vertex_buffer(0, self.buffer.slice(..));
            pass.draw(0..self.count, 0..1);
        }
    }
}

/// The outside view's GPU state (a Resource, inserted beside `Views` by whoever owns the
/// target): the upload system of [`super::OutsidePlugin`] fills it while the view shows; the
/// owner of the target calls [`OutsideRenderer::draw`].
#[derive(Resource)]
pub struct OutsideRenderer {
    uniforms: UniformSetup,
    mesh_pipeline: wgpu::RenderPipeline,
    line_pipeline: wgpu::RenderPipeline,
    face_pipeline: wgpu::RenderPipeline,
    mesh: Vertices,
    lines: Vertices,
    faces: Vertices,
    pub(crate) scene: OutsideScene,
    /// The camera of the last upload, for a view of its aspect.
    pub(crate) camera: Option<OutsideCamera>,
}

impl OutsideRenderer {
    /// `color_format` is the format of the target it draws into (a surface's, or
    /// [`crate::OFFSCREEN_FORMAT`]).
    pub fn new(gpu: &Gpu, color_format: wgpu::TextureFormat) -> Self {
        let device = &gpu.device;
        let shader = device.create_shader_module(wgpu::include_wgsl!("outside.wgsl"));
        let uniforms = UniformSetup::new(device, "outside", size_of::<FrameUniforms>());
        let pipeline = |kind: PipelineKind| {
            create_pipeline(device, &shader, &uniforms.layout, color_format, kind)
        };
        Self {
            mesh_pipeline: pipeline(PipelineKind::Mesh),
            line_pipeline: pipeline(PipelineKind::Lines),
            face_pipeline: pipeline(PipelineKind::Faces),
            uniforms,
            mesh: Vertices::new(device),
            lines: Vertices::new(device),
            faces: Vertices::new(device),
            scene: OutsideScene::default(),
            camera: None,
        }
    }

    /// Uploads the scene's three vertex lists and the camera.
    pub(crate) fn upload(&mut self, gpu: &Gpu, camera: OutsideCamera) {
        self.mesh.upload(gpu, &self.scene.mesh);
        self.lines.upload(gpu, &self.scene.lines);
        self.faces.upload(gpu, &self.scene.faces);
        let uniforms = FrameUniforms {
            view_projection: camera.view_projection().to_cols_array_2d(),
            eye: camera.eye.extend(1.0).to_array(),
        };
        gpu.queue
            .write_buffer(&self.uniforms.buffer, 0, bytemuck::bytes_of(&uniforms));
        self.camera = Some(camera);
    }

    /// Records the view into a pass with a [`DEPTH_FORMAT`] depth attachment (cleared to 1.0);
    /// the caller sets the viewport. The model and the lines first, then the translucent planes
    /// over them (tested against their depth, not writing it).
    pub fn draw(&self, pass: &mut wgpu::RenderPass<'_>) {
        pass.set_bind_group(0, &self.uniforms.bind_group, &[]);
        self.mesh.draw(pass, &self.mesh_pipeline);
        self.lines.draw(pass, &self.line_pipeline);
        self.faces.draw(pass, &self.face_pipeline);
    }

    /// The camera the last upload used (what a test projects with).
    pub fn camera(&self) -> Option<OutsideCamera> {
        self.camera
    }
}

#[derive(Clone, Copy, PartialEq)]
enum PipelineKind {
    Mesh,
    Lines,
    Faces,
}

fn create_pipeline(
    device: &wgpu::Device,
    shader: &wgpu::ShaderModule,
    layout: &wgpu::PipelineLayout,
    color_format: wgpu::TextureFormat,
    kind: PipelineKind,
) -> wgpu::RenderPipeline {
    let attributes = wgpu::vertex_attr_array![
        0 => Float32x3, 1 => Float32x4, 2 => Float32x2, 3 => Unorm8x4
    ];
    let (topology, fragment, blend) = match kind {
        PipelineKind::Mesh => (wgpu::PrimitiveTopology::TriangleList, "fs_mesh", None),
        PipelineKind::Lines => (wgpu::PrimitiveTopology::LineList, "fs_flat", None),
        PipelineKind::Faces => (
            wgpu::PrimitiveTopology::TriangleList,
            "fs_flat",
            Some(wgpu::BlendState::ALPHA_BLENDING),
        ),
    };
    VertexPipeline {
        label: "outside",
        shader,
        layout,
        fragment,
        vertex: wgpu::VertexBufferLayout {
            array_stride: size_of::<OutsideVertex>() as u64,
            step_mode: wgpu::VertexStepMode::Vertex,
            attributes: &attributes,
        },
        // Both faces of every triangle: the outside view shows what the camera culls too.
        topology,
        depth_stencil: Some(wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(kind != PipelineKind::Faces),
            depth_compare: Some(wgpu::CompareFunction::Less),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        color_format,
        blend,
    }
    .create(device)
}

fn vertex_buffer(device: &wgpu::Device, size: u64) -> wgpu::Buffer {
    device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("outside vertices"),
        size,
        usage: wgpu::BufferUsages::VERTEX | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    })
}

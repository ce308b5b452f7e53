//! The Close2GL view: draws the 2D buffer the Close2GL system wrote, through a pass-through
//! pipeline (pixels to NDC, one flat colour; no depth, no culling, no 3D transform). Its lines
//! and points are the GPU's line and point lists where the device has the polygon-mode features
//! (so the reference's polygon modes and these follow the same rules), and otherwise, as the
//! reference draws its own there, the software rasterizer's one-pixel rectangles and squares as
//! triangles, one instance a line or point (`pixel_shapes.wgsl`): a line's rectangle drawn a
//! little larger and its fragments kept where the software's exact rectangle covers their
//! centres, so that no backend's sub-pixel snapping changes them.

use bytemuck::{Pod, Zeroable};
use close2gl_core::{Close2glFrame, Topology};
use glam::Vec3;

use crate::grow_buffer::GrowBuffer;
use crate::reference::{SHAPE_VERTICES, needs_faces, with_pixel_shapes};

/// The uniform block of close2gl.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct FrameUniforms {
    size: [f32; 2],
    _pad: [f32; 2],
    color: [f32; 4],
}

pub(crate) struct Close2glView {
    shader: wgpu::ShaderModule,
    layout: wgpu::PipelineLayout,
    color_format: wgpu::TextureFormat,
    uniforms: wgpu::Buffer,
    bind_group: wgpu::BindGroup,
    /// Points, lines, triangles: made when first needed.
    pipelines: [Option<wgpu::RenderPipeline>; 3],
    vertices: GrowBuffer,
    vertex_count: u32,
    topology: Topology,
    /// Whether lines and points are drawn as shapes (the device lacks the polygon modes).
    shapes: bool,
}

fn slot(topology: Topology) -> usize {
    match topology {
        Topology::Points => 0,
        Topology::Lines => 1,
        Topology::Triangles => 2,
    }
}

const VERTEX_SIZE: u64 = size_of::<[f32; 2]>() as u64;

impl Close2glView {
    pub(crate) fn new(device: &wgpu::Device, color_format: wgpu::TextureFormat) -> Self {
        let shader = with_pixel_shapes(device, "close2gl.wgsl", include_str!("close2gl.wgsl"));
        let crate::uniforms::UniformSetup {
            buffer: uniforms,
            bind_group,
            layout,
        } = crate::uniforms::UniformSetup::new(device, "close2gl", size_of::<FrameUniforms>());
        Self {
            shader,
            layout,
            color_format,
            uniforms,
            bind_group,
            pipelines: [None, None, None],
            vertices: GrowBuffer::new(device, "close2gl vertices", wgpu::BufferUsages::VERTEX),
            vertex_count: 0,
            topology: Topology::Triangles,
            shapes: needs_faces(device.features()),
        }
    }

    /// Uploads `vertices` (the frame's 2D buffer, or a shown trace's in its topology; the GPU
    /// buffer grows by doubling when they do not fit) and the uniforms, and makes sure the
    /// pipeline for the frame's topology exists.
    pub(crate) fn update(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        frame: &Close2glFrame,
        vertices: &[[f32; 2]],
        color: Vec3,
    ) {
        self.vertices
            .write(device, queue, bytemuck::cast_slice(vertices));
        self.vertex_count = vertices.len() as u32;
        self.topology = frame.topology;
        let uniforms = FrameUniforms {
            size: [
                frame.viewport.width.max(1) as f32,
                frame.viewport.height.max(1) as f32,
            ],
            _pad: [0.0; 2],
            color: color.extend(1.0).to_array(),
        };
        queue.write_buffer(&self.uniforms, 0, bytemuck::bytes_of(&uniforms));
        let slot = slot(frame.topology);
        if self.pipelines[slot].is_none() {
            self.pipelines[slot] = Some(self.create_pipeline(device, frame.topology));
        }
    }

    pub(crate) fn draw(&self, pass: &mut wgpu::RenderPass<'_>) {
        let Some(pipeline) = &self.pipelines[slot(self.topology)] else {
            return;
        };
        if self.vertex_count == 0 {
            return;
        }
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, &self.bind_group, &[]);
        pass.set_vertex_buffer(0, self.vertices.slice());
        match Feed::new(self.topology, self.shapes) {
            Feed::Shapes { per_shape, .. } => {
                pass.draw(0..SHAPE_VERTICES, 0..self.vertex_count / per_shape);
            }
            Feed::Primitives(_) => pass.draw(0..self.vertex_count, 0..1),
        }
    }

    fn create_pipeline(&self, device: &wgpu::Device, topology: Topology) -> wgpu::RenderPipeline {
        let feed = Feed::new(topology, self.shapes);
        device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some("close2gl"),
            layout: Some(&self.layout),
            vertex: wgpu::VertexState {
                module: &self.shader,
                entry_point: Some(feed.entry_point()),
                compilation_options: Default::default(),
                buffers: &[Some(feed.layout())],
            },
            primitive: wgpu::PrimitiveState {
                topology: feed.topology(),
                cull_mode: None,
                ..Default::default()
            },
            depth_stencil: None,
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &self.shader,
                entry_point: Some(feed.fragment_entry_point()),
                compilation_options: Default::default(),
                targets: &[Some(self.color_format.into())],
            }),
            multiview_mask: None,
            cache: None,
        })
    }
}

/// How the 2D buffer of one topology reaches the GPU.
#[derive(Clone, Copy)]
enum Feed {
    /// As the GPU's own primitives, one buffer vertex a vertex.
    Primitives(wgpu::PrimitiveTopology),
    /// Each line or point one instance of `per_shape` buffer vertices, drawn by `entry_point` as
    /// its shape's two triangles.
    Shapes {
        per_shape: u32,
        entry_point: &'static str,
    },
}

impl Feed {
    fn new(topology: Topology, shapes: bool) -> Feed {
        match (topology, shapes) {
            (Topology::Lines, true) => Feed::Shapes {
                per_shape: 2,
                entry_point: "vs_line",
            },
            (Topology::Points, true) => Feed::Shapes {
                per_shape: 1,
                entry_point: "vs_point",
            },
            (Topology::Points, false) => Feed::Primitives(wgpu::PrimitiveTopology::PointList),
            (Topology::Lines, false) => Feed::Primitives(wgpu::PrimitiveTopology::LineList),
            (Topology::Triangles, _) => Feed::Primitives(wgpu::PrimitiveTopology::TriangleList),
        }
    }

    fn entry_point(self) -> &'static str {
        match self {
            Feed::Primitives(_) => "vs_main",
            Feed::Shapes { entry_point, .. } => entry_point,
        }
    }

    /// A line's rectangle keeps only the fragments its exact rectangle covers (`fs_line`).
    fn fragment_entry_point(self) -> &'static str {
        match self {
            Feed::Shapes { per_shape: 2, .. } => "fs_line",
            _ => "fs_main",
        }
    }

    fn topology(self) -> wgpu::PrimitiveTopology {
        match self {
            Feed::Primitives(topology) => topology,
            Feed::Shapes { .. } => wgpu::PrimitiveTopology::TriangleList,
        }
    }

    /// The buffer's layout: a vertex a vertex, or a line's two or a point's one an instance.
    fn layout(self) -> wgpu::VertexBufferLayout<'static> {
        let (attributes, step_mode): (&'static [wgpu::VertexAttribute], _) = match self {
            Feed::Shapes { per_shape: 2, .. } => (&LINE, wgpu::VertexStepMode::Instance),
            Feed::Shapes { .. } => (&POINT, wgpu::VertexStepMode::Instance),
            Feed::Primitives(_) => (&POINT, wgpu::VertexStepMode::Vertex),
        };
        wgpu::VertexBufferLayout {
            array_stride: VERTEX_SIZE * attributes.len() as u64,
            step_mode,
            attributes,
        }
    }
}

/// One pixel position.
const POINT: [wgpu::VertexAttribute; 1] = wgpu::vertex_attr_array![0 => Float32x2];
/// A line's two ends.
const LINE: [wgpu::VertexAttribute; 2] = wgpu::vertex_attr_array![0 => Float32x2, 1 => Float32x2];

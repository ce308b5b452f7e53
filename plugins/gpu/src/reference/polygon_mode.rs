//! glPolygonMode on any adapter. Where the device has `POLYGON_MODE_LINE` / `POLYGON_MODE_POINT`
//! the triangles are drawn with wgpu's polygon mode. Where it lacks them (WebGL2, some mobile and
//! older desktop adapters, or a device opened without them: `CLOSE2GL_NO_POLYGON_MODE=1`), each
//! face is drawn as one instance carrying its three corners: its three edges as one-pixel
//! rectangles or its corners (with those clipping adds on the near plane) as one-pixel squares,
//! each two triangles (`pixel_shapes.wgsl`, the shapes Close2GL's software rasterizer draws, so
//! that the triangle fill rule decides their pixels on every backend; a line's rectangle drawn
//! 1/8 pixel larger, its fragments kept where the software's exact rectangle covers their
//! centres, so that no backend's sub-pixel snapping changes them), with the depth test; and
//! culling, which the hardware would apply to each shape's triangles rather than to the face, is
//! decided in the vertex shader from the face's clip positions (`kept_faces.wgsl`), so that the
//! same faces are kept as OpenGL keeps.

use bytemuck::{Pod, Zeroable};
use close2gl_core::{FrontFace, RenderMode};
use wgpu::util::DeviceExt;

use super::{PipelineKey, Vertex};

/// How a key's faces reach the rasterizer on a device with some features.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum FaceDrawing {
    /// Indexed triangles in wgpu's polygon mode.
    Triangles(wgpu::PolygonMode),
    /// One instance a face, drawn as its edges' rectangles (`true`) or its points' squares,
    /// culled by the shader.
    Instanced { edges: bool },
}

impl FaceDrawing {
    pub(crate) fn new(features: wgpu::Features, mode: RenderMode) -> Self {
        let has = |feature| features.contains(feature);
        match mode {
            RenderMode::Solid => Self::Triangles(wgpu::PolygonMode::Fill),
            RenderMode::Wireframe if has(wgpu::Features::POLYGON_MODE_LINE) => {
                Self::Triangles(wgpu::PolygonMode::Line)
            }
            RenderMode::Points if has(wgpu::Features::POLYGON_MODE_POINT) => {
                Self::Triangles(wgpu::PolygonMode::Point)
            }
            RenderMode::Wireframe => Self::Instanced { edges: true },
            RenderMode::Points => Self::Instanced { edges: false },
        }
    }

    /// Vertices drawn per instance: a triangle's 3; for lines, a rectangle's 6 for each of 3
    /// edges; for points, a square's 6 for each of the 3 corners and the 3 that clipping at the
    /// near plane may add (`kept_faces.wgsl`).
    pub(crate) fn vertices_per_face(self) -> u32 {
        match self {
            Self::Triangles(_) => 3,
            Self::Instanced { edges: true } => 3 * SHAPE_VERTICES,
            Self::Instanced { edges: false } => 6 * SHAPE_VERTICES,
        }
    }

    /// The override constants of `kept_faces.wgsl` for `key` (none for triangles).
    pub(crate) fn constants(self, key: PipelineKey) -> Vec<(&'static str, f64)> {
        let Self::Instanced { edges } = self else {
            return Vec::new();
        };
        let flag = |on: bool| f64::from(u8::from(on));
        vec![
            ("SHAPES", 1.0),
            ("EDGES", flag(edges)),
            ("CULL_BACK", flag(key.backface_culling)),
            ("CLOCKWISE", flag(key.front_face == FrontFace::Cw)),
        ]
    }

    /// The reference shader's vertex entry point and its vertex buffer: the mesh's vertices for
    /// triangles, the faces as instances otherwise.
    pub(super) fn vertex_stage(self) -> (&'static str, wgpu::VertexBufferLayout<'static>) {
        match self {
            Self::Triangles(_) => (
                "vs_main",
                wgpu::VertexBufferLayout {
                    array_stride: size_of::<Vertex>() as u64,
                    step_mode: wgpu::VertexStepMode::Vertex,
                    attributes: &VERTEX_ATTRIBUTES,
                },
            ),
            Self::Instanced { .. } => ("vs_face", face_layout()),
        }
    }

    /// The primitive state: the key's culling and front face for triangles; for instanced faces
    /// the shapes' triangles, which the hardware does not cull (the shader culls the faces).
    pub(crate) fn primitive_state(self, key: PipelineKey) -> wgpu::PrimitiveState {
        let front_face = match key.front_face {
            FrontFace::Ccw => wgpu::FrontFace::Ccw,
            FrontFace::Cw => wgpu::FrontFace::Cw,
        };
        match self {
            Self::Triangles(polygon_mode) => wgpu::PrimitiveState {
                topology: wgpu::PrimitiveTopology::TriangleList,
                front_face,
                cull_mode: key.backface_culling.then_some(wgpu::Face::Back),
                polygon_mode,
                ..Default::default()
            },
            Self::Instanced { .. } => wgpu::PrimitiveState {
                topology: wgpu::PrimitiveTopology::TriangleList,
                front_face,
                cull_mode: None,
                ..Default::default()
            },
        }
    }
}

/// A shader module of `source` with `kept_faces.wgsl`'s functions after it.
pub(crate) fn with_kept_faces(
    device: &wgpu::Device,
    label: &str,
    source: &str,
) -> wgpu::ShaderModule {
    let kept_faces = include_str!("../kept_faces.wgsl");
    with_pixel_shapes(device, label, &format!("{source}\n{kept_faces}"))
}

/// A shader module of `source` with `pixel_shapes.wgsl`'s functions after it.
pub(crate) fn with_pixel_shapes(
    device: &wgpu::Device,
    label: &str,
    source: &str,
) -> wgpu::ShaderModule {
    let shapes = include_str!("../pixel_shapes.wgsl");
    device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(label),
        source: wgpu::ShaderSource::Wgsl(format!("{source}\n{shapes}").into()),
    })
}

/// The vertices of one line's rectangle or one point's square: two triangles
/// (`pixel_shapes.wgsl`).
pub(crate) const SHAPE_VERTICES: u32 = 6;

/// Whether a device with `features` draws some mode as instanced faces (and the Close2GL view
/// its lines and points as shapes).
pub(crate) fn needs_faces(features: wgpu::Features) -> bool {
    !features.contains(wgpu::Features::POLYGON_MODE_LINE | wgpu::Features::POLYGON_MODE_POINT)
}

/// One instance of `vs_face`: a face's three corners.
#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct Face([Vertex; 3]);

/// The faces of `triangles` (in their order) as `vs_face`'s instances.
pub(super) fn face_buffer(
    device: &wgpu::Device,
    vertices: &[Vertex],
    triangles: &[[u32; 3]],
) -> wgpu::Buffer {
    let faces: Vec<Face> = triangles
        .iter()
        .map(|t| Face(t.map(|i| vertices[i as usize])))
        .collect();
    device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("reference faces"),
        contents: bytemuck::cast_slice(&faces),
        usage: wgpu::BufferUsages::VERTEX,
    })
}

/// A vertex: position, normal and uv.
const VERTEX_ATTRIBUTES: [wgpu::VertexAttribute; 3] =
    wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x2];

/// The vertex buffer layout of instanced faces: three corners of position, normal and uv.
const FACE_ATTRIBUTES: [wgpu::VertexAttribute; 9] = wgpu::vertex_attr_array![
    0 => Float32x3, 1 => Float32x3, 2 => Float32x2,
    3 => Float32x3, 4 => Float32x3, 5 => Float32x2,
    6 => Float32x3, 7 => Float32x3, 8 => Float32x2,
];

fn face_layout() -> wgpu::VertexBufferLayout<'static> {
    wgpu::VertexBufferLayout {
        array_stride: size_of::<Face>() as u64,
        step_mode: wgpu::VertexStepMode::Instance,
        attributes: &FACE_ATTRIBUTES,
    }
}

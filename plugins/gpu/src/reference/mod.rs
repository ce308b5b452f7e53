//! The reference renderer: the mesh drawn by the GPU from glam's own camera matrices, with depth
//! test, glPolygonMode-style points / wireframe / solid, culling, the four shading modes, and the
//! texture modulating the shaded colour; in the fate view, the GPU's own facing and depth-test
//! answers over it ([`overlay`]).

mod overlay;
mod polygon_mode;

use std::collections::HashMap;

use bytemuck::{Pod, Zeroable};
use close2gl_core::camera_matrices;
use close2gl_core::limits::has_no_area;
use close2gl_core::{
    Appearance, Camera, FrontFace, Lighting, Mesh, Overlay, PipelineSettings, RenderMode, Shading,
    Texture, TextureFilter, Viewport,
};
use glam::{Mat4, Vec3};
use wgpu::util::DeviceExt;

use crate::attachments::DEPTH_FORMAT;
use crate::reference_texture::ReferenceBindings;
use overlay::OverlayPipelines;
pub(crate) use polygon_mode::{
    FaceDrawing, SHAPE_VERTICES, needs_faces, with_kept_faces, with_pixel_shapes,
};

/// [`camera_matrices`] for a mesh uploaded relative to `origin` (see [`GpuMesh::origin`]): the
/// camera is moved by the same amount, so eye space is unchanged.
pub(crate) fn relative_matrices(camera: &Camera, origin: Vec3) -> (Mat4, Mat4) {
    camera_matrices(&Camera {
        position: camera.position - origin,
        ..*camera
    })
}

/// The uniform block of reference.wgsl, field for field.
#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct Uniforms {
    view_projection: [[f32; 4]; 4],
    modelview: [[f32; 4]; 4],
    normal_matrix: [[f32; 4]; 4],
    light: [f32; 4],
    ambient: [f32; 4],
    intensity: [f32; 4],
    color: [f32; 4],
    material: [f32; 4],
    attenuation: [f32; 4],
    /// x: 1 when the texture modulates the colour, else 0.
    texturing: [f32; 4],
    /// xy: the target's size in pixels, which lines and points drawn face by face are measured in.
    viewport: [f32; 4],
}

impl Uniforms {
    /// The uniforms for a mesh uploaded relative to `origin` (see [`GpuMesh::origin`]): the
    /// camera and the light are moved by the same amount, so eye space is unchanged.
    fn new(
        camera: &Camera,
        look: &Appearance,
        lighting: &Lighting,
        origin: Vec3,
        textured: bool,
        viewport: Viewport,
    ) -> Self {
        let (view, projection) = relative_matrices(camera, origin);
        let light = view.transform_point3(lighting.light_position - origin);
        let [c0, c1, c2] = lighting.attenuation;
        Self {
            view_projection: (projection * view).to_cols_array_2d(),
            modelview: view.to_cols_array_2d(),
            normal_matrix: view.inverse().transpose().to_cols_array_2d(),
            light: light.extend(1.0).to_array(),
            ambient: (lighting.ia * lighting.ka).extend(1.0).to_array(),
            intensity: lighting.il.extend(1.0).to_array(),
            color: look.color.extend(1.0).to_array(),
            material: [lighting.kd, lighting.ks, lighting.shininess, 0.0],
            attenuation: [c0, c1, c2, 0.0],
            texturing: [f32::from(u8::from(textured)), 0.0, 0.0, 0.0],
            viewport: viewport_size(viewport),
        }
    }
}

/// What makes one reference pipeline differ from another.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct PipelineKey {
    shading: Shading,
    mode: RenderMode,
    backface_culling: bool,
    front_face: FrontFace,
}

impl PipelineKey {
    pub(crate) fn new(pipeline: &PipelineSettings, shading: Shading) -> Self {
        Self {
            shading,
            mode: pipeline.mode,
            backface_culling: pipeline.backface_culling,
            front_face: pipeline.front_face,
        }
    }
}

/// The mesh on the GPU: positions, normals and texture coordinates interleaved, and a u32 index
/// buffer.
///
/// Triangles of (nearly) zero area (repeated or collinear corners, as at a UV sphere's poles,
/// where sin(π) in f32 leaves the pole's copies 1e-7 apart) come last in the index buffer. They
/// have no facing: OpenGL counts a zero-area polygon as a back face, so glCullFace removes it,
/// while on a GPU the facing of such a sliver is rounding noise (lavapipe draws the corners and
/// edges of some of them in point and line mode). Drawing only `culled_index_count` indices when
/// culling is on gives OpenGL's answer on every adapter; in fill mode they cover no pixel.
struct GpuMesh {
    /// The centre of the model's bounding box, which the uploaded positions are relative to.
    /// A view matrix for world coordinates would carry the model's distance from the world
    /// origin in its translation, and in f32 P·V·p then cancels most of a small model's digits
    /// when it lies far away; relative to its own centre (as GPU renderers of geographic data
    /// do) the numbers stay the model's size.
    origin: Vec3,
    vertices: wgpu::Buffer,
    indices: wgpu::Buffer,
    index_count: u32,
    culled_index_count: u32,
    /// The triangles, in the index buffer's order, as instances of `vs_face`, on a device that
    /// draws lines or points face by face ([`polygon_mode`]).
    faces: Option<wgpu::Buffer>,
    /// Whether the mesh came with texture coordinates (without, it is never textured).
    has_uvs: bool,
}

/// Interleaved vertex: position, normal, texture coordinates ((0, 0) for a mesh without).
#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct Vertex {
    position: [f32; 3],
    normal: [f32; 3],
    uv: [f32; 2],
}

impl Vertex {
    fn of(mesh: &Mesh, origin: Vec3) -> Vec<Vertex> {
        let uv = |i: usize| mesh.uvs.get(i).map_or([0.0; 2], |uv| uv.to_array());
        mesh.positions
            .iter()
            .zip(&mesh.normals)
            .enumerate()
            .map(|(i, (p, n))| Vertex {
                position: (*p - origin).to_array(),
                normal: n.to_array(),
                uv: uv(i),
            })
            .collect()
    }
}

pub(crate) struct Reference {
    shader: wgpu::ShaderModule,
    color_format: wgpu::TextureFormat,
    features: wgpu::Features,
    bindings: ReferenceBindings,
    /// One pipeline per (shading, polygon mode, culling, front face), made the first time that
    /// combination is drawn: building all 48 up front would cost seconds on a software GPU.
    pipelines: HashMap<PipelineKey, wgpu::RenderPipeline>,
    /// The fate view's overlays for each key, made the first time they are shown.
    overlays: HashMap<PipelineKey, OverlayPipelines>,
    current: Option<(PipelineKey, TextureFilter)>,
    /// Whether the model is drawn textured (the settings, the mesh's coordinates and a texture).
    textured: bool,
    mesh: Option<GpuMesh>,
}

impl Reference {
    pub(crate) fn new(
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        color_format: wgpu::TextureFormat,
    ) -> Self {
        let shader =
            polygon_mode::with_kept_faces(device, "reference.wgsl", include_str!("reference.wgsl"));
        Self {
            shader,
            color_format,
            features: device.features(),
            bindings: ReferenceBindings::new(device, queue, size_of::<Uniforms>()),
            pipelines: HashMap::new(),
            overlays: HashMap::new(),
            current: None,
            textured: false,
            mesh: None,
        }
    }

    /// Uploads the mesh (its caller knows it changed), unless it is invalid.
    pub(crate) fn upload_mesh(&mut self, device: &wgpu::Device, mesh: &Mesh) {
        // An invalid mesh never reaches the GPU (the model plugin refuses it too): the previous
        // one stays.
        if mesh.validate().is_err() {
            return;
        }
        let origin = mesh.bounding_sphere().0;
        let corners = Vertex::of(mesh, origin);
        let vertices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("reference vertices"),
            contents: bytemuck::cast_slice(&corners),
            usage: wgpu::BufferUsages::VERTEX,
        });
        let has_area = |t: &&[u32; 3]| has_area(t.map(|i| mesh.positions[i as usize]));
        let (mut triangles, degenerate): (Vec<[u32; 3]>, Vec<[u32; 3]>) =
            mesh.triangles.iter().partition(has_area);
        let culled_index_count = triangles.len() as u32 * 3;
        triangles.extend(degenerate);
        let faces = polygon_mode::needs_faces(self.features)
            .then(|| polygon_mode::face_buffer(device, &corners, &triangles));
        let indices = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
            label: Some("reference indices"),
            contents: bytemuck::cast_slice(&triangles),
            usage: wgpu::BufferUsages::INDEX,
        });
        self.mesh = Some(GpuMesh {
            origin,
            vertices,
            indices,
            index_count: triangles.len() as u32 * 3,
            culled_index_count,
            faces,
            has_uvs: !mesh.uvs.is_empty(),
        });
    }

    /// Whether a texture is bound (not the untextured placeholder).
    pub(crate) fn is_textured(&self) -> bool {
        self.bindings.has_texture()
    }

    /// Uploads the texture (its caller knows it changed); `None` (an app without a model
    /// plugin) draws untextured.
    pub(crate) fn upload_texture(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        texture: Option<&Texture>,
    ) {
        self.bindings.sync(device, queue, texture);
    }

    /// Writes the uniforms for a target of `viewport`'s size and makes sure the pipeline for
    /// the settings exists.
    pub(crate) fn update(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        (camera, viewport): (&Camera, Viewport),
        (pipeline, look, overlay): (&PipelineSettings, &Appearance, Overlay),
        lighting: &Lighting,
    ) {
        let (origin, has_uvs) = self
            .mesh
            .as_ref()
            .map_or((Vec3::ZERO, false), |m| (m.origin, m.has_uvs));
        let textured = look.texture && has_uvs && self.bindings.has_texture();
        let uniforms = Uniforms::new(camera, look, lighting, origin, textured, viewport);
        queue.write_buffer(self.bindings.uniforms(), 0, bytemuck::bytes_of(&uniforms));
        let key = PipelineKey::new(pipeline, look.shading);
        if !self.pipelines.contains_key(&key) {
            let pipeline = self.create_pipeline(device, key);
            self.pipelines.insert(key, pipeline);
        }
        if overlay == Overlay::FateView && !self.overlays.contains_key(&key) {
            let overlays = self.create_overlays(device, key);
            self.overlays.insert(key, overlays);
        }
        self.current = Some((key, look.texture_filter));
        self.textured = textured;
    }

    /// The shading the model is drawn with, and the texture's filter when it is textured.
    pub(crate) fn drawn_look(&self) -> (Shading, Option<TextureFilter>) {
        match self.current {
            Some((key, filter)) => (key.shading, self.textured.then_some(filter)),
            None => (Shading::None, None),
        }
    }

    /// The shaded model, and with `overlays` the GPU's own facing and depth-test answers over it.
    pub(crate) fn draw(&self, pass: &mut wgpu::RenderPass<'_>, overlays: bool) {
        let Some((key, _)) = self.current else {
            return;
        };
        self.draw_with(pass, &self.pipelines[&key]);
        if overlays {
            self.draw_overlays(pass);
        }
    }

    /// How this device draws what it has no polygon mode for, if anything.
    pub(crate) fn limitations(&self) -> Option<String> {
        let missing: Vec<&str> = [
            (wgpu::Features::POLYGON_MODE_LINE, "POLYGON_MODE_LINE"),
            (wgpu::Features::POLYGON_MODE_POINT, "POLYGON_MODE_POINT"),
        ]
        .into_iter()
        .filter(|(feature, _)| !self.features.contains(*feature))
        .map(|(_, name)| name)
        .collect();
        (!missing.is_empty()).then(|| {
            format!(
                "lines and points drawn face by face as one-pixel rectangles and squares, culled \
                 in the shader (the device lacks {})",
                missing.join(", ")
            )
        })
    }

    fn create_pipeline(&self, device: &wgpu::Device, key: PipelineKey) -> wgpu::RenderPipeline {
        self.create_drawing(device, key, &SHADED)
    }

    /// One of the reference's pipelines for `key`: the shaded model, or an overlay over it.
    fn create_drawing(
        &self,
        device: &wgpu::Device,
        key: PipelineKey,
        drawing: &Drawing<'_>,
    ) -> wgpu::RenderPipeline {
        let faces = FaceDrawing::new(self.features, key.mode);
        let mut constants = shader_constants(key.shading, drawing.constants);
        constants.extend(faces.constants(key));
        let options = wgpu::PipelineCompilationOptions {
            constants: &constants,
            ..Default::default()
        };
        let (entry_point, layout) = faces.vertex_stage();
        device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(drawing.fragment),
            layout: Some(&self.bindings.pipeline_layout),
            vertex: wgpu::VertexState {
                module: &self.shader,
                entry_point: Some(entry_point),
                compilation_options: options.clone(),
                buffers: &[Some(layout)],
            },
            primitive: faces.primitive_state(key),
            depth_stencil: Some(wgpu::DepthStencilState {
                format: DEPTH_FORMAT,
                depth_write_enabled: Some(drawing.depth_write),
                depth_compare: Some(drawing.depth_compare),
                stencil: Default::default(),
                bias: Default::default(),
            }),
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: &self.shader,
                entry_point: Some(drawing.fragment),
                compilation_options: options,
                targets: &[Some(wgpu::ColorTargetState {
                    format: self.color_format,
                    blend: drawing.blend,
                    write_mask: wgpu::ColorWrites::ALL,
                })],
            }),
            multiview_mask: None,
            cache: None,
        })
    }

    /// Records the mesh (only the triangles with area when culling is on) with `pipeline`.
    fn draw_with(&self, pass: &mut wgpu::RenderPass<'_>, pipeline: &wgpu::RenderPipeline) {
        let (Some(mesh), Some((key, filter))) = (&self.mesh, self.current) else {
            return;
        };
        pass.set_pipeline(pipeline);
        pass.set_bind_group(0, self.bindings.bind_group(filter), &[]);
        let count = if key.backface_culling {
            mesh.culled_index_count
        } else {
            mesh.index_count
        };
        let drawing = FaceDrawing::new(self.features, key.mode);
        match (drawing, &mesh.faces) {
            (FaceDrawing::Instanced { .. }, Some(faces)) => {
                pass.set_vertex_buffer(0, faces.slice(..));
                pass.draw(0..drawing.vertices_per_face(), 0..count / 3);
            }
            _ => {
                pass.set_vertex_buffer(0, mesh.vertices.slice(..));
                pass.set_index_buffer(mesh.indices.slice(..), wgpu::IndexFormat::Uint32);
                pass.draw_indexed(0..count, 0, 0..1);
            }
        }
    }
}

/// How one of the reference's pipelines draws: its fragment entry point, depth test, blending
/// and the override constants it adds to the shading's.
struct Drawing<'a> {
    fragment: &'a str,
    depth_write: bool,
    depth_compare: wgpu::CompareFunction,
    blend: Option<wgpu::BlendState>,
    constants: &'a [(&'a str, f64)],
}

/// The shaded model itself.
const SHADED: Drawing<'static> = Drawing {
    fragment: "fs_main",
    depth_write: true,
    depth_compare: wgpu::CompareFunction::Less,
    blend: None,
    constants: &[],
};

/// Whether a triangle has area by the rule Close2GL culls by (see `ZERO_AREA`), measured here in
/// world space: a shape's area over its longest edge squared is the same after the projection,
/// for a triangle that faces the camera.
pub(crate) fn has_area([a, b, c]: [Vec3; 3]) -> bool {
    let longest = (b - a)
        .length_squared()
        .max((c - b).length_squared())
        .max((a - c).length_squared());
    !has_no_area((b - a).cross(c - a).length(), longest)
}

/// A target's size in pixels as a uniform (xy; at least 1, so that the shaders never divide by
/// 0).
pub(crate) fn viewport_size(viewport: Viewport) -> [f32; 4] {
    let Viewport { width, height } = viewport;
    [width.max(1) as f32, height.max(1) as f32, 0.0, 0.0]
}

/// The background colour as wgpu's clear colour.
pub fn clear_color(background: Vec3) -> wgpu::Color {
    wgpu::Color {
        r: background.x as f64,
        g: background.y as f64,
        b: background.z as f64,
        a: 1.0,
    }
}

/// The shader's override constants: which lighting `shading` is, then the drawing's own.
fn shader_constants<'a>(shading: Shading, own: &[(&'a str, f64)]) -> Vec<(&'a str, f64)> {
    let flag = |on: bool| f64::from(u8::from(on));
    let mut constants = vec![
        ("GOURAUD", flag(shading.per_vertex())),
        ("PHONG", flag(shading == Shading::Phong)),
        ("SPECULAR", flag(shading.specular())),
    ];
    constants.extend_from_slice(own);
    constants
}

#[cfg(test)]
mod tests {
    use close2gl_core::limits::ZERO_AREA;
    use close2gl_core::{Close2glFrame, Viewport};
    use close2gl_pipeline::FastPipeline;

    use super::*;

    /// A triangle 10 units wide and `ratio` × 10 tall (twice its area over its longest edge
    /// squared is `ratio`), facing a camera on +z, wound counter-clockwise as seen from it.
    fn sliver(ratio: f32) -> [Vec3; 3] {
        let (z, width) = (-20.0, 10.0);
        [
            Vec3::new(-5.0, 0.0, z),
            Vec3::new(5.0, 0.0, z),
            Vec3::new(0.0, ratio * width, z),
        ]
    }

    /// Close2GL's verdict on the triangle: drawn (it has a facing) or culled (it has none).
    fn close2gl_draws(corners: [Vec3; 3]) -> bool {
        let mesh = Mesh {
            face_normals: Vec::new(),
            name: "sliver".into(),
            positions: corners.to_vec(),
            normals: vec![Vec3::Z; 3],
            uvs: Vec::new(),
            triangles: vec![[0, 1, 2]],
        };
        let camera = Camera {
            near: 1.0,
            far: 100.0,
            ..Camera::default()
        };
        let viewport = Viewport {
            width: 400,
            height: 400,
        };
        let mut frame = Close2glFrame::default();
        let settings = PipelineSettings::default();
        FastPipeline::default().run(
            &mesh,
            &camera,
            &settings,
            viewport,
            &mut frame,
            &mut Default::default(),
        );
        frame.counts.drawn == 1
    }

    #[test]
    fn both_views_draw_a_sliver_exactly_when_the_one_zero_area_rule_says_it_has_area() {
        // Equal fields of view on a square viewport scale x and y alike, so the ratio is the
        // same in world space and in window space.
        for (ratio, has) in [
            (ZERO_AREA * 0.5, false),
            (ZERO_AREA * 2.0, true),
            (0.3, true),
        ] {
            let corners = sliver(ratio);
            assert_eq!(has_area(corners), has, "the reference at ratio {ratio}");
            assert_eq!(close2gl_draws(corners), has, "Close2GL at ratio {ratio}");
        }
    }
}

//! The reference probe: which mesh triangle the GPU itself drew at one pixel, and at what depth.
//!
//! An ID pass draws the mesh as the reference does (glam's matrices, the same culling, front
//! face, polygon mode and depth test) into an R32Uint target holding each fragment's mesh
//! triangle index + 1 and an R32Float target holding its depth; one texel of each is read back.
//! The index comes from a flat per-face attribute of an instanced draw (one instance a face, which
//! is also how lines and points are drawn without polygon modes, a line's fragments kept by the
//! reference's own test, the override constants given to both stages) rather than
//! WGSL's `primitive_index`: that builtin is an optional feature (Vulkan needs geometry shaders
//! for it, WebGPU and older Metal GPUs lack it), and the reference's index buffer is reordered
//! (zero-area triangles last), so a primitive index would need a table back to mesh order anyway.
//! A flat attribute works on every adapter and carries the mesh's own index.

use bytemuck::{Pod, Zeroable};
use close2gl_core::{Mesh, Scene, Shading, Viewport};
use wgpu::util::DeviceExt;

use crate::attachments::DEPTH_FORMAT;
use crate::attachments::texture_2d;
use crate::gpu::Gpu;
use crate::readback::Mapping;
use crate::reference::{
    FaceDrawing, PipelineKey, has_area, relative_matrices, viewport_size, with_kept_faces,
};
use crate::uniforms::UniformSetup;

/// The GPU's answer for one pixel of the reference view.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ReferenceHit {
    /// The mesh triangle (its index in `Mesh::triangles`) that won the depth test there.
    pub triangle: u32,
    /// Its depth there, wgpu's 0 (near) .. 1 (far).
    pub depth: f32,
}

/// One instance of the ID pass: a face's corners (relative to the mesh's origin) and its
/// triangle's index.
#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct IdFace {
    corners: [[f32; 3]; 3],
    triangle: u32,
}

/// The uniform block of id_pass.wgsl.
#[repr(C)]
#[derive(Clone, Copy, Pod, Zeroable)]
struct IdUniforms {
    view_projection: [[f32; 4]; 4],
    viewport: [f32; 4],
}

const ID_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Uint;
const DEPTH_OUT_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::R32Float;

/// The reference's triangle at pixel (`x`, `y`) of the viewport (from the top-left), or `None`
/// where it drew only background. Draws the whole viewport once and reads back one texel: for a
/// click or a headless question, not for every frame.
pub fn probe_reference(
    gpu: &Gpu,
    scene: Scene<'_>,
    pixel: (u32, u32),
) -> Result<Option<ReferenceHit>, String> {
    start_probe(gpu, scene, pixel)?.wait(gpu)
}

/// [`probe_reference`] without the wait: the pass is drawn and its texel's copy submitted, and
/// [`ReferenceProbe::finish`] answers once the GPU is done (in a browser, frames later).
pub fn start_probe(
    gpu: &Gpu,
    scene: Scene<'_>,
    (x, y): (u32, u32),
) -> Result<ReferenceProbe, String> {
    let Viewport { width, height } = scene.viewport;
    if x >= width || y >= height {
        return Err(format!(
            "pixel {x},{y} is outside the {width}x{height} viewport"
        ));
    }
    scene
        .mesh
        .validate()
        .map_err(|e| format!("cannot probe an invalid mesh: {e}"))?;
    let faces = id_faces(scene.mesh, scene.pipeline.backface_culling);
    if faces.is_empty() {
        return Ok(ReferenceProbe(None));
    }
    let targets = Targets::new(&gpu.device, (width, height));
    draw(gpu, scene, &faces, &targets);
    Ok(ReferenceProbe(Some(copy_texel(gpu, &targets, (x, y)))))
}

/// A reference probe on its way back from the GPU (`None`: nothing was drawn to probe).
pub struct ReferenceProbe(Option<Mapping>);

impl ReferenceProbe {
    /// The reference's answer once the GPU has copied it; `None` while it has not yet.
    pub fn finish(&self, gpu: &Gpu) -> Option<Result<Option<ReferenceHit>, String>> {
        match &self.0 {
            Some(mapping) => mapping.finish(gpu, WHAT, read_hit),
            None => Some(Ok(None)),
        }
    }

    /// The reference's answer, waiting for the GPU (which a browser cannot do: it asks
    /// [`Self::finish`] frame after frame).
    pub fn wait(&self, gpu: &Gpu) -> Result<Option<ReferenceHit>, String> {
        match &self.0 {
            Some(mapping) => mapping.wait(gpu, WHAT, read_hit),
            None => Ok(None),
        }
    }
}

const WHAT: &str = "the probed pixel";

/// The hit in a texel's mapped bytes: the ID (triangle + 1, 0 for the background) at 0, the
/// depth one copy row further.
fn read_hit(bytes: &[u8]) -> Option<ReferenceHit> {
    let stride = wgpu::COPY_BYTES_PER_ROW_ALIGNMENT as usize;
    let word = |at: usize| [bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]];
    let (id, depth) = (
        u32::from_le_bytes(word(0)),
        f32::from_le_bytes(word(stride)),
    );
    id.checked_sub(1)
        .map(|triangle| ReferenceHit { triangle, depth })
}

/// Each drawn triangle with its mesh index. With culling on, triangles without area are left
/// out, as the reference leaves them out.
fn id_faces(mesh: &Mesh, culling: bool) -> Vec<IdFace> {
    let origin = mesh.bounding_sphere().0;
    let corners = |t: &[u32; 3]| t.map(|i| mesh.positions[i as usize]);
    mesh.triangles
        .iter()
        .enumerate()
        .filter(|(_, t)| !culling || has_area(corners(t)))
        .map(|(index, t)| IdFace {
            corners: corners(t).map(|p| (p - origin).to_array()),
            triangle: index as u32,
        })
        .collect()
}

/// The ID pass's attachments: triangle ids, their depth as a colour, and the depth buffer.
struct Targets {
    id: wgpu::Texture,
    depth_out: wgpu::Texture,
    depth: wgpu::Texture,
}

impl Targets {
    fn new(device: &wgpu::Device, size: (u32, u32)) -> Targets {
        let readable = crate::attachments::READABLE_TARGET;
        Targets {
            id: texture_2d(device, "probe ids", size, ID_FORMAT, readable),
            depth_out: texture_2d(device, "probe depth", size, DEPTH_OUT_FORMAT, readable),
            depth: texture_2d(
                device,
                "probe depth buffer",
                size,
                DEPTH_FORMAT,
                wgpu::TextureUsages::RENDER_ATTACHMENT,
            ),
        }
    }
}

fn draw(gpu: &Gpu, scene: Scene<'_>, faces: &[IdFace], targets: &Targets) {
    let device = &gpu.device;
    let setup = UniformSetup::new(device, "probe", size_of::<IdUniforms>());
    let (view, projection) = relative_matrices(scene.camera, scene.mesh.bounding_sphere().0);
    let uniforms = IdUniforms {
        view_projection: (projection * view).to_cols_array_2d(),
        viewport: viewport_size(scene.viewport),
    };
    gpu.queue
        .write_buffer(&setup.buffer, 0, bytemuck::bytes_of(&uniforms));
    let buffer = device.create_buffer_init(&wgpu::util::BufferInitDescriptor {
        label: Some("probe faces"),
        contents: bytemuck::cast_slice(faces),
        usage: wgpu::BufferUsages::VERTEX,
    });
    // Ids are not shaded: the key's shading is never read here.
    let key = PipelineKey::new(scene.pipeline, Shading::None);
    let drawing = FaceDrawing::new(device.features(), scene.pipeline.mode);
    let pipeline = create_pipeline(device, &setup.layout, key, drawing);
    let id_view = targets.id.create_view(&Default::default());
    let depth_out_view = targets.depth_out.create_view(&Default::default());
    let depth_view = targets.depth.create_view(&Default::default());
    let far = wgpu::Color {
        r: 1.0,
        ..wgpu::Color::TRANSPARENT
    };
    let mut encoder = device.create_command_encoder(&Default::default());
    {
        let mut pass = encoder.begin_render_pass(&wgpu::RenderPassDescriptor {
            label: Some("probe"),
            color_attachments: &[
                Some(crate::attachments::color_attachment(
                    &id_view,
                    wgpu::LoadOp::Clear(wgpu::Color::TRANSPARENT),
                )),
                Some(crate::attachments::color_attachment(
                    &depth_out_view,
                    wgpu::LoadOp::Clear(far),
                )),
            ],
            depth_stencil_attachment: Some(crate::attachments::depth_attachment(&depth_view)),
            timestamp_writes: None,
            occlusion_query_set: None,
            multiview_mask: None,
        });
        pass.set_pipeline(&pipeline);
        pass.set_bind_group(0, &setup.bind_group, &[]);
        pass.set_vertex_buffer(0, buffer.slice(..));
        pass.draw(0..drawing.vertices_per_face(), 0..faces.len() as u32);
    }
    gpu.queue.submit([encoder.finish()]);
}

fn create_pipeline(
    device: &wgpu::Device,
    layout: &wgpu::PipelineLayout,
    key: PipelineKey,
    drawing: FaceDrawing,
) -> wgpu::RenderPipeline {
    let shader = with_kept_faces(device, "id_pass.wgsl", include_str!("id_pass.wgsl"));
    let attributes =
        wgpu::vertex_attr_array![0 => Float32x3, 1 => Float32x3, 2 => Float32x3, 3 => Uint32];
    let constants = drawing.constants(key);
    let options = wgpu::PipelineCompilationOptions {
        constants: &constants,
        ..Default::default()
    };
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some("probe"),
        layout: Some(layout),
        vertex: wgpu::VertexState {
            module: &shader,
            entry_point: Some("vs_main"),
            compilation_options: options.clone(),
            buffers: &[Some(wgpu::VertexBufferLayout {
                array_stride: size_of::<IdFace>() as u64,
                step_mode: wgpu::VertexStepMode::Instance,
                attributes: &attributes,
            })],
        },
        primitive: drawing.primitive_state(key),
        depth_stencil: Some(wgpu::DepthStencilState {
            format: DEPTH_FORMAT,
            depth_write_enabled: Some(true),
            depth_compare: Some(wgpu::CompareFunction::Less),
            stencil: Default::default(),
            bias: Default::default(),
        }),
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module: &shader,
            entry_point: Some("fs_main"),
            // A line's fragments are kept by the same constants' test as the reference's.
            compilation_options: options,
            targets: &[Some(ID_FORMAT.into()), Some(DEPTH_OUT_FORMAT.into())],
        }),
        multiview_mask: None,
        cache: None,
    })
}

/// Copies texel (`x`, `y`) of the id and depth targets into one buffer (each at a copy-aligned
/// offset), to be mapped once the copy is done.
fn copy_texel(gpu: &Gpu, targets: &Targets, (x, y): (u32, u32)) -> Mapping {
    let stride = wgpu::COPY_BYTES_PER_ROW_ALIGNMENT as u64;
    let buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("probe readback"),
        size: 2 * stride,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    for (layer, texture) in [&targets.id, &targets.depth_out].into_iter().enumerate() {
        encoder.copy_texture_to_buffer(
            wgpu::TexelCopyTextureInfo {
                texture,
                mip_level: 0,
                origin: wgpu::Origin3d { x, y, z: 0 },
                aspect: wgpu::TextureAspect::All,
            },
            wgpu::TexelCopyBufferInfo {
                buffer: &buffer,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: layer as u64 * stride,
                    bytes_per_row: None,
                    rows_per_image: None,
                },
            },
            wgpu::Extent3d {
                width: 1,
                height: 1,
                depth_or_array_layers: 1,
            },
        );
    }
    gpu.queue.submit([encoder.finish()]);
    Mapping::start(buffer)
}

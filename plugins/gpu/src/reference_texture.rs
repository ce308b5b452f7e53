//! The reference view's group 0: its uniforms, the model's texture with its full mip chain, and
//! one sampler per filter, as one bind group per filter so that switching filters is only a
//! different `set_bind_group`.

use close2gl_core::{Image, Texture, TextureFilter};

/// The bind groups of the reference pipelines and the texture behind them.
pub(crate) struct ReferenceBindings {
    uniforms: wgpu::Buffer,
    layout: wgpu::BindGroupLayout,
    pub(crate) pipeline_layout: wgpu::PipelineLayout,
    /// In the order of `TextureFilter::ALL`.
    samplers: Vec<wgpu::Sampler>,
    bind_groups: Vec<wgpu::BindGroup>,
    /// Whether a `Texture` is bound; false while the placeholder is (no `Texture` resource),
    /// which is then never sampled into the colour.
    textured: bool,
}

impl ReferenceBindings {
    pub(crate) fn new(device: &wgpu::Device, queue: &wgpu::Queue, uniforms_size: usize) -> Self {
        let uniforms = device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("reference"),
            size: uniforms_size as u64,
            usage: wgpu::BufferUsages::UNIFORM | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let layout = bind_group_layout(device);
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("reference"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let samplers = TextureFilter::ALL
            .iter()
            .map(|filter| device.create_sampler(&sampler_descriptor(*filter)))
            .collect();
        let mut bindings = Self {
            uniforms,
            layout,
            pipeline_layout,
            samplers,
            bind_groups: Vec::new(),
            textured: false,
        };
        bindings.bind(device, queue, &placeholder());
        bindings
    }

    pub(crate) fn uniforms(&self) -> &wgpu::Buffer {
        &self.uniforms
    }

    /// Uploads the texture (its caller knows it changed); without a texture, goes back to the
    /// placeholder.
    pub(crate) fn sync(
        &mut self,
        device: &wgpu::Device,
        queue: &wgpu::Queue,
        texture: Option<&Texture>,
    ) {
        match texture {
            Some(texture) => self.bind(device, queue, &texture.image),
            None => self.bind(device, queue, &placeholder()),
        }
        self.textured = texture.is_some();
    }

    /// Whether a texture (not the placeholder) is bound.
    pub(crate) fn has_texture(&self) -> bool {
        self.textured
    }

    pub(crate) fn bind_group(&self, filter: TextureFilter) -> &wgpu::BindGroup {
        let index = TextureFilter::ALL.iter().position(|f| *f == filter);
        &self.bind_groups[index.expect("every filter is in ALL")]
    }

    fn bind(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, image: &Image) {
        let view = upload(device, queue, image).create_view(&Default::default());
        self.bind_groups = self
            .samplers
            .iter()
            .map(|sampler| {
                device.create_bind_group(&wgpu::BindGroupDescriptor {
                    label: Some("reference"),
                    layout: &self.layout,
                    entries: &[
                        wgpu::BindGroupEntry {
                            binding: 0,
                            resource: self.uniforms.as_entire_binding(),
                        },
                        wgpu::BindGroupEntry {
                            binding: 1,
                            resource: wgpu::BindingResource::TextureView(&view),
                        },
                        wgpu::BindGroupEntry {
                            binding: 2,
                            resource: wgpu::BindingResource::Sampler(sampler),
                        },
                    ],
                })
            })
            .collect();
    }
}

/// Binding 0: the uniforms (both stages); 1: the texture; 2: its sampler (fragment stage).
fn bind_group_layout(device: &wgpu::Device) -> wgpu::BindGroupLayout {
    let entry = |binding, visibility, ty| wgpu::BindGroupLayoutEntry {
        binding,
        visibility,
        ty,
        count: None,
    };
    device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
        label: Some("reference"),
        entries: &[
            entry(
                0,
                wgpu::ShaderStages::VERTEX_FRAGMENT,
                wgpu::BindingType::Buffer {
                    ty: wgpu::BufferBindingType::Uniform,
                    has_dynamic_offset: false,
                    min_binding_size: None,
                },
            ),
            entry(
                1,
                wgpu::ShaderStages::FRAGMENT,
                wgpu::BindingType::Texture {
                    sample_type: wgpu::TextureSampleType::Float { filterable: true },
                    view_dimension: wgpu::TextureViewDimension::D2,
                    multisampled: false,
                },
            ),
            entry(
                2,
                wgpu::ShaderStages::FRAGMENT,
                wgpu::BindingType::Sampler(wgpu::SamplerBindingType::Filtering),
            ),
        ],
    })
}

/// OpenGL's GL_NEAREST, GL_LINEAR and GL_LINEAR_MIPMAP_LINEAR, wrapping with GL_REPEAT. The
/// first two read level 0 only, as OpenGL does for a filter without mipmaps: clamping the level
/// of detail to 0 is how WebGPU says it.
fn sampler_descriptor(filter: TextureFilter) -> wgpu::SamplerDescriptor<'static> {
    let (filter_mode, mipmap_filter, lod_max_clamp) = match filter {
        TextureFilter::Nearest => (
            wgpu::FilterMode::Nearest,
            wgpu::MipmapFilterMode::Nearest,
            0.0,
        ),
        TextureFilter::Bilinear => (
            wgpu::FilterMode::Linear,
            wgpu::MipmapFilterMode::Nearest,
            0.0,
        ),
        TextureFilter::Trilinear => (
            wgpu::FilterMode::Linear,
            wgpu::MipmapFilterMode::Linear,
            wgpu::SamplerDescriptor::default().lod_max_clamp,
        ),
    };
    wgpu::SamplerDescriptor {
        label: Some(filter.name()),
        address_mode_u: wgpu::AddressMode::Repeat,
        address_mode_v: wgpu::AddressMode::Repeat,
        mag_filter: filter_mode,
        min_filter: filter_mode,
        mipmap_filter,
        lod_max_clamp,
        ..Default::default()
    }
}

/// The image and its box-filtered mip chain (core's, so that Close2GL's rasterizer samples the
/// same levels), as an RGBA8 texture read as stored, without sRGB decoding.
fn upload(device: &wgpu::Device, queue: &wgpu::Queue, image: &Image) -> wgpu::Texture {
    let chain = image.mip_chain();
    let size = |level: &Image| wgpu::Extent3d {
        width: level.width,
        height: level.height,
        depth_or_array_layers: 1,
    };
    let texture = device.create_texture(&wgpu::TextureDescriptor {
        label: Some("reference texture"),
        size: size(image),
        mip_level_count: chain.len() as u32,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format: wgpu::TextureFormat::Rgba8Unorm,
        usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
        view_formats: &[],
    });
    for (mip_level, level) in chain.iter().enumerate() {
        queue.write_texture(
            wgpu::TexelCopyTextureInfo {
                texture: &texture,
                mip_level: mip_level as u32,
                origin: wgpu::Origin3d::ZERO,
                aspect: wgpu::TextureAspect::All,
            },
            bytemuck::cast_slice(&level.pixels),
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(4 * level.width),
                rows_per_image: None,
            },
            size(level),
        );
    }
    texture
}

/// Bound when there is no texture, since the layout needs one; the shader's flag keeps it out
/// of the colour.
fn placeholder() -> Image {
    Image {
        width: 1,
        height: 1,
        pixels: vec![[255; 4]],
    }
}

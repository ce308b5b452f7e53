//! What the views that show an image one texel per pixel share (the software rasterizer's image,
//! the live difference): one triangle over the viewport (`fullscreen.wgsl`) followed by the
//! view's own fragment stage, reading unfiltered textures with `textureLoad`.

/// A texture the fragment stage reads with `textureLoad` at `binding`.
pub(crate) fn texture_entry(binding: u32) -> wgpu::BindGroupLayoutEntry {
    wgpu::BindGroupLayoutEntry {
        binding,
        visibility: wgpu::ShaderStages::FRAGMENT,
        ty: wgpu::BindingType::Texture {
            sample_type: wgpu::TextureSampleType::Float { filterable: false },
            view_dimension: wgpu::TextureViewDimension::D2,
            multisampled: false,
        },
        count: None,
    }
}

/// The pipeline of one image view: `fullscreen.wgsl`'s vertex stage, `fragment`'s `fs_main`
/// (WGSL that may use `Varyings` and `texel_at`), one bind group of `layout`, writing
/// `color_format` with `blend` (`None`: replacing what is there); `with_depth` for a pass with a
/// depth attachment (the reference's), which it neither tests nor writes.
pub(crate) fn pipeline(
    device: &wgpu::Device,
    label: &str,
    fragment: &str,
    layout: &wgpu::BindGroupLayout,
    (color_format, blend): (wgpu::TextureFormat, Option<wgpu::BlendState>),
    with_depth: bool,
) -> wgpu::RenderPipeline {
    let source = format!("{}\n{fragment}", include_str!("fullscreen.wgsl"));
    let shader = device.create_shader_module(wgpu::ShaderModuleDescriptor {
        label: Some(label),
        source: wgpu::ShaderSource::Wgsl(source.into()),
    });
    let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
        label: Some(label),
        bind_group_layouts: &[Some(layout)],
        immediate_size: 0,
    });
    device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
        label: Some(label),
        layout: Some(&pipeline_layout),
        vertex: wgpu::VertexState {
            module: &shader,
            entry_point: Some("vs_main"),
            compilation_options: Default::default(),
            buffers: &[],
        },
        primitive: Default::default(),
        depth_stencil: with_depth.then(crate::attachments::depth_untouched),
        multisample: Default::default(),
        fragment: Some(wgpu::FragmentState {
            module: &shader,
            entry_point: Some("fs_main"),
            compilation_options: Default::default(),
            targets: &[Some(wgpu::ColorTargetState {
                format: color_format,
                blend,
                write_mask: wgpu::ColorWrites::ALL,
            })],
        }),
        multiview_mask: None,
        cache: None,
    })
}

//! The render pipeline the views that draw their own vertex lists share (the fate view and the
//! highlight, the outside view): one vertex buffer, both faces drawn, one colour target.

/// What differs between those pipelines.
pub(crate) struct VertexPipeline<'a> {
    pub label: &'a str,
    pub shader: &'a wgpu::ShaderModule,
    pub layout: &'a wgpu::PipelineLayout,
    pub fragment: &'a str,
    pub vertex: wgpu::VertexBufferLayout<'a>,
    pub topology: wgpu::PrimitiveTopology,
    pub depth_stencil: Option<wgpu::DepthStencilState>,
    pub color_format: wgpu::TextureFormat,
    pub blend: Option<wgpu::BlendState>,
}

impl VertexPipeline<'_> {
    pub(crate) fn create(self, device: &wgpu::Device) -> wgpu::RenderPipeline {
        device.create_render_pipeline(&wgpu::RenderPipelineDescriptor {
            label: Some(self.label),
            layout: Some(self.layout),
            vertex: wgpu::VertexState {
                module: self.shader,
                entry_point: Some("vs_main"),
                compilation_options: Default::default(),
                buffers: &[Some(self.vertex)],
            },
            primitive: wgpu::PrimitiveState {
                topology: self.topology,
                cull_mode: None,
                ..Default::default()
            },
            depth_stencil: self.depth_stencil,
            multisample: Default::default(),
            fragment: Some(wgpu::FragmentState {
                module: self.shader,
                entry_point: Some(self.fragment),
                compilation_options: Default::default(),
                targets: &[Some(wgpu::ColorTargetState {
                    format: self.color_format,
                    blend: self.blend,
                    write_mask: wgpu::ColorWrites::ALL,
                })],
            }),
            multiview_mask: None,
            cache: None,
        })
    }
}

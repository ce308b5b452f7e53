//! The live difference (`Overlay::Difference`): this frame's two views drawn again into
//! textures of the viewport's size, then compared pixel by pixel in the Close2GL view's place,
//! exactly as `close2gl render` writes diff.png ([`close2gl_core::parity::diff_image`]). A student who
//! switches to simple clipping sees at once, in magenta, what Close2GL no longer draws.

use crate::attachments::DEPTH_FORMAT;
use crate::attachments::texture_2d;
use crate::fullscreen;

/// The two views' images for one viewport size, and the bind group that compares them.
pub(crate) struct Inputs {
    pub(crate) reference: wgpu::TextureView,
    pub(crate) close2gl: wgpu::TextureView,
    pub(crate) depth: wgpu::TextureView,
    size: (u32, u32),
    bind_group: wgpu::BindGroup,
}

pub(crate) struct DifferenceView {
    pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    color_format: wgpu::TextureFormat,
    /// None until the first frame of the difference.
    inputs: Option<Inputs>,
}

impl DifferenceView {
    pub(crate) fn new(device: &wgpu::Device, color_format: wgpu::TextureFormat) -> Self {
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("difference"),
            entries: &[fullscreen::texture_entry(0), fullscreen::texture_entry(1)],
        });
        let fragment = include_str!("difference.wgsl");
        Self {
            pipeline: fullscreen::pipeline(
                device,
                "difference",
                fragment,
                &layout,
                (color_format, None),
                false,
            ),
            layout,
            color_format,
            inputs: None,
        }
    }

    /// Makes the textures the two views are drawn into for a `size` viewport (again when the
    /// size changes). The views are compared by their alpha, so they must be cleared with
    /// alpha 0 (`Views::clear_color`).
    pub(crate) fn prepare(&mut self, device: &wgpu::Device, size: (u32, u32)) {
        if self
            .inputs
            .as_ref()
            .is_none_or(|inputs| inputs.size != size)
        {
            self.inputs = Some(self.make_inputs(device, size));
        }
    }

    pub(crate) fn inputs(&self) -> Option<&Inputs> {
        self.inputs.as_ref()
    }

    fn make_inputs(&self, device: &wgpu::Device, size: (u32, u32)) -> Inputs {
        let usage = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::TEXTURE_BINDING;
        let view = |label, format, usage| {
            texture_2d(device, label, size, format, usage).create_view(&Default::default())
        };
        let reference = view("difference: reference", self.color_format, usage);
        let close2gl = view("difference: close2gl", self.color_format, usage);
        let depth = view(
            "difference: depth",
            DEPTH_FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        );
        let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("difference"),
            layout: &self.layout,
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&reference),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: wgpu::BindingResource::TextureView(&close2gl),
                },
            ],
        });
        Inputs {
            reference,
            close2gl,
            depth,
            size,
            bind_group,
        }
    }

    /// The comparison, one texel per pixel of the viewport the caller set.
    pub(crate) fn draw(&self, pass: &mut wgpu::RenderPass<'_>) {
        let Some(inputs) = &self.inputs else {
            return;
        };
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, &inputs.bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
}

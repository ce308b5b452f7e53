//! A view that shows an image instead of drawing the scene: the Close2GL view's software
//! rasterizer image, and both views' fixed images while a raster trace is open (`ViewImages`).
//! The image is uploaded into a texture (remade only when its size changes) and drawn as one
//! triangle covering the viewport, stretched to it (a fixed frame comes on a canvas of the
//! view's shape: `close2gl_core::Letterbox`).

use close2gl_core::Image;

use crate::fullscreen;

/// The image's colour replaces the target's; its alpha (0 where the rasterizer drew nothing, 1
/// where it drew) is the larger of the two: the coverage on a target cleared with alpha 0 (as
/// `close2gl render` and the live difference clear theirs), and still opaque on a window,
/// which is cleared opaque because a web page or a compositor may show what its alpha lets
/// through.
const KEEP_OPAQUE: wgpu::BlendState = wgpu::BlendState {
    color: wgpu::BlendComponent::REPLACE,
    alpha: wgpu::BlendComponent {
        src_factor: wgpu::BlendFactor::One,
        dst_factor: wgpu::BlendFactor::One,
        operation: wgpu::BlendOperation::Max,
    },
};

pub(crate) struct ImageView {
    pipeline: wgpu::RenderPipeline,
    layout: wgpu::BindGroupLayout,
    /// The texture, its bind group and its size; none before the first image.
    image: Option<(wgpu::Texture, wgpu::BindGroup)>,
}

impl ImageView {
    /// `with_depth` for a view drawn in a pass with a depth attachment (the reference's).
    pub(crate) fn new(
        device: &wgpu::Device,
        color_format: wgpu::TextureFormat,
        with_depth: bool,
    ) -> Self {
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("image view"),
            entries: &[fullscreen::texture_entry(0)],
        });
        let fragment = include_str!("image.wgsl");
        Self {
            pipeline: fullscreen::pipeline(
                device,
                "image view",
                fragment,
                &layout,
                (color_format, Some(KEEP_OPAQUE)),
                with_depth,
            ),
            layout,
            image: None,
        }
    }

    /// Uploads `image` (its caller knows it is new), unless it is empty or incomplete.
    pub(crate) fn update(&mut self, device: &wgpu::Device, queue: &wgpu::Queue, image: &Image) {
        let size = wgpu::Extent3d {
            width: image.width,
            height: image.height,
            depth_or_array_layers: 1,
        };
        let complete = image.pixels.len() == image.width as usize * image.height as usize;
        if image.width == 0 || image.height == 0 || !complete {
            return;
        }
        if self.image.as_ref().is_none_or(|(t, _)| t.size() != size) {
            let texture = device.create_texture(&wgpu::TextureDescriptor {
                label: Some("image view"),
                size,
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format: wgpu::TextureFormat::Rgba8Unorm,
                usage: wgpu::TextureUsages::TEXTURE_BINDING | wgpu::TextureUsages::COPY_DST,
                view_formats: &[],
            });
            let view = texture.create_view(&Default::default());
            let bind_group = device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("image view"),
                layout: &self.layout,
                entries: &[wgpu::BindGroupEntry {
                    binding: 0,
                    resource: wgpu::BindingResource::TextureView(&view),
                }],
            });
            self.image = Some((texture, bind_group));
        }
        let Some((texture, _)) = &self.image else {
            return;
        };
        queue.write_texture(
            texture.as_image_copy(),
            bytemuck::cast_slice(&image.pixels),
            wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(4 * image.width),
                rows_per_image: Some(image.height),
            },
            size,
        );
    }

    pub(crate) fn draw(&self, pass: &mut wgpu::RenderPass<'_>) {
        let Some((_, bind_group)) = &self.image else {
            return;
        };
        pass.set_pipeline(&self.pipeline);
        pass.set_bind_group(0, bind_group, &[]);
        pass.draw(0..3, 0..1);
    }
}

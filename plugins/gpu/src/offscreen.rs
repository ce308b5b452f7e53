//! Offscreen rendering with exactly the systems and draw calls a window uses: the same `Views`,
//! the same `Render` schedule, a texture instead of a surface, and a readback to RGBA8.

use std::time::Instant;

use bevy_ecs::prelude::*;
use close2gl_core::{
    App, Close2glFrame, Plugin, Rasterizer, RenderSettings, SoftwareFrame, StageCounts, Viewport,
};

use crate::parity::to_rgb8;
use crate::{DEPTH_FORMAT, Gpu, GpuPlugin, Image, Views};

/// The offscreen colour format: linear 8-bit, so an image's bytes are the colour values the
/// shaders wrote (times 255) and the background can be recognised exactly.
pub const OFFSCREEN_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// Makes an app render offscreen on `gpu`: inserts `Gpu` and `Views` (in [`OFFSCREEN_FORMAT`])
/// and adds [`GpuPlugin`]. Then call [`render_offscreen`] for each frame wanted.
pub struct OffscreenPlugin(pub Gpu);

impl Plugin for OffscreenPlugin {
    fn build(&self, app: &mut App) {
        let views = Views::new(&self.0, OFFSCREEN_FORMAT);
        app.insert_resource(self.0.clone())
            .insert_resource(views)
            .add_plugins(GpuPlugin);
    }
}

/// Both views of one frame, read back.
#[derive(Clone, Debug)]
pub struct Snapshot {
    pub reference: Image,
    pub close2gl: Image,
    /// The reference view's GPU draw, submit to completion, in milliseconds.
    pub reference_ms: f64,
    /// Close2GL's geometry stage (for the frame shown) plus its 2D draw, submit to completion;
    /// with the software rasterizer, the geometry stage plus the rasterizer's whole frame.
    pub close2gl_ms: f64,
    pub counts: StageCounts,
    /// The background as stored in the images: what "not covered" looks like.
    pub background: [u8; 3],
}

/// The textures one viewport size needs, kept between frames.
#[derive(Resource)]
struct Target {
    size: Viewport,
    reference: wgpu::Texture,
    close2gl: wgpu::Texture,
    depth: wgpu::Texture,
    /// Both colour textures, one after the other, rows padded to wgpu's copy alignment.
    readback: wgpu::Buffer,
    padded_row: u32,
}

impl Target {
    fn new(device: &wgpu::Device, size: Viewport) -> Target {
        let texture = |label, format, usage| {
            device.create_texture(&wgpu::TextureDescriptor {
                label: Some(label),
                size: wgpu::Extent3d {
                    width: size.width,
                    height: size.height,
                    depth_or_array_layers: 1,
                },
                mip_level_count: 1,
                sample_count: 1,
                dimension: wgpu::TextureDimension::D2,
                format,
                usage,
                view_formats: &[],
            })
        };
        let color = wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC;
        let padded_row = (size.width * 4).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
        Target {
            size,
            reference: texture("reference", OFFSCREEN_FORMAT, color),
            close2gl: texture("close2gl", OFFSCREEN_FORMAT, color),
            depth: texture(
                "depth",
                DEPTH_FORMAT,
                wgpu::TextureUsages::RENDER_ATTACHMENT,
            ),
            readback: device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("readback"),
                size: 2 * padded_row as u64 * size.height as u64,
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            }),
            padded_row,
        }
    }

    fn layer_bytes(&self) -> u64 {
        self.padded_row as u64 * self.size.height as u64
    }
}

/// Runs one frame of `app` (all schedules, `Render` included) and draws both views offscreen at
/// the `Viewport` size. The app needs [`OffscreenPlugin`] (or `Gpu`, `Views` in
/// [`OFFSCREEN_FORMAT`] and [`GpuPlugin`]), a `Camera` and a `Mesh`.
pub fn render_offscreen(app: &mut App) -> Result<Snapshot, String> {
    app.update();
    let world = app.world_mut();
    let gpu = world
        .get_resource::<Gpu>()
        .ok_or("render_offscreen needs the Gpu resource (add OffscreenPlugin)")?
        .clone();
    let size = *world
        .get_resource::<Viewport>()
        .ok_or("render_offscreen needs the Viewport resource")?;
    let max = gpu.device.limits().max_texture_dimension_2d;
    if size.width == 0 || size.height == 0 || size.width > max || size.height > max {
        return Err(format!(
            "cannot render {}x{}: this adapter draws 1x1 to {max}x{max}",
            size.width, size.height
        ));
    }
    if world
        .get_resource::<Target>()
        .is_none_or(|t| t.size != size)
    {
        world.insert_resource(Target::new(&gpu.device, size));
    }
    let views = world
        .get_resource::<Views>()
        .ok_or("render_offscreen needs the Views resource (add OffscreenPlugin)")?;
    let target = world.resource::<Target>();
    let frame = world.resource::<Close2glFrame>();
    let settings = world.resource::<RenderSettings>();
    let background = to_rgb8(settings.background);
    let software = settings.close2gl_raster == Rasterizer::Software;

    let reference_ms = draw(
        &gpu,
        views,
        &target.reference,
        Some(&target.depth),
        |views, pass| views.draw_reference(pass),
    );
    let close2gl_draw_ms = draw(&gpu, views, &target.close2gl, None, |views, pass| {
        views.draw_close2gl(pass)
    });
    let close2gl_ms = frame.stage_ms
        + match world.get_resource::<SoftwareFrame>() {
            Some(image) if software => image.raster_ms,
            _ => close2gl_draw_ms,
        };
    let [reference, close2gl] = read_back(&gpu, target)?;
    Ok(Snapshot {
        reference,
        close2gl,
        reference_ms,
        close2gl_ms,
        counts: frame.counts,
        background,
    })
}

/// One view into `color`, cleared to the background: record, submit, wait. Returns milliseconds.
fn draw(
    gpu: &Gpu,
    views: &Views,
    color: &wgpu::Texture,
    depth: Option<&wgpu::Texture>,
    record: impl FnOnce(&Views, &mut wgpu::RenderPass<'_>),
) -> f64 {
    let start = Instant::now();
    let color_view = color.create_view(&Default::default());
    let depth_view = depth.map(|d| d.create_view(&Default::default()));
    crate::submit_pass(
        gpu,
        &color_view,
        depth_view.as_ref(),
        wgpu::LoadOp::Clear(views.clear_color()),
        |pass| record(views, pass),
    );
    // A failed wait means a lost device; the readback that follows reports it.
    let _ = gpu.device.poll(wgpu::PollType::wait_indefinitely());
    start.elapsed().as_secs_f64() * 1e3
}

/// Copies both colour textures into the readback buffer and unpads them into images.
fn read_back(gpu: &Gpu, target: &Target) -> Result<[Image; 2], String> {
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    for (layer, texture) in [&target.reference, &target.close2gl]
        .into_iter()
        .enumerate()
    {
        encoder.copy_texture_to_buffer(
            texture.as_image_copy(),
            wgpu::TexelCopyBufferInfo {
                buffer: &target.readback,
                layout: wgpu::TexelCopyBufferLayout {
                    offset: layer as u64 * target.layer_bytes(),
                    bytes_per_row: Some(target.padded_row),
                    rows_per_image: Some(target.size.height),
                },
            },
            texture.size(),
        );
    }
    gpu.queue.submit([encoder.finish()]);
    let slice = target.readback.slice(..);
    let (sender, receiver) = std::sync::mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |result| {
        let _ = sender.send(result);
    });
    gpu.device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| format!("the GPU did not finish the frame: {e}"))?;
    receiver
        .recv()
        .map_err(|e| format!("the GPU readback was dropped: {e}"))?
        .map_err(|e| format!("cannot read the frame back from the GPU: {e}"))?;
    let images = {
        let bytes = slice
            .get_mapped_range()
            .map_err(|e| format!("cannot read the frame back from the GPU: {e}"))?;
        let (width, height) = (target.size.width, target.size.height);
        let image = |layer: u64| {
            let start = (layer * target.layer_bytes()) as usize;
            let pixels = bytes[start..start + target.layer_bytes() as usize]
                .chunks_exact(target.padded_row as usize)
                .flat_map(|row| row[..width as usize * 4].chunks_exact(4))
                .map(|p| [p[0], p[1], p[2], p[3]])
                .collect();
            Image {
                width,
                height,
                pixels,
            }
        };
        [image(0), image(1)]
    };
    target.readback.unmap();
    Ok(images)
}

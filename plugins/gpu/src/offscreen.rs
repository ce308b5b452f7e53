//! Offscreen rendering with exactly the systems and draw calls a window uses: the same `Views`,
//! the same upload systems, a texture instead of a surface, and a readback to RGBA8 whose alpha
//! says which pixels each view covered.

use bevy_ecs::prelude::*;
use close2gl_core::parity::ColorTolerance;
use close2gl_core::{
    App, Close2glFrame, PipelineSettings, Plugin, Rasterizer, SoftwareFrame, StageCounts, Viewport,
};

use crate::GpuPlugin;
use crate::attachments::DEPTH_FORMAT;
use crate::attachments::{READABLE_TARGET, texture_2d};
use crate::gpu::Gpu;
use crate::outside::{OutsidePlugin, OutsideRenderer};
use crate::pass::submit_pass_timed;
use crate::readback::Readback;
use crate::views::Views;
use close2gl_core::Image;

/// The offscreen colour format: linear 8-bit, so an image's bytes are the colour values the
/// shaders wrote (times 255), and its alpha the coverage (0: nothing drawn, 255: drawn).
pub const OFFSCREEN_FORMAT: wgpu::TextureFormat = wgpu::TextureFormat::Rgba8Unorm;

/// Makes an app render offscreen on `gpu`: inserts `Gpu`, `Views` and the outside view's
/// renderer (in [`OFFSCREEN_FORMAT`]) and adds [`GpuPlugin`] and the outside view's plugin
/// (unless the app has them). Then call [`render_offscreen`] for each frame
/// wanted.
pub struct OffscreenPlugin(pub Gpu);

impl Plugin for OffscreenPlugin {
    fn build(&self, app: &mut App) {
        let views = Views::new(&self.0, OFFSCREEN_FORMAT);
        let outside = OutsideRenderer::new(&self.0, OFFSCREEN_FORMAT);
        app.insert_resource(self.0.clone())
            .insert_resource(views)
            .insert_resource(outside)
            .add_plugin_once(GpuPlugin)
            .add_plugin_once(OutsidePlugin);
    }
}

/// Both views of one frame, read back: each image's alpha is 255 where its view drew and 0
/// where it did not ([`close2gl_core::parity::coverage`]).
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
    /// What the two views' colours are held to, by what they drew.
    pub tolerance: ColorTolerance,
}

/// The textures one viewport size needs, kept between frames.
#[derive(Resource)]
struct Target {
    size: Viewport,
    reference: wgpu::Texture,
    close2gl: wgpu::Texture,
    depth: wgpu::Texture,
    /// Both colour textures, one after the other.
    readback: Readback,
}

impl Target {
    fn new(device: &wgpu::Device, size: Viewport) -> Target {
        let pixels = (size.width, size.height);
        let color = |label| texture_2d(device, label, pixels, OFFSCREEN_FORMAT, READABLE_TARGET);
        let depth_usage = wgpu::TextureUsages::RENDER_ATTACHMENT;
        Target {
            size,
            reference: color("reference"),
            close2gl: color("close2gl"),
            depth: texture_2d(device, "depth", pixels, DEPTH_FORMAT, depth_usage),
            readback: Readback::new(device, pixels, 2),
        }
    }
}

/// Runs one frame of `app` (its uploads included) and draws both views offscreen at
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
    sized_target(world, &gpu, size)?;
    let views = world
        .get_resource::<Views>()
        .ok_or("render_offscreen needs the Views resource (add OffscreenPlugin)")?;
    let target = world.resource::<Target>();
    let frame = world.resource::<Close2glFrame>();
    let software = world.resource::<PipelineSettings>().close2gl_raster == Rasterizer::Software;

    let reference_ms = draw(
        &gpu,
        (&target.reference, Some(&target.depth)),
        views.reference_clear_color(),
        |pass| views.draw_reference(pass),
    );
    let close2gl_draw_ms = draw(
        &gpu,
        (&target.close2gl, None),
        views.clear_color(),
        |pass| views.draw_close2gl(pass),
    );
    let close2gl_ms = frame.geometry_ms
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
        tolerance: views.color_tolerance(),
    })
}

/// Makes sure the world's [`Target`] is `size` (making a new one when it is not), or says why
/// the adapter cannot draw that size.
fn sized_target(world: &mut World, gpu: &Gpu, size: Viewport) -> Result<(), String> {
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
    Ok(())
}

/// One view into `color` (with `depth`), cleared to `clear` (alpha 0, so that the alpha read
/// back is the view's coverage): record, submit, wait. Returns milliseconds.
fn draw(
    gpu: &Gpu,
    (color, depth): (&wgpu::Texture, Option<&wgpu::Texture>),
    clear: wgpu::Color,
    record: impl FnOnce(&mut wgpu::RenderPass<'_>),
) -> f64 {
    let color_view = color.create_view(&Default::default());
    let depth_view = depth.map(|d| d.create_view(&Default::default()));
    let clear = wgpu::LoadOp::Clear(clear);
    submit_pass_timed(gpu, &color_view, depth_view.as_ref(), clear, record)
}

/// Both colour textures read back as images.
fn read_back(gpu: &Gpu, target: &Target) -> Result<[Image; 2], String> {
    let mut layers = target
        .readback
        .read(gpu, &[&target.reference, &target.close2gl])?
        .into_iter()
        .map(|pixels| Image {
            width: target.size.width,
            height: target.size.height,
            pixels,
        });
    match (layers.next(), layers.next()) {
        (Some(reference), Some(close2gl)) => Ok([reference, close2gl]),
        _ => Err("the GPU readback returned fewer images than asked".into()),
    }
}

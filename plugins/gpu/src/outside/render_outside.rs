//! The outside view drawn offscreen (`close2gl render --view outside`, the tests), with the
//! renderer the window draws with.

use bevy_ecs::prelude::*;
use close2gl_core::{App, Appearance, Viewport};

use super::OutsideRenderer;
use crate::attachments::{READABLE_TARGET, texture_2d};
use crate::readback::Readback;
use crate::reference::clear_color;
use close2gl_core::Image;

use crate::attachments::DEPTH_FORMAT;
use crate::gpu::Gpu;
use crate::offscreen::OFFSCREEN_FORMAT;
use crate::pass::submit_pass;

/// The outside view's textures for one size, kept between frames.
#[derive(Resource)]
struct OutsideTarget {
    size: Viewport,
    color: wgpu::Texture,
    depth: wgpu::Texture,
    readback: Readback,
}

/// Draws the outside view as the last frame's uploads left it (after
/// [`crate::render_offscreen`], say) at the `Viewport` size, and reads it back. The app needs
/// `Gpu`, an [`OutsideRenderer`] in [`OFFSCREEN_FORMAT`] and `OutsideView::show` set when the
/// frame ran (the [`crate::OffscreenPlugin`] inserts the renderer).
pub fn render_outside(app: &mut App) -> Result<Image, String> {
    let world = app.world_mut();
    let gpu = world
        .get_resource::<Gpu>()
        .ok_or("render_outside needs the Gpu resource (add OffscreenPlugin)")?
        .clone();
    let size = *world.resource::<Viewport>();
    if world
        .get_resource::<OutsideTarget>()
        .is_none_or(|t| t.size != size)
    {
        let pixels = (size.width, size.height);
        let device = &gpu.device;
        world.insert_resource(OutsideTarget {
            size,
            color: texture_2d(device, "outside", pixels, OFFSCREEN_FORMAT, READABLE_TARGET),
            depth: texture_2d(device, "outside depth", pixels, DEPTH_FORMAT, {
                wgpu::TextureUsages::RENDER_ATTACHMENT
            }),
            readback: Readback::new(device, pixels, 1),
        });
    }
    let renderer = world
        .get_resource::<OutsideRenderer>()
        .ok_or("render_outside needs the OutsideRenderer resource (add OffscreenPlugin)")?;
    if renderer.camera().is_none() {
        return Err("the outside view was not shown in the last frame (set outside.show)".into());
    }
    let target = world.resource::<OutsideTarget>();
    let background = world.resource::<Appearance>().background;
    let color = target.color.create_view(&Default::default());
    let depth = target.depth.create_view(&Default::default());
    let clear = wgpu::LoadOp::Clear(clear_color(background));
    submit_pass(&gpu, &color, Some(&depth), clear, |pass| {
        renderer.draw(pass)
    });
    let pixels = target
        .readback
        .read(&gpu, &[&target.color])?
        .pop()
        .ok_or("the GPU readback returned no image")?;
    Ok(Image {
        width: size.width,
        height: size.height,
        pixels,
    })
}

//! Screenshots: a window's frame drawn once more into a texture that can be read back (a
//! surface texture may not allow copies), with the same calls, then saved as PNG: the whole
//! window for `--screenshot`, each view alone for the screenshot key.

use close2gl_gpu::attachments::{READABLE_TARGET, texture_2d};
use close2gl_gpu::{Gpu, Image, Pending, Readback};

use std::path::Path;

use bevy_ecs::world::World;
use close2gl_core::CommandLine;

use crate::view_layout::PixelRect;

/// Saves the two views as `close2gl-NNN-reference.png` and `close2gl-NNN-close2gl.png` in `dir`
/// (the first number not taken), with `close2gl-NNN-command.txt`: the `close2gl render` line
/// that writes the same two images into `close2gl-NNN-render/`. Returns what to tell the user.
pub fn save_views(
    dir: &Path,
    reference: &Image,
    close2gl: &Image,
    world: &mut World,
) -> Result<String, String> {
    std::fs::create_dir_all(dir)
        .map_err(|e| format!("{}: cannot create the directory: {e}", dir.display()))?;
    let stem = (1..=9999)
        .map(|n| format!("close2gl-{n:03}"))
        .find(|stem| !dir.join(format!("{stem}-command.txt")).exists())
        .ok_or_else(|| format!("{}: no free screenshot name left", dir.display()))?;
    let out = dir.join(format!("{stem}-render")).display().to_string();
    let write = world.get_resource::<CommandLine>().map(|c| c.0);
    let command = write
        .and_then(|write| write(world, &out))
        .ok_or("no model is shown")?;
    let names = [
        format!("{stem}-reference.png"),
        format!("{stem}-close2gl.png"),
        format!("{stem}-command.txt"),
    ];
    reference.write_png(&dir.join(&names[0]))?;
    close2gl.write_png(&dir.join(&names[1]))?;
    let text = dir.join(&names[2]);
    std::fs::write(&text, command + "\n")
        .map_err(|e| format!("{}: cannot write: {e}", text.display()))?;
    Ok(format!(
        "Saved {}, {} and {} in {}",
        names[0],
        names[1],
        names[2],
        dir.display()
    ))
}

/// Draws with `draw` into a `width` x `height` texture of `format` and starts reading it back
/// as RGBA: for a window whose surface cannot be read back itself, or for the views alone.
/// `coverage`: the alpha drawn is the views' coverage, kept (see [`read_back`]).
pub fn capture(
    gpu: &Gpu,
    (format, width, height): (wgpu::TextureFormat, u32, u32),
    coverage: bool,
    draw: impl FnOnce(&wgpu::TextureView),
) -> Result<PendingImage, String> {
    let texture = texture_2d(
        &gpu.device,
        "screenshot",
        (width, height),
        format,
        READABLE_TARGET,
    );
    draw(&texture.create_view(&Default::default()));
    read_back(gpu, &texture, coverage)
}

/// A window's frame on its way back from the GPU, as RGBA once it is in.
pub struct PendingImage {
    pending: Pending,
    swap_red_blue: bool,
    /// Whether the alpha is the views' coverage (kept) or the window's (made opaque).
    coverage: bool,
    width: u32,
    height: u32,
}

/// Starts reading back what `texture` (a window's frame, in its 8-bit colour format) holds.
/// With `coverage` its alpha is kept: the views drawn on a target cleared with alpha 0 say in
/// it which pixels they covered. Without, the image is opaque: a window's alpha is how it
/// blends with the desktop, not part of the picture.
pub fn read_back(
    gpu: &Gpu,
    texture: &wgpu::Texture,
    coverage: bool,
) -> Result<PendingImage, String> {
    let swap_red_blue = match texture.format() {
        wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb => true,
        wgpu::TextureFormat::Rgba8Unorm | wgpu::TextureFormat::Rgba8UnormSrgb => false,
        other => return Err(format!("cannot save a screenshot of a {other:?} window")),
    };
    let (width, height) = (texture.width(), texture.height());
    let pending = Readback::new(&gpu.device, (width, height), 1).start(gpu, &[texture]);
    Ok(PendingImage {
        pending,
        swap_red_blue,
        coverage,
        width,
        height,
    })
}

impl PendingImage {
    /// The image once the GPU has copied it; `None` while it has not yet.
    pub fn finish(&self, gpu: &Gpu) -> Option<Result<Image, String>> {
        let stored = self.pending.finish(gpu)?;
        let swap = self.swap_red_blue;
        let alpha = |a: u8| if self.coverage { a } else { 255 };
        Some(stored.map(|layers| {
            Image {
                width: self.width,
                height: self.height,
                pixels: layers
                    .concat()
                    .into_iter()
                    .map(|p| match swap {
                        true => [p[2], p[1], p[0], alpha(p[3])],
                        false => [p[0], p[1], p[2], alpha(p[3])],
                    })
                    .collect(),
            }
        }))
    }
}

/// The part of `image` under `rect` (clamped to the image).
pub fn crop(image: &Image, rect: PixelRect) -> Image {
    let x0 = rect.x.min(image.width);
    let y0 = rect.y.min(image.height);
    let width = rect.width.min(image.width - x0);
    let height = rect.height.min(image.height - y0);
    let mut pixels = Vec::with_capacity((width * height) as usize);
    for y in y0..y0 + height {
        let row = (y * image.width + x0) as usize;
        pixels.extend_from_slice(&image.pixels[row..row + width as usize]);
    }
    Image {
        width,
        height,
        pixels,
    }
}

/// Images side by side, top-aligned, on black: the two windows of the "windows" layout as one
/// picture.
pub fn side_by_side(images: &[Image]) -> Image {
    let width = images.iter().map(|i| i.width).sum();
    let height = images.iter().map(|i| i.height).max().unwrap_or(0);
    let mut out = Image::filled(width, height, [0, 0, 0, 255]);
    let mut left = 0;
    for image in images {
        for y in 0..image.height {
            let from = (y * image.width) as usize;
            let to = (y * width + left) as usize;
            out.pixels[to..to + image.width as usize]
                .copy_from_slice(&image.pixels[from..from + image.width as usize]);
        }
        left += image.width;
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn windows_are_placed_side_by_side_top_aligned() {
        let a = Image::filled(2, 3, [1, 1, 1, 255]);
        let b = Image::filled(1, 2, [2, 2, 2, 255]);
        let both = side_by_side(&[a, b]);
        assert_eq!((both.width, both.height), (3, 3));
        assert_eq!(both.pixel(1, 2), [1, 1, 1, 255]);
        assert_eq!(both.pixel(2, 1), [2, 2, 2, 255]);
        assert_eq!(both.pixel(2, 2), [0, 0, 0, 255], "below the shorter window");
    }

    #[test]
    fn a_crop_keeps_the_rectangle_and_stops_at_the_border() {
        let mut image = Image::filled(4, 3, [0, 0, 0, 255]);
        image.pixels[(2 * 4 + 3) as usize] = [9, 9, 9, 255];
        let rect = PixelRect {
            x: 2,
            y: 1,
            width: 5,
            height: 2,
        };
        let part = crop(&image, rect);
        assert_eq!((part.width, part.height), (2, 2));
        assert_eq!(part.pixel(1, 1), [9, 9, 9, 255]);
    }
}

//! `--screenshot`: a window's frame drawn once more into a texture that can be read back (a
//! surface texture may not allow copies), with the same calls, then saved as PNG.

use close2gl_gpu::texture::{READABLE_TARGET, texture_2d};
use close2gl_gpu::{Gpu, Image, Readback};

/// Draws with `draw` into a `width` x `height` texture of `format` and reads it back as RGBA.
pub fn capture(
    gpu: &Gpu,
    format: wgpu::TextureFormat,
    width: u32,
    height: u32,
    draw: impl FnOnce(&wgpu::TextureView),
) -> Result<Image, String> {
    let swap_red_blue = match format {
        wgpu::TextureFormat::Bgra8Unorm | wgpu::TextureFormat::Bgra8UnormSrgb => true,
        wgpu::TextureFormat::Rgba8Unorm | wgpu::TextureFormat::Rgba8UnormSrgb => false,
        other => return Err(format!("cannot save a screenshot of a {other:?} window")),
    };
    let size = (width, height);
    let texture = texture_2d(&gpu.device, "screenshot", size, format, READABLE_TARGET);
    draw(&texture.create_view(&Default::default()));
    let stored = Readback::new(&gpu.device, size, 1)
        .read(gpu, &[&texture])?
        .concat();
    // A window's alpha is how it blends with the desktop, not part of the picture.
    let pixels = stored
        .into_iter()
        .map(|p| match swap_red_blue {
            true => [p[2], p[1], p[0], 255],
            false => [p[0], p[1], p[2], 255],
        })
        .collect();
    Ok(Image {
        width,
        height,
        pixels,
    })
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
}

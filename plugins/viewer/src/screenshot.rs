//! `--screenshot`: a window's frame drawn once more into a texture that can be read back (a
//! surface texture may not allow copies), with the same calls, then saved as PNG.

use close2gl_gpu::{Gpu, Image};

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
    let texture = gpu.device.create_texture(&wgpu::TextureDescriptor {
        label: Some("screenshot"),
        size: wgpu::Extent3d {
            width,
            height,
            depth_or_array_layers: 1,
        },
        mip_level_count: 1,
        sample_count: 1,
        dimension: wgpu::TextureDimension::D2,
        format,
        usage: wgpu::TextureUsages::RENDER_ATTACHMENT | wgpu::TextureUsages::COPY_SRC,
        view_formats: &[],
    });
    draw(&texture.create_view(&Default::default()));

    let padded_row = (width * 4).next_multiple_of(wgpu::COPY_BYTES_PER_ROW_ALIGNMENT);
    let buffer = gpu.device.create_buffer(&wgpu::BufferDescriptor {
        label: Some("screenshot readback"),
        size: padded_row as u64 * height as u64,
        usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
        mapped_at_creation: false,
    });
    let mut encoder = gpu.device.create_command_encoder(&Default::default());
    encoder.copy_texture_to_buffer(
        texture.as_image_copy(),
        wgpu::TexelCopyBufferInfo {
            buffer: &buffer,
            layout: wgpu::TexelCopyBufferLayout {
                offset: 0,
                bytes_per_row: Some(padded_row),
                rows_per_image: Some(height),
            },
        },
        texture.size(),
    );
    gpu.queue.submit([encoder.finish()]);
    let slice = buffer.slice(..);
    let (sender, receiver) = std::sync::mpsc::channel();
    slice.map_async(wgpu::MapMode::Read, move |result| {
        let _ = sender.send(result);
    });
    let failed = |e: &dyn std::fmt::Display| format!("cannot read the window back: {e}");
    gpu.device
        .poll(wgpu::PollType::wait_indefinitely())
        .map_err(|e| failed(&e))?;
    receiver
        .recv()
        .map_err(|e| failed(&e))?
        .map_err(|e| failed(&e))?;
    let bytes = slice.get_mapped_range().map_err(|e| failed(&e))?;
    let pixels = bytes
        .chunks_exact(padded_row as usize)
        .flat_map(|row| row[..width as usize * 4].chunks_exact(4))
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

//! Texture images: PNG and JPEG files through the `image` crate, decoded to RGBA8 within bounds
//! that a hostile header cannot talk past.

use std::path::Path;

use close2gl_core::Image;
use close2gl_core::limits::MAX_PIXELS;

/// The most bytes a decoder may allocate: a 16384 × 16384 RGBA8 image, the largest texture a
/// GPU takes here, and a little for the decoder's own work.
const MAX_DECODE_BYTES: u64 = 4 * (MAX_PIXELS as u64) * (MAX_PIXELS as u64) + (64 << 20);

/// Reads a PNG or JPEG file as RGBA8. Every error is one line naming the file.
pub fn load_texture(path: &Path) -> Result<Image, String> {
    let label = path.display();
    let file =
        close2gl_core::files::open(path).map_err(|e| format!("{label}: cannot read: {e}"))?;
    let mut reader = image::ImageReader::new(std::io::BufReader::new(file))
        .with_guessed_format()
        .map_err(|e| format!("{label}: cannot read: {e}"))?;
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(MAX_PIXELS);
    limits.max_image_height = Some(MAX_PIXELS);
    limits.max_alloc = Some(MAX_DECODE_BYTES);
    reader.limits(limits);
    let image = reader.decode().map_err(|e| match e {
        image::ImageError::Limits(_) => {
            format!("{label}: too large: a texture is at most {MAX_PIXELS}×{MAX_PIXELS} pixels")
        }
        image::ImageError::Unsupported(_) => {
            format!("{label}: not a PNG or JPEG image ({e})")
        }
        e => format!("{label}: not a readable PNG or JPEG image: {e}"),
    })?;
    let rgba = image.to_rgba8();
    let (width, height) = rgba.dimensions();
    Ok(Image {
        width,
        height,
        pixels: rgba.pixels().map(|p| p.0).collect(),
    })
}

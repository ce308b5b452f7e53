//! The one RGBA8 image type: a texture's file, a view read back from the GPU, the pictures the
//! tools write; and its PNG encoding.

use std::fs::File;
use std::io::{BufReader, BufWriter};
use std::path::Path;

/// Rows from the top, pixels left to right, RGBA 8 bits per channel, used as they are (no sRGB
/// decoding): a texture's texel modulates the colour its file stores, and a view's bytes are
/// the colour values the shaders wrote, times 255.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Image {
    pub width: u32,
    pub height: u32,
    pub pixels: Vec<[u8; 4]>,
}

impl Image {
    pub fn filled(width: u32, height: u32, color: [u8; 4]) -> Image {
        Image {
            width,
            height,
            pixels: vec![color; width as usize * height as usize],
        }
    }

    pub fn pixel(&self, x: u32, y: u32) -> [u8; 4] {
        self.pixels[y as usize * self.width as usize + x as usize]
    }

    /// Writes an 8-bit RGBA PNG; the error names the file.
    pub fn write_png(&self, path: &Path) -> Result<(), String> {
        let fail = |e: &dyn std::fmt::Display| format!("{}: cannot write: {e}", path.display());
        let file = File::create(path).map_err(|e| fail(&e))?;
        self.encode_png(BufWriter::new(file)).map_err(|e| fail(&e))
    }

    /// The image as the bytes of an 8-bit RGBA PNG (for a page that inlines its pictures).
    pub fn to_png(&self) -> Result<Vec<u8>, String> {
        let mut bytes = Vec::new();
        self.encode_png(&mut bytes).map_err(|e| e.to_string())?;
        Ok(bytes)
    }

    fn encode_png(&self, out: impl std::io::Write) -> Result<(), png::EncodingError> {
        let mut encoder = png::Encoder::new(out, self.width, self.height);
        encoder.set_color(png::ColorType::Rgba);
        encoder.set_depth(png::BitDepth::Eight);
        let mut writer = encoder.write_header()?;
        writer.write_image_data(self.pixels.as_flattened())?;
        writer.finish()
    }

    /// Reads an 8-bit RGB or RGBA PNG (what [`Image::write_png`] and most tools write).
    pub fn read_png(path: &Path) -> Result<Image, String> {
        let fail = |e: &dyn std::fmt::Display| format!("{}: cannot read PNG: {e}", path.display());
        let file = File::open(path).map_err(|e| fail(&e))?;
        let mut reader = png::Decoder::new(BufReader::new(file))
            .read_info()
            .map_err(|e| fail(&e))?;
        let size = reader
            .output_buffer_size()
            .ok_or_else(|| fail(&"the image is too large"))?;
        let mut bytes = vec![0; size];
        let info = reader.next_frame(&mut bytes).map_err(|e| fail(&e))?;
        let bytes = &bytes[..info.buffer_size()];
        let pixels: Vec<[u8; 4]> = match (info.color_type, info.bit_depth) {
            (png::ColorType::Rgba, png::BitDepth::Eight) => bytes
                .chunks_exact(4)
                .map(|p| [p[0], p[1], p[2], p[3]])
                .collect(),
            (png::ColorType::Rgb, png::BitDepth::Eight) => bytes
                .chunks_exact(3)
                .map(|p| [p[0], p[1], p[2], 255])
                .collect(),
            (color, depth) => {
                return Err(fail(&format!(
                    "expected 8-bit RGB or RGBA, found {color:?} at {depth:?}"
                )));
            }
        };
        Ok(Image {
            width: info.width,
            height: info.height,
            pixels,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_png_reads_back_as_written() {
        let mut image = Image::filled(5, 3, [1, 2, 3, 255]);
        image.pixels[7] = [250, 0, 128, 255];
        let path = std::env::temp_dir().join(format!("close2gl-image-{}.png", std::process::id()));
        image.write_png(&path).unwrap();
        let read = Image::read_png(&path).unwrap();
        std::fs::remove_file(&path).unwrap();
        assert_eq!(read, image);
        assert_eq!(read.pixel(2, 1), [250, 0, 128, 255]);
    }

    #[test]
    fn a_file_that_is_not_a_png_is_an_error_naming_it() {
        let path =
            std::env::temp_dir().join(format!("close2gl-not-png-{}.png", std::process::id()));
        std::fs::write(&path, b"not a png").unwrap();
        let error = Image::read_png(&path).unwrap_err();
        std::fs::remove_file(&path).unwrap();
        assert!(error.starts_with(&path.display().to_string()), "{error}");
    }
}

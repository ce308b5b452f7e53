//! The buffers a raster trace names: a PPM (`P6` binary or `P3` text, maxval 255, rows from the
//! top) for colours and textures, a PFM (`Pf`, one float per pixel, rows from the bottom as PFM
//! has them) for depth. Each reads from bytes (grade reads a program's files itself) into rows
//! from the top, and writes back, so that tests and examples make the files a program would.

use close2gl_core::Image;

use crate::syntax::FormatError;

/// A depth buffer: `width × height` values, rows from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct DepthImage {
    pub width: u32,
    pub height: u32,
    pub values: Vec<f32>,
}

/// The header's fields after the magic, skipping blanks and `#` comments, and where the data
/// starts (after the single blank that ends the header).
fn header(bytes: &[u8], count: usize) -> Option<(Vec<String>, usize)> {
    let mut fields = Vec::new();
    let mut at = 2;
    while fields.len() < count {
        match bytes.get(at)? {
            b'#' => {
                while *bytes.get(at)? != b'\n' {
                    at += 1;
                }
            }
            b if b.is_ascii_whitespace() => at += 1,
            _ => {
                let start = at;
                while bytes.get(at).is_some_and(|b| !b.is_ascii_whitespace()) {
                    at += 1;
                }
                fields.push(String::from_utf8_lossy(&bytes[start..at]).into_owned());
            }
        }
    }
    bytes.get(at).filter(|b| b.is_ascii_whitespace())?;
    Some((fields, at + 1))
}

/// The size in a header's first two fields: each in 1..=MAX_PIXELS.
fn size(fields: &[String]) -> Option<(u32, u32)> {
    let max = close2gl_core::limits::MAX_PIXELS;
    let dimension = |s: &String| s.parse::<u32>().ok().filter(|d| (1..=max).contains(d));
    Some((dimension(&fields[0])?, dimension(&fields[1])?))
}

/// A PPM image: `P6` or `P3`, maxval 255; `file` labels its errors.
pub fn read_ppm(bytes: &[u8], file: &str) -> Result<Image, FormatError> {
    let error = |what: &str| FormatError::new(file, 0, format!("expected {what}"));
    let magic = bytes.get(..2);
    let text = match magic {
        Some(b"P6") => false,
        Some(b"P3") => true,
        _ => return Err(error("a PPM image (starting 'P6' or 'P3')")),
    };
    let (fields, data) = header(bytes, 3).ok_or_else(|| error("a PPM header 'P6 W H 255'"))?;
    let (width, height) =
        size(&fields).ok_or_else(|| error("a PPM width and height in 1..=16384"))?;
    if fields[2] != "255" {
        return Err(error(&format!("a PPM of maxval 255, found {}", fields[2])));
    }
    let count = width as usize * height as usize * 3;
    let samples: Vec<u8> = match text {
        false => bytes[data.min(bytes.len())..]
            .iter()
            .take(count)
            .copied()
            .collect(),
        true => String::from_utf8_lossy(&bytes[data.min(bytes.len())..])
            .split_ascii_whitespace()
            .take(count)
            .map_while(|w| w.parse::<u8>().ok())
            .collect(),
    };
    if samples.len() != count {
        let found = samples.len();
        return Err(error(&format!(
            "{count} samples for {width}×{height} pixels, found {found}"
        )));
    }
    let pixels = samples
        .chunks_exact(3)
        .map(|c| [c[0], c[1], c[2], 255])
        .collect();
    Ok(Image {
        width,
        height,
        pixels,
    })
}

/// A PFM depth buffer: `Pf`, one float per pixel, little-endian when the scale is negative.
pub fn read_pfm(bytes: &[u8], file: &str) -> Result<DepthImage, FormatError> {
    let error = |what: &str| FormatError::new(file, 0, format!("expected {what}"));
    if bytes.get(..2) != Some(b"Pf") {
        return Err(error("a PFM depth buffer (starting 'Pf': one channel)"));
    }
    let (fields, data) = header(bytes, 3).ok_or_else(|| error("a PFM header 'Pf W H -1'"))?;
    let (width, height) =
        size(&fields).ok_or_else(|| error("a PFM width and height in 1..=16384"))?;
    let little = match fields[2].parse::<f64>() {
        Ok(scale) if scale < 0.0 => true,
        Ok(scale) if scale > 0.0 => false,
        _ => {
            return Err(error(&format!(
                "a PFM scale (-1: little-endian), found {}",
                fields[2]
            )));
        }
    };
    let count = width as usize * height as usize;
    let Some(raw) = bytes.get(data..data + 4 * count) else {
        let found = (bytes.len() - data) / 4;
        return Err(error(&format!(
            "{count} floats for {width}×{height} pixels, found {found}"
        )));
    };
    let value = |b: &[u8]| {
        let b = [b[0], b[1], b[2], b[3]];
        if little {
            f32::from_le_bytes(b)
        } else {
            f32::from_be_bytes(b)
        }
    };
    let rows: Vec<&[u8]> = raw.chunks_exact(4 * width as usize).rev().collect();
    let values = rows
        .into_iter()
        .flat_map(|row| row.chunks_exact(4).map(value))
        .collect();
    Ok(DepthImage {
        width,
        height,
        values,
    })
}

/// `image` as a binary PPM (alpha dropped).
pub fn ppm_bytes(image: &Image) -> Vec<u8> {
    let mut bytes = format!("P6\n{} {}\n255\n", image.width, image.height).into_bytes();
    bytes.extend(image.pixels.iter().flat_map(|p| [p[0], p[1], p[2]]));
    bytes
}

/// `depth` (rows from the top) as a little-endian PFM.
pub fn pfm_bytes(depth: &DepthImage) -> Vec<u8> {
    let mut bytes = format!("Pf\n{} {}\n-1\n", depth.width, depth.height).into_bytes();
    for row in depth.values.chunks_exact(depth.width as usize).rev() {
        bytes.extend(row.iter().flat_map(|v| v.to_le_bytes()));
    }
    bytes
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn images_read_back_what_was_written_with_rows_from_the_top() {
        let image = Image {
            width: 2,
            height: 2,
            pixels: vec![
                [1, 2, 3, 255],
                [4, 5, 6, 255],
                [7, 8, 9, 255],
                [10, 11, 12, 255],
            ],
        };
        assert_eq!(read_ppm(&ppm_bytes(&image), "a.ppm"), Ok(image));
        let depth = DepthImage {
            width: 2,
            height: 2,
            values: vec![0.25, 0.5, 0.75, 1.0],
        };
        let bytes = pfm_bytes(&depth);
        // PFM's first row is the bottom one: 0.75 comes first, the top row's 0.25 last but one.
        assert_eq!(
            &bytes[bytes.len() - 16..bytes.len() - 12],
            &0.75f32.to_le_bytes()
        );
        assert_eq!(
            &bytes[bytes.len() - 8..bytes.len() - 4],
            &0.25f32.to_le_bytes()
        );
        assert_eq!(read_pfm(&bytes, "a.pfm"), Ok(depth));
        let text = b"P3\n# a comment\n1 1\n255\n 9 8\n7\n";
        assert_eq!(read_ppm(text, "t.ppm").unwrap().pixels, [[9, 8, 7, 255]]);
    }

    #[test]
    fn a_short_or_foreign_file_is_a_one_line_error_naming_it() {
        let short = read_ppm(b"P6\n4 4\n255\n\x01\x02", "frame.ppm").unwrap_err();
        assert_eq!(
            short.to_string(),
            "frame.ppm:0: expected 48 samples for 4×4 pixels, found 2"
        );
        let png = read_ppm(b"\x89PNG\r\n", "frame.ppm").unwrap_err();
        assert!(png.message.contains("'P6' or 'P3'"), "{png}");
        let colour = read_pfm(b"PF\n1 1\n-1\n", "depth.pfm").unwrap_err();
        assert!(colour.message.contains("one channel"), "{colour}");
        let deep = read_ppm(b"P6 1 1 65535\n\0\0\0\0\0\0", "d.ppm").unwrap_err();
        assert!(deep.message.contains("maxval 255"), "{deep}");
    }
}

//! The texture both views map onto a model's texture coordinates, and its mipmap chain.

use bevy_ecs::prelude::*;

use crate::Image;

impl Image {
    /// The next mipmap level: half the size (rounded down, at least 1), each texel the mean of
    /// the 2×2 texels it covers (rounded to nearest; an odd last row or column is reused).
    pub fn half(&self) -> Image {
        let (width, height) = ((self.width / 2).max(1), (self.height / 2).max(1));
        let texel = |x: u32, y: u32| {
            self.pixels[(y.min(self.height - 1) * self.width + x.min(self.width - 1)) as usize]
        };
        let mut pixels = Vec::with_capacity((width * height) as usize);
        for y in 0..height {
            for x in 0..width {
                let four = [
                    texel(2 * x, 2 * y),
                    texel(2 * x + 1, 2 * y),
                    texel(2 * x, 2 * y + 1),
                    texel(2 * x + 1, 2 * y + 1),
                ];
                pixels.push(std::array::from_fn(|c| {
                    let sum: u32 = four.iter().map(|p| p[c] as u32).sum();
                    ((sum + 2) / 4) as u8
                }));
            }
        }
        Image {
            width,
            height,
            pixels,
        }
    }

    /// This image and every smaller level down to 1×1.
    pub fn mip_chain(&self) -> Vec<Image> {
        let mut levels = vec![self.clone()];
        while let Some(last) = levels.last().filter(|l| l.width > 1 || l.height > 1) {
            let next = last.half();
            levels.push(next);
        }
        levels
    }
}

/// The texture of the current model (a Resource): the image given in `[model] texture`, dropped
/// on the window or picked in the panel, or the course's 8×8 checkerboard when none is given.
#[derive(Resource, Clone, Debug, PartialEq)]
pub struct Texture {
    /// The file it came from; `None` for the built-in checkerboard.
    pub source: Option<std::path::PathBuf>,
    pub image: Image,
}

impl Default for Texture {
    fn default() -> Self {
        Texture {
            source: None,
            image: checkerboard(),
        }
    }
}

/// The course's 8×8 checkerboard: 256×256 texels, squares of 32, white and dark grey, the
/// bottom-left square white.
pub fn checkerboard() -> Image {
    let size = 256;
    let pixels = (0..size * size)
        .map(|i| {
            let (x, y) = (i % size, size - 1 - i / size);
            if (x / 32 + y / 32) % 2 == 0 {
                [255, 255, 255, 255]
            } else {
                [48, 48, 48, 255]
            }
        })
        .collect();
    Image {
        width: size,
        height: size,
        pixels,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_mip_chain_halves_down_to_one_texel_averaging_boxes() {
        let chain = checkerboard().mip_chain();
        let sizes: Vec<_> = chain.iter().map(|l| (l.width, l.height)).collect();
        assert_eq!(sizes.len(), 9);
        assert_eq!(sizes[1], (128, 128));
        assert_eq!(sizes[8], (1, 1));
        // Squares of 32 texels stay pure down to level 5 (squares of 1); level 6 averages them.
        // Rows run from the top: the bottom-left texel of the 8×8 level is white, its neighbour
        // grey.
        assert_eq!(chain[5].pixels[7 * 8], [255, 255, 255, 255]);
        assert_eq!(chain[5].pixels[7 * 8 + 1], [48, 48, 48, 255]);
        let grey = ((2 * 255 + 2 * 48 + 2) / 4) as u8;
        assert_eq!(chain[6].pixels[0], [grey, grey, grey, 255]);
        assert_eq!(chain[8].pixels[0], [grey, grey, grey, 255]);
    }

    #[test]
    fn odd_sizes_reuse_their_last_row_and_column() {
        let image = Image {
            width: 3,
            height: 1,
            pixels: vec![[0; 4], [100; 4], [200; 4]],
        };
        let half = image.half();
        assert_eq!((half.width, half.height), (1, 1));
        assert_eq!(half.pixels[0], [50; 4]);
        assert_eq!(image.mip_chain().len(), 2);
    }
}

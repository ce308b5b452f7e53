//! The colour and depth buffers, stored tile after tile: each 64×64 tile is one contiguous
//! block, so a thread drawing a tile owns its memory and keeps it in cache; and the colour as
//! they store it (RGBA8, as a UNORM target).

use glam::Vec3;
use rayon::prelude::*;

use crate::lanes::{F8, LANES, V8};

/// Tile edge in pixels.
pub(crate) const TILE: i32 = 64;
pub(crate) const TILE_PIXELS: usize = (TILE * TILE) as usize;
/// Pixels in one row of a tile.
pub(crate) const ROW: usize = TILE as usize;

/// A tile's pixel rectangle, inclusive, clipped to the viewport.
#[derive(Clone, Copy, Debug)]
pub(crate) struct TileRect {
    pub x0: i32,
    pub y0: i32,
    pub x1: i32,
    pub y1: i32,
}

/// The viewport cut into tiles.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Grid {
    pub width: i32,
    pub height: i32,
    pub tiles_x: i32,
    pub tiles_y: i32,
}

/// The id buffer's value where no triangle drew.
pub(crate) const NO_TRIANGLE: u32 = u32::MAX;

/// Tiled colour (RGBA8 packed) and depth (f32, the reference's Depth32Float); while fates are
/// recorded, beside the depth buffer, which triangle drew each pixel last (the depth test's
/// winner): first the index of its set-up triangle, then, once the frame is drawn, its mesh
/// triangle.
#[derive(Debug, Default)]
pub(crate) struct Target {
    pub grid: Grid,
    pub color: Vec<u32>,
    pub depth: Vec<f32>,
    pub ids: Vec<u32>,
    /// While a tile is shaded after its depth test (see `deferred`): which triangle each pixel
    /// shows, by the frame's numbering.
    pub visible: Vec<u32>,
}

impl Target {
    /// Sizes the buffers for a viewport, the id buffer only when `record` (empty otherwise);
    /// keeps them (and allocates nothing) when the size is the same as last frame's.
    pub(crate) fn resize(&mut self, width: u32, height: u32, record: bool) {
        let (width, height) = (width as i32, height as i32);
        self.grid = Grid {
            width,
            height,
            tiles_x: (width as u32).div_ceil(TILE as u32) as i32,
            tiles_y: (height as u32).div_ceil(TILE as u32) as i32,
        };
        let pixels = self.grid.tiles() * TILE_PIXELS;
        self.color.resize(pixels, 0);
        self.depth.resize(pixels, 1.0);
        self.visible.resize(pixels, NO_TRIANGLE);
        self.ids
            .resize(if record { pixels } else { 0 }, NO_TRIANGLE);
    }

    /// Where pixel (x, y) is stored, when it is inside the viewport.
    pub(crate) fn index(&self, x: u32, y: u32) -> Option<usize> {
        let (x, y) = (x as i32, y as i32);
        if x >= self.grid.width || y >= self.grid.height {
            return None;
        }
        let tile = (y / TILE * self.grid.tiles_x + x / TILE) as usize;
        Some(tile * TILE_PIXELS + ((y % TILE) * TILE + x % TILE) as usize)
    }

    /// Copies the tiles into `out` as rows from the top (`width` pixels each), in parallel by
    /// rows of tiles.
    pub(crate) fn resolve(&self, out: &mut Vec<[u8; 4]>) {
        let Grid { width, tiles_x, .. } = self.grid;
        let (width, tiles_x) = (width as usize, tiles_x as usize);
        out.resize(width * self.grid.height as usize, [0; 4]);
        let tile = TILE as usize;
        out.par_chunks_mut(tile * width)
            .enumerate()
            .for_each(|(ty, band)| {
                let rows = band.len() / width;
                for tx in 0..tiles_x {
                    let start = (ty * tiles_x + tx) * TILE_PIXELS;
                    let source = &self.color[start..start + TILE_PIXELS];
                    let columns = tile.min(width - tx * tile);
                    for r in 0..rows {
                        let row = &mut band[r * width + tx * tile..][..columns];
                        for (p, c) in row.iter_mut().zip(&source[r * tile..]) {
                            *p = c.to_le_bytes();
                        }
                    }
                }
            });
    }
}

impl Grid {
    pub(crate) fn tiles(&self) -> usize {
        (self.tiles_x * self.tiles_y) as usize
    }

    pub(crate) fn tile_rect(&self, tile: usize) -> TileRect {
        let (tx, ty) = (tile as i32 % self.tiles_x, tile as i32 / self.tiles_x);
        TileRect {
            x0: tx * TILE,
            y0: ty * TILE,
            x1: ((tx + 1) * TILE).min(self.width) - 1,
            y1: ((ty + 1) * TILE).min(self.height) - 1,
        }
    }
}

/// A colour in 0..1 as the RGBA8 bytes a UNORM target stores (clamped, rounded to nearest),
/// packed little-endian.
pub(crate) fn pack(rgb: Vec3) -> u32 {
    pack8(V8::splat(rgb))[0]
}

/// The background as the image stores it: its colour with alpha 0, where no primitive drew, as
/// the GPU views clear theirs. Coverage is read from alpha, never from colour (a GPU may round
/// the same background colour to another byte).
pub(crate) fn pack_background(rgb: Vec3) -> u32 {
    pack(rgb) & 0x00ff_ffff
}

#[inline(always)]
pub(crate) fn pack8(rgb: V8) -> [u32; LANES] {
    let byte = |c: F8| {
        let c = c.max(F8::splat(0.0)).min(F8::splat(1.0));
        let c = c * F8::splat(255.0) + F8::splat(0.5);
        let mut bytes = [0u32; LANES];
        for (byte, c) in bytes.iter_mut().zip(c.0) {
            // SAFETY: c is in 0.5..=255.5 (clamped above; NaN clamps to 0), which an i32
            // holds; truncating it rounds the colour to nearest. The checked `as` conversion
            // would not vectorise.
            *byte = unsafe { c.to_int_unchecked::<i32>() } as u32;
        }
        bytes
    };
    let (r, g, b) = (byte(rgb.x), byte(rgb.y), byte(rgb.z));
    let mut packed = [0u32; LANES];
    for (p, ((r, g), b)) in packed.iter_mut().zip(r.into_iter().zip(g).zip(b)) {
        *p = r | g << 8 | b << 16 | 0xff << 24;
    }
    packed
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn packing_rounds_like_a_unorm_target() {
        assert_eq!(
            pack(Vec3::new(0.0, 1.0, 0.5)).to_le_bytes(),
            [0, 255, 128, 255]
        );
        assert_eq!(
            pack(Vec3::new(-1.0, 2.0, 0.1)).to_le_bytes(),
            [0, 255, 26, 255]
        );
        let background = pack_background(Vec3::new(0.08, 0.08, 0.1));
        assert_eq!(
            background.to_le_bytes(),
            [20, 20, 26, 0],
            "uncovered: alpha 0"
        );
    }
}

//! Close2GL's texturing: its own copy of the texture's mipmap chain (made once per image) and its
//! own sampling, eight pixels at a time: nearest, bilinear, and trilinear with the level of
//! detail from the screen-space derivatives of the texture coordinates over each 2×2 quad of
//! pixels, as GPUs take them. Wrap mode: repeat. Texture coordinates are OpenGL's: t grows
//! upwards, and the image's rows run from the top.

use close2gl_core::{Image8, Texture, TextureFilter};

use crate::lanes::{F8, LANES, V8};

/// The mipmap chain of the current texture, rebuilt only when the texture's generation changes.
#[derive(Debug, Default)]
pub(crate) struct Mips {
    generation: Option<u64>,
    levels: Vec<Image8>,
}

impl Mips {
    pub(crate) fn update(&mut self, texture: &Texture) {
        if self.generation != Some(texture.generation) {
            self.levels = texture.image.mip_chain();
            self.generation = Some(texture.generation);
        }
    }

    pub(crate) fn sampler(&self, filter: TextureFilter) -> Sampler<'_> {
        Sampler {
            levels: &self.levels,
            filter,
        }
    }
}

/// Samples one mipmap chain with one filter.
#[derive(Clone, Copy)]
pub(crate) struct Sampler<'a> {
    levels: &'a [Image8],
    filter: TextureFilter,
}

impl Sampler<'_> {
    /// The colours at eight points (s, t), with `lod` the level of detail there (log2 of the
    /// pixel's footprint in level-0 texels; used by trilinear only).
    #[inline(always)]
    pub(crate) fn sample(&self, s: F8, t: F8, lod: F8) -> V8 {
        // One decision per eight pixels, not per pixel.
        match self.filter {
            TextureFilter::Nearest => lanes(|i| nearest(&self.levels[0], s.0[i], t.0[i])),
            TextureFilter::Bilinear => lanes(|i| bilinear(&self.levels[0], s.0[i], t.0[i])),
            TextureFilter::Trilinear => lanes(|i| self.trilinear(s.0[i], t.0[i], lod.0[i])),
        }
    }

    /// Bilinear in the two levels around `lod`, blended by its fraction; below level 0
    /// (magnified) it is level 0's bilinear.
    #[inline(always)]
    fn trilinear(&self, s: f32, t: f32, lod: f32) -> [f32; 3] {
        let top = (self.levels.len() - 1) as f32;
        let lod = if lod.is_nan() {
            0.0
        } else {
            lod.clamp(0.0, top)
        };
        let (below, fraction) = (lod.floor(), lod - lod.floor());
        let first = bilinear(&self.levels[below as usize], s, t);
        if fraction == 0.0 {
            return first;
        }
        let second = bilinear(&self.levels[below as usize + 1], s, t);
        std::array::from_fn(|c| first[c] + (second[c] - first[c]) * fraction)
    }

    /// Level 0's width and height, for turning derivatives of (s, t) into texels.
    pub(crate) fn size(&self) -> (f32, f32) {
        (self.levels[0].width as f32, self.levels[0].height as f32)
    }
}

/// Eight texels, lane by lane, as three channels.
#[inline(always)]
fn lanes(texel: impl Fn(usize) -> [f32; 3]) -> V8 {
    let (mut r, mut g, mut b) = ([0.0f32; LANES], [0.0f32; LANES], [0.0f32; LANES]);
    for (i, ((r, g), b)) in r.iter_mut().zip(&mut g).zip(&mut b).enumerate() {
        [*r, *g, *b] = texel(i);
    }
    V8 {
        x: F8(r),
        y: F8(g),
        z: F8(b),
    }
}

/// `i` wrapped into 0..n (repeat): a mask when n is a power of two, as texture sizes mostly
/// are, and a division only otherwise.
#[inline(always)]
fn wrap(i: i32, n: u32) -> u32 {
    if n.is_power_of_two() {
        i as u32 & (n - 1)
    } else {
        i.rem_euclid(n as i32) as u32
    }
}

/// Texel (x, y) of `level`, wrapped (repeat), as RGB in 0..1.
#[inline(always)]
fn texel(level: &Image8, x: i32, y: i32) -> [f32; 3] {
    let (x, y) = (wrap(x, level.width), wrap(y, level.height));
    let [r, g, b, _] = level.pixels[(y * level.width + x) as usize];
    let scale = 1.0 / 255.0;
    [r as f32 * scale, g as f32 * scale, b as f32 * scale]
}

/// Where (s, t) falls in `level`, in texels from the top-left corner.
#[inline(always)]
fn position(level: &Image8, s: f32, t: f32) -> (f32, f32) {
    (s * level.width as f32, (1.0 - t) * level.height as f32)
}

// The filters are inlined into the lane loops, so that they are compiled for the CPU features
// the tile code is (a call into libm's floorf, or a call per lane, would cost more than the
// filtering).

/// The texel (s, t) falls in.
#[inline(always)]
fn nearest(level: &Image8, s: f32, t: f32) -> [f32; 3] {
    let (x, y) = position(level, s, t);
    texel(level, floor(x), floor(y))
}

/// The four texels whose centres surround (s, t), weighted by nearness.
#[inline(always)]
fn bilinear(level: &Image8, s: f32, t: f32) -> [f32; 3] {
    let (x, y) = position(level, s, t);
    let (x, y) = (x - 0.5, y - 0.5);
    let (x0, y0) = (floor(x), floor(y));
    let (fx, fy) = (x - x0 as f32, y - y0 as f32);
    let [a, b, c, d] =
        [(0, 0), (1, 0), (0, 1), (1, 1)].map(|(dx, dy)| texel(level, x0 + dx, y0 + dy));
    std::array::from_fn(|k| {
        let top = a[k] + (b[k] - a[k]) * fx;
        let bottom = c[k] + (d[k] - c[k]) * fx;
        top + (bottom - top) * fy
    })
}

/// floor as a whole number of texels; far-off or non-finite coordinates land somewhere in the
/// texture rather than overflowing (wrapping makes any whole number valid).
#[inline(always)]
fn floor(x: f32) -> i32 {
    if x.is_finite() {
        x.floor().clamp(-1e9, 1e9) as i32
    } else {
        0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use close2gl_core::checkerboard;

    fn mips() -> Mips {
        let mut mips = Mips::default();
        mips.update(&Texture::default());
        mips
    }

    #[test]
    fn nearest_finds_the_checker_square_and_repeats() {
        let image = checkerboard();
        // The bottom-left square is white, its right neighbour grey; s = 1.05 wraps to 0.05.
        assert_eq!(nearest(&image, 0.05, 0.05), [1.0; 3]);
        assert!(nearest(&image, 0.17, 0.05)[0] < 0.2);
        assert_eq!(nearest(&image, 1.05, 0.05), [1.0; 3]);
        assert_eq!(nearest(&image, -0.95, -0.95), [1.0; 3]);
    }

    #[test]
    fn bilinear_blends_across_a_square_edge() {
        let image = checkerboard();
        // Exactly on the edge between a white and a grey column: half of each.
        let edge = bilinear(&image, 32.0 / 256.0, 0.05)[0];
        let half = (1.0 + 48.0 / 255.0) / 2.0;
        assert!((edge - half).abs() < 1e-6, "{edge} vs {half}");
    }

    #[test]
    fn trilinear_goes_grey_when_a_pixel_covers_many_squares() {
        let mips = mips();
        let sampler = mips.sampler(TextureFilter::Trilinear);
        let grey = (2.0 * 255.0 + 2.0 * 48.0 + 2.0) / 4.0 / 255.0;
        let far = sampler.sample(F8::splat(0.3), F8::splat(0.3), F8::splat(7.0));
        assert!((far.x.0[0] - grey).abs() < 2.0 / 255.0, "{}", far.x.0[0]);
        let near = sampler.sample(F8::splat(0.05), F8::splat(0.05), F8::splat(-2.0));
        assert_eq!(near.x.0[0], 1.0, "magnified: level 0");
    }
}

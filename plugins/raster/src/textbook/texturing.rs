//! Texturing: the texture's mipmap chain, level 0 first, each level half the one before; wrap
//! mode repeat; t grows upwards, and an image's rows run from the top. Nearest takes the texel
//! (s, t) falls in; bilinear the four whose centres surround it; trilinear the bilinear of the
//! two levels around the level of detail, blended by its fraction.

use close2gl_core::{Image, RasterMistake as M, RasterMistakes, TextureFilter};
use glam::{Vec2, Vec3};

use super::interpolation::Pixel;

/// A texture's mipmap chain.
pub struct Mips(Vec<Image>);

impl Mips {
    pub(super) fn new(levels: Vec<Image>) -> Mips {
        Mips(levels)
    }

    /// The texel the filter finds for `here`, as 0..1 per channel.
    pub(super) fn sample(&self, here: &Pixel, filter: TextureFilter) -> Vec3 {
        let (st, mistakes) = (here.uv(), here.mistakes);
        if mistakes.has(M::NoWrapBlack) && (st.min_element() < 0.0 || st.max_element() > 1.0) {
            return Vec3::ZERO;
        }
        let level = Level {
            mips: self,
            mistakes,
        };
        match filter {
            TextureFilter::Nearest => level.nearest(st),
            TextureFilter::Bilinear => level.bilinear(0, st),
            TextureFilter::Trilinear => level.trilinear(st, self.level_of_detail(here)),
        }
    }

    /// log2 of the pixel's footprint in level-0 texels: the longer of the steps of (s, t) across
    /// and down the 2×2 quad of pixels it is in (from an even column and row), as GPUs take it,
    /// whether or not the triangle covers the quad's other pixels.
    fn level_of_detail(&self, here: &Pixel) -> f32 {
        let mistakes = here.mistakes;
        let size = match mistakes.has(M::LodUnscaled) {
            true => Vec2::ONE,
            false => Vec2::new(self.0[0].width as f32, self.0[0].height as f32),
        };
        let (x, y) = here.at();
        let (dx, dy) = (-(x & 1), -(y & 1));
        let corner = here.uv_beside(dx, dy);
        let across = (here.uv_beside(dx + 1, dy) - corner) * size;
        let down = (here.uv_beside(dx, dy + 1) - corner) * size;
        let rho = match mistakes.has(M::LodOneAxis) {
            true => across.length(),
            false => across.length().max(down.length()),
        };
        match mistakes.has(M::LodAbsolute) {
            true => rho.log2().abs(),
            false => rho.log2(),
        }
    }
}

/// The chain as one pixel's sampling sees it, with its mistakes.
struct Level<'a> {
    mips: &'a Mips,
    mistakes: RasterMistakes,
}

impl Level<'_> {
    /// The texel in column x, row y of `level`, wrapped (or clamped), as 0..1 per channel.
    fn texel(&self, level: usize, x: f32, y: f32) -> Vec3 {
        let image = &self.mips.0[level];
        let clamp = self.mistakes.has(M::ClampNotRepeat);
        // Clamped first, so that far-off (or NaN) coordinates wrap without overflow.
        let wrap = |i: f32, n: u32| {
            let i = i.clamp(-1e9, 1e9) as i64;
            match clamp {
                true => i.clamp(0, n as i64 - 1) as usize,
                false => i.rem_euclid(n as i64) as usize,
            }
        };
        let [r, g, b, _] =
            image.pixels[wrap(y, image.height) * image.width as usize + wrap(x, image.width)];
        Vec3::new(r as f32, g as f32, b as f32) / 255.0
    }

    /// Where (s, t) falls in `level`, in texels from its top-left corner.
    fn position(&self, level: usize, st: Vec2) -> Vec2 {
        let image = &self.mips.0[level];
        let size = Vec2::new(image.width as f32, image.height as f32);
        let t = if self.mistakes.has(M::TNotFlipped) {
            st.y
        } else {
            1.0 - st.y
        };
        Vec2::new(st.x, t) * size
    }

    /// The texel (s, t) falls in, at level 0.
    fn nearest(&self, st: Vec2) -> Vec3 {
        let at = self.position(0, st);
        let p = match self.mistakes.has(M::NearestRounds) {
            true => at.round(),
            false => at.floor(),
        };
        self.texel(0, p.x, p.y)
    }

    /// The four texels of `level` whose centres surround (s, t), weighted by nearness.
    fn bilinear(&self, level: usize, st: Vec2) -> Vec3 {
        let half = if self.mistakes.has(M::BilinearNoHalfTexel) {
            0.0
        } else {
            0.5
        };
        let p = self.position(level, st) - half;
        let (corner, f) = (p.floor(), p - p.floor());
        let texel = |dx: f32, dy: f32| self.texel(level, corner.x + dx, corner.y + dy);
        let upper = texel(0.0, 0.0).lerp(texel(1.0, 0.0), f.x);
        let lower = texel(0.0, 1.0).lerp(texel(1.0, 1.0), f.x);
        upper.lerp(lower, f.y)
    }

    /// Bilinear in the two levels around `lod`, blended by its fraction: level 0 when magnified
    /// (or when the footprint is not a number), the last level beyond it.
    fn trilinear(&self, st: Vec2, lod: f32) -> Vec3 {
        let top = (self.mips.0.len() - 1) as f32;
        let lod = lod.max(0.0).min(top);
        if self.mistakes.has(M::MipNearestLevel) {
            return self.bilinear(lod.round() as usize, st);
        }
        let below = lod.floor();
        let near = self.bilinear(below as usize, st);
        let far = self.bilinear((below + 1.0).min(top) as usize, st);
        near.lerp(far, lod - below)
    }
}

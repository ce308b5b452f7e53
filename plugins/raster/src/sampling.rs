//! Close2GL's texturing: its own copy of the texture's mipmap chain (made once per image), the
//! level of detail from the screen-space derivatives of the texture coordinates over each 2×2
//! quad of pixels, as GPUs take them, and its own sampling, eight pixels at a time: nearest,
//! bilinear, and trilinear. Wrap mode: repeat. Texture coordinates are OpenGL's: t grows
//! upwards, and the image's rows run from the top.
//!
//! Everything but the texel loads is lane-wide arithmetic (the compiler makes it SIMD); the
//! filter is a type, so that each filter's pixel loop is compiled on its own and nearest and
//! bilinear never pay for the level of detail.

use close2gl_core::Texture;

use crate::lanes::{F8, LANES, V8};
use crate::varyings::{Interpolant, Planes};

/// The mipmap chain of the current texture, built when a new texture is set (the raster system
/// sets it when bevy's change ticks say the `Texture` resource changed).
#[derive(Debug, Default)]
pub(crate) struct Mips {
    /// Every level's texels, level 0 first, as little-endian RGBA8.
    texels: Vec<u32>,
    levels: Vec<Level>,
    /// Every level's sides are powers of two (then they all are, down to 1×1): wrapping is a
    /// mask, not a division.
    power_of_two: bool,
}

/// One level's size and where its texels start.
#[derive(Clone, Copy, Debug, Default)]
struct Level {
    width: u32,
    height: u32,
    offset: u32,
}

impl Mips {
    /// Builds the chain of `texture`, or drops it when there is none.
    pub(crate) fn set(&mut self, texture: Option<&Texture>) {
        self.texels.clear();
        self.levels.clear();
        let Some(texture) = texture else {
            return;
        };
        for image in texture.image.mip_chain() {
            self.levels.push(Level {
                width: image.width,
                height: image.height,
                // At most 16384² texels at level 0 (the loader's limit), 4/3 of it in all.
                offset: self.texels.len() as u32,
            });
            self.texels
                .extend(image.pixels.iter().map(|&p| u32::from_le_bytes(p)));
        }
        let base = texture.image.width.max(1);
        self.power_of_two = base.is_power_of_two() && texture.image.height.is_power_of_two();
    }

    /// Whether there is a texture to sample.
    pub(crate) fn is_set(&self) -> bool {
        !self.levels.is_empty()
    }

    /// Level 0's width and height, for turning derivatives of (s, t) into texels.
    fn size(&self) -> (f32, f32) {
        let level = self.levels.first().copied().unwrap_or_default();
        (level.width as f32, level.height as f32)
    }

    /// log2 of the pixel's footprint in level-0 texels, from the differences of (s, t) across
    /// the pixel's 2×2 quad (its top-left pixel to the one right of it and the one below), as a
    /// GPU takes them: ρ = max(|∂(s,t)/∂x|, |∂(s,t)/∂y|) in texels. Lanes pair up into quads
    /// (eight-pixel blocks start at even columns), so the row's own `st` give half the quad
    /// and only the quad's other row is interpolated (from the triangle's `planes`).
    #[inline(always)]
    pub(crate) fn level_of_detail(&self, planes: &Planes, x: F8, y: f32, st: (F8, F8)) -> F8 {
        let upper_row = ((y - 0.5) as u32).is_multiple_of(2);
        let other_y = if upper_row { y + 1.0 } else { y - 1.0 };
        let other = planes.texture_coordinates(x, other_y, planes.w(x, other_y));
        let ((s0, t0), (s1, t1)) = if upper_row { (st, other) } else { (other, st) };
        let across = (
            quad_right(s0) - quad_left(s0),
            quad_right(t0) - quad_left(t0),
        );
        let down = (quad_left(s1) - quad_left(s0), quad_left(t1) - quad_left(t0));
        self.footprint_log2(across, down)
    }

    /// log2 of ρ, the larger of the quad's differences of (s, t) `across` (its top-left pixel
    /// to the one right of it) and `down` (to the one below), each as a length in level-0
    /// texels.
    #[inline(always)]
    pub(crate) fn footprint_log2(&self, across: (F8, F8), down: (F8, F8)) -> F8 {
        let (width, height) = self.size();
        let length = |(ds, dt): (F8, F8)| {
            let (ds, dt) = (ds * F8::splat(width), dt * F8::splat(height));
            (ds * ds + dt * dt).sqrt()
        };
        length(across).max(length(down)).log2()
    }

    /// The texel each of eight points (s, t) falls in, at level 0.
    #[inline(always)]
    fn nearest(&self, s: F8, t: F8) -> V8 {
        let levels = [self.levels[0]; LANES];
        let (x, y) = position(&levels, s, t);
        let (column, row) = (
            self.columns(&levels, whole(x.floor()), 0),
            self.rows(&levels, whole(y.floor()), 0),
        );
        let texels = self.fetch(row, column);
        let mut rgb = [F8::splat(0.0); 3];
        for (k, c) in rgb.iter_mut().enumerate() {
            *c = channel(&texels, k) * F8::splat(1.0 / 255.0);
        }
        V8 {
            x: rgb[0],
            y: rgb[1],
            z: rgb[2],
        }
    }

    /// At each point, the four texels of `level` whose centres surround it, weighted by
    /// nearness.
    #[inline(always)]
    fn bilinear(&self, level: [u32; LANES], s: F8, t: F8) -> V8 {
        let mut levels = [Level::default(); LANES];
        for (l, &i) in levels.iter_mut().zip(&level) {
            *l = self.levels[i as usize];
        }
        let (x, y) = position(&levels, s, t);
        let (x, y) = (x - F8::splat(0.5), y - F8::splat(0.5));
        let (x0, y0) = (x.floor(), y.floor());
        let (fx, fy) = (x - x0, y - y0);
        let (x0, y0) = (whole(x0), whole(y0));
        let (left, right) = (self.columns(&levels, x0, 0), self.columns(&levels, x0, 1));
        let (top, bottom) = (self.rows(&levels, y0, 0), self.rows(&levels, y0, 1));
        let [a, b, c, d] = [(top, left), (top, right), (bottom, left), (bottom, right)]
            .map(|(row, column)| self.fetch(row, column));
        let mut rgb = [F8::splat(0.0); 3];
        for (k, out) in rgb.iter_mut().enumerate() {
            let (a, b, c, d) = (
                channel(&a, k),
                channel(&b, k),
                channel(&c, k),
                channel(&d, k),
            );
            let upper = (b - a).mul_add(fx, a);
            let lower = (d - c).mul_add(fx, c);
            *out = (lower - upper).mul_add(fy, upper) * F8::splat(1.0 / 255.0);
        }
        V8 {
            x: rgb[0],
            y: rgb[1],
            z: rgb[2],
        }
    }

    /// Bilinear in the two levels around `lod`, blended by its fraction; below level 0
    /// (magnified) it is level 0's bilinear, beyond the last level the last level's.
    #[inline(always)]
    fn trilinear(&self, s: F8, t: F8, lod: F8) -> V8 {
        let top = (self.levels.len() - 1) as f32;
        // NaN (a degenerate footprint) takes level 0: `max` gives its second operand then.
        let lod = lod.max(F8::splat(0.0)).min(F8::splat(top));
        let below = lod.floor();
        let fraction = lod - below;
        let mut first = [0u32; LANES];
        let mut second = [0u32; LANES];
        for ((f, n), b) in first.iter_mut().zip(&mut second).zip(below.0) {
            // SAFETY: b is a whole number in 0..=top (clamped above).
            *f = unsafe { b.to_int_unchecked::<u32>() };
            *n = (*f + 1).min(top as u32);
        }
        let near = self.bilinear(first, s, t);
        if fraction.0 == [0.0; LANES] {
            return near;
        }
        let far = self.bilinear(second, s, t);
        V8 {
            x: (far.x - near.x).mul_add(fraction, near.x),
            y: (far.y - near.y).mul_add(fraction, near.y),
            z: (far.z - near.z).mul_add(fraction, near.z),
        }
    }

    /// Columns `x + dx` wrapped into each lane's level (repeat).
    #[inline(always)]
    fn columns(&self, levels: &[Level; LANES], x: [i32; LANES], dx: i32) -> [u32; LANES] {
        let mut out = [0u32; LANES];
        for ((o, &x), level) in out.iter_mut().zip(&x).zip(levels) {
            *o = wrap(x + dx, level.width, self.power_of_two);
        }
        out
    }

    /// Where rows `y + dy`, wrapped into each lane's level, start in `texels`.
    #[inline(always)]
    fn rows(&self, levels: &[Level; LANES], y: [i32; LANES], dy: i32) -> [u32; LANES] {
        let mut out = [0u32; LANES];
        for ((o, &y), level) in out.iter_mut().zip(&y).zip(levels) {
            *o = level.offset + wrap(y + dy, level.height, self.power_of_two) * level.width;
        }
        out
    }

    /// The texels at `row + column`, lane by lane: the one part that is not SIMD arithmetic.
    #[inline(always)]
    fn fetch(&self, row: [u32; LANES], column: [u32; LANES]) -> [u32; LANES] {
        let mut out = [0u32; LANES];
        for (o, (r, c)) in out.iter_mut().zip(row.into_iter().zip(column)) {
            let index = (r + c) as usize;
            debug_assert!(index < self.texels.len());
            // SAFETY: the column is wrapped below its level's width and the row below its
            // height, so the index lies within the level, which lies within `texels`. A
            // bounds check per texel measured slower: docs/performance.md#textures.
            *o = unsafe { *self.texels.get_unchecked(index) };
        }
        out
    }
}

/// Each lane takes its quad's left pixel's value.
#[inline(always)]
fn quad_left(v: F8) -> F8 {
    let mut out = [0.0; LANES];
    for (i, o) in out.iter_mut().enumerate() {
        *o = v.0[i & !1];
    }
    F8(out)
}

/// Each lane takes its quad's right pixel's value.
#[inline(always)]
fn quad_right(v: F8) -> F8 {
    let mut out = [0.0; LANES];
    for (i, o) in out.iter_mut().enumerate() {
        *o = v.0[i | 1];
    }
    F8(out)
}

/// Where eight points (s, t) fall in their levels, in texels from the top-left corner.
#[inline(always)]
fn position(levels: &[Level; LANES], s: F8, t: F8) -> (F8, F8) {
    let (mut width, mut height) = ([0.0f32; LANES], [0.0f32; LANES]);
    for ((w, h), level) in width.iter_mut().zip(&mut height).zip(levels) {
        (*w, *h) = (level.width as f32, level.height as f32);
    }
    (s * F8(width), (F8::splat(1.0) - t) * F8(height))
}

/// Whole numbers of texels as integers; far-off coordinates are clamped (wrapping makes any
/// whole number valid) and NaN lands at the clamp's low end: no overflow, no panic.
#[inline(always)]
fn whole(x: F8) -> [i32; LANES] {
    let x = x.max(F8::splat(-1e9)).min(F8::splat(1e9));
    let mut out = [0i32; LANES];
    for (o, x) in out.iter_mut().zip(x.0) {
        // SAFETY: x is within ±1e9 (clamped above), which an i32 holds; the checked `as`
        // conversion would not vectorise.
        *o = unsafe { x.to_int_unchecked::<i32>() };
    }
    out
}

/// `i` wrapped into 0..n (repeat): a mask when n is a power of two, as texture sizes mostly
/// are, and a division only otherwise.
#[inline(always)]
fn wrap(i: i32, n: u32, power_of_two: bool) -> u32 {
    if power_of_two {
        i as u32 & (n - 1)
    } else {
        i.rem_euclid(n as i32) as u32
    }
}

/// Channel `k` (0 red, 1 green, 2 blue) of eight texels, in 0..=255.
#[inline(always)]
fn channel(texels: &[u32; LANES], k: usize) -> F8 {
    let mut out = [0.0f32; LANES];
    for (o, t) in out.iter_mut().zip(texels) {
        *o = ((t >> (8 * k)) & 0xff) as f32;
    }
    F8(out)
}

/// A texture filter: how eight points (s, t) become colours. `lod` gives the level of detail
/// (log2 of the pixel's footprint in level-0 texels) for the filters that use it.
pub(crate) trait Filter: Sync {
    fn sample(&self, mips: &Mips, s: F8, t: F8, lod: impl Fn() -> F8) -> V8;
}

pub(crate) struct Nearest;
pub(crate) struct Bilinear;
pub(crate) struct Trilinear;

impl Filter for Nearest {
    #[inline(always)]
    fn sample(&self, mips: &Mips, s: F8, t: F8, _: impl Fn() -> F8) -> V8 {
        mips.nearest(s, t)
    }
}

impl Filter for Bilinear {
    #[inline(always)]
    fn sample(&self, mips: &Mips, s: F8, t: F8, _: impl Fn() -> F8) -> V8 {
        mips.bilinear([0; LANES], s, t)
    }
}

impl Filter for Trilinear {
    #[inline(always)]
    fn sample(&self, mips: &Mips, s: F8, t: F8, lod: impl Fn() -> F8) -> V8 {
        mips.trilinear(s, t, lod())
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use close2gl_core::Image;

    fn mips(image: Image) -> Mips {
        let mut mips = Mips::default();
        mips.set(Some(&Texture {
            source: None,
            image,
        }));
        mips
    }

    fn red(colour: V8) -> f32 {
        colour.x.0[0]
    }

    #[test]
    fn nearest_finds_the_checker_square_and_repeats() {
        let mips = mips(Texture::default().image);
        let at = |s: f32, t: f32| red(mips.nearest(F8::splat(s), F8::splat(t)));
        // The bottom-left square is white, its right neighbour grey; s = 1.05 wraps to 0.05.
        assert_eq!(at(0.05, 0.05), 1.0);
        assert!(at(0.17, 0.05) < 0.2);
        assert_eq!(at(1.05, 0.05), 1.0);
        assert_eq!(at(-0.95, -0.95), 1.0);
    }

    #[test]
    fn bilinear_blends_across_a_square_edge() {
        let mips = mips(Texture::default().image);
        // Exactly on the edge between a white and a grey column: half of each.
        let edge = red(mips.bilinear([0; LANES], F8::splat(32.0 / 256.0), F8::splat(0.05)));
        let half = (1.0 + 48.0 / 255.0) / 2.0;
        assert!((edge - half).abs() < 1e-6, "{edge} vs {half}");
    }

    #[test]
    fn trilinear_goes_grey_when_a_pixel_covers_many_squares() {
        let mips = mips(Texture::default().image);
        let grey = (2.0 * 255.0 + 2.0 * 48.0 + 2.0) / 4.0 / 255.0;
        let far = mips.trilinear(F8::splat(0.3), F8::splat(0.3), F8::splat(7.0));
        assert!((red(far) - grey).abs() < 2.0 / 255.0, "{}", red(far));
        let near = mips.trilinear(F8::splat(0.05), F8::splat(0.05), F8::splat(-2.0));
        assert_eq!(red(near), 1.0, "magnified: level 0");
        let lost = mips.trilinear(F8::splat(0.05), F8::splat(0.05), F8::splat(f32::NAN));
        assert_eq!(red(lost), 1.0, "no footprint: level 0");
    }

    #[test]
    fn sizes_that_are_not_powers_of_two_wrap_and_hostile_coordinates_stay_inside() {
        // 3×1: red, green, blue; the levels below are 1×1.
        let image = Image {
            width: 3,
            height: 1,
            pixels: vec![[255, 0, 0, 255], [0, 255, 0, 255], [0, 0, 255, 255]],
        };
        let mips = mips(image);
        let s = F8([0.1, 0.5, 0.9, 1.1, -0.1, 1e30, f32::NAN, f32::INFINITY]);
        let t = F8::splat(0.5);
        let got = mips.nearest(s, t);
        assert_eq!(&got.x.0[..5], &[1.0, 0.0, 0.0, 1.0, 0.0]);
        assert_eq!(&got.y.0[..5], &[0.0, 1.0, 0.0, 0.0, 0.0]);
        assert_eq!(&got.z.0[..5], &[0.0, 0.0, 1.0, 0.0, 1.0]);
        for lod in [-1.0, 0.5, 1.0, 40.0, f32::NAN, f32::INFINITY] {
            // Non-finite coordinates give NaN colours (packing turns them black); the others
            // stay colours.
            let got = mips.trilinear(s, t, F8::splat(lod));
            let finite = &got.x.0[..6];
            assert!(
                finite.iter().all(|c| (0.0..=1.0).contains(c)),
                "{lod}: {got:?}"
            );
        }
    }
}

//! The four shadings, computed as the reference view's shader (reference.wgsl) computes them:
//! the same lighting formula term for term, lit per vertex and interpolated (Gouraud) or lit per
//! pixel from the interpolated eye position and normal (Phong), and the colour written as an
//! 8-bit UNORM target stores it (clamped, rounded to nearest).

use close2gl_core::{Lighting, Shading};
use glam::Vec3;

use crate::lanes::{F8, LANES, V8};
use crate::setup::{Plane, Triangle, VARYINGS};
use crate::texture::{Filter, Mips};

/// The lighting constants of a frame, with the light in eye space.
#[derive(Clone, Copy, Debug)]
pub struct Light {
    pub position: Vec3,
    /// Ia · ka.
    pub ambient: Vec3,
    pub intensity: Vec3,
    pub kd: f32,
    /// 0 for the shadings without a specular term.
    pub ks: f32,
    pub shininess: f32,
    pub attenuation: [f32; 3],
}

impl Light {
    pub fn new(lighting: &Lighting, light_eye: Vec3, shading: Shading) -> Light {
        let specular = matches!(shading, Shading::GouraudAds | Shading::Phong);
        Light {
            position: light_eye,
            ambient: lighting.ia * lighting.ka,
            intensity: lighting.il,
            kd: lighting.kd,
            ks: if specular { lighting.ks } else { 0.0 },
            shininess: lighting.shininess,
            attenuation: lighting.attenuation,
        }
    }

    /// I = Ia ka + f_att Il (kd max(N·L, 0) + ks max(V·R, 0)^n), in eye space, for eight
    /// points at once.
    #[inline(always)]
    pub(crate) fn illumination(&self, eye: V8, normal: V8) -> V8 {
        let zero = F8::splat(0.0);
        let n = safe_normalize(normal);
        let to_light = V8::splat(self.position).sub(eye);
        let d2 = to_light.dot(to_light);
        let d = d2.sqrt();
        let l = safe_normalize(to_light);
        let v = safe_normalize(eye.scale(F8::splat(-1.0)));
        let n_dot_l = n.dot(l);
        // r = reflect(-l, n) = 2 (n·l) n - l.
        let r = n.scale(F8::splat(2.0) * n_dot_l).sub(l);
        let [c0, c1, c2] = self.attenuation.map(F8::splat);
        let f_att = (F8::splat(1.0) / (c0 + c1 * d + c2 * d2)).min(F8::splat(1.0));
        let diffuse = F8::splat(self.kd) * n_dot_l.max(zero);
        let specular = F8::splat(self.ks) * v.dot(r).max(F8::splat(1e-20)).pow(self.shininess);
        let lit = f_att * (diffuse + specular);
        let channel =
            |ambient: f32, intensity: f32| F8::splat(ambient) + F8::splat(intensity) * lit;
        V8 {
            x: channel(self.ambient.x, self.intensity.x),
            y: channel(self.ambient.y, self.intensity.y),
            z: channel(self.ambient.z, self.intensity.z),
        }
    }
}

/// Normalises without producing NaN for a zero vector, as the shader's safe_normalize.
#[inline(always)]
fn safe_normalize(x: V8) -> V8 {
    x.scale(F8::splat(1.0) / x.dot(x).max(F8::splat(1e-30)).sqrt())
}

/// A colour in 0..1 as the RGBA8 bytes a UNORM target stores (clamped, rounded to nearest),
/// packed little-endian.
pub fn pack(rgb: Vec3) -> u32 {
    pack8(V8::splat(rgb))[0]
}

#[inline(always)]
fn pack8(rgb: V8) -> [u32; LANES] {
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

/// The varyings the shadings use come first; the texture coordinates (s, t) sit here, after
/// the most any shading uses (Phong's eye position and normal).
pub const UV: usize = 6;

/// What a vertex carries to the pixels for its shading: nothing (flat colour), the Gouraud
/// intensity, or the eye position and normal (Phong). The texture coordinates come on top.
pub fn varyings_used(shading: Shading) -> usize {
    match shading {
        Shading::None => 0,
        Shading::GouraudAd | Shading::GouraudAds => 3,
        Shading::Phong => UV,
    }
}

/// The vertex stage: a vertex's varyings from its eye position, normal and texture coordinates.
#[inline(always)]
pub fn vertex_varyings(
    shading: Shading,
    light: &Light,
    eye: Vec3,
    normal: Vec3,
    uv: [f32; 2],
) -> [f32; VARYINGS] {
    let mut v = match shading {
        Shading::None => [0.0; VARYINGS],
        Shading::GouraudAd | Shading::GouraudAds => {
            let i = light.illumination(V8::splat(eye), V8::splat(normal));
            [i.x.0[0], i.y.0[0], i.z.0[0], 0.0, 0.0, 0.0, 0.0, 0.0]
        }
        Shading::Phong => [eye.x, eye.y, eye.z, normal.x, normal.y, normal.z, 0.0, 0.0],
    };
    v[UV..UV + 2].copy_from_slice(&uv);
    v
}

/// The pixel stage: the colours of eight pixels of a triangle, centred at (x, y). Inlined into
/// the row loop (see `tile::draw_run`).
pub(crate) trait PixelShader: Sync {
    fn shade(&self, t: &Triangle, x: F8, y: f32) -> [u32; LANES];
}

/// A shading's colour at eight pixels before texturing, given w there.
pub(crate) trait Colour: Sync {
    fn colour(&self, t: &Triangle, x: F8, y: f32, w: F8) -> V8;
}

/// What the texture does to a colour: nothing, or modulate it by the texel.
pub(crate) trait Texturing: Sync {
    fn modulate(&self, colour: V8, t: &Triangle, x: F8, y: f32, w: F8) -> V8;
}

/// A shading and a texturing, packed as the target stores them.
pub(crate) struct Shaded<C, T> {
    pub colour: C,
    pub texturing: T,
}

impl<C: Colour, T: Texturing> PixelShader for Shaded<C, T> {
    #[inline(always)]
    fn shade(&self, t: &Triangle, x: F8, y: f32) -> [u32; LANES] {
        // Unused (flat colour, no texture), the division is compiled away.
        let w = w(t, x, y);
        let colour = self.colour.colour(t, x, y, w);
        pack8(self.texturing.modulate(colour, t, x, y, w))
    }
}

/// The user's colour, unlit.
pub(crate) struct Flat(pub Vec3);

impl Colour for Flat {
    #[inline(always)]
    fn colour(&self, _: &Triangle, _: F8, _: f32, _: F8) -> V8 {
        V8::splat(self.0)
    }
}

/// No texture.
pub(crate) struct Untextured;

impl Texturing for Untextured {
    #[inline(always)]
    fn modulate(&self, colour: V8, _: &Triangle, _: F8, _: f32, _: F8) -> V8 {
        colour
    }
}

/// The colour times the texel at the pixel's texture coordinates.
pub(crate) struct Textured<'a, F> {
    pub mips: &'a Mips,
    pub filter: F,
}

impl<F: Filter> Texturing for Textured<'_, F> {
    #[inline(always)]
    fn modulate(&self, colour: V8, t: &Triangle, x: F8, y: f32, w: F8) -> V8 {
        let (s, tt) = texture_coordinates(t, x, y, w);
        let texel = self
            .filter
            .sample(self.mips, s, tt, || self.lod(t, x, y, s, tt));
        V8 {
            x: colour.x * texel.x,
            y: colour.y * texel.y,
            z: colour.z * texel.z,
        }
    }
}

impl<F> Textured<'_, F> {
    /// log2 of the pixel's footprint in level-0 texels, from the differences of (s, t) across
    /// the pixel's 2×2 quad (its top-left pixel to the one right of it and the one below), as a
    /// GPU takes them: ρ = max(|∂(s,t)/∂x|, |∂(s,t)/∂y|) in texels. Lanes pair up into quads
    /// (eight-pixel groups start at even columns), so the row's own (s, t) give half the quad
    /// and only the quad's other row is computed.
    #[inline(always)]
    fn lod(&self, t: &Triangle, x: F8, y: f32, s: F8, tt: F8) -> F8 {
        let upper_row = ((y - 0.5) as u32).is_multiple_of(2);
        let other_y = if upper_row { y + 1.0 } else { y - 1.0 };
        let (s_other, t_other) = texture_coordinates(t, x, other_y, w(t, x, other_y));
        let ((s0, t0), (s1, t1)) = if upper_row {
            ((s, tt), (s_other, t_other))
        } else {
            ((s_other, t_other), (s, tt))
        };
        let (width, height) = self.mips.size();
        let length = |ds: F8, dt: F8| {
            let (ds, dt) = (ds * F8::splat(width), dt * F8::splat(height));
            (ds * ds + dt * dt).sqrt()
        };
        let across = length(
            quad_right(s0) - quad_left(s0),
            quad_right(t0) - quad_left(t0),
        );
        let down = length(quad_left(s1) - quad_left(s0), quad_left(t1) - quad_left(t0));
        across.max(down).log2()
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

/// Perspective-correct texture coordinates (s, t) at eight pixels, given w there.
#[inline(always)]
fn texture_coordinates(t: &Triangle, x: F8, y: f32, w: F8) -> (F8, F8) {
    (
        at(t, &t.varyings[UV], x, y) * w,
        at(t, &t.varyings[UV + 1], x, y) * w,
    )
}

/// A plane's value at eight pixel centres of one row.
#[inline(always)]
fn at(t: &Triangle, plane: &Plane, x: F8, y: f32) -> F8 {
    let row = plane.a + plane.dady * (y - t.origin[1]);
    (x - F8::splat(t.origin[0])).mul_add(F8::splat(plane.dadx), F8::splat(row))
}

/// Perspective-correct varyings `first..first + 3` at eight pixels, given w there.
#[inline(always)]
fn varying3(t: &Triangle, first: usize, x: F8, y: f32, w: F8) -> V8 {
    let v = |k: usize| at(t, &t.varyings[k], x, y) * w;
    V8 {
        x: v(first),
        y: v(first + 1),
        z: v(first + 2),
    }
}

/// w at eight pixels, from the plane of 1/w.
#[inline(always)]
fn w(t: &Triangle, x: F8, y: f32) -> F8 {
    F8::splat(1.0) / at(t, &t.inv_w, x, y)
}

/// The interpolated intensity times the user's colour.
pub(crate) struct Gouraud {
    pub color: Vec3,
}

impl Colour for Gouraud {
    #[inline(always)]
    fn colour(&self, t: &Triangle, x: F8, y: f32, w: F8) -> V8 {
        multiply(self.color, varying3(t, 0, x, y, w))
    }
}

/// Lit at every pixel from the interpolated eye position and normal.
pub(crate) struct Phong {
    pub color: Vec3,
    pub light: Light,
}

impl Colour for Phong {
    #[inline(always)]
    fn colour(&self, t: &Triangle, x: F8, y: f32, w: F8) -> V8 {
        let (eye, normal) = (varying3(t, 0, x, y, w), varying3(t, 3, x, y, w));
        multiply(self.color, self.light.illumination(eye, normal))
    }
}

/// The user's colour times a light, channel by channel.
#[inline(always)]
fn multiply(color: Vec3, light: V8) -> V8 {
    V8 {
        x: F8::splat(color.x) * light.x,
        y: F8::splat(color.y) * light.y,
        z: F8::splat(color.z) * light.z,
    }
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
    }

    #[test]
    fn a_light_straight_ahead_gives_ambient_plus_diffuse_plus_full_specular() {
        let lighting = Lighting {
            attenuation: [1.0, 0.0, 0.0],
            ..Lighting::default()
        };
        // Eye at the origin looking down -z at a point whose normal faces the eye and the light.
        let light = Light::new(&lighting, Vec3::new(0.0, 0.0, 0.0), Shading::Phong);
        let lit = |light: &Light| {
            let i = light.illumination(V8::splat(Vec3::new(0.0, 0.0, -2.0)), V8::splat(Vec3::Z));
            Vec3::new(i.x.0[0], i.y.0[0], i.z.0[0])
        };
        let i = lit(&light);
        let expected = lighting.ia * lighting.ka + lighting.il * (lighting.kd + lighting.ks);
        assert!(
            (i - expected).abs().max_element() < 1e-6,
            "{i} vs {expected}"
        );
        let ad = Light::new(&lighting, Vec3::ZERO, Shading::GouraudAd);
        let i = lit(&ad);
        let expected = lighting.ia * lighting.ka + lighting.il * lighting.kd;
        assert!((i - expected).abs().max_element() < 1e-6);
    }

    #[test]
    fn a_zero_normal_does_not_make_nan() {
        let light = Light::new(&Lighting::default(), Vec3::ONE, Shading::Phong);
        let i = light.illumination(V8::splat(Vec3::ZERO), V8::splat(Vec3::ZERO));
        assert!(
            [i.x, i.y, i.z]
                .iter()
                .all(|c| c.0.iter().all(|x| x.is_finite()))
        );
    }
}

//! The four shadings, computed as the reference view's shader (reference.wgsl) computes them:
//! the same lighting formula term for term, lit per vertex and interpolated (Gouraud) or lit per
//! pixel from the interpolated eye position and normal (Phong), and the colour written as an
//! 8-bit UNORM target stores it (clamped, rounded to nearest).

use close2gl_core::{Lighting, RenderSettings, Shading};
use glam::Vec3;

use crate::lanes::{F8, LANES, V8};
use crate::setup::{Plane, Triangle, VARYINGS};

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

/// What a vertex carries to the pixels, per shading: nothing (flat colour), the Gouraud
/// intensity, or the eye position and normal (Phong).
pub fn varyings_used(shading: Shading) -> usize {
    match shading {
        Shading::None => 0,
        Shading::GouraudAd | Shading::GouraudAds => 3,
        Shading::Phong => VARYINGS,
    }
}

/// The vertex stage: a vertex's varyings from its eye position and normal.
#[inline(always)]
pub fn vertex_varyings(
    shading: Shading,
    light: &Light,
    eye: Vec3,
    normal: Vec3,
) -> [f32; VARYINGS] {
    match shading {
        Shading::None => [0.0; VARYINGS],
        Shading::GouraudAd | Shading::GouraudAds => {
            let i = light.illumination(V8::splat(eye), V8::splat(normal));
            [i.x.0[0], i.y.0[0], i.z.0[0], 0.0, 0.0, 0.0]
        }
        Shading::Phong => [eye.x, eye.y, eye.z, normal.x, normal.y, normal.z],
    }
}

/// The pixel stage: the colours of eight pixels of a triangle, centred at (x, y). Implementations
/// are inlined into the row loop (see `tile::shade_row`).
pub(crate) trait PixelShader: Sync {
    fn shade(&self, t: &Triangle, x: F8, y: f32) -> [u32; LANES];
}

/// The user's colour, unlit.
pub(crate) struct Flat(pub u32);

impl PixelShader for Flat {
    #[inline(always)]
    fn shade(&self, _: &Triangle, _: F8, _: f32) -> [u32; LANES] {
        [self.0; LANES]
    }
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

impl PixelShader for Gouraud {
    #[inline(always)]
    fn shade(&self, t: &Triangle, x: F8, y: f32) -> [u32; LANES] {
        let light = varying3(t, 0, x, y, w(t, x, y));
        pack8(multiply(self.color, light))
    }
}

/// Lit at every pixel from the interpolated eye position and normal.
pub(crate) struct Phong {
    pub color: Vec3,
    pub light: Light,
}

impl PixelShader for Phong {
    #[inline(always)]
    fn shade(&self, t: &Triangle, x: F8, y: f32) -> [u32; LANES] {
        let w = w(t, x, y);
        let (eye, normal) = (varying3(t, 0, x, y, w), varying3(t, 3, x, y, w));
        pack8(multiply(self.color, self.light.illumination(eye, normal)))
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

/// The flat colour of `settings`, packed.
pub(crate) fn flat_color(settings: &RenderSettings) -> u32 {
    pack(settings.color)
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

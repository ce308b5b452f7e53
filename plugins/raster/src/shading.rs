//! The four shadings, computed as the reference view's shader (reference.wgsl) computes them:
//! the same lighting formula term for term, lit per vertex and interpolated (Gouraud) or lit per
//! pixel from the interpolated eye position and normal (Phong), and the colour written as an
//! 8-bit UNORM target stores it (clamped, rounded to nearest).

use close2gl_core::{Lighting, RenderSettings, Shading};
use glam::Vec3;

use crate::setup::{Triangle, VARYINGS};

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

    /// I = Ia ka + f_att Il (kd max(N·L, 0) + ks max(V·R, 0)^n), in eye space.
    #[inline(always)]
    pub fn illumination(&self, eye: Vec3, normal: Vec3) -> Vec3 {
        let n = safe_normalize(normal);
        let to_light = self.position - eye;
        let d = to_light.length();
        let l = safe_normalize(to_light);
        let v = safe_normalize(-eye);
        let r = -l + 2.0 * n.dot(l) * n;
        let [c0, c1, c2] = self.attenuation;
        let f_att = (1.0 / (c0 + c1 * d + c2 * d * d)).min(1.0);
        let diffuse = self.kd * n.dot(l).max(0.0);
        let specular = if self.ks == 0.0 {
            0.0
        } else {
            self.ks * v.dot(r).max(1e-20).powf(self.shininess)
        };
        self.ambient + f_att * self.intensity * (diffuse + specular)
    }
}

/// Normalises without producing NaN for a zero vector, as the shader's safe_normalize.
#[inline(always)]
fn safe_normalize(x: Vec3) -> Vec3 {
    x * (1.0 / x.dot(x).max(1e-30).sqrt())
}

/// A colour in 0..1 as the RGBA8 bytes a UNORM target stores, packed little-endian.
#[inline(always)]
pub fn pack(rgb: Vec3) -> u32 {
    let byte = |c: f32| (c.clamp(0.0, 1.0) * 255.0 + 0.5) as u32;
    byte(rgb.x) | byte(rgb.y) << 8 | byte(rgb.z) << 16 | 0xff << 24
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
            let i = light.illumination(eye, normal);
            [i.x, i.y, i.z, 0.0, 0.0, 0.0]
        }
        Shading::Phong => [eye.x, eye.y, eye.z, normal.x, normal.y, normal.z],
    }
}

/// The pixel stage: the colour of the pixel centred at (x, y) of a triangle.
pub(crate) trait PixelShader: Sync {
    fn shade(&self, triangle: &Triangle, x: f32, y: f32) -> u32;
}

/// The user's colour, unlit.
pub(crate) struct Flat(pub u32);

impl PixelShader for Flat {
    #[inline(always)]
    fn shade(&self, _: &Triangle, _: f32, _: f32) -> u32 {
        self.0
    }
}

/// Perspective-correct varying k at (x, y), given w there.
#[inline(always)]
fn varying(t: &Triangle, k: usize, x: f32, y: f32, w: f32) -> f32 {
    t.at(&t.varyings[k], x, y) * w
}

/// The interpolated intensity times the user's colour.
pub(crate) struct Gouraud {
    pub color: Vec3,
}

impl PixelShader for Gouraud {
    #[inline(always)]
    fn shade(&self, t: &Triangle, x: f32, y: f32) -> u32 {
        let w = 1.0 / t.at(&t.inv_w, x, y);
        let light = Vec3::new(
            varying(t, 0, x, y, w),
            varying(t, 1, x, y, w),
            varying(t, 2, x, y, w),
        );
        pack(self.color * light)
    }
}

/// Lit at every pixel from the interpolated eye position and normal.
pub(crate) struct Phong {
    pub color: Vec3,
    pub light: Light,
}

impl PixelShader for Phong {
    #[inline(always)]
    fn shade(&self, t: &Triangle, x: f32, y: f32) -> u32 {
        let w = 1.0 / t.at(&t.inv_w, x, y);
        let v = [0, 1, 2, 3, 4, 5].map(|k| varying(t, k, x, y, w));
        let eye = Vec3::new(v[0], v[1], v[2]);
        let normal = Vec3::new(v[3], v[4], v[5]);
        pack(self.color * self.light.illumination(eye, normal))
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
        let i = light.illumination(Vec3::new(0.0, 0.0, -2.0), Vec3::Z);
        let expected = lighting.ia * lighting.ka + lighting.il * (lighting.kd + lighting.ks);
        assert!(
            (i - expected).abs().max_element() < 1e-6,
            "{i} vs {expected}"
        );
        let ad = Light::new(&lighting, Vec3::ZERO, Shading::GouraudAd);
        let i = ad.illumination(Vec3::new(0.0, 0.0, -2.0), Vec3::Z);
        let expected = lighting.ia * lighting.ka + lighting.il * lighting.kd;
        assert!((i - expected).abs().max_element() < 1e-6);
    }

    #[test]
    fn a_zero_normal_does_not_make_nan() {
        let light = Light::new(&Lighting::default(), Vec3::ONE, Shading::Phong);
        assert!(light.illumination(Vec3::ZERO, Vec3::ZERO).is_finite());
    }
}

//! Lighting, the lecture's: I = Ia ka + f_att Il (kd max(N·L, 0) + ks max(V·R, 0)^n), with
//! f_att = min(1 / (c0 + c1 d + c2 d²), 1), in eye space (the eye at the origin): the reference
//! shader's formula, term for term; without the specular term for Gouraud AD.

use close2gl_core::{Lighting, RasterMistake as M, RasterMistakes, Shading};
use glam::Vec3;

/// The light of a frame, and the lighting mistakes made with it.
#[derive(Clone, Copy, Debug)]
pub struct Light {
    lighting: Lighting,
    /// Where the light is in eye space; and in the world, where `light_in_world` takes it from.
    eye: Vec3,
    world: Vec3,
    specular: bool,
    mistakes: RasterMistakes,
}

impl Light {
    /// The light of `lighting`, at `eye` in eye space and `world` in the world, for `shading`.
    pub fn new(
        lighting: &Lighting,
        eye: Vec3,
        world: Vec3,
        shading: Shading,
        mistakes: RasterMistakes,
    ) -> Light {
        Light {
            lighting: *lighting,
            eye,
            world,
            specular: shading.specular() && !mistakes.has(M::NoSpecular),
            mistakes,
        }
    }

    /// The intensity at `eye` (eye space) with normal `normal`.
    pub fn illuminate(&self, eye: Vec3, normal: Vec3) -> Vec3 {
        let (k, has) = (&self.lighting, |m| self.mistakes.has(m));
        // Normalised without a NaN for a zero vector, as the shader's safe_normalize.
        let unit = |v: Vec3| v / v.dot(v).max(1e-30).sqrt();
        let light = if has(M::LightInWorld) {
            self.world
        } else {
            self.eye
        };
        let n = if has(M::NormalNotRenormalized) {
            normal
        } else {
            unit(normal)
        };
        let to_light = light - eye;
        let l = unit(to_light);
        let v = if has(M::ViewerAtInfinity) {
            Vec3::Z
        } else {
            unit(-eye)
        };
        let clamp = |x: f32, unclamped: bool| if unclamped { x } else { x.max(0.0) };
        let diffuse = k.kd * clamp(n.dot(l), has(M::DiffuseUnclamped));
        let highlight = match has(M::BlinnPhong) {
            true => n.dot(unit(l + v)),
            false => v.dot(2.0 * n.dot(l) * n - l),
        };
        let ks = if self.specular { k.ks } else { 0.0 };
        let specular = ks * clamp(highlight, has(M::SpecularUnclamped)).powf(k.shininess);
        let ([c0, c1, c2], d) = (k.attenuation, to_light.length());
        let f_att = match has(M::NoAttenuation) {
            true => 1.0,
            false => (1.0 / (c0 + c1 * d + c2 * d * d)).min(1.0),
        };
        k.ia * k.ka + k.il * f_att * (diffuse + specular)
    }
}

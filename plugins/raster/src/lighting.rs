//! Lighting, computed as the reference view's shader (reference.wgsl) computes it: the same
//! formula term for term, in eye space, for eight points at once. Gouraud lights each vertex
//! with it (the vertex stage), Phong each pixel (the pixel shader).

use close2gl_core::{Lighting, Shading};
use glam::Vec3;

use crate::lanes::{F8, V8};

/// The lighting constants of a frame, with the light in eye space.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Light {
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
    pub(crate) fn new(lighting: &Lighting, light_eye: Vec3, shading: Shading) -> Light {
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

#[cfg(test)]
mod tests {
    use super::*;

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

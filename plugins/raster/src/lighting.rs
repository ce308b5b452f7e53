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
    /// Whether f_att may fall below 1 somewhere this frame; when it cannot (see
    /// [`Light::reaching`]), its distance and division are skipped, the same 1 either way.
    pub attenuated: bool,
}

impl Light {
    pub(crate) fn new(lighting: &Lighting, light_eye: Vec3, shading: Shading) -> Light {
        let specular = shading.specular();
        Light {
            position: light_eye,
            ambient: lighting.ia * lighting.ka,
            intensity: lighting.il,
            kd: lighting.kd,
            ks: if specular { lighting.ks } else { 0.0 },
            shininess: lighting.shininess,
            attenuation: lighting.attenuation,
            attenuated: true,
        }
    }

    /// The light for a frame whose points are all within `farthest` of it. f_att is 1 wherever
    /// c0 + c1 d + c2 d² <= 1; when that holds at twice `farthest`, a margin far beyond the
    /// rounding of interpolation, it is 1 everywhere and its arithmetic is skipped.
    pub(crate) fn reaching(self, farthest: f32) -> Light {
        let d = 2.0 * farthest;
        let [c0, c1, c2] = self.attenuation;
        // Written so that a NaN or infinite distance keeps the attenuation.
        let always_one = c0 + c1 * d + c2 * d * d <= 1.0;
        Light {
            attenuated: !always_one,
            ..self
        }
    }

    /// I = Ia ka + f_att Il (kd max(N·L, 0) + ks max(V·R, 0)^n), in eye space, for eight
    /// points at once.
    #[inline(always)]
    pub(crate) fn illumination(&self, eye: V8, normal: V8) -> V8 {
        let zero = F8::splat(0.0);
        let n = safe_normalize(normal);
        let to_light = V8::splat(self.position).sub(eye);
        let l = safe_normalize(to_light);
        let v = safe_normalize(eye.scale(F8::splat(-1.0)));
        let n_dot_l = n.dot(l);
        // r = reflect(-l, n) = 2 (n·l) n - l.
        let r = n.scale(F8::splat(2.0) * n_dot_l).sub(l);
        let diffuse = F8::splat(self.kd) * n_dot_l.max(zero);
        let specular = F8::splat(self.ks) * v.dot(r).max(F8::splat(1e-20)).pow(self.shininess);
        let lit = diffuse + specular;
        let lit = if self.attenuated {
            self.f_att(to_light) * lit
        } else {
            lit
        };
        let channel =
            |ambient: f32, intensity: f32| F8::splat(ambient) + F8::splat(intensity) * lit;
        V8 {
            x: channel(self.ambient.x, self.intensity.x),
            y: channel(self.ambient.y, self.intensity.y),
            z: channel(self.ambient.z, self.intensity.z),
        }
    }

    /// min(1 / (c0 + c1 d + c2 d²), 1), d the distance to the light.
    #[inline(always)]
    fn f_att(&self, to_light: V8) -> F8 {
        let d2 = to_light.dot(to_light);
        let d = d2.sqrt();
        let [c0, c1, c2] = self.attenuation.map(F8::splat);
        (F8::splat(1.0) / (c0 + c1 * d + c2 * d2)).min(F8::splat(1.0))
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
    fn attenuation_is_skipped_only_where_it_is_one_everywhere() {
        // c = (0.01, 0.001, 0): f_att is 1 up to d = 990, so up to a farthest point at 495.
        let lighting = Lighting {
            attenuation: [0.01, 0.001, 0.0],
            ..Lighting::default()
        };
        let light = Light::new(&lighting, Vec3::ZERO, Shading::Phong);
        assert!(!light.reaching(490.0).attenuated);
        for far in [500.0, f32::INFINITY, f32::NAN] {
            assert!(light.reaching(far).attenuated, "{far}");
        }
        let skipped = light.reaching(490.0);
        let eye = V8 {
            x: F8::ramp(-3.0),
            y: F8::splat(2.0),
            z: F8::ramp(-400.0),
        };
        let normal = V8::splat(Vec3::new(0.3, 0.4, 1.0));
        let (a, b) = (
            light.illumination(eye, normal),
            skipped.illumination(eye, normal),
        );
        assert_eq!([a.x, a.y, a.z], [b.x, b.y, b.z]);
        // Beyond d = 990 the light does fade, and the attenuated light says so.
        let far = V8::splat(Vec3::new(0.0, 0.0, -2000.0));
        let faded = light.illumination(far, V8::splat(Vec3::Z)).x.0[0];
        let full = skipped.illumination(far, V8::splat(Vec3::Z)).x.0[0];
        assert!(faded < full, "{faded} vs {full}");
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

//! The outside view's stage morph: where a world point is drawn at a stage between world
//! coordinates (0), eye coordinates (1: M applied, the camera at the origin looking down -z) and
//! normalised device coordinates (2: P applied and divided, the view volume become the cube).
//! Between two stops the point moves on the straight line joining its two positions, so the
//! morph is continuous. Everything the outside view draws (the model, the volume, the camera's
//! gizmo) goes through [`StageMorph::place`], so they morph together.

use close2gl_core::Camera;
use glam::{Vec3, Vec4};

use crate::frustum::world_corners;
use crate::matrices::ClipTransform;

/// How far from the cube a divided point may be drawn, in cube half-widths: a point with w near
/// 0 divides to near infinity, and the outside camera needs finite numbers.
const NDC_LIMIT: f32 = 1e3;

/// How far from the cube's centre the outside view shows what the division threw, in cube
/// half-widths: a point just in front of or behind the eye (w near 0) lands arbitrarily far
/// away, and its triangles would fill the view and hide the cube.
pub const SHOWN_LIMIT: f32 = 2.0;

/// A point as the outside view draws it at one stage.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Placed {
    /// Where it is drawn, in the outside view's coordinates.
    pub position: Vec3,
    /// Its clip coordinates P·M·p, from the pipeline's own transform: inside the view volume
    /// exactly when |x|, |y|, |z| <= w.
    pub clip: Vec4,
    /// Past the eye stage with w <= 0 (at or behind the eye): the division throws it to the
    /// wrong side, and the outside view draws it in its warning colour.
    pub behind_eye: bool,
    /// Past the eye stage, divided to more than [`SHOWN_LIMIT`] cube half-widths away.
    pub thrown_far: bool,
}

/// Whether the segment or triangle with these corners has an image to show at its stage. Past
/// the eye stage, one with corners on both sides of w = 0 has none (its edges pass through
/// infinity, where the division sends w = 0), nor has one with a corner thrown beyond
/// [`SHOWN_LIMIT`].
pub fn has_image(corners: &[Placed]) -> bool {
    let behind = corners.iter().filter(|c| c.behind_eye).count();
    (behind == 0 || behind == corners.len()) && !corners.iter().any(|c| c.thrown_far)
}

/// The stage morph for one camera. World positions are drawn relative to `origin` (the model's
/// centre: small numbers for a model far from the world's origin); the NDC cube is drawn
/// `ndc_scale` times its size, so that it fills the outside view as the world did. NDC is
/// left-handed (z = -1 is the near plane): its z is drawn negated, so that the near face stays
/// towards the eye throughout the morph.
#[derive(Clone, Copy, Debug)]
pub struct StageMorph {
    transform: ClipTransform,
    origin: Vec3,
    ndc_scale: f32,
    stage: f32,
}

impl StageMorph {
    pub fn new(camera: &Camera, frame: &OutsideFraming, stage: f32) -> Self {
        Self {
            transform: ClipTransform::new(camera),
            origin: frame.origin,
            ndc_scale: frame.ndc_scale(),
            stage: stage.clamp(0.0, 2.0),
        }
    }

    /// Where the world point `p` is drawn at this stage.
    pub fn place(&self, p: Vec3) -> Placed {
        let clip = self.transform.apply(p);
        let eye = self.transform.eye(p);
        let divided = self.stage > 1.0;
        let (position, thrown_far) = if divided {
            let ndc = self.ndc(clip);
            let far = ndc.abs().max_element() > SHOWN_LIMIT * self.ndc_scale;
            (eye.lerp(ndc, self.stage - 1.0), far)
        } else {
            ((p - self.origin).lerp(eye, self.stage), false)
        };
        Placed {
            position,
            clip,
            behind_eye: divided && clip.w <= 0.0,
            thrown_far,
        }
    }

    /// The divided point (x, y, -z)/w, scaled to the drawn cube. A w of exactly 0 divides as the
    /// smallest positive w, and the result is kept within `NDC_LIMIT` cube half-widths.
    pub fn ndc(&self, clip: Vec4) -> Vec3 {
        let w = if clip.w == 0.0 {
            f32::MIN_POSITIVE
        } else {
            clip.w
        };
        let divided = Vec3::new(clip.x, clip.y, -clip.z) / w;
        divided.clamp(Vec3::splat(-NDC_LIMIT), Vec3::splat(NDC_LIMIT)) * self.ndc_scale
    }

    /// The stage's own mix of three positions given per stop (a framing centre, say).
    pub fn blend(&self, [world, eye, ndc]: [Vec3; 3]) -> Vec3 {
        if self.stage <= 1.0 {
            world.lerp(eye, self.stage)
        } else {
            eye.lerp(ndc, self.stage - 1.0)
        }
    }
}

/// How far beyond the model's farthest point from the eye the far plane may lie before the
/// outside view draws it faded: past that it only marks where the volume ends, far from what
/// is clipped.
pub const FAR_FADED_BEYOND: f32 = 2.0;

/// What the outside camera frames: one sphere around the model, the eye and the near plane (the
/// part of the view volume that clips the model: its side planes run through the model, in the
/// frame), so that the model fills a good part of the view; or, asked for, around the whole view
/// volume, far plane included (a far plane hundreds of times farther than the model shrinks the
/// model to a dot there). At the eye stage it is the same sphere moved by M; at the NDC stage the
/// cube is drawn to the same radius, so the framing never jumps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OutsideFraming {
    /// The model's centre: world positions are drawn relative to it.
    pub origin: Vec3,
    /// The sphere's centre at the world, eye and NDC stops, in drawn coordinates.
    pub centres: [Vec3; 3],
    pub radius: f32,
    /// The far plane lies more than [`FAR_FADED_BEYOND`] times the model's farthest distance
    /// from the eye: drawn faded.
    pub far_faded: bool,
}

impl OutsideFraming {
    /// The model, the eye and the near plane, seen by `camera`; the model's bounds `(lo, hi)`.
    pub fn new(camera: &Camera, bounds: (Vec3, Vec3)) -> Self {
        Self::framing(camera, bounds, false)
    }

    /// The whole view volume with the model and the eye.
    pub fn whole_volume(camera: &Camera, bounds: (Vec3, Vec3)) -> Self {
        Self::framing(camera, bounds, true)
    }

    fn framing(camera: &Camera, (lo, hi): (Vec3, Vec3), whole_volume: bool) -> Self {
        let origin = (lo + hi) * 0.5;
        let corners = world_corners(camera);
        let eye = camera.position;
        let (near, far) = corners.split_at(4);
        let far = if whole_volume { far } else { &[] };
        let points = near.iter().chain(far).chain([&lo, &hi, &eye]);
        let (min, max) = points.fold((Vec3::INFINITY, Vec3::NEG_INFINITY), |(a, b), p| {
            (a.min(*p - origin), b.max(*p - origin))
        });
        let centre = (min + max) * 0.5;
        let radius = ((max - min).length() * 0.5).max(f32::MIN_POSITIVE);
        let eye_centre = ClipTransform::new(camera).eye(centre + origin);
        let model_reach = [lo, hi]
            .map(|p| (p - eye).length())
            .into_iter()
            .fold(0.0, f32::max);
        Self {
            origin,
            centres: [centre, eye_centre, Vec3::ZERO],
            radius,
            far_faded: camera.far > FAR_FADED_BEYOND * model_reach,
        }
    }

    /// The drawn cube's half-width: its corners lie on the frame's sphere.
    pub fn ndc_scale(&self) -> f32 {
        self.radius / 3f32.sqrt()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::frustum::NDC_CORNERS;

    fn scene() -> (Camera, (Vec3, Vec3)) {
        let centre = Vec3::new(440.0, -224.0, 63.0);
        let camera = Camera {
            hfov: 70.0,
            vfov: 40.0,
            near: 900.0,
            far: 5000.0,
            ..Camera::default()
        }
        .looking_at(centre + Vec3::new(800.0, 300.0, 1200.0), centre, Vec3::Y)
        .expect("a valid pose");
        (camera, (centre - 600.0, centre + 600.0))
    }

    /// Points spread over the model's box and well beyond it, behind the eye included.
    fn points((lo, hi): (Vec3, Vec3)) -> impl Iterator<Item = Vec3> {
        let size = hi - lo;
        (0..4000u32).map(move |i| {
            let f = |k: u32| ((i.wrapping_mul(k) % 1009) as f32 / 1009.0) * 5.0 - 2.0;
            lo + size * Vec3::new(f(7919), f(104_729), f(15_485_863))
        })
    }

    #[test]
    fn at_the_ndc_stage_every_point_inside_the_view_volume_lands_inside_the_cube() {
        let (camera, bounds) = scene();
        let frame = OutsideFraming::new(&camera, bounds);
        let morph = StageMorph::new(&camera, &frame, 2.0);
        let half = frame.ndc_scale() * (1.0 + 1e-5);
        let (mut inside, mut outside) = (0, 0);
        for p in points(bounds) {
            let placed = morph.place(p);
            let c = placed.clip;
            let in_volume = c.x.abs() <= c.w && c.y.abs() <= c.w && c.z.abs() <= c.w;
            let in_cube = placed.position.abs().max_element() <= half;
            if in_volume {
                inside += 1;
                assert!(in_cube, "{p} -> {}", placed.position);
            } else {
                outside += 1;
                // In front of the eye, outside the volume is outside the cube; behind it, the
                // division may throw a point anywhere, the cube included: that is the warning.
                let edge = frame.ndc_scale() * (1.0 - 1e-5);
                assert!(
                    c.w <= 0.0 || placed.position.abs().max_element() >= edge,
                    "{p}"
                );
            }
            assert_eq!(placed.behind_eye, c.w <= 0.0);
        }
        assert!(
            inside > 100 && outside > 100,
            "{inside} inside, {outside} outside"
        );
    }

    #[test]
    fn the_volume_becomes_the_cube_with_its_near_face_towards_the_eye() {
        let (camera, bounds) = scene();
        let frame = OutsideFraming::new(&camera, bounds);
        let morph = StageMorph::new(&camera, &frame, 2.0);
        for (corner, [x, y, z]) in world_corners(&camera).iter().zip(NDC_CORNERS) {
            let drawn = morph.place(*corner).position / frame.ndc_scale();
            let expected = Vec3::new(x, y, -z);
            assert!(
                (drawn - expected).abs().max_element() < 1e-3,
                "{drawn} != {expected}"
            );
        }
    }

    #[test]
    fn the_stops_are_world_eye_and_ndc_and_the_morph_is_continuous() {
        let (camera, bounds) = scene();
        let frame = OutsideFraming::new(&camera, bounds);
        let transform = ClipTransform::new(&camera);
        let p = bounds.0 + Vec3::new(100.0, 700.0, 300.0);
        let at = |stage| StageMorph::new(&camera, &frame, stage).place(p).position;
        assert_eq!(at(0.0), p - frame.origin);
        assert_eq!(at(1.0), transform.eye(p));
        let clip = transform.apply(p);
        let ndc = Vec3::new(clip.x, clip.y, -clip.z) / clip.w * frame.ndc_scale();
        assert!((at(2.0) - ndc).length() < 1e-3 * frame.radius);
        for stop in [1.0f32, 2.0] {
            let (before, after) = (at(stop - 1e-4), at(stop));
            assert!((before - after).length() < 1e-2 * frame.radius, "{stop}");
        }
    }

    #[test]
    fn the_frame_holds_the_model_the_volume_and_the_eye() {
        let (camera, bounds) = scene();
        // A far plane near the model (about 2,100 from the eye): not faded.
        let camera = Camera {
            far: 3000.0,
            ..camera
        };
        let inside = |frame: &OutsideFraming, p: Vec3| {
            (p - frame.origin - frame.centres[0]).length() <= frame.radius * 1.0001
        };
        let corners = world_corners(&camera);
        for (frame, framed) in [
            (OutsideFraming::new(&camera, bounds), &corners[..4]),
            (OutsideFraming::whole_volume(&camera, bounds), &corners[..]),
        ] {
            assert!(framed.iter().all(|c| inside(&frame, *c)));
            assert!([camera.position, bounds.0, bounds.1].map(|p| inside(&frame, p)) == [true; 3]);
            assert!(!frame.far_faded, "the far plane is near the model");
        }
    }

    #[test]
    fn a_far_plane_far_beyond_the_model_does_not_shrink_it_to_a_dot_unless_asked() {
        let (camera, bounds) = scene();
        let model = (bounds.1 - bounds.0).length() * 0.5;
        let far_away = Camera {
            far: camera.far * 100.0,
            ..camera
        };
        let frame = OutsideFraming::new(&far_away, bounds);
        let inside = |frame: &OutsideFraming, p: Vec3| {
            (p - frame.origin - frame.centres[0]).length() <= frame.radius * 1.0001
        };
        let corners = world_corners(&far_away);
        assert!(
            corners[..4].iter().all(|c| inside(&frame, *c)),
            "the near face"
        );
        assert!([bounds.0, bounds.1, camera.position].map(|p| inside(&frame, p)) == [true; 3]);
        assert!(
            frame.radius < 3.0 * model,
            "the model is a third of the frame or more: {} vs {model}",
            frame.radius
        );
        let nearer = OutsideFraming::new(&camera, bounds);
        assert!(
            (frame.radius - nearer.radius).abs() < 1e-4 * frame.radius,
            "framed as with the scene's own far plane"
        );
        assert!(frame.far_faded);
        let whole = OutsideFraming::whole_volume(&far_away, bounds);
        assert!(
            corners.iter().all(|c| inside(&whole, *c)),
            "the far face too"
        );
    }

    #[test]
    fn past_the_eye_stage_a_triangle_across_w_0_has_no_image() {
        let (camera, bounds) = scene();
        let frame = OutsideFraming::new(&camera, bounds);
        let target = frame.origin;
        let corners = [
            target,
            target + camera.u * 50.0,
            camera.position + camera.n * 100.0,
        ];
        for (stage, expected) in [(0.0, true), (1.0, true), (1.01, false), (2.0, false)] {
            let morph = StageMorph::new(&camera, &frame, stage);
            let placed = corners.map(|c| morph.place(c));
            assert_eq!(has_image(&placed), expected, "stage {stage}");
        }
        let in_front = StageMorph::new(&camera, &frame, 2.0);
        assert!(has_image(
            &corners[..2]
                .iter()
                .map(|c| in_front.place(*c))
                .collect::<Vec<_>>()
        ));
    }

    #[test]
    fn a_point_on_the_eye_plane_stays_finite() {
        let (camera, bounds) = scene();
        let frame = OutsideFraming::new(&camera, bounds);
        let morph = StageMorph::new(&camera, &frame, 2.0);
        let placed = morph.place(camera.position + camera.u * 10.0);
        assert!(placed.position.is_finite() && placed.behind_eye && placed.thrown_far);
    }
}

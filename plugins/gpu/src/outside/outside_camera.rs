//! The outside view's own camera: it orbits the centre of what the stage frames (the model, the
//! view volume and the eye), from the yaw, pitch and zoom of `OutsideOrbit`. Its matrices come
//! from glam: the outside view is an illustration, not one of the two pipelines compared.

use close2gl_core::OutsideOrbit;
use close2gl_pipeline::morph::OutsideFraming;
use glam::camera::rh::proj::directx::perspective;
use glam::camera::rh::view::look_at_mat4;
use glam::{Mat4, Vec3};

use super::outside_scene::Billboard;

/// The outside camera's vertical field of view.
const FOV_DEGREES: f32 = 40.0;

/// Where the outside camera is and what it sees, for one stage and one view size.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OutsideCamera {
    pub eye: Vec3,
    pub target: Vec3,
    pub view: Mat4,
    pub projection: Mat4,
}

impl OutsideCamera {
    /// The camera for `orbit` around the stage's framing centre `target` (the frame's centres
    /// blended as the stage blends them), for a view `aspect` (width / height) wide: the frame's
    /// sphere just fits at zoom 1.
    pub fn new(orbit: &OutsideOrbit, frame: &OutsideFraming, target: Vec3, aspect: f32) -> Self {
        let half = (FOV_DEGREES.to_radians() * 0.5).tan();
        let narrowest = half.min(half * aspect);
        let distance = frame.radius / narrowest.atan().sin() * orbit.zoom;
        let eye = target + direction(orbit) * distance.max(f32::MIN_POSITIVE);
        let view = look_at_mat4(eye, target, Vec3::Y);
        // The scene reaches a radius past the target, and what the division throws beyond it is
        // cut by the far plane rather than squeezing the depth range.
        let far = distance + frame.radius * 4.0;
        let near = (distance - frame.radius * 2.0).max(far * 1e-4);
        let projection = perspective(FOV_DEGREES.to_radians(), aspect, near, far);
        Self {
            eye,
            target,
            view,
            projection,
        }
    }

    pub fn view_projection(&self) -> Mat4 {
        self.projection * self.view
    }

    /// The camera's right and up directions, which the gizmo's letters face.
    pub(crate) fn billboard(orbit: &OutsideOrbit) -> Billboard {
        let forward = -direction(orbit);
        let right = forward.cross(Vec3::Y).normalize();
        Billboard {
            right,
            up: right.cross(forward),
        }
    }
}

/// From the target towards the camera.
fn direction(orbit: &OutsideOrbit) -> Vec3 {
    let (sin_yaw, cos_yaw) = orbit.yaw.sin_cos();
    let (sin_pitch, cos_pitch) = orbit.pitch.sin_cos();
    Vec3::new(cos_pitch * sin_yaw, sin_pitch, cos_pitch * cos_yaw)
}

#[cfg(test)]
mod tests {
    use close2gl_core::Camera;

    use super::*;

    /// How much of the outside view's height the model's bounding box covers, as the default
    /// orbit and `frame` see it at the world stage, in a view `aspect` wide.
    fn box_height(frame: &OutsideFraming, (lo, hi): (Vec3, Vec3), aspect: f32) -> f32 {
        let outside = OutsideCamera::new(&OutsideOrbit::default(), frame, frame.centres[0], aspect);
        let ys = (0..8).map(|i| {
            let corner = Vec3::select(glam::BVec3::new(i & 1 != 0, i & 2 != 0, i & 4 != 0), hi, lo);
            let clip = outside.view_projection() * (corner - frame.origin).extend(1.0);
            clip.y / clip.w
        });
        let (low, high) = ys.fold((f32::INFINITY, f32::NEG_INFINITY), |(a, b), y| {
            (a.min(y), b.max(y))
        });
        (high - low) / 2.0
    }

    /// The cow (about 1500 units long, near 359, far 8617 as its framing chose) and
    /// `far_away.in`'s 1200-unit model 500 units out: by default the model covers a quarter of
    /// the outside view's height or more in a view 4:3 or wider (its own window in the windows
    /// layout); framing the whole volume it is smaller. The split layout's third column at
    /// 1366x768 is narrow (0.47:1): there the sphere fits its width, and the long cow covers
    /// about a fifth of the height.
    #[test]
    fn the_default_framing_shows_the_model_over_a_quarter_of_the_view_height() {
        let cow = (
            Vec3::new(-750.0, -300.0, -200.0),
            Vec3::new(750.0, 300.0, 200.0),
        );
        let cow_camera = Camera {
            near: 359.0,
            far: 8617.0,
            ..Camera::default()
        }
        .looking_at(Vec3::new(300.0, 200.0, 1800.0), Vec3::ZERO, Vec3::Y);
        let centre = Vec3::new(440.0, -224.0, 63.0);
        let far_away = (centre - 600.0, centre + 600.0);
        let far_away_camera = Camera {
            near: 519.62,
            far: 12470.77,
            ..Camera::default()
        }
        .looking_at(Vec3::new(440.0, -224.0, 2141.46), centre, Vec3::Y);
        for (bounds, camera) in [(cow, cow_camera), (far_away, far_away_camera)] {
            let camera = camera.expect("a valid pose");
            for aspect in [4.0 / 3.0, 16.0 / 9.0] {
                let framed = box_height(&OutsideFraming::new(&camera, bounds), bounds, aspect);
                assert!(framed >= 0.25, "{framed} of the height at aspect {aspect}");
                let whole = box_height(
                    &OutsideFraming::whole_volume(&camera, bounds),
                    bounds,
                    aspect,
                );
                assert!(whole < framed, "{whole} vs {framed}");
            }
        }
    }
}

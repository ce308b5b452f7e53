//! The outside view's own camera: it orbits the centre of what the stage frames (the model, the
//! view volume and the eye), from the yaw, pitch and zoom of `OutsideOrbit`. Its matrices come
//! from glam: the outside view is an illustration, not one of the two pipelines compared.

use close2gl_core::OutsideOrbit;
use close2gl_pipeline::morph::StageFrame;
use glam::camera::rh::proj::directx::perspective;
use glam::camera::rh::view::look_at_mat4;
use glam::{Mat4, Vec3};

use super::scene::Billboard;

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
    pub fn new(orbit: &OutsideOrbit, frame: &StageFrame, target: Vec3, aspect: f32) -> Self {
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

//! The assignment's camera (u, v, n, hfov, vfov, near, far), its mode and speeds, and the
//! actions that move it.

use bevy_ecs::prelude::*;
use glam::Vec3;

use crate::limits::DEFAULT_FOV;

/// The virtual camera of the assignment: a centre of projection, an orthonormal right-handed
/// frame (u right, v up, n pointing backwards, away from what it sees), the two fields of view
/// in degrees and the clipping distances. `target` is the look-at point: on the -n axis, at the
/// distance orbiting keeps.
#[derive(Component, Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    pub position: Vec3,
    pub u: Vec3,
    pub v: Vec3,
    pub n: Vec3,
    pub target: Vec3,
    pub hfov: f32,
    pub vfov: f32,
    pub near: f32,
    pub far: f32,
    pub mode: CameraMode,
}

impl Default for Camera {
    /// The assignment's initial camera: at the origin, u = x, v = y, n = z, both fields of view
    /// [`DEFAULT_FOV`] (60°).
    fn default() -> Self {
        Self {
            position: Vec3::ZERO,
            u: Vec3::X,
            v: Vec3::Y,
            n: Vec3::Z,
            target: Vec3::NEG_Z,
            hfov: DEFAULT_FOV,
            vfov: DEFAULT_FOV,
            near: 0.1,
            far: 100.0,
            mode: CameraMode::Free,
        }
    }
}

impl Camera {
    /// Re-aims the camera at `target` from `position`, keeping `up` as close to v as it can.
    /// An `up` within `PARALLEL_UP` of the view direction (or zero) gives no sideways
    /// direction, so +y stands in for it, or -z when the view itself is along y (looking down,
    /// the top of the image points to -z): the frame is always orthonormal. Returns `None` only
    /// when there is no view direction: the target on the camera, or a coordinate not finite.
    pub fn looking_at(mut self, position: Vec3, target: Vec3, up: Vec3) -> Option<Self> {
        if !(position.is_finite() && target.is_finite() && up.is_finite()) {
            return None;
        }
        // Halved, the difference of two finite points cannot overflow.
        let n =
            direction(position - target).or_else(|| direction(position * 0.5 - target * 0.5))?;
        let across = |up: Vec3| {
            let u = direction(up)?.cross(n);
            // Gram–Schmidt: what rounding left of n in the cross product goes.
            (u.length() > PARALLEL_UP).then(|| (u - n * n.dot(u)).normalize())
        };
        let u = across(up)
            .or_else(|| across(Vec3::Y))
            .or_else(|| across(Vec3::NEG_Z))?;
        self.position = position;
        self.target = target;
        self.n = n;
        self.u = u;
        self.v = n.cross(u);
        Some(self)
    }

    /// Distance from the centre of projection to the look-at point.
    pub fn distance(&self) -> f32 {
        self.position.distance(self.target)
    }
}

/// The sine of the smallest angle between `up` and the view direction that
/// [`Camera::looking_at`] takes: about 0.06°. Closer, the cross product that gives u is mostly
/// rounding, and u would not be square to n.
pub const PARALLEL_UP: f32 = 1e-3;

/// `v` as a unit vector, however small it is; `None` when it is zero or not finite.
fn direction(v: Vec3) -> Option<Vec3> {
    v.try_normalize().or_else(|| {
        let largest = v.abs().max_element();
        (largest > 0.0 && largest.is_finite()).then(|| (v / largest).normalize())
    })
}

named_enum!(
    /// How translations and mouse drags move the camera.
    CameraMode {
        /// Translate along u, v, n; rotate about them.
        Free = "free",
        /// Keep the look-at point fixed: sideways moves orbit it, forward moves approach it.
        LookAt = "look_at"
    }
);

/// The framed pose the camera returns to on reset (set when a model loads).
#[derive(Component, Clone, Copy, Debug, PartialEq)]
pub struct CameraHome(pub Camera);

/// How fast input moves the camera. Translations scale with the model's size, so a 2-unit cube
/// and a 1200-unit cow feel the same.
#[derive(Resource, Clone, Copy, Debug, PartialEq)]
pub struct CameraSpeeds {
    /// Model radii per second while a move key is held.
    pub move_speed: f32,
    /// Degrees per pixel of mouse drag, and degrees per second × 60 for held rotate keys.
    pub rotate_speed: f32,
    /// Radius of the loaded model's bounding sphere: the unit `move_speed` is measured in.
    pub model_radius: f32,
}

impl Default for CameraSpeeds {
    fn default() -> Self {
        Self {
            move_speed: 1.0,
            rotate_speed: 0.25,
            model_radius: 1.0,
        }
    }
}

/// One request to change the camera; the input system emits them, the camera system applies them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CameraAction {
    /// World units along the camera's own axes (in look-at mode, u and v orbit the target and n
    /// approaches it).
    Translate { u: f32, v: f32, n: f32 },
    /// Radians about the camera's own axes: pitch about u, yaw about v, roll about n (in look-at
    /// mode, pitch and yaw orbit the target).
    Rotate { pitch: f32, yaw: f32, roll: f32 },
    /// Radians around the look-at point, in any mode: yaw about v, pitch about u.
    Orbit { yaw: f32, pitch: f32 },
    /// Multiplies tan(fov/2) of both fields of view (below 1 zooms in).
    Zoom { factor: f32 },
    /// Back to the framed pose.
    Reset,
    /// Free ↔ look-at.
    ToggleMode,
}

/// This frame's camera actions, drained by the camera system.
#[derive(Resource, Default, Debug, Clone)]
pub struct CameraActions(pub Vec<CameraAction>);

/// What other plugins ask of the [`Camera`] during a frame. The camera plugin, the component's
/// one writer inside a frame, applies it in `FrameSet::Camera`, so that whoever asks before that
/// set sees the camera it asked for drawn in the same frame.
#[derive(Resource, Clone, Copy, Debug, Default, PartialEq)]
pub struct CameraRequest {
    /// The camera as edited where it stands (the panel's lens, a watched configuration's, a
    /// redraw asked for): set first, before a new model is framed and the frame's actions move
    /// it, as if it had been so when the frame began.
    pub edited: Option<Camera>,
    /// A camera that replaces the frame's (a trace's own): set last, after the framing of a new
    /// model and the actions, so that it is the one this frame draws.
    pub replacement: Option<Camera>,
}

impl CameraRequest {
    /// The camera to edit: the one already asked for this frame, else `current`, so that two
    /// edits made in one frame both land.
    pub fn edit(&mut self, current: &Camera) -> &mut Camera {
        self.edited.get_or_insert(*current)
    }
}

/// An explicit camera pose: where the camera is, what it looks at, and which way is up.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LookAtPose {
    pub position: Vec3,
    pub target: Vec3,
    pub up: Vec3,
    /// The camera's own u, v, n, when given (as a copied view's command gives them): taken as
    /// they are instead of being derived from the target and up, so that the view is
    /// reproduced to the bit.
    pub basis: Option<[Vec3; 3]>,
}

/// What framing a newly loaded model must respect: an explicit pose from the config replaces the
/// framed one, and pinned near/far distances replace the ones that follow the model's size.
#[derive(Resource, Clone, Copy, Debug, Default, PartialEq)]
pub struct Framing {
    pub pose: Option<LookAtPose>,
    pub near: Option<f32>,
    pub far: Option<f32>,
}

/// The next newly loaded mesh leaves the camera where it is (a watched file saved again: the
/// user is looking at a detail and wants to see it change, not to be thrown back to the framed
/// pose). Cleared when a mesh arrives.
#[derive(Resource, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct KeepPose(pub bool);

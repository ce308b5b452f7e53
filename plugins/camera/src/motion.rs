//! Camera moves, all relative to the camera's own frame (Hill's "sliding" and "rotating the
//! camera"): translation along u, v, n; rotation about them; orbiting the look-at point; zoom.

use close2gl_core::limits::FOV_RANGE;
use close2gl_core::{Camera, CameraAction, CameraMode};
use glam::{Quat, Vec3};

/// Applies one action. `home` is the framed pose `Reset` returns to.
pub fn apply(camera: &mut Camera, action: CameraAction, home: Option<&Camera>) {
    match (action, camera.mode) {
        (CameraAction::Translate { u, v, n }, CameraMode::Free) => slide(camera, u, v, n),
        (CameraAction::Translate { u, v, n }, CameraMode::LookAt) => {
            // Sideways moves become arcs of the same length around the look-at point.
            let distance = camera.distance();
            orbit(camera, u / distance, -v / distance);
            approach(camera, n);
        }
        (CameraAction::Rotate { pitch, yaw, roll }, CameraMode::Free) => {
            rotate(camera, camera.u, pitch);
            rotate(camera, camera.v, yaw);
            rotate(camera, camera.n, roll);
            camera.target = camera.position - camera.n * camera.distance();
        }
        (CameraAction::Rotate { pitch, yaw, roll }, CameraMode::LookAt) => {
            orbit(camera, yaw, pitch);
            rotate(camera, camera.n, roll);
        }
        (CameraAction::Orbit { yaw, pitch }, _) => orbit(camera, yaw, pitch),
        (CameraAction::Zoom { factor }, _) => zoom(camera, factor),
        (CameraAction::Reset, _) => {
            if let Some(home) = home {
                camera.position = home.position;
                camera.target = home.target;
                (camera.u, camera.v, camera.n) = (home.u, home.v, home.n);
            }
        }
        (CameraAction::ToggleMode, mode) => {
            camera.mode = match mode {
                CameraMode::Free => CameraMode::LookAt,
                CameraMode::LookAt => CameraMode::Free,
            }
        }
    }
}

/// pos = pos + k·axis: the look-at point travels along, so it stays in front.
fn slide(camera: &mut Camera, u: f32, v: f32, n: f32) {
    let step = camera.u * u + camera.v * v + camera.n * n;
    camera.position += step;
    camera.target += step;
}

/// Turns the frame about `axis` (one of u, v, n) by `angle` radians, keeping it orthonormal.
fn rotate(camera: &mut Camera, axis: Vec3, angle: f32) {
    if angle == 0.0 {
        return;
    }
    let q = Quat::from_axis_angle(axis, angle);
    let n = (q * camera.n).normalize();
    // Gram–Schmidt against n: rounding must not let the frame drift from orthonormal.
    let u = q * camera.u;
    let u = (u - n * n.dot(u)).normalize();
    camera.n = n;
    camera.u = u;
    camera.v = n.cross(u);
}

/// Rotates the camera about the look-at point: yaw about v, pitch about u, distance unchanged.
fn orbit(camera: &mut Camera, yaw: f32, pitch: f32) {
    let distance = camera.distance();
    rotate(camera, camera.v, yaw);
    rotate(camera, camera.u, pitch);
    camera.position = camera.target + camera.n * distance;
}

/// Moves along n towards (negative) or away from the look-at point, never onto or past it.
fn approach(camera: &mut Camera, n: f32) {
    let distance = (camera.distance() + n).max(camera.near * 0.5);
    camera.position = camera.target + camera.n * distance;
}

/// Scales tan(fov/2) of both fields of view, so their ratio (the image's aspect) is kept.
fn zoom(camera: &mut Camera, factor: f32) {
    if !(factor.is_finite() && factor > 0.0) {
        return;
    }
    let scaled = |fov: f32| {
        2.0 * ((fov.to_radians() * 0.5).tan() * factor)
            .atan()
            .to_degrees()
    };
    let (h, v) = (scaled(camera.hfov), scaled(camera.vfov));
    if FOV_RANGE.contains(&h) && FOV_RANGE.contains(&v) {
        (camera.hfov, camera.vfov) = (h, v);
    }
}

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

/// The zoom rule, the one every zoom follows (the scroll wheel's `CameraAction::Zoom`, the
/// panel's locked fields of view): scales tan(fov/2) of both fields of view by `factor`, so that
/// their ratio (the image's aspect) is kept. A zoom that would take either out of `FOV_RANGE` is
/// not made.
pub fn zoom(camera: &mut Camera, factor: f32) {
    if !(factor.is_finite() && factor > 0.0) {
        return;
    }
    let scaled = |fov: f32| 2.0 * (half_tan(fov) * factor).atan().to_degrees();
    let (h, v) = (scaled(camera.hfov), scaled(camera.vfov));
    if FOV_RANGE.contains(&h) && FOV_RANGE.contains(&v) {
        (camera.hfov, camera.vfov) = (h, v);
    }
}

/// The [`zoom`] factor that takes a field of view from `from` to `to` degrees.
pub fn zoom_factor(from: f32, to: f32) -> f32 {
    half_tan(to) / half_tan(from)
}

/// tan(fov/2), `fov` in degrees: what a zoom scales.
fn half_tan(fov: f32) -> f32 {
    (fov.to_radians() * 0.5).tan()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn lens(hfov: f32, vfov: f32) -> Camera {
        Camera {
            hfov,
            vfov,
            ..Camera::default()
        }
    }

    #[test]
    fn a_zoom_to_a_field_of_view_lands_on_it_and_keeps_the_aspect() {
        let mut camera = lens(90.0, 60.0);
        zoom(&mut camera, zoom_factor(60.0, 70.0));
        assert!((camera.vfov - 70.0).abs() < 1e-4, "vfov {}", camera.vfov);
        let aspect = half_tan(camera.hfov) / half_tan(camera.vfov);
        assert!((aspect - half_tan(90.0) / half_tan(60.0)).abs() < 1e-5);
        assert!(
            camera.hfov > 100.5,
            "more than the 10 degrees of vfov: {}",
            camera.hfov
        );
    }

    #[test]
    fn a_zoom_that_would_leave_the_range_is_not_made() {
        let mut camera = lens(165.0, 60.0);
        zoom(&mut camera, zoom_factor(60.0, 90.0));
        assert_eq!((camera.hfov, camera.vfov), (165.0, 60.0));
        zoom(&mut camera, f32::NAN);
        zoom(&mut camera, 0.0);
        assert_eq!((camera.hfov, camera.vfov), (165.0, 60.0));
    }
}

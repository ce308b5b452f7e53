//! "Rendering the object in the centre of the windows": the camera looks at the bounding box's
//! centre from +z, at the distance where the bounding sphere fits both fields of view.

use close2gl_core::{Camera, Framing, LookAtPose};
use glam::Vec3;

/// The framed camera for a model whose bounding sphere is (`centre`, `radius`), keeping the
/// lens (fields of view, mode) of `lens`, honouring an explicit pose and pinned near/far.
pub fn frame(centre: Vec3, radius: f32, lens: &Camera, framing: &Framing) -> Camera {
    // A model that is a single point still gets a usable camera, scaled to where it is.
    let radius = radius.max(1e-6 * (1.0 + centre.abs().max_element()));
    let half_fov = lens.hfov.min(lens.vfov).to_radians() * 0.5;
    let distance = radius / half_fov.sin();

    let LookAtPose {
        position,
        target,
        up,
        basis,
    } = framing.pose.unwrap_or(LookAtPose {
        position: centre + Vec3::Z * distance,
        target: centre,
        up: Vec3::Y,
        basis: None,
    });
    // The clipping planes hug the model as seen from where the camera really is; from inside the
    // model, near shrinks to a small fraction of its size.
    let seen_from = position.distance(centre);
    let lens = Camera {
        near: (0.5 * (seen_from - radius)).max(radius * 1e-3),
        far: 4.0 * (seen_from + radius),
        ..*lens
    };
    let from_plus_z = Camera {
        position: centre + Vec3::Z * distance,
        target: centre,
        u: Vec3::X,
        v: Vec3::Y,
        n: Vec3::Z,
        ..lens
    };
    let mut camera = match (framing.pose, basis) {
        (Some(_), Some([u, v, n])) => Camera {
            position,
            target,
            u,
            v,
            n,
            ..lens
        },
        (Some(_), None) => lens.looking_at(position, target, up).unwrap_or(from_plus_z),
        (None, _) => from_plus_z,
    };
    pin_clipping_planes(&mut camera, framing);
    camera
}

/// Config-pinned near/far win; the other one is moved if it would cross the pinned one.
pub fn pin_clipping_planes(camera: &mut Camera, framing: &Framing) {
    match (framing.near, framing.far) {
        (Some(near), Some(far)) => (camera.near, camera.far) = (near, far),
        (Some(near), None) => (camera.near, camera.far) = (near, camera.far.max(near * 100.0)),
        (None, Some(far)) => (camera.near, camera.far) = (camera.near.min(far * 0.01), far),
        (None, None) => {}
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fits(camera: &Camera, centre: Vec3, radius: f32) -> bool {
        let d = camera.position.distance(centre);
        let half = camera.hfov.min(camera.vfov).to_radians() * 0.5;
        (radius / d - half.sin()).abs() < 1e-4
            && camera.near < d - radius
            && camera.far > d + radius
    }

    #[test]
    fn frames_from_plus_z_at_the_fitting_distance() {
        for (centre, radius) in [
            (Vec3::ZERO, 1.0),
            (Vec3::new(440.0, -224.0, 63.0), 600.0),
            (Vec3::new(0.0, 0.0, -3.0), 0.0005),
            (Vec3::new(1.0, 2.0, 3.0), 50_000.0),
        ] {
            let camera = frame(centre, radius, &Camera::default(), &Framing::default());
            assert_eq!((camera.u, camera.v, camera.n), (Vec3::X, Vec3::Y, Vec3::Z));
            assert_eq!(camera.target, centre);
            assert!(fits(&camera, centre, radius), "{camera:?}");
        }
    }

    #[test]
    fn the_narrower_field_of_view_decides() {
        let lens = Camera {
            hfov: 90.0,
            vfov: 30.0,
            ..Camera::default()
        };
        let camera = frame(Vec3::ZERO, 1.0, &lens, &Framing::default());
        assert!((camera.position.z - 1.0 / 15f32.to_radians().sin()).abs() < 1e-4);
    }

    #[test]
    fn planes_follow_an_explicit_pose_even_from_inside_the_model() {
        for position in [Vec3::new(0.0, 0.0, 100.0), Vec3::new(0.1, 0.0, 0.0)] {
            let framing = Framing {
                pose: Some(LookAtPose {
                    position,
                    target: Vec3::ZERO,
                    up: Vec3::Y,
                    basis: None,
                }),
                ..Framing::default()
            };
            let camera = frame(Vec3::ZERO, 1.0, &Camera::default(), &framing);
            assert!(camera.near > 0.0 && camera.near < camera.far);
            assert!(
                camera.far > position.length() + 1.0,
                "the whole model is before far"
            );
            assert!(
                camera.near < (position.length() - 1.0).max(0.01),
                "near = {}",
                camera.near
            );
        }
    }

    #[test]
    fn an_explicit_pose_and_pinned_planes_win() {
        let framing = Framing {
            pose: Some(LookAtPose {
                position: Vec3::new(5.0, 0.0, 0.0),
                target: Vec3::ZERO,
                up: Vec3::Y,
                basis: None,
            }),
            near: Some(0.5),
            far: None,
        };
        let camera = frame(Vec3::ZERO, 1.0, &Camera::default(), &framing);
        assert_eq!(camera.position, Vec3::new(5.0, 0.0, 0.0));
        assert!((camera.n - Vec3::X).length() < 1e-6);
        assert_eq!(camera.near, 0.5);
        assert!(camera.far > camera.near);
    }

    #[test]
    fn a_given_basis_is_taken_as_it_is() {
        // Not what looking_at would derive from the target: the basis wins, bit for bit.
        let (u, v, n) = (
            Vec3::new(0.6, 0.0, -0.8),
            Vec3::new(0.0, 1.0, 0.0),
            Vec3::new(0.8, 0.0, 0.6),
        );
        let framing = Framing {
            pose: Some(LookAtPose {
                position: Vec3::new(4.0, 0.1, 3.0),
                target: Vec3::ZERO,
                up: Vec3::Y,
                basis: Some([u, v, n]),
            }),
            ..Framing::default()
        };
        let camera = frame(Vec3::ZERO, 1.0, &Camera::default(), &framing);
        assert_eq!((camera.u, camera.v, camera.n), (u, v, n));
        assert_eq!(camera.position, Vec3::new(4.0, 0.1, 3.0));
    }
}

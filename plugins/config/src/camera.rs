//! The configuration's `[camera]` and the app's `Camera`, both ways and in one place: the lens
//! the config sets on the camera (at start, and again whenever `--watch` reads the file), the
//! framing rules it gives each newly loaded model (its pose, its pinned planes), and the other
//! way, the config that gives a camera back exactly, which copy as command writes.

use close2gl_camera::framing::pin_clipping_planes;
use close2gl_core::glam::Vec3;
use close2gl_core::{Camera, Framing, LookAtPose};

use super::{CameraConfig, Config};

impl CameraConfig {
    /// Sets the config's lens on `camera`: both fields of view, the mode, and near and far where
    /// the config pins them (the other one moved if it would cross, as framing does). The pose is
    /// not the lens: a running camera keeps its own, and a new model is framed by
    /// [`Self::framing`].
    pub fn set_lens(&self, camera: &mut Camera) {
        (camera.hfov, camera.vfov, camera.mode) = (self.hfov, self.vfov, self.mode);
        pin_clipping_planes(camera, &self.framing());
    }

    /// What framing a newly loaded model must respect: the config's pose, if it gives one, and
    /// its pinned planes.
    pub fn framing(&self) -> Framing {
        Framing {
            pose: self.pose(),
            near: self.near,
            far: self.far,
        }
    }

    /// The config that gives `camera` back exactly: its pose with its own u, v, n, and its whole
    /// lens, near and far pinned; `up` and the speeds as by default.
    pub fn pinning(camera: &Camera) -> Self {
        Self {
            position: Some(camera.position),
            target: Some(camera.target),
            u: Some(camera.u),
            v: Some(camera.v),
            n: Some(camera.n),
            hfov: camera.hfov,
            vfov: camera.vfov,
            near: Some(camera.near),
            far: Some(camera.far),
            mode: camera.mode,
            ..Config::default().camera
        }
    }

    /// The explicit pose, when the config gives a position (the target defaults to the origin);
    /// when absent the camera frames the model.
    pub fn pose(&self) -> Option<LookAtPose> {
        self.position.map(|position| LookAtPose {
            position,
            target: self.target.unwrap_or(Vec3::ZERO),
            up: self.up,
            basis: self.basis(),
        })
    }

    /// u, v, n when all three are given.
    pub fn basis(&self) -> Option<[Vec3; 3]> {
        Some([self.u?, self.v?, self.n?])
    }
}

#[cfg(test)]
mod tests {
    use close2gl_core::CameraMode;

    use super::*;

    #[test]
    fn a_pinned_camera_comes_back_as_it_was() {
        let camera = Camera {
            hfov: 50.5,
            vfov: 40.25,
            near: 0.3,
            far: 70.0,
            mode: CameraMode::LookAt,
            ..Camera::default()
        }
        .looking_at(Vec3::new(3.0, 4.0, 5.0), Vec3::new(0.5, 0.0, -1.0), Vec3::Y)
        .expect("a valid pose");
        let config = CameraConfig::pinning(&camera);
        let mut lens = Camera::default();
        config.set_lens(&mut lens);
        let Framing { pose, near, far } = config.framing();
        assert_eq!((near, far), (Some(0.3), Some(70.0)));
        let pose = pose.expect("the pose is pinned");
        let [u, v, n] = pose.basis.expect("the basis is pinned");
        let back = Camera {
            position: pose.position,
            target: pose.target,
            u,
            v,
            n,
            ..lens
        };
        assert_eq!(back, camera);
    }

    #[test]
    fn a_pinned_near_beyond_the_cameras_far_moves_far_too() {
        let config = CameraConfig {
            near: Some(500.0),
            hfov: 45.0,
            ..Config::default().camera
        };
        let mut camera = Camera::default();
        config.set_lens(&mut camera);
        assert_eq!(
            (camera.hfov, camera.vfov),
            (45.0, Config::default().camera.vfov)
        );
        assert_eq!(camera.near, 500.0);
        assert!(camera.far > camera.near, "far {}", camera.far);
    }
}

//! What close2gl expects of a camera after a scene's motion, from `trace-format.md`'s own
//! definitions: `move` along the camera's own axis, `rotate` about it by the right-hand rule,
//! `orbit` along u or v keeping the look-at point. The grader judges a program's final camera
//! against these (and against the accepted variants: the other way round, an arc).

use close2gl_trace_format::{Axis, CameraLines};
use glam::DVec3;

/// Where a camera is and how it is turned.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pose {
    pub position: DVec3,
    pub u: DVec3,
    pub v: DVec3,
    pub n: DVec3,
}

impl Pose {
    pub fn of(camera: &CameraLines) -> Self {
        Self {
            position: camera.position,
            u: camera.u,
            v: camera.v,
            n: camera.n,
        }
    }

    pub fn axis(&self, axis: Axis) -> DVec3 {
        match axis {
            Axis::U => self.u,
            Axis::V => self.v,
            Axis::N => self.n,
        }
    }

    /// `move AXIS D`: the position moves by D along the camera's own axis; the axes stay.
    pub fn moved(&self, axis: Axis, distance: f64) -> Self {
        Self {
            position: self.position + distance * self.axis(axis),
            ..*self
        }
    }

    /// `rotate AXIS DEG`: the other two axes turn about `axis` by the right-hand rule (a
    /// negative angle turns them the other way round); the position stays. `rotate u` turns v
    /// toward n, `rotate v` turns n toward u, `rotate n` turns u toward v.
    pub fn rotated(&self, axis: Axis, degrees: f64) -> Self {
        let (sin, cos) = degrees.to_radians().sin_cos();
        // (a, b) turns as a' = a cos + b sin, b' = b cos - a sin: a toward b.
        let turn = |a: DVec3, b: DVec3| (a * cos + b * sin, b * cos - a * sin);
        let mut pose = *self;
        match axis {
            Axis::U => (pose.v, pose.n) = turn(self.v, self.n),
            Axis::V => (pose.n, pose.u) = turn(self.n, self.u),
            Axis::N => (pose.u, pose.v) = turn(self.u, self.v),
        }
        pose
    }

    /// `orbit AXIS D` done as a straight move along the axis, then turned to look back at
    /// `lookat`: the position only (the axes follow from it).
    pub fn orbited_straight(&self, axis: Axis, distance: f64) -> DVec3 {
        self.position + distance * self.axis(axis)
    }

    /// `orbit AXIS D` done as an arc of length D around `lookat`, toward the axis, at the same
    /// distance from it.
    pub fn orbited_arc(&self, axis: Axis, distance: f64, lookat: DVec3) -> DVec3 {
        let radius = self.position.distance(lookat);
        let angle = distance / radius;
        let outward = (self.position - lookat) / radius;
        lookat + radius * (outward * angle.cos() + self.axis(axis) * angle.sin())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn identity() -> Pose {
        Pose {
            position: DVec3::new(0.0, 0.0, 5.0),
            u: DVec3::X,
            v: DVec3::Y,
            n: DVec3::Z,
        }
    }

    fn close(a: DVec3, b: DVec3) -> bool {
        a.distance(b) < 1e-12
    }

    #[test]
    fn the_spec_words_of_each_rotation() {
        // `rotate u 10` turns v toward n: the view tilts up (the view direction -n goes up).
        let up = identity().rotated(Axis::U, 90.0);
        assert!(close(up.v, DVec3::Z) && close(up.n, -DVec3::Y) && close(up.u, DVec3::X));
        // `rotate v 10` turns n toward u: the view turns left.
        let left = identity().rotated(Axis::V, 90.0);
        assert!(close(left.n, DVec3::X) && close(left.u, -DVec3::Z));
        let roll = identity().rotated(Axis::N, 90.0);
        assert!(close(roll.u, DVec3::Y) && close(roll.v, -DVec3::X) && close(roll.n, DVec3::Z));
        for pose in [up, left, roll] {
            assert!(
                pose.u.cross(pose.v).dot(pose.n) > 0.999,
                "still right-handed"
            );
        }
    }

    #[test]
    fn an_orbit_arc_keeps_the_distance_and_a_straight_one_does_not() {
        let pose = identity();
        let arc = pose.orbited_arc(Axis::U, 1.0, DVec3::ZERO);
        assert!((arc.length() - 5.0).abs() < 1e-12 && arc.x > 0.0);
        let straight = pose.orbited_straight(Axis::U, 1.0);
        assert!(close(straight, DVec3::new(1.0, 0.0, 5.0)));
        assert!(close(
            pose.moved(Axis::N, -1.0).position,
            DVec3::new(0.0, 0.0, 4.0)
        ));
    }
}

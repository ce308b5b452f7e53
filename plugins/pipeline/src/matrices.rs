//! The three matrices of the assignment, written out entry by entry as the textbook prints them:
//! glam only holds the numbers. Each is given row by row ([`modelview_rows`],
//! [`projection_rows`], [`viewport_rows`]) and transposed into glam's column-major storage.
//! Each is written once, in either precision ([`Real`]): f32 for Close2GL's own frame, f64 for
//! a student's program as `check` recomputes it. No mistake is made here: a program's classic
//! mistakes change entries of these rows beside them (`program/given.rs`).

use std::ops::{Add, Div, Mul, Neg, Sub};

use close2gl_core::Camera;
use glam::{DMat4, Mat4, Vec3, Vec4};

/// The two precisions M, P and V are built in.
pub trait Real:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    const ZERO: Self;
    const ONE: Self;
    const HALF: Self;
    const TWO: Self;
    /// glam's 4×4 matrix of this precision.
    type Mat4;
    fn tan(self) -> Self;
    fn to_radians(self) -> Self;
    /// A matrix from its rows, so the code reads like the printed matrices.
    fn from_rows(rows: [[Self; 4]; 4]) -> Self::Mat4;
}

/// `Real` for one of the two floats: the same impl, with its own glam matrix.
macro_rules! real {
    ($float:ident, $mat4:ty) => {
        impl Real for $float {
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const HALF: Self = 0.5;
            const TWO: Self = 2.0;
            type Mat4 = $mat4;
            fn tan(self) -> Self {
                $float::tan(self)
            }
            fn to_radians(self) -> Self {
                $float::to_radians(self)
            }
            fn from_rows(rows: [[Self; 4]; 4]) -> $mat4 {
                <$mat4>::from_cols_array_2d(&rows).transpose()
            }
        }
    };
}

real!(f32, Mat4);
real!(f64, DMat4);

fn dot<S: Real>(a: [S; 3], b: [S; 3]) -> S {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// M: world → camera coordinates, from the camera's u, v, n and centre of projection c
/// (Hill, matrix 7.2, with the corrected 1 in the corner): rows u, v, n, and d = -c·(u, v, n).
pub fn modelview_rows<S: Real>([u, v, n]: [[S; 3]; 3], c: [S; 3]) -> [[S; 4]; 4] {
    let d = [-dot(c, u), -dot(c, v), -dot(c, n)];
    let o = S::ZERO;
    [
        [u[0], u[1], u[2], d[0]],
        [v[0], v[1], v[2], d[1]],
        [n[0], n[1], n[2], d[2]],
        [o, o, o, S::ONE],
    ]
}

/// The near plane's window from the two fields of view (degrees): right = near·tan(hfov/2),
/// top = near·tan(vfov/2); left = -right, bottom = -top.
pub fn near_window<S: Real>([hfov, vfov]: [S; 2], near: S) -> [S; 2] {
    let half_angle = |degrees: S| degrees.to_radians() * S::HALF;
    [near * half_angle(hfov).tan(), near * half_angle(vfov).tan()]
}

/// P: camera coordinates → clip coordinates (the OpenGL red book's glFrustum matrix), mapping the
/// view volume to the normalized cube |x|, |y|, |z| <= w, for a near window symmetric about the
/// axis ([`near_window`]): 2n/(r − l) = n/r and (r + l)/(r − l) = 0.
pub fn projection_rows<S: Real>([right, top]: [S; 2], [near, far]: [S; 2]) -> [[S; 4]; 4] {
    let o = S::ZERO;
    [
        [near / right, o, o, o],
        [o, near / top, o, o],
        [
            o,
            o,
            -(far + near) / (far - near),
            -S::TWO * far * near / (far - near),
        ],
        [o, o, -S::ONE, o],
    ]
}

/// V: the normalized image plane [-1, 1]² → the 2D system's L R B T (`gluOrtho2D`'s),
/// x' = x·(R−L)/2 + (R+L)/2, y' = y·(T−B)/2 + (T+B)/2, and the normalized depth [-1, 1] → the
/// depth range [0, 1] (glDepthRange's default, and the range of the reference's depth buffer).
pub fn viewport_rows<S: Real>([left, right, bottom, top]: [S; 4]) -> [[S; 4]; 4] {
    let o = S::ZERO;
    [
        [(right - left) * S::HALF, o, o, (right + left) / S::TWO],
        [o, (top - bottom) * S::HALF, o, (top + bottom) / S::TWO],
        [o, o, S::HALF, S::HALF],
        [o, o, o, S::ONE],
    ]
}

/// Close2GL's M (f32, no mistake).
pub fn modelview(camera: &Camera) -> Mat4 {
    let axes = [camera.u, camera.v, camera.n].map(|axis| axis.to_array());
    f32::from_rows(modelview_rows(axes, camera.position.to_array()))
}

/// Close2GL's P (f32, no mistake).
pub fn projection(hfov_deg: f32, vfov_deg: f32, near: f32, far: f32) -> Mat4 {
    let window = near_window([hfov_deg, vfov_deg], near);
    f32::from_rows(projection_rows(window, [near, far]))
}

/// Close2GL's V (f32, no mistake): its 2D buffer is window pixels [0, width] × [0, height]
/// with the origin at the top-left corner and y growing downwards (as every window system and
/// wgpu count pixels), `gluOrtho2D(0, W, H, 0)`: the top of the image plane (+1) lands on row 0.
pub fn viewport(width: f32, height: f32) -> Mat4 {
    f32::from_rows(viewport_rows([0.0, width, height, 0.0]))
}

/// The camera's P·M (why not M·P? M acts first on the point, so it stands on the right).
pub fn projection_modelview(camera: &Camera) -> Mat4 {
    projection(camera.hfov, camera.vfov, camera.near, camera.far) * modelview(camera)
}

/// P·M as Close2GL applies it to every vertex. M is a rotation after a translation,
/// M = R·T(-c) (move the centre of projection to the origin, then turn u, v, n onto x, y, z),
/// and the two factors are applied apart: T(-c) as one subtraction, then P·R. Multiplied out,
/// P·M·p adds terms as large as the model's distance from the origin to get a result as small as
/// the model, and in f32 a 1 cm model 1 km from the origin would lose most of its digits; the
/// subtraction of two nearby f32 values is exact.
#[derive(Clone, Copy, Debug)]
pub struct ClipTransform {
    centre: Vec3,
    rotation: Mat4,
    projection_rotation: Mat4,
}

impl ClipTransform {
    pub fn new(camera: &Camera) -> Self {
        let at_origin = Camera {
            position: Vec3::ZERO,
            ..*camera
        };
        let rotation = modelview(&at_origin);
        Self {
            centre: camera.position,
            rotation,
            projection_rotation: projection(camera.hfov, camera.vfov, camera.near, camera.far)
                * rotation,
        }
    }

    /// The eye-space position M·p of the world point `p`.
    #[inline]
    pub fn eye(&self, p: Vec3) -> Vec3 {
        self.rotation.transform_vector3(p - self.centre)
    }

    /// The eye-space direction of the world normal `n`: M's rotation alone, whose inverse
    /// transpose is itself.
    #[inline]
    pub fn eye_normal(&self, n: Vec3) -> Vec3 {
        self.rotation.transform_vector3(n)
    }

    /// The clip coordinates P·M·p of the world point `p`.
    #[inline]
    pub fn apply(&self, p: Vec3) -> Vec4 {
        self.projection_rotation * (p - self.centre).extend(1.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec4;
    use glam::camera::rh::proj::opengl;

    fn assert_close(a: Mat4, b: Mat4) {
        let (a, b) = (a.to_cols_array(), b.to_cols_array());
        for (x, y) in a.iter().zip(&b) {
            assert!((x - y).abs() <= 1e-5 * (1.0 + y.abs()), "{a:?}\n!=\n{b:?}");
        }
    }

    fn camera_at(position: Vec3, target: Vec3, up: Vec3) -> Camera {
        Camera::default()
            .looking_at(position, target, up)
            .expect("a valid pose")
    }

    #[test]
    fn modelview_matches_glam_look_at() {
        for (eye, target, up) in [
            (Vec3::new(0.0, 0.0, 5.0), Vec3::ZERO, Vec3::Y),
            (
                Vec3::new(3.0, -2.0, 7.0),
                Vec3::new(1.0, 1.0, -1.0),
                Vec3::Y,
            ),
            (
                Vec3::new(440.0, -224.0, 1500.0),
                Vec3::new(440.0, -224.0, 63.0),
                Vec3::new(0.3, 1.0, 0.1),
            ),
        ] {
            let camera = camera_at(eye, target, up);
            assert_close(
                modelview(&camera),
                glam::camera::rh::view::look_at_mat4(eye, target, up),
            );
        }
    }

    #[test]
    fn projection_matches_glam_perspective_and_frustum() {
        for (hfov, vfov, near, far) in [
            (60.0f32, 60.0f32, 0.1, 100.0),
            (90.0, 45.0, 1.0, 3000.0),
            (20.0, 150.0, 0.01, 5.0),
        ] {
            let aspect = (hfov.to_radians() / 2.0).tan() / (vfov.to_radians() / 2.0).tan();
            let p = projection(hfov, vfov, near, far);
            assert_close(p, opengl::perspective(vfov.to_radians(), aspect, near, far));
            let r = near * (hfov.to_radians() / 2.0).tan();
            let t = near * (vfov.to_radians() / 2.0).tan();
            assert_close(p, opengl::frustum(-r, r, -t, t, near, far));
        }
    }

    #[test]
    fn viewport_maps_the_image_plane_corners_to_the_window_corners() {
        let v = viewport(640.0, 480.0);
        assert_eq!(
            v * Vec4::new(-1.0, 1.0, -1.0, 1.0),
            Vec4::new(0.0, 0.0, 0.0, 1.0)
        );
        assert_eq!(
            v * Vec4::new(1.0, -1.0, 1.0, 1.0),
            Vec4::new(640.0, 480.0, 1.0, 1.0)
        );
        assert_eq!(
            v * Vec4::new(0.0, 0.0, 0.5, 1.0),
            Vec4::new(320.0, 240.0, 0.75, 1.0),
            "depth -1..1 lands in 0..1"
        );
    }

    #[test]
    fn the_clip_transform_is_p_times_m() {
        let camera = camera_at(
            Vec3::new(3.0, -2.0, 7.0),
            Vec3::new(1.0, 1.0, -1.0),
            Vec3::Y,
        );
        let pm = projection_modelview(&camera);
        let transform = ClipTransform::new(&camera);
        for p in [
            Vec3::ZERO,
            Vec3::new(1.0, 2.0, -3.0),
            Vec3::new(-40.0, 5.0, 9.0),
        ] {
            let (a, b) = (transform.apply(p), pm * p.extend(1.0));
            assert!((a - b).abs().max_element() <= 1e-5 * (1.0 + b.abs().max_element()));
        }
    }

    #[test]
    fn a_tiny_model_far_from_the_origin_keeps_its_digits() {
        // A 2 mm model 900 units from the origin, seen from 10 cm away.
        let centre = Vec3::new(-217.03, -630.31, 795.44);
        let camera = camera_at(centre + Vec3::new(0.03, 0.02, 0.09), centre, Vec3::Y);
        let p64 = projection(camera.hfov, camera.vfov, camera.near, camera.far).as_dmat4();
        let exact = |p: Vec3| {
            let d = p.as_dvec3() - camera.position.as_dvec3();
            let eye = [camera.u, camera.v, camera.n].map(|axis| axis.as_dvec3().dot(d));
            p64 * DVec4::new(eye[0], eye[1], eye[2], 1.0)
        };
        let pm = projection_modelview(&camera);
        let transform = ClipTransform::new(&camera);
        let (mut worst_transform, mut worst_pm) = (0.0f64, 0.0f64);
        for i in 0..100 {
            let offset = Vec3::new(i as f32, (i * 7 % 13) as f32, (i * 3 % 11) as f32) * 1e-5;
            let p = centre + offset;
            let exact = exact(p);
            let error = |clip: Vec4| (clip.as_dvec4() - exact).abs().max_element() / exact.w;
            worst_transform = worst_transform.max(error(transform.apply(p)));
            worst_pm = worst_pm.max(error(pm * p.extend(1.0)));
        }
        // In normalised device coordinates (the view volume is 2 wide): about f32's own precision
        // for the two-step transform, visibly off for the multiplied-out matrix.
        assert!(worst_transform < 1e-5, "{worst_transform}");
        assert!(
            worst_pm > 100.0 * worst_transform,
            "{worst_pm} vs {worst_transform}"
        );
    }

    #[test]
    fn the_default_camera_sees_down_minus_z() {
        let camera = Camera::default();
        let clip = projection_modelview(&camera) * Vec4::new(0.0, 0.0, -1.0, 1.0);
        assert!(clip.w > 0.0 && clip.z.abs() <= clip.w);
    }
}

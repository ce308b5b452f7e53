//! The view volume in world coordinates, from the real matrices: each corner is inverse(P·M)
//! applied to a corner of the NDC cube, then divided by its w. Not rebuilt from hfov and vfov,
//! so that what the outside view draws is what the pipeline clips against.

use close2gl_core::Camera;
use glam::{DMat4, DVec3, DVec4, Vec3};

use crate::matrices::{modelview, projection};

/// The NDC cube's corners in the order the `render` report lists them: x fastest, then y, then
/// z; z = -1 is the near plane.
pub const NDC_CORNERS: [[f32; 3]; 8] = [
    [-1.0, -1.0, -1.0],
    [1.0, -1.0, -1.0],
    [-1.0, 1.0, -1.0],
    [1.0, 1.0, -1.0],
    [-1.0, -1.0, 1.0],
    [1.0, -1.0, 1.0],
    [-1.0, 1.0, 1.0],
    [1.0, 1.0, 1.0],
];

/// The twelve edges of the volume, as pairs of indices into [`NDC_CORNERS`]: the near face's
/// four (the window's outline), the far face's four, then the four running from near to far.
pub const EDGES: [[usize; 2]; 12] = [
    [0, 1],
    [1, 3],
    [3, 2],
    [2, 0],
    [4, 5],
    [5, 7],
    [7, 6],
    [6, 4],
    [0, 4],
    [1, 5],
    [2, 6],
    [3, 7],
];

/// The eight world-space corners of the camera's view volume, in [`NDC_CORNERS`]' order.
///
/// M = R·T(-c), so inverse(P·M) = T(c)·R⁻¹·P⁻¹, and the factors are inverted apart (as
/// `ClipTransform` applies them apart): inverse(P) and the rotation's inverse act on numbers of
/// the volume's own size, and the centre of projection is added last. Inverting P·M multiplied
/// out would carry the camera's distance from the origin through the whole product, and a model
/// far from the origin would lose the digits that place its corners. The arithmetic is in f64.
pub fn world_corners(camera: &Camera) -> [Vec3; 8] {
    let at_origin = Camera {
        position: Vec3::ZERO,
        ..*camera
    };
    let rotation = modelview(&at_origin).as_dmat4();
    let p = projection(camera.hfov, camera.vfov, camera.near, camera.far).as_dmat4();
    let unproject: DMat4 = rotation.inverse() * p.inverse();
    let centre = camera.position.as_dvec3();
    NDC_CORNERS.map(|[x, y, z]| {
        let h = unproject * DVec4::new(x.into(), y.into(), z.into(), 1.0);
        (centre + DVec3::new(h.x, h.y, h.z) / h.w).as_vec3()
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::matrices::ClipTransform;

    fn camera(position: Vec3, target: Vec3, hfov: f32, vfov: f32, near: f32, far: f32) -> Camera {
        Camera {
            hfov,
            vfov,
            near,
            far,
            ..Camera::default()
        }
        .looking_at(position, target, Vec3::Y)
        .expect("a valid pose")
    }

    /// The far-away model of assets/far_away.in (1,200 units across at (440, -224, 63)) seen
    /// from the side with unequal fields of view, and a unit model at the origin.
    fn scenes() -> [(Camera, f32); 3] {
        let far_centre = Vec3::new(440.0, -224.0, 63.0);
        [
            (
                camera(
                    far_centre + Vec3::new(900.0, 300.0, 1500.0),
                    far_centre,
                    70.0,
                    35.0,
                    200.0,
                    4000.0,
                ),
                1200.0,
            ),
            (
                camera(Vec3::new(0.0, 0.0, 3.0), Vec3::ZERO, 40.0, 90.0, 0.5, 10.0),
                2.0,
            ),
            (
                camera(
                    far_centre + Vec3::new(-30.0, 5.0, 20.0),
                    far_centre,
                    120.0,
                    20.0,
                    3.0,
                    80.0,
                ),
                1200.0,
            ),
        ]
    }

    #[test]
    fn each_corner_maps_back_onto_its_ndc_corner_through_p_times_m() {
        for (camera, size) in scenes() {
            let transform = ClipTransform::new(&camera);
            for (corner, ndc) in world_corners(&camera).iter().zip(NDC_CORNERS) {
                let clip = transform.apply(*corner);
                let back = clip.truncate() / clip.w;
                // An error in NDC of e is an error of about e times the volume's half-width at
                // that depth in world units; relative to the model's size:
                let half_width = (*corner - camera.position).length();
                let error = (back - Vec3::from(ndc)).abs().max_element() * half_width / size;
                assert!(error <= 1e-4, "{corner} -> {back} for {ndc:?}: {error}");
            }
        }
    }

    #[test]
    fn the_near_corners_sit_at_near_tan_half_fov_off_the_view_axis() {
        for (camera, size) in scenes() {
            let corners = world_corners(&camera);
            let right = camera.near * (camera.hfov.to_radians() / 2.0).tan();
            let top = camera.near * (camera.vfov.to_radians() / 2.0).tan();
            for (corner, [x, y, z]) in corners.iter().zip(NDC_CORNERS) {
                let depth = if z < 0.0 { camera.near } else { camera.far };
                let scale = depth / camera.near;
                let expected = camera.position - camera.n * depth
                    + camera.u * (x * right * scale)
                    + camera.v * (y * top * scale);
                let error = (*corner - expected).length() / size;
                assert!(error <= 1e-4, "{corner} != {expected}: {error}");
            }
        }
    }

    #[test]
    fn the_edges_join_corners_that_differ_in_one_coordinate() {
        for [a, b] in EDGES {
            let differ = (0..3)
                .filter(|&i| NDC_CORNERS[a][i] != NDC_CORNERS[b][i])
                .count();
            assert_eq!(differ, 1, "{a}-{b}");
        }
    }
}

use std::collections::HashMap;

use close2gl_core::{Mesh, PrimitiveKind, PrimitiveParams};
use glam::Vec3;

use super::primitive;

/// Coarse and odd parameters as well as the defaults, so that orientation does not hold by
/// luck of a fine mesh.
fn parameter_sets() -> [PrimitiveParams; 3] {
    let coarse = PrimitiveParams {
        box_size: Vec3::new(2.0, 0.5, 7.0),
        sphere_radius: 0.3,
        sphere_stacks: 2,
        sphere_slices: 3,
        torus_r0: 5.0,
        torus_r1: 0.5,
        torus_n0: 3,
        torus_n1: 3,
        cone_radius: 3.0,
        cone_height: 0.2,
        cone_slices: 3,
        cylinder_radius: 0.1,
        cylinder_height: 9.0,
        cylinder_slices: 3,
    };
    let odd = PrimitiveParams {
        sphere_stacks: 7,
        sphere_slices: 5,
        torus_r0: 1.0,
        torus_r1: 0.9,
        torus_n0: 11,
        torus_n1: 4,
        cone_radius: 0.5,
        cone_height: 40.0,
        cone_slices: 17,
        ..coarse
    };
    [PrimitiveParams::default(), coarse, odd]
}

fn corners(mesh: &Mesh, t: [u32; 3]) -> [Vec3; 3] {
    t.map(|i| mesh.positions[i as usize])
}

/// Where "outside" is measured from for a vertex: the origin for the convex shapes, the tube's
/// centre line for the torus.
fn inner_point(kind: PrimitiveKind, p: &PrimitiveParams, at: Vec3) -> Vec3 {
    match kind {
        PrimitiveKind::Torus => Vec3::new(at.x, 0.0, at.z).normalize() * p.torus_r0,
        _ => Vec3::ZERO,
    }
}

#[test]
fn every_primitive_is_valid_named_and_sized_as_the_lecture_says() {
    for p in parameter_sets() {
        for &kind in PrimitiveKind::ALL {
            let mesh = primitive(kind, &p).unwrap();
            mesh.validate().unwrap();
            assert_eq!(mesh.name, kind.name());
            let expected = match kind {
                PrimitiveKind::Box => 12,
                PrimitiveKind::Sphere => 2 * p.sphere_slices * (p.sphere_stacks - 1),
                PrimitiveKind::Torus => 2 * p.torus_n0 * p.torus_n1,
                PrimitiveKind::Cone => 2 * p.cone_slices,
                PrimitiveKind::Cylinder => 4 * p.cylinder_slices,
            };
            assert_eq!(mesh.triangles.len(), expected as usize, "{kind:?}");
        }
    }
}

#[test]
fn every_triangle_is_ccw_seen_from_outside() {
    for p in parameter_sets() {
        for &kind in PrimitiveKind::ALL {
            let mesh = primitive(kind, &p).unwrap();
            for &t in &mesh.triangles {
                let [a, b, c] = corners(&mesh, t);
                let centroid = (a + b + c) / 3.0;
                // On a coarse torus the tube's centre line is a polygon: its point level with
                // the triangle is the mean of the corners' own centres.
                let inner = [a, b, c].map(|v| inner_point(kind, &p, v));
                let outward = centroid - (inner[0] + inner[1] + inner[2]) / 3.0;
                let facing = (b - a).cross(c - a).dot(outward);
                assert!(facing > 0.0, "{kind:?} {t:?}: {a} {b} {c}");
            }
        }
    }
}

#[test]
fn normals_are_unit_outward_and_agree_with_the_winding() {
    for p in parameter_sets() {
        for &kind in PrimitiveKind::ALL {
            let mesh = primitive(kind, &p).unwrap();
            for (&at, &n) in mesh.positions.iter().zip(&mesh.normals) {
                assert!((n.length() - 1.0).abs() < 1e-5, "{kind:?} {n}");
                let outward = at - inner_point(kind, &p, at);
                assert!(n.dot(outward) > 0.0, "{kind:?} at {at}: {n}");
            }
            for &t in &mesh.triangles {
                let [a, b, c] = corners(&mesh, t);
                let face = (b - a).cross(c - a);
                for i in t {
                    assert!(mesh.normals[i as usize].dot(face) > 0.0, "{kind:?} {t:?}");
                }
            }
        }
    }
}

#[test]
fn every_primitive_is_closed_each_edge_met_once_each_way() {
    let key = |p: Vec3| p.to_array().map(f32::to_bits);
    for p in parameter_sets() {
        for &kind in PrimitiveKind::ALL {
            let mesh = primitive(kind, &p).unwrap();
            let mut edges: HashMap<_, i32> = HashMap::new();
            for &t in &mesh.triangles {
                let [a, b, c] = corners(&mesh, t).map(key);
                for (from, to) in [(a, b), (b, c), (c, a)] {
                    *edges.entry((from, to)).or_default() += 1;
                }
            }
            for (&(from, to), &count) in &edges {
                assert_eq!(count, 1, "{kind:?}: edge used twice the same way");
                assert_eq!(edges.get(&(to, from)), Some(&1), "{kind:?}: open edge");
            }
        }
    }
}

#[test]
fn exact_normals_match_the_lecture_formulas() {
    let p = PrimitiveParams::default();
    let sphere = primitive(PrimitiveKind::Sphere, &p).unwrap();
    for (&at, &n) in sphere.positions.iter().zip(&sphere.normals) {
        assert!((at / p.sphere_radius - n).length() < 1e-6);
    }
    let torus = primitive(PrimitiveKind::Torus, &p).unwrap();
    for (&at, &n) in torus.positions.iter().zip(&torus.normals) {
        let centre = Vec3::new(at.x, 0.0, at.z).normalize() * p.torus_r0;
        assert!(((at - centre) / p.torus_r1 - n).length() < 1e-5);
    }
    let cylinder = primitive(PrimitiveKind::Cylinder, &p).unwrap();
    for (&at, &n) in cylinder.positions.iter().zip(&cylinder.normals) {
        let on_cap = at.y.abs() == p.cylinder_height / 2.0 && n.y != 0.0;
        if !on_cap {
            assert!((Vec3::new(at.x, 0.0, at.z) / p.cylinder_radius - n).length() < 1e-6);
        }
    }
    // A cone's side normal is perpendicular to the slant line from the apex through the point.
    let cone = primitive(PrimitiveKind::Cone, &p).unwrap();
    let apex = Vec3::Y * p.cone_height / 2.0;
    for (&at, &n) in cone.positions.iter().zip(&cone.normals) {
        if n.y < 0.0 || at == apex {
            continue;
        }
        assert!((at - apex).normalize().dot(n).abs() < 1e-6);
    }
}

#[test]
fn parameters_out_of_range_are_errors_naming_the_key() {
    let cases = [
        (
            PrimitiveKind::Sphere,
            PrimitiveParams {
                sphere_radius: f32::NAN,
                ..PrimitiveParams::default()
            },
            "primitives.sphere_radius",
        ),
        (
            PrimitiveKind::Torus,
            PrimitiveParams {
                torus_n1: 2,
                ..PrimitiveParams::default()
            },
            "primitives.torus_n1",
        ),
        (
            PrimitiveKind::Cylinder,
            PrimitiveParams {
                cylinder_slices: u32::MAX,
                ..PrimitiveParams::default()
            },
            "primitives.cylinder_slices",
        ),
        (
            PrimitiveKind::Box,
            PrimitiveParams {
                box_size: Vec3::new(1.0, 0.0, 1.0),
                ..PrimitiveParams::default()
            },
            "primitives.box_size[1]",
        ),
    ];
    for (kind, p, key) in cases {
        let error = primitive(kind, &p).unwrap_err();
        assert!(error.starts_with(key), "{error}");
    }
}

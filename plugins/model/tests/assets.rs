//! The bundled models in assets/ load cleanly, are closed, and face outwards.

use std::collections::HashMap;
use std::path::Path;

use close2gl_core::{Mesh, ModelSource, PrimitiveParams};
use close2gl_model::{LoadedModel, load};
use glam::Vec3;

fn asset(name: &str) -> LoadedModel {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../assets")
        .join(name);
    let model = load(&ModelSource::File(path), &PrimitiveParams::default()).unwrap();
    assert!(model.warnings.is_empty(), "{name}: {:?}", model.warnings);
    model.mesh.validate().unwrap();
    model
}

fn corners(mesh: &Mesh, t: [u32; 3]) -> [Vec3; 3] {
    t.map(|i| mesh.positions[i as usize])
}

/// Every edge, by position, is used once in each direction: closed and consistently wound.
fn assert_closed(mesh: &Mesh) {
    let key = |p: Vec3| p.to_array().map(f32::to_bits);
    let mut edges: HashMap<_, u32> = HashMap::new();
    for &t in &mesh.triangles {
        let [a, b, c] = corners(mesh, t).map(key);
        for edge in [(a, b), (b, c), (c, a)] {
            *edges.entry(edge).or_default() += 1;
        }
    }
    for (&(from, to), &count) in &edges {
        assert_eq!(count, 1, "{}: edge used twice the same way", mesh.name);
        assert_eq!(edges.get(&(to, from)), Some(&1), "{}: open edge", mesh.name);
    }
}

/// Every vertex normal agrees with the winding of the triangles that use it.
fn assert_normals_follow_the_winding(mesh: &Mesh) {
    for &t in &mesh.triangles {
        let [a, b, c] = corners(mesh, t);
        let face = (b - a).cross(c - a);
        for i in t {
            assert!(
                mesh.normals[i as usize].dot(face) > 0.0,
                "{}: {t:?}",
                mesh.name
            );
        }
    }
}

/// For a convex model: every triangle is CCW seen from outside, i.e. faces away from `centre`.
fn assert_ccw_outward_from(mesh: &Mesh, centre: Vec3) {
    for &t in &mesh.triangles {
        let [a, b, c] = corners(mesh, t);
        let centroid = (a + b + c) / 3.0;
        assert!((b - a).cross(c - a).dot(centroid - centre) > 0.0, "{t:?}");
    }
}

#[test]
fn the_default_knot_is_a_closed_outward_tube_of_about_8000_triangles() {
    let mesh = asset("knot.obj").mesh;
    assert_eq!(mesh.name, "knot");
    assert_eq!(mesh.triangles.len(), 8192);
    // 256 rings of 16: each corner shared by six triangles, stored once.
    assert_eq!(mesh.positions.len(), 4096);
    assert_closed(&mesh);
    assert_normals_follow_the_winding(&mesh);
    // The curve reaches 3 from the axis and 1 from the plane; the tube adds 0.55.
    let (lo, hi) = mesh.bounds();
    let reach = Vec3::new(3.56, 3.56, 1.56);
    assert!(lo.cmpge(-reach).all() && hi.cmple(reach).all(), "{lo} {hi}");
    assert!((hi - lo).cmpgt(Vec3::new(6.0, 6.0, 3.0)).all(), "{lo} {hi}");
}

#[test]
fn the_cube_is_the_specs_two_unit_cube_at_z_minus_two_to_minus_four() {
    let mesh = asset("cube.in").mesh;
    assert_eq!(mesh.name, "CUBE");
    assert_eq!(mesh.triangles.len(), 12);
    assert_eq!(
        mesh.bounds(),
        (Vec3::new(-1.0, -1.0, -4.0), Vec3::new(1.0, 1.0, -2.0))
    );
    assert_closed(&mesh);
    assert_normals_follow_the_winding(&mesh);
    assert_ccw_outward_from(&mesh, Vec3::new(0.0, 0.0, -3.0));
}

#[test]
fn the_textured_cube_is_the_cube_with_the_whole_texture_on_every_side() {
    let (plain, textured) = (asset("cube.in").mesh, asset("textured_cube.in").mesh);
    let geometry =
        |m: &Mesh| -> Vec<[Vec3; 3]> { m.triangles.iter().map(|&t| corners(m, t)).collect() };
    assert_eq!(geometry(&plain), geometry(&textured));
    assert_eq!(textured.uvs.len(), textured.positions.len());
    for pair in textured.triangles.chunks(2) {
        let mut side: Vec<[i32; 2]> = pair
            .iter()
            .flatten()
            .map(|&i| (textured.uvs[i as usize] * 1.0).as_ivec2().to_array())
            .collect();
        side.sort();
        side.dedup();
        assert_eq!(
            side,
            vec![[0, 0], [0, 1], [1, 0], [1, 1]],
            "a side's corners"
        );
    }
}

#[test]
fn the_far_away_model_is_1200_units_across_around_its_centre() {
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets/far_away.in"),
    )
    .unwrap();
    assert!(text.contains("\r\n") && text.contains("   ") && !text.ends_with('\n'));

    let mesh = asset("far_away.in").mesh;
    assert_eq!(mesh.triangles.len(), 320);
    let centre = Vec3::new(440.0, -224.0, 63.0);
    let (lo, hi) = mesh.bounds();
    assert!(((lo + hi) / 2.0).abs_diff_eq(centre, 1.0));
    assert!((hi - lo).max_element() > 1190.0 && (hi - lo).max_element() < 1201.0);
    assert_closed(&mesh);
    assert_normals_follow_the_winding(&mesh);
    assert_ccw_outward_from(&mesh, centre);
}

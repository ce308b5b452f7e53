//! The `.obj` loader: triangulation and merging, smooth normals when the file has none, and
//! line-precise errors for bad records and references.

use close2gl_model::parse_obj;
use glam::Vec3;

/// A square pyramid on the y = 0 plane, apex up, CCW seen from outside; no normals.
const PYRAMID: &str = "# pyramid
o pyramid
v -1 0 -1
v 1 0 -1
v 1 0 1
v -1 0 1
v 0 1 0
f 1 2 3 4
f 4 3 5
f 3 2 5
f 2 1 5
f 1 4 5
";

#[test]
fn faces_are_triangulated_in_file_winding_and_normals_computed_when_missing() {
    let model = parse_obj(PYRAMID, "models/pyramid.obj").unwrap();
    let mesh = &model.mesh;
    mesh.validate().unwrap();
    assert_eq!(mesh.name, "pyramid");
    // The square base becomes two triangles.
    assert_eq!(mesh.triangles.len(), 6);
    let centre = Vec3::new(0.0, 0.4, 0.0);
    for &[a, b, c] in &mesh.triangles {
        let [a, b, c] = [a, b, c].map(|i| mesh.positions[i as usize]);
        assert!((b - a).cross(c - a).dot((a + b + c) / 3.0 - centre) > 0.0);
    }
    // The sides' normals cancel sideways at the apex.
    let apex = mesh.positions.iter().position(|&p| p == Vec3::Y).unwrap();
    assert!(mesh.normals[apex].abs_diff_eq(Vec3::Y, 1e-6));
    assert!(mesh.normals.iter().all(|n| (n.length() - 1.0).abs() < 1e-5));
}

#[test]
fn smooth_normals_are_area_weighted_and_shared_by_position() {
    // Two triangles meet at the origin: a big one facing +z and a small one facing +x.
    let text = "v 0 0 0\nv 4 0 0\nv 0 4 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 4 5\n";
    let model = parse_obj(text, "t.obj").unwrap();
    let mesh = &model.mesh;
    let origin = mesh
        .positions
        .iter()
        .position(|&p| p == Vec3::ZERO)
        .unwrap();
    // Areas 8 and 0.5: the shared corner's normal leans 16:1 towards +z.
    let expected = Vec3::new(0.5, 0.0, 8.0).normalize();
    assert!(mesh.normals[origin].abs_diff_eq(expected, 1e-6));
}

#[test]
fn the_files_normals_are_used_normalised() {
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 2\nvn 0 3 4\nf 1//1 2//1 3//2\n";
    let model = parse_obj(text, "t.obj").unwrap();
    let mesh = &model.mesh;
    assert_eq!(mesh.normals[0], Vec3::Z);
    assert!(mesh.normals[2].abs_diff_eq(Vec3::new(0.0, 0.6, 0.8), 1e-6));
}

#[test]
fn a_zero_normal_falls_back_to_the_smooth_one() {
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n";
    let model = parse_obj(text, "t.obj").unwrap();
    assert!(model.mesh.normals.iter().all(|&n| n == Vec3::Z));
}

#[test]
fn all_objects_are_merged_into_one_mesh() {
    let text = "o a\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n\
                o b\nv 0 0 5\nv 1 0 5\nv 0 1 5\nvt 0 0\nf -3/1 -2/1 -1/1\n";
    let model = parse_obj(text, "two.obj").unwrap();
    assert_eq!(model.mesh.triangles.len(), 2);
    assert_eq!(model.mesh.positions.len(), 6);
    model.mesh.validate().unwrap();
}

#[test]
fn texture_seams_do_not_split_smooth_normals() {
    // The same corner used with two texture coordinates stays two vertices (one per texture
    // coordinate), but both get the normal of the whole fold.
    let text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvt 0 0\nvt 1 1\n\
                f 1/1 2/1 3/1\nf 1/2 3/2 4/2\n";
    let mesh = parse_obj(text, "t.obj").unwrap().mesh;
    let at_origin: Vec<Vec3> = mesh
        .positions
        .iter()
        .zip(&mesh.normals)
        .filter(|(p, _)| **p == Vec3::ZERO)
        .map(|(_, &n)| n)
        .collect();
    assert_eq!(at_origin.len(), 2, "one vertex per texture coordinate");
    assert_eq!(at_origin[0], at_origin[1], "and one normal for both");
    assert_eq!(mesh.uvs.len(), mesh.positions.len());
}

#[test]
fn bad_records_are_errors_naming_their_line() {
    let head = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    let cases = [
        (
            "f 1 2 9",
            "t.obj:4: expected 'f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...', found 'f 1 2 9' \
             (v index 9 refers to no record: the file has 3)",
        ),
        (
            "f 1 2 -4",
            "t.obj:4: expected 'f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...', found 'f 1 2 -4' \
             (v index -4 refers to no record: the file has 3)",
        ),
        (
            "f 1 2 0",
            "t.obj:4: expected 'f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...', found 'f 1 2 0' \
             (v index 0 refers to no record: the file has 3)",
        ),
        (
            "f 1/-99999999999999/1 2 3",
            "t.obj:4: expected 'f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...', found \
             'f 1/-99999999999999/1 2 3' (vt index -99999999999999 refers to no record: the file has 0)",
        ),
        (
            "f 1//-2 2 3",
            "t.obj:4: expected 'f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...', found 'f 1//-2 2 3' \
             (vn index -2 refers to no record: the file has 0)",
        ),
        (
            "f 1//1/1 2 3",
            "t.obj:4: expected 'f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...', found 'f 1//1/1 2 3' \
             (vn index 1 refers to no record: the file has 0)",
        ),
        (
            "f 1/// 2 3",
            "t.obj:4: expected 'f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...', found 'f 1/// 2 3'",
        ),
        (
            "f /1 2 3",
            "t.obj:4: expected 'f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...', found 'f /1 2 3'",
        ),
        (
            "f 1 2",
            "t.obj:4: expected 'f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...', found 'f 1 2'",
        ),
        (
            "f 1 x 3",
            "t.obj:4: expected 'f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...', found 'f 1 x 3'",
        ),
        (
            "v 1 nan 0",
            "t.obj:4: expected 'v x y z [w]', found 'v 1 nan 0' (numbers must be finite)",
        ),
        ("vn 1 0", "t.obj:4: expected 'vn x y z', found 'vn 1 0'"),
        (
            "vt inf 0",
            "t.obj:4: expected 'vt u v', found 'vt inf 0' (numbers must be finite)",
        ),
    ];
    for (line, message) in cases {
        let text = format!("{head}{line}\n");
        assert_eq!(parse_obj(&text, "t.obj").unwrap_err(), message);
    }
}

#[test]
fn a_zero_w_is_an_error_naming_its_line() {
    let error = parse_obj("v 0 0 0 0\nf 1 1 1\n", "w.obj").unwrap_err();
    assert_eq!(
        error,
        "w.obj:1: expected 'v x y z [w]', found 'v 0 0 0 0' (w must not be zero)"
    );
}

#[test]
fn a_tiny_w_that_overflows_a_position_is_an_error() {
    let error = parse_obj("v 1e30 0 0 1e-30\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "w.obj").unwrap_err();
    assert_eq!(error, "w.obj: vertex 0 is not finite");
}

#[test]
fn a_file_without_faces_is_an_error() {
    for text in ["", "v 0 0 0\nv 1 0 0\n", "v 0 0 0\nv 1 0 0\nl 1 2\np 1\n"] {
        assert_eq!(
            parse_obj(text, "e.obj").unwrap_err(),
            "e.obj: no triangles (faces need at least 3 vertices)"
        );
    }
}

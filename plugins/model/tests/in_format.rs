//! The `.in` loader against the spec (see the README's Models section): the course samples, every
//! layout variant real files show, and a file:line error for each kind of bad input.

use close2gl_model::{LoadedModel, parse_in};
use glam::Vec3;

/// One CCW triangle in the z = 0 plane facing +z. Lines: 1 name, 2 count, 3 materials,
/// 4-7 the material, 8 comment, 9 v0, 10 v1, 11 v2, 12 face normal.
const TRIANGLE: &str = "Object name = T
# triangles = 1
Material count = 1
ambient color 0.1 0.1 0.1
diffuse color 0.5 0.5 0.5
specular color 1 1 1
material shine 10
-- 3*[pos(x,y,z) normal(x,y,z) color_index] face_normal(x,y,z)
v0 0 0 0 0 0 1 0
v1 1 0 0 0 0 1 0
v2 0 1 0 0 0 1 0
face normal 0 0 1
";

/// `TRIANGLE` with line `number` (1-based) replaced by `text`.
fn with_line(number: usize, text: &str) -> String {
    let mut lines: Vec<&str> = TRIANGLE.lines().collect();
    lines[number - 1] = text;
    lines.join("\n") + "\n"
}

fn parse(text: &str) -> Result<LoadedModel, String> {
    parse_in(text, "t.in")
}

fn the_triangle(model: &LoadedModel) {
    let mesh = &model.mesh;
    mesh.validate().unwrap();
    assert_eq!(mesh.triangles, vec![[0, 1, 2]]);
    assert_eq!(
        mesh.positions,
        vec![Vec3::ZERO, Vec3::X, Vec3::Y],
        "positions in file order"
    );
    assert!(mesh.normals.iter().all(|&n| n == Vec3::Z));
}

#[test]
fn the_course_samples_load() {
    let tetra = parse_in(include_str!("data/tetra.in"), "tetra.in").unwrap();
    tetra.mesh.validate().unwrap();
    assert_eq!(tetra.mesh.name, "TETRA");
    assert_eq!(tetra.mesh.triangles.len(), 4);
    assert!(tetra.warnings.is_empty(), "{:?}", tetra.warnings);
    // Each face has its own normal, so no corner is shared across faces.
    assert_eq!(tetra.mesh.positions.len(), 12);

    let quad = parse_in(
        include_str!("data/quad_two_materials.in"),
        "quad_two_materials.in",
    )
    .unwrap();
    quad.mesh.validate().unwrap();
    assert_eq!(quad.mesh.name, "QUAD");
    assert_eq!(quad.mesh.triangles.len(), 2);
    assert!(quad.warnings.is_empty(), "{:?}", quad.warnings);
    // The diagonal's two corners are shared: 4 vertices for 6 corners.
    assert_eq!(quad.mesh.positions.len(), 4);
}

#[test]
fn the_plain_triangle_loads() {
    let model = parse(TRIANGLE).unwrap();
    the_triangle(&model);
    assert_eq!(model.mesh.name, "T");
    assert!(model.warnings.is_empty());
}

#[test]
fn runs_of_spaces_leading_and_trailing_spaces_and_tabs_are_layout() {
    let spaced = TRIANGLE
        .lines()
        .map(|l| format!("   {}  \t ", l.replace(' ', "   ")))
        .collect::<Vec<_>>()
        .join("\n");
    let model = parse(&spaced).unwrap();
    the_triangle(&model);
    assert_eq!(model.mesh.name, "T");
}

#[test]
fn crlf_line_endings_and_a_missing_final_newline_load() {
    let crlf = TRIANGLE.replace('\n', "\r\n");
    the_triangle(&parse(&crlf).unwrap());
    the_triangle(&parse(TRIANGLE.trim_end()).unwrap());
    the_triangle(&parse(crlf.trim_end()).unwrap());
}

#[test]
fn blank_lines_and_a_byte_order_mark_are_skipped() {
    let text = format!("\u{feff}{}", TRIANGLE.replace('\n', "\n\n  \n"));
    the_triangle(&parse(&text).unwrap());
}

#[test]
fn numbers_in_every_spelling_load() {
    let text = with_line(9, "v0 -0.000 0e0 0.0 0 -0 1.0 0")
        .replace("v1 1 0 0", "v1 1e0 -0.000 0")
        .replace("v2 0 1 0", "v2 +0 1000e-3 0");
    the_triangle(&parse(&text).unwrap());
    let small = parse(&with_line(10, "v1 1e-3 0 0 0 0 1 0")).unwrap();
    assert_eq!(small.mesh.positions[1], Vec3::new(0.001, 0.0, 0.0));
}

#[test]
fn the_comment_line_may_say_anything_or_be_missing() {
    the_triangle(&parse(&with_line(8, "-- x y z, normal, material index")).unwrap());
    the_triangle(&parse(&with_line(8, "vertices follow")).unwrap());
    let without: String = TRIANGLE
        .lines()
        .filter(|l| !l.starts_with("--"))
        .map(|l| format!("{l}\n"))
        .collect();
    the_triangle(&parse(&without).unwrap());
}

#[test]
fn keywords_are_matched_whatever_their_case() {
    let text = TRIANGLE
        .replace("Object name", "OBJECT NAME")
        .replace("Material count", "material Count")
        .replace("face normal", "Face Normal");
    the_triangle(&parse(&text).unwrap());
}

#[test]
fn texture_coordinates_follow_the_texture_line() {
    let textured = |texture: &str, st: &str| {
        TRIANGLE
            .replace("-- 3*", &format!("{texture}\n-- 3*"))
            .replace(" 0 0 1 0\n", &format!(" 0 0 1 0{st}\n"))
    };
    the_triangle(&parse(&textured("Texture = YES", " 0.5 0.25")).unwrap());
    the_triangle(&parse(&textured("Texture = NO", "")).unwrap());
    the_triangle(&parse(&textured("texture=yes", " 1 1")).unwrap());
    // Without the line, either form is taken.
    the_triangle(&parse(&textured("", " 0.5 0.25")).unwrap());

    let missing_st = parse(&textured("Texture = YES", "")).unwrap_err();
    assert_eq!(
        missing_st,
        "t.in:10: expected 'v0 x y z nx ny nz material s t', found 'v0 0 0 0 0 0 1 0'"
    );
    let extra_st = parse(&textured("Texture = NO", " 0.5 0.25")).unwrap_err();
    assert!(extra_st.starts_with("t.in:10: expected 'v0 x y z nx ny nz material', found"));
    let bad = parse(&textured("Texture = MAYBE", "")).unwrap_err();
    assert_eq!(
        bad,
        "t.in:8: expected 'Texture = YES|NO', found 'Texture = MAYBE'"
    );
}

#[test]
fn a_header_count_that_lies_is_a_warning_and_the_data_wins() {
    let model = parse(&with_line(2, "# triangles = 7")).unwrap();
    the_triangle(&model);
    assert_eq!(
        model.warnings,
        vec!["t.in: header says 7 triangles, found 1"]
    );

    let twice = format!(
        "{TRIANGLE}{}",
        TRIANGLE.lines().skip(8).collect::<Vec<_>>().join("\n")
    );
    let model = parse(&twice).unwrap();
    assert_eq!(model.mesh.triangles.len(), 2);
    assert_eq!(
        model.warnings,
        vec!["t.in: header says 1 triangles, found 2"]
    );
}

#[test]
fn a_header_claiming_four_billion_triangles_allocates_nothing_from_it() {
    let model = parse(&with_line(2, "# triangles = 4000000000")).unwrap();
    the_triangle(&model);
    assert_eq!(
        model.warnings,
        vec!["t.in: header says 4000000000 triangles, found 1"]
    );
    // The material count is only counted too: the loop meets a vertex and stops.
    let error = parse(&with_line(3, "Material count = 4000000000")).unwrap_err();
    assert_eq!(
        error,
        "t.in:8: expected 'ambient color r g b', found '-- 3*[pos(x,y,z) normal(x,y,z) color_index] face_normal(x,y,…'"
    );
}

#[test]
fn the_object_name_falls_back_to_the_file_stem() {
    let model = parse_in(&with_line(1, "Object name ="), "models/cube.in").unwrap();
    assert_eq!(model.mesh.name, "cube");
    let spaced = parse(&with_line(1, "Object name =  my  model ")).unwrap();
    assert_eq!(spaced.mesh.name, "my  model");
}

#[test]
fn each_malformed_record_is_an_error_naming_its_line() {
    let cases = [
        (
            1,
            "Object = T",
            "t.in:1: expected 'Object name = <name>', found 'Object = T'",
        ),
        (
            2,
            "# triangles = many",
            "t.in:2: expected '# triangles = <N>', found '# triangles = many'",
        ),
        (
            2,
            "# triangles = -1",
            "t.in:2: expected '# triangles = <N>', found '# triangles = -1'",
        ),
        (
            3,
            "Materials = 1",
            "t.in:3: expected 'Material count = <M>', found 'Materials = 1'",
        ),
        (
            5,
            "diffuse color 0.5 0.5",
            "t.in:5: expected 'diffuse color r g b', found 'diffuse color 0.5 0.5'",
        ),
        (
            7,
            "material shine",
            "t.in:7: expected 'material shine s', found 'material shine'",
        ),
        (
            10,
            "v1 1.0 abc",
            "t.in:10: expected 'v1 x y z nx ny nz material', found 'v1 1.0 abc'",
        ),
        (
            10,
            "v2 1 0 0 0 0 1 0",
            "t.in:10: expected 'v1 x y z nx ny nz material', found 'v2 1 0 0 0 0 1 0'",
        ),
        (
            11,
            "v2 0 1 0 0 0 1",
            "t.in:11: expected 'v2 x y z nx ny nz material', found 'v2 0 1 0 0 0 1'",
        ),
        (
            12,
            "face normal 0 0",
            "t.in:12: expected 'face normal nx ny nz', found 'face normal 0 0'",
        ),
        (
            12,
            "normal 0 0 1",
            "t.in:12: expected 'face normal nx ny nz', found 'normal 0 0 1'",
        ),
    ];
    for (line, text, message) in cases {
        assert_eq!(parse(&with_line(line, text)).unwrap_err(), message);
    }
}

#[test]
fn non_finite_numbers_are_errors() {
    for (line, text) in [
        (9, "v0 nan 0 0 0 0 1 0"),
        (10, "v1 1 inf 0 0 0 1 0"),
        (11, "v2 0 1 0 0 -infinity 1 0"),
        (11, "v2 0 1e39 0 0 0 1 0"),
        (12, "face normal 0 NaN 1"),
        (4, "ambient color 0.1 nan 0.1"),
    ] {
        let error = parse(&with_line(line, text)).unwrap_err();
        assert!(
            error.starts_with(&format!("t.in:{line}: expected '"))
                && error.ends_with(&format!("found '{text}' (numbers must be finite)")),
            "{error}"
        );
    }
}

#[test]
fn material_indices_must_name_a_material() {
    for index in ["1", "-1", "0.5", "7"] {
        let text = format!("v1 1 0 0 0 0 1 {index}");
        let error = parse(&with_line(10, &text)).unwrap_err();
        assert_eq!(
            error,
            format!(
                "t.in:10: expected 'v1 x y z nx ny nz material', found '{text}' \
                 (the material index must be a whole number below the material count, 1)"
            )
        );
    }
    // Written as a float, a whole index is still an index.
    the_triangle(&parse(&with_line(10, "v1 1 0 0 0 0 1 0.0")).unwrap());
}

#[test]
fn a_truncated_triangle_is_an_error_at_the_missing_record() {
    let lines: Vec<&str> = TRIANGLE.lines().collect();
    for (kept, what) in [
        (9, "v1 x y z nx ny nz material"),
        (10, "v2 x y z nx ny nz material"),
        (11, "face normal nx ny nz"),
    ] {
        let text = lines[..kept].join("\n");
        assert_eq!(
            parse(&text).unwrap_err(),
            format!("t.in:{}: expected '{what}', found end of file", kept + 1)
        );
    }
    // A second triangle cut short fails the same way, not as a shorter mesh.
    let text = format!("{TRIANGLE}v0 0 0 0 0 0 1 0\nv1 1 0 0 0 0 1 0\n");
    assert_eq!(
        parse(&text).unwrap_err(),
        "t.in:15: expected 'v2 x y z nx ny nz material', found end of file"
    );
}

#[test]
fn a_file_without_triangles_is_an_error() {
    let header: String = TRIANGLE.lines().take(8).map(|l| format!("{l}\n")).collect();
    assert_eq!(
        parse(&header).unwrap_err(),
        "t.in:9: expected 'v0 x y z nx ny nz material', found end of file"
    );
    assert_eq!(
        parse("").unwrap_err(),
        "t.in:1: expected 'Object name = <name>', found end of file"
    );
}

#[test]
fn inward_vertex_normals_are_flipped_to_the_face_normal() {
    let model = parse(&with_line(10, "v1 1 0 0 0 0 -1 0")).unwrap();
    the_triangle(&model);
    assert_eq!(
        model.warnings,
        vec!["t.in: 1 vertex normals pointed against their face normal and were flipped"]
    );
}

#[test]
fn zero_normals_fall_back_to_the_face_normal_then_to_the_winding() {
    let zero_vertex = parse(&with_line(9, "v0 0 0 0 0 0 0 0")).unwrap();
    the_triangle(&zero_vertex);

    let zero_face = with_line(12, "face normal 0 0 0").replace(" 0 0 1 0\n", " 0 0 0 0\n");
    let model = parse(&zero_face).unwrap();
    the_triangle(&model);
    assert!(model.warnings.is_empty());
}

#[test]
fn normals_are_normalised_and_tilted_ones_kept() {
    let model = parse(&with_line(9, "v0 0 0 0 0 3 4 0")).unwrap();
    assert!(model.mesh.normals[0].abs_diff_eq(Vec3::new(0.0, 0.6, 0.8), 1e-6));
}

#[test]
fn a_face_normal_against_the_winding_is_reported() {
    // The face normal stays the reference for the vertex normals, which are flipped to it.
    let text = with_line(12, "face normal 0 0 -1");
    let model = parse(&text).unwrap();
    assert!(model.mesh.normals.iter().all(|&n| n == Vec3::NEG_Z));
    assert_eq!(
        model.warnings,
        vec![
            "t.in: 3 vertex normals pointed against their face normal and were flipped",
            "t.in: 1 face normals point against their triangle's winding",
        ]
    );
}

#[test]
fn material_values_out_of_range_are_a_warning() {
    let model = parse(&with_line(5, "diffuse color 1.5 0.5 0.5")).unwrap();
    the_triangle(&model);
    assert_eq!(
        model.warnings,
        vec![
            "t.in:5: material value out of range (colours 0..1, shine >= 0); ignored, the model is drawn in the chosen colour"
        ]
    );
}

#[test]
fn identical_corners_are_shared_across_triangles() {
    // Two triangles of a square share the diagonal's corners (same position, same normal).
    let text = format!(
        "{}v0 1 0 0 0 0 1 0\nv1 1 1 0 0 0 1 0\nv2 0 1 0 0 0 1 0\nface normal 0 0 1\n",
        with_line(2, "# triangles = 2")
    );
    let model = parse(&text).unwrap();
    assert_eq!(model.mesh.triangles, vec![[0, 1, 2], [1, 3, 2]]);
    assert_eq!(model.mesh.positions.len(), 4);
    assert!(model.warnings.is_empty());
}

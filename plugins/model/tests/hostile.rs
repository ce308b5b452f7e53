//! What a user's file can do to the loaders by accident or by malice: a header that lies by
//! billions, one endless line, bytes that are not UTF-8, OBJ references to nothing, NaN,
//! triangles without area, files that are not models at all. Each is a one-line error naming
//! the file (and the line, where there is one) or a documented, sane result; none panics.
//! (The memory these take is measured from outside, in the root crate's `tests/hostile_input.rs`.)

use std::path::PathBuf;

use close2gl_core::limits::MAX_LINE_BYTES;
use close2gl_core::{ModelSource, PrimitiveParams};
use close2gl_model::{LoadedModel, load, parse_in, parse_obj};

/// A file or directory of this test run's own, removed when dropped.
struct Temp(PathBuf);

impl Temp {
    fn file(name: &str, contents: &[u8]) -> Self {
        let temp = Self::path(name);
        std::fs::write(&temp.0, contents).expect("write a temp file");
        temp
    }

    fn path(name: &str) -> Self {
        Self(std::env::temp_dir().join(format!("close2gl_hostile_{}_{name}", std::process::id())))
    }

    fn load(&self) -> Result<LoadedModel, String> {
        load(
            &ModelSource::File(self.0.clone()),
            &PrimitiveParams::default(),
        )
    }

    fn label(&self) -> String {
        self.0.display().to_string()
    }
}

impl Drop for Temp {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
        let _ = std::fs::remove_dir(&self.0);
    }
}

/// A one-triangle `.in` file whose header says `triangles` and `materials`.
fn one_triangle_in(triangles: &str, materials: &str) -> String {
    format!(
        "Object name = T\n# triangles = {triangles}\nMaterial count = {materials}\n\
         ambient color 0.2 0.2 0.2\ndiffuse color 0.8 0.8 0.8\nspecular color 0 0 0\n\
         material shine 1\n-- comment\n\
         v0 0 0 0 0 0 1 0\nv1 1 0 0 0 0 1 0\nv2 0 1 0 0 0 1 0\nface normal 0 0 1\n"
    )
}

fn one_line(message: &str) {
    assert!(!message.contains('\n'), "one line: {message:?}");
}

#[test]
fn a_header_claiming_billions_of_triangles_is_only_a_warning() {
    for claim in ["4000000000", "18446744073709551615"] {
        let model = parse_in(&one_triangle_in(claim, "1"), "big.in").expect("loads");
        assert_eq!(model.mesh.triangles.len(), 1);
        assert_eq!(
            model.warnings,
            vec![format!("big.in: header says {claim} triangles, found 1")]
        );
    }
}

#[test]
fn a_header_claiming_billions_of_materials_fails_where_the_blocks_run_out() {
    for claim in ["4000000000", "18446744073709551615"] {
        let error = parse_in(&one_triangle_in("1", claim), "big.in").unwrap_err();
        assert_eq!(
            error,
            "big.in:8: expected 'ambient color r g b', found '-- comment'"
        );
    }
}

#[test]
fn negative_huge_and_non_numeric_counts_name_their_line() {
    for claim in ["-1", "4e9", "lots", "18446744073709551616", ""] {
        let error = parse_in(&one_triangle_in(claim, "1"), "m.in").unwrap_err();
        assert_eq!(
            error,
            format!(
                "m.in:2: expected '# triangles = <N>', found '{}'",
                format!("# triangles = {claim}").trim()
            )
        );
        let error = parse_in(&one_triangle_in("1", claim), "m.in").unwrap_err();
        assert!(
            error.starts_with("m.in:3: expected 'Material count = <M>'"),
            "{error}"
        );
    }
}

#[test]
fn one_endless_line_stops_at_the_line_limit_in_both_formats() {
    // Twice the limit with no newline: the loader must give up after the limit, not read on.
    let endless = vec![b'7'; 2 * MAX_LINE_BYTES];
    for name in ["endless.in", "endless.obj"] {
        let file = Temp::file(name, &endless);
        let error = file.load().unwrap_err();
        one_line(&error);
        assert!(
            error.starts_with(&format!(
                "{}:1: expected 'a line of at most {MAX_LINE_BYTES} bytes', found '7777",
                file.label()
            )),
            "{error}"
        );
    }
}

#[test]
fn invalid_utf8_in_a_record_is_an_error_at_its_line_and_elsewhere_harmless() {
    let mut bad_vertex = one_triangle_in("1", "1").into_bytes();
    let at = bad_vertex.windows(2).position(|w| w == b"v1").expect("v1");
    bad_vertex[at + 3] = 0xff;
    let file = Temp::file("bad_utf8.in", &bad_vertex);
    let error = file.load().unwrap_err();
    assert!(
        error.starts_with(&format!(
            "{}:10: expected 'v1 x y z nx ny nz material', found 'v1 \u{fffd}",
            file.label()
        )),
        "{error}"
    );

    // A name typed in Latin-1: shown with a replacement character, not refused.
    let text = one_triangle_in("1", "1");
    let (_, after_name) = text.split_once('\n').expect("lines");
    let file = Temp::file(
        "latin1.in",
        &[&b"Object name = caf\xe9\n"[..], after_name.as_bytes()].concat(),
    );
    assert_eq!(file.load().expect("loads").mesh.name, "caf\u{fffd}");

    let obj = Temp::file(
        "bad_utf8.obj",
        b"# caf\xe9\nv 0 0 0\nv 1 \xff 0\nv 0 1 0\nf 1 2 3\n",
    );
    let error = obj.load().unwrap_err();
    assert_eq!(
        error,
        format!(
            "{}:3: expected 'v x y z [w]', found 'v 1 \u{fffd} 0'",
            obj.label()
        )
    );
    let obj = Temp::file(
        "latin1.obj",
        b"# caf\xe9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
    );
    assert_eq!(obj.load().expect("loads").mesh.triangles.len(), 1);
}

const THREE_VERTICES: &str = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

#[test]
fn obj_references_out_of_range_negative_or_zero_name_their_line() {
    for (face, why) in [
        ("f 1 2 4", "v index 4 refers to no record: the file has 3"),
        (
            "f 1 2 99999999",
            "v index 99999999 refers to no record: the file has 3",
        ),
        (
            "f -1 -2 -4",
            "v index -4 refers to no record: the file has 3",
        ),
        ("f 0 1 2", "v index 0 refers to no record: the file has 3"),
        (
            "f 1/1 2/1 3/1",
            "vt index 1 refers to no record: the file has 0",
        ),
        (
            "f 1//2 2//2 3//2",
            "vn index 2 refers to no record: the file has 0",
        ),
    ] {
        let error = parse_obj(&format!("{THREE_VERTICES}{face}\n"), "m.obj").unwrap_err();
        assert_eq!(
            error,
            format!(
                "m.obj:4: expected 'f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...', found '{face}' ({why})"
            )
        );
    }
    // Beyond any integer: not a number at all.
    let face = "f 1 2 99999999999999999999999";
    let error = parse_obj(&format!("{THREE_VERTICES}{face}\n"), "m.obj").unwrap_err();
    assert_eq!(
        error,
        format!("m.obj:4: expected 'f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...', found '{face}'")
    );
}

#[test]
fn negative_obj_references_count_back_from_their_face() {
    let relative = parse_obj(&format!("{THREE_VERTICES}f -3 -2 -1\n"), "m.obj").expect("loads");
    let absolute = parse_obj(&format!("{THREE_VERTICES}f 1 2 3\n"), "m.obj").expect("loads");
    assert_eq!(relative.mesh, absolute.mesh);
}

#[test]
fn nan_and_infinite_coordinates_name_their_line_in_both_formats() {
    for number in ["nan", "NaN", "inf", "-inf", "1e39"] {
        let text = one_triangle_in("1", "1").replace("v1 1 0 0", &format!("v1 {number} 0 0"));
        let error = parse_in(&text, "m.in").unwrap_err();
        assert_eq!(
            error,
            format!(
                "m.in:10: expected 'v1 x y z nx ny nz material', found 'v1 {number} 0 0 0 0 1 0' \
                 (numbers must be finite)"
            )
        );
        let text = THREE_VERTICES.replace("v 1 0 0", &format!("v 1 {number} 0")) + "f 1 2 3\n";
        let error = parse_obj(&text, "m.obj").unwrap_err();
        assert_eq!(
            error,
            format!(
                "m.obj:2: expected 'v x y z [w]', found 'v 1 {number} 0' (numbers must be finite)"
            )
        );
    }
}

#[test]
fn zero_area_triangles_load_and_keep_unit_normals() {
    // All three corners on one point, and three on a line: kept (the pipeline's zero-area rule
    // culls them), with the face normal or, without one, +z.
    let text = one_triangle_in("2", "1")
        + "v0 1 1 1 0 0 0 0\nv1 1 1 1 0 0 0 0\nv2 1 1 1 0 0 0 0\nface normal 0 0 0\n";
    let model = parse_in(&text, "m.in").expect("loads");
    assert_eq!(model.mesh.triangles.len(), 2);
    let obj = parse_obj("v 0 0 0\nv 1 1 1\nv 2 2 2\nf 1 2 3\n", "m.obj").expect("loads");
    assert_eq!(obj.mesh.triangles.len(), 1);
    for mesh in [&model.mesh, &obj.mesh] {
        for normal in &mesh.normals {
            assert!((normal.length() - 1.0).abs() < 1e-6, "{normal}");
        }
    }
}

#[test]
fn garbage_and_empty_files_say_what_they_lack() {
    let cases: [(&str, &[u8], &str); 5] = [
        (
            "empty.in",
            b"",
            ":1: expected 'Object name = <name>', found end of file",
        ),
        (
            "empty.obj",
            b"",
            ": no triangles (faces need at least 3 vertices)",
        ),
        (
            "garbage.obj",
            b"hello, world\nthis is not a model\n\x89PNG\r\n\x1a\n",
            ": no triangles (faces need at least 3 vertices)",
        ),
        (
            "garbage.in",
            b"\x89PNG\r\n\x1a\n\x00\x00",
            ":1: expected 'Object name = <name>', found '\u{fffd}PNG'",
        ),
        (
            "only_header.in",
            b"Object name = X\n# triangles = 5\nMaterial count = 0\n",
            ":4: expected 'v0 x y z nx ny nz material', found end of file",
        ),
    ];
    for (name, contents, expected) in cases {
        let file = Temp::file(name, contents);
        let error = file.load().unwrap_err();
        assert_eq!(error, format!("{}{expected}", file.label()));
    }
}

#[test]
fn a_directory_or_a_missing_file_is_one_line_naming_it() {
    let directory = Temp::path("a_directory.obj");
    std::fs::create_dir_all(&directory.0).expect("mkdir");
    assert_eq!(
        directory.load().unwrap_err(),
        format!(
            "{}: expected a .in or .obj file, found a directory or device",
            directory.label()
        )
    );
    let missing = Temp::path("missing.in");
    let error = missing.load().unwrap_err();
    assert!(
        error.starts_with(&format!("{}: cannot read: ", missing.label())),
        "{error}"
    );
    one_line(&error);
}

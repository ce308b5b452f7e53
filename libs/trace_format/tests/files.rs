//! Reading real files: the label is the path as given, and a file's own faults (it cannot be
//! read, it is too big, it is not UTF-8) are `FormatError`s like a bad line's.

mod common;

use std::path::Path;

use close2gl_testkit::TempDir;
use close2gl_trace_format::{FormatError, parse_scene, read_scene, read_trace};
use common::{SCENE, TRACE};

#[test]
fn a_trace_file_reads_as_its_text_with_the_path_as_label() {
    let dir = TempDir::new("trace_file");
    let path = dir.write("cow.trace", TRACE.as_bytes());
    let trace = read_trace(&path).unwrap();
    assert_eq!(trace.file, path.display().to_string());
    assert_eq!(trace.window, (640, 480));

    let bad = dir.write("bad.trace", format!("{TRACE}tri 1\n").as_bytes());
    let error = read_trace(&bad).unwrap_err();
    assert_eq!(
        (error.file.as_str(), error.line),
        (bad.to_str().unwrap(), 11)
    );
    assert!(
        error
            .to_string()
            .starts_with(&format!("{}:11: expected", bad.display()))
    );
}

#[test]
fn a_scene_file_reads_and_finds_its_model_beside_it() {
    let dir = TempDir::new("scene_file");
    let path = dir.write("view.scene", SCENE.as_bytes());
    let scene = read_scene(&path).unwrap();
    assert_eq!(scene.file, path.display().to_string());
    assert_eq!(scene.model_path(&path), dir.join("cow.in"));

    let up = parse_scene(&SCENE.replace("cow.in", "../models/cow.in"), "s").unwrap();
    assert_eq!(
        up.model_path(Path::new("grading/view.scene")),
        Path::new("grading/../models/cow.in")
    );
    assert_eq!(
        up.model_path(Path::new("view.scene")),
        Path::new("../models/cow.in")
    );
    let absolute = parse_scene(&SCENE.replace("cow.in", "/data/cow.in"), "s").unwrap();
    assert_eq!(
        absolute.model_path(Path::new("grading/view.scene")),
        Path::new("/data/cow.in")
    );
}

#[test]
fn a_file_that_cannot_be_read_is_an_error_at_line_zero() {
    let dir = TempDir::new("unreadable");
    let missing = dir.join("missing.trace");
    let error = read_trace(&missing).unwrap_err();
    assert_eq!(
        (error.line, error.file.clone()),
        (0, missing.display().to_string())
    );
    assert!(
        error
            .to_string()
            .starts_with(&format!("{}:0: cannot read: ", missing.display())),
        "{error}"
    );
    // A directory opens on Linux and fails on the read.
    let error = read_scene(&dir).unwrap_err();
    assert_eq!(error.line, 0, "{error}");
    assert!(error.message.starts_with("cannot read: "), "{error}");
}

#[test]
fn bytes_that_are_not_utf8_are_named_by_their_line() {
    let dir = TempDir::new("not_utf8");
    let mut bytes = TRACE.as_bytes().to_vec();
    bytes.extend_from_slice(b"model caf\xe9.in\n");
    let path = dir.write("latin1.trace", &bytes);
    let error = read_trace(&path).unwrap_err();
    assert_eq!(
        error.to_string(),
        format!(
            "{}:11: expected UTF-8 text, found the byte 0xe9",
            path.display()
        )
    );
    let path = dir.write("binary.scene", b"\xff\xfe\x00c\x00l");
    let error = read_scene(&path).unwrap_err();
    assert_eq!(error.line, 1, "{error}");
}

#[test]
fn a_file_over_a_gibibyte_is_refused_before_it_is_read() {
    let dir = TempDir::new("huge");
    let path = dir.join("huge.trace");
    // Sparse: it takes no disk, and the reader must not read it to refuse it.
    let file = std::fs::File::create(&path).unwrap();
    file.set_len((1 << 30) + 1).unwrap();
    let error = read_trace(&path).unwrap_err();
    assert_eq!(
        error.to_string(),
        format!(
            "{}:0: expected a file of at most 1 GiB, found 1073741825 bytes",
            path.display()
        )
    );
}

/// The fuzzers start from these: each must read, or a campaign starts at the first line.
#[test]
fn the_fuzz_seeds_are_valid_files() {
    let seeds = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../fuzz/seeds");
    let trace: fn(&Path) -> Result<(), FormatError> = |p| read_trace(p).map(drop);
    let scene: fn(&Path) -> Result<(), FormatError> = |p| read_scene(p).map(drop);
    for (folder, read) in [("trace_parser", trace), ("scene_parser", scene)] {
        let files = std::fs::read_dir(seeds.join(folder)).unwrap();
        let mut count = 0;
        for file in files {
            let path = file.unwrap().path();
            read(&path).unwrap_or_else(|e| panic!("{e}"));
            count += 1;
        }
        assert!(count >= 3, "{folder}: {count} seeds");
    }
}

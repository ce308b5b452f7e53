//! The configuration: the documented defaults are the built-in ones, overrides apply in order,
//! and every bad key, type or range is a one-line error naming the key.

use std::path::Path;

use close2gl::config::{Config, load};
use close2gl::core::{
    CameraMode, ModelSource, Overlay, PrimitiveKind, Rasterizer, RenderMode, Shading,
};

fn with(overrides: &[&str]) -> Result<Config, String> {
    let overrides: Vec<String> = overrides.iter().map(|s| s.to_string()).collect();
    load(
        Some(Path::new(concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/config.toml"
        ))),
        &overrides,
    )
}

/// config.toml documents every key with its built-in default, except the two the first run
/// changes to show both views shaded (the file says so beside them).
#[test]
fn the_documented_config_is_the_default() {
    let documented = with(&[]).expect("config.toml loads");
    let mut first_run = Config::default();
    first_run.render.appearance.shading = Shading::Phong;
    first_run.render.pipeline.close2gl_raster = Rasterizer::Software;
    assert_eq!(documented, first_run);
}

#[test]
fn overrides_apply_in_order_and_bare_words_are_strings() {
    let c = with(&[
        "render.mode=points",
        "render.mode=wireframe",
        "camera.mode=look_at",
        "camera.hfov=45",
        "model.primitive=torus",
    ])
    .expect("valid overrides");
    assert_eq!(c.render.pipeline.mode, RenderMode::Wireframe);
    assert_eq!(c.camera.mode, CameraMode::LookAt);
    assert_eq!(c.camera.hfov, 45.0);
    assert_eq!(c.model, ModelSource::Primitive(PrimitiveKind::Torus));
    let c = with(&[
        "camera.position=[1, 2, 3]",
        "camera.near=0.5",
        "camera.far=9",
    ])
    .expect("a pose");
    assert_eq!(
        c.camera.pose().map(|p| p.position.to_array()),
        Some([1.0, 2.0, 3.0])
    );
}

#[test]
fn the_fate_view_reads_by_its_name_and_by_its_old_one() {
    for name in ["fate_view", "fates"] {
        let c = with(&[&format!("render.overlay={name}")]).expect("a known overlay");
        assert_eq!(c.render.overlay, Overlay::FateView, "{name}");
    }
    let error = with(&["render.overlay=fate"]).expect_err("an unknown overlay");
    assert!(error.contains("\"fate_view\""), "{error}");
}

#[test]
fn bad_values_name_the_key_and_the_allowed_range() {
    for (set, expected) in [
        (
            "camera.hfov=180",
            "camera.hfov: expected a number of degrees in 0.5..=170, found 180",
        ),
        (
            "camera.vfov=0",
            "camera.vfov: expected a number of degrees in 0.5..=170",
        ),
        ("camera.near=-1", "camera.near: expected a number > 0"),
        (
            "render.color=[1, 2, 0]",
            "render.color: expected [r, g, b], each in 0..1",
        ),
        (
            "render.mode=shaded",
            "render.mode: expected one of \"points\", \"wireframe\", \"solid\", found \"shaded\"",
        ),
        (
            "render.backface_culling=yes",
            "render.backface_culling: expected true or false, found string",
        ),
        (
            "camera.hfov=wide",
            "camera.hfov: expected a number, found string",
        ),
        ("camera.zoom=2", "camera.zoom: unknown key"),
        ("nosection=1", "expected section.key=value"),
        (
            "window.width=0",
            "window.width: expected an integer in 1..=16384, found 0",
        ),
    ] {
        let error = with(&[set]).expect_err(set);
        assert!(error.contains(expected), "{set}: {error}");
        assert!(!error.contains('\n'), "one line: {error}");
    }
    let error = with(&["camera.near=5", "camera.far=1"]).expect_err("near >= far");
    assert!(
        error.contains("camera.near") && error.contains("camera.far"),
        "{error}"
    );
}

#[test]
fn a_bad_file_names_the_file_and_line() {
    let dir = close2gl_testkit::TempDir::new("config");
    let file = dir.join("bad.toml");
    for (text, expected) in [
        ("[camera]\nhfov = 60\nvfov = = 3\n", "bad.toml:3:"),
        (
            "[render]\nmode = \"solid\"\nsparkle = true\n",
            "bad.toml: render.sparkle: unknown key",
        ),
        ("[teapot]\nx = 1\n", "bad.toml: teapot.x: unknown key"),
    ] {
        std::fs::write(&file, text).expect("write");
        let error = load(Some(&file), &[]).expect_err(text);
        assert!(error.contains(expected), "{text:?}: {error}");
    }
    let missing = load(Some(&dir.join("missing.toml")), &[]).expect_err("missing file");
    assert!(missing.contains("missing.toml: cannot read"), "{missing}");
}

/// Found by the fuzzer (`fuzz/`, target `config`): keys, values and `--set` items are quoted in
/// errors as typed, and a newline in them (a shell argument, a quoted TOML key or string) made
/// the error two lines. Control characters now show as '?'.
#[test]
fn control_characters_in_keys_and_values_keep_the_error_on_one_line() {
    let overrides = |items: &[&str]| items.iter().map(|s| s.to_string()).collect::<Vec<_>>();
    for (text, items, expected) in [
        (
            "",
            overrides(&["\u{8}\u{8}\n=0.0"]),
            "--set ???=0.0: expected",
        ),
        ("", overrides(&["render.mode=\"a\nb\""]), "a?b"),
        (
            "",
            overrides(&["rend\ner.mode=1"]),
            "--set rend?er.mode: unknown key",
        ),
        (
            "[render]\n\"mo\\nde\" = 1\n",
            Vec::new(),
            "t.toml: render.mo?de: unknown key",
        ),
        ("[render]\nmode = \"x\\ry\"\n", Vec::new(), "found \"x?y\""),
    ] {
        let error =
            close2gl::config::load_text(text, "t.toml", Path::new("."), &items).expect_err(text);
        assert!(!error.contains(['\n', '\r']), "one line: {error:?}");
        assert!(error.contains(expected), "{text:?} {items:?}: {error}");
    }
}

/// Found by the fuzzer (`fuzz/`, target `config`): `camera.rotate_speed=1e38` was accepted (any
/// number > 0), and on the first frame 1e38 · 360 · dt overflowed to infinity times zero: the
/// camera's basis became NaN and both views went blank. The speeds now keep to the panel's
/// ranges.
#[test]
fn camera_speeds_keep_to_the_panels_ranges() {
    for (set, expected) in [
        (
            "camera.rotate_speed=1e38",
            "camera.rotate_speed: expected a number in 0.01..=10, found 1",
        ),
        (
            "camera.move_speed=1e38",
            "camera.move_speed: expected a number in 0.01..=100, found 1",
        ),
        (
            "camera.move_speed=0",
            "camera.move_speed: expected a number in 0.01..=100, found 0",
        ),
    ] {
        let error = with(&[set]).expect_err(set);
        assert!(error.contains(expected), "{set}: {error}");
    }
    let c = with(&["camera.rotate_speed=10", "camera.move_speed=100"]).expect("the panel's maxima");
    assert_eq!(
        (c.camera.speeds.rotate_speed, c.camera.speeds.move_speed),
        (10.0, 100.0)
    );
}

//! The command line as a user meets it: `close2gl stats` prints the pipeline's counts as JSON,
//! and bad input stops with a one-line error and exit code 2.

use std::process::{Command, Output};

use close2gl_testkit::TempDir;
use serde_json::Value;

fn close2gl(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .expect("the binary runs")
}

fn stats(args: &[&str]) -> Value {
    let out = close2gl(&[&["stats"], args].concat());
    assert!(
        out.status.success(),
        "stats {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("one JSON object")
}

#[test]
fn stats_counts_a_box_seen_from_a_corner() {
    let s = stats(&[
        "box",
        "--size",
        "400x300",
        "--set",
        "camera.position=[3, 2, 4]",
    ]);
    assert_eq!(s["triangles_in"], 12);
    assert_eq!(s["clipped"], 0);
    assert_eq!(s["culled"], 6);
    assert_eq!(s["drawn"], 6);
    assert_eq!(s["output_primitives"], 6);
    let b: Vec<f64> = serde_json::from_value(s["bounds_px"].clone()).expect("bounds");
    assert!(
        b[0] > 0.0 && b[1] > 0.0 && b[2] < 400.0 && b[3] < 300.0 && b[0] < b[2] && b[1] < b[3],
        "{b:?}"
    );
}

#[test]
fn culling_off_draws_every_triangle_and_cw_draws_the_back() {
    let pose = ["box", "--set", "camera.position=[3, 2, 4]"];
    let off = stats(&[&pose[..], &["--set", "render.backface_culling=false"]].concat());
    assert_eq!(
        (off["drawn"].as_u64(), off["culled"].as_u64()),
        (Some(12), Some(0))
    );
    let cw = stats(&[&pose[..], &["--set", "render.front_face=cw"]].concat());
    assert_eq!(cw["drawn"], 6);
}

#[test]
fn simple_clipping_drops_what_full_clipping_cuts() {
    // A camera inside the sphere: every triangle near the view's borders is cut.
    let pose = [
        "sphere",
        "--set",
        "camera.position=[0, 0, 0.5]",
        "--set",
        "camera.target=[0, 0, -1]",
        "--set",
        "render.backface_culling=false",
    ];
    let full = stats(&[&pose[..], &["--set", "render.clipping=full"]].concat());
    let simple = stats(&[&pose[..], &["--set", "render.clipping=simple"]].concat());
    assert!(
        simple["clipped"].as_u64() > full["clipped"].as_u64(),
        "{simple} vs {full}"
    );
    assert!(
        full["output_primitives"].as_u64() > full["drawn"].as_u64(),
        "cut triangles become several: {full}"
    );
}

#[test]
fn points_and_wireframe_count_their_primitives() {
    let points = stats(&[
        "box",
        "--set",
        "camera.position=[3, 2, 4]",
        "--set",
        "render.mode=points",
    ]);
    assert_eq!(points["output_primitives"], 18);
    let lines = stats(&[
        "box",
        "--set",
        "camera.position=[3, 2, 4]",
        "--set",
        "render.mode=wireframe",
    ]);
    assert_eq!(lines["output_primitives"], 18);
}

#[test]
fn dump_writes_the_2d_buffer() {
    let dir = TempDir::new("cli");
    let json = dir.join("buffer.json");
    stats(&[
        "box",
        "--set",
        "camera.position=[3, 2, 4]",
        "--dump",
        json.to_str().expect("utf-8"),
    ]);
    let dumped: Value =
        serde_json::from_str(&std::fs::read_to_string(&json).expect("written")).expect("JSON");
    assert_eq!(dumped["topology"], "triangles");
    assert_eq!(dumped["vertices"].as_array().map(Vec::len), Some(18));
    let csv = dir.join("buffer.csv");
    stats(&[
        "box",
        "--set",
        "camera.position=[3, 2, 4]",
        "--dump",
        csv.to_str().expect("utf-8"),
    ]);
    assert_eq!(
        std::fs::read_to_string(&csv)
            .expect("written")
            .lines()
            .count(),
        19
    );
}

/// With the software rasterizer, stats also says how long it took and how many pixels it
/// covered: the box from a corner covers a good part of a small view; seen from behind (front
/// faces clockwise, so all six visible faces are culled), nothing.
#[test]
fn stats_with_the_software_rasterizer_reports_its_pixels() {
    let software = [
        "box",
        "--size",
        "80x60",
        "--set",
        "camera.position=[3, 2, 4]",
        "--set",
        "render.close2gl_raster=software",
    ];
    let s = stats(&software);
    let covered = s["covered_pixels"].as_u64().expect("covered_pixels");
    // The box's outline spans about 19 × 14 pixels of the 80 × 60 view.
    assert!((100..=400).contains(&covered), "{s}");
    assert!(s["raster_ms"].as_f64().is_some_and(|ms| ms >= 0.0), "{s}");
    let s = stats(&[&software[..], &["--set", "render.mode=points"]].concat());
    let points = s["covered_pixels"].as_u64().expect("covered_pixels");
    assert!(
        (1..=7).contains(&points),
        "six visible faces share 7 corners: {s}"
    );
    let gpu = stats(&[&software[..5], &["--set", "render.close2gl_raster=gpu"]].concat());
    assert!(gpu.get("covered_pixels").is_none(), "{gpu}");
}

#[test]
fn bench_load_times_a_model_file_into_its_mesh() {
    let dir = TempDir::new("cli");
    let grid_in = dir.join("grid.in");
    let grid_obj = dir.join("grid.obj");
    let written = [
        close2gl_testkit::write_grid_in(&grid_in, "grid", 40).expect("write the .in grid"),
        close2gl_testkit::write_grid_obj(&grid_obj, "grid", 40).expect("write the .obj grid"),
    ];
    for (path, grid) in [grid_in, grid_obj].iter().zip(written) {
        let path = path.to_str().expect("utf-8");
        let out = close2gl(&["bench", "--load", path, "--frames", "3"]);
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        let report: Value = serde_json::from_slice(&out.stdout).expect("one JSON object");
        let load = &report["load"];
        assert_eq!(load["file"], path, "{report}");
        assert_eq!(load["bytes"], grid.bytes, "{report}");
        assert_eq!(load["triangles"], grid.triangles, "{report}");
        assert_eq!(load["vertices"], grid.vertices, "{report}");
        let ms = load["median_ms"].as_f64().expect("median_ms");
        let mb_per_s = load["mb_per_s"].as_f64().expect("mb_per_s");
        assert!(ms > 0.0, "{report}");
        let implied = grid.bytes as f64 / 1e6 / (ms / 1e3);
        assert!((mb_per_s / implied - 1.0).abs() < 1e-9, "{report}");
    }
}

#[test]
fn bench_raster_grid_draws_the_generated_big_model() {
    let out = close2gl(&[
        "bench",
        "--raster",
        "--grid",
        "--triangles",
        "2000",
        "--frames",
        "2",
        "--size",
        "96x64",
        "--set",
        "render.shading=phong",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let report: Value = serde_json::from_slice(&out.stdout).expect("one JSON object");
    // 32 × 32 squares of two triangles: the nearest grid of at least 2,000.
    assert_eq!(report["triangles"], 2048, "{report}");
    assert_eq!(report["model"], "grid of 2048 triangles", "{report}");
    assert_eq!(report["shading"], "phong", "{report}");
    assert!(
        report["software_median_ms"]
            .as_f64()
            .is_some_and(|ms| ms > 0.0),
        "{report}"
    );
}

#[test]
fn bad_input_is_one_line_and_exit_code_2() {
    let dir = TempDir::new("cli");
    let bad_model = dir.join("bad.in");
    std::fs::write(&bad_model, "Object name = X\n# triangles = 1\nMaterial count = 1\nambient color 0 0 0\ndiffuse color 1 1 1\nspecular color 0 0 0\nmaterial shine 0\n-- cols\nv0 1.0 abc 0 0 0 1 0\n").expect("write");
    for (args, expected) in [
        (vec!["stats", "--set", "camera.hfov=200"], "camera.hfov"),
        (
            vec!["stats", "--set", "render.colour=[1,1,1]"],
            "render.colour: unknown key",
        ),
        (vec!["stats", "no/such/model.obj"], "no/such/model.obj"),
        (
            vec!["stats", bad_model.to_str().expect("utf-8")],
            "bad.in:9:",
        ),
        (vec!["stats", "--size", "0x10"], "--size 0x10"),
        (vec!["stats", "model.stl"], "model.stl"),
        (
            vec!["stats", "--set", "render.close2gl_raster=vulkan"],
            "render.close2gl_raster",
        ),
        (vec!["bench", "--raster", "--fill"], "--fill"),
        (vec!["bench", "--grid"], "--raster"),
        (
            vec!["bench", "--raster", "--grid", "assets/cube.in"],
            "--grid",
        ),
        (
            vec!["bench", "--load", "assets/cube.in", "--fill"],
            "--load",
        ),
        (
            vec!["bench", "--load", bad_model.to_str().expect("utf-8")],
            "bad.in:9:",
        ),
        (
            vec!["bench", "--load", "no/such/grid.in"],
            "no/such/grid.in",
        ),
        (vec!["stats", "--set", "outside.stage=3"], "outside.stage"),
        (
            vec!["stats", "--set", "outside.stage=\"clip\""],
            "\"world\", \"eye\", \"ndc\"",
        ),
        (
            vec!["render", "--view", "inside", "--out", "/nonexistent"],
            "--view",
        ),
        (
            vec!["render", "--stage", "4", "--out", "/nonexistent"],
            "--stage",
        ),
    ] {
        let out = close2gl(&args);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
        assert!(stderr.contains(expected), "{args:?}: {stderr}");
        assert_eq!(stderr.trim().lines().count(), 1, "{args:?}: {stderr}");
        assert!(!stderr.contains("panicked"), "{stderr}");
    }
}

#[test]
fn render_view_outside_writes_the_picture_and_the_volumes_corners() {
    let dir = TempDir::new("cli");
    let out_dir = dir.join("outside");
    let dir = out_dir.to_str().expect("utf-8");
    let near = 2.0f64;
    let out = close2gl(&[
        "render",
        "box",
        "--size",
        "160x120",
        "--view",
        "outside",
        "--stage",
        "ndc",
        "--set",
        "camera.position=[0, 0, 5]",
        "--set",
        "camera.target=[0, 0, 0]",
        "--set",
        "camera.near=2",
        "--set",
        "camera.far=9",
        "--set",
        "camera.hfov=90",
        "--set",
        "camera.vfov=60",
        "--out",
        dir,
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let report: Value = serde_json::from_slice(&out.stdout).expect("one JSON object");
    assert_eq!(report["outside_stage"], 2.0);
    assert!(out_dir.join("outside.png").is_file());
    let corners: Vec<[f64; 3]> =
        serde_json::from_value(report["frustum_world"].clone()).expect("eight corners");
    // The near corners at z = 5 - near, x = ±near·tan(45°), y = ±near·tan(30°), in the NDC
    // corners' order: x fastest, then y, near before far.
    let (x, y) = (near, near * 30f64.to_radians().tan());
    for (corner, expected) in corners[..4].iter().zip([
        [-x, -y, 5.0 - near],
        [x, -y, 5.0 - near],
        [-x, y, 5.0 - near],
        [x, y, 5.0 - near],
    ]) {
        for (a, b) in corner.iter().zip(expected) {
            assert!((a - b).abs() < 1e-4, "{corner:?} != {expected:?}");
        }
    }
    assert!(
        corners[4..].iter().all(|c| (c[2] + 4.0).abs() < 1e-4),
        "far at z = -4"
    );
}

/// `render.mistake` makes Close2GL's stage make a classic mistake: inverted culling keeps the
/// back faces, a field of view not halved draws the model three times smaller, and every
/// mistake of the catalogue runs (and keeps the triangle count).
#[test]
fn stats_with_a_mistake_shows_its_symptom() {
    let args = [
        "box",
        "--size",
        "400x300",
        "--set",
        "camera.position=[3, 2, 4]",
    ];
    let with = |mistake: &str| {
        let set = format!("render.mistake={mistake}");
        stats(&[&args[..], &["--set", &set]].concat())
    };
    let right = stats(&args);
    let inverted = with("culling_inverted");
    assert_eq!(
        (inverted["culled"].clone(), inverted["drawn"].clone()),
        (right["drawn"].clone(), right["culled"].clone())
    );
    let width =
        |s: &Value| s["bounds_px"][2].as_f64().unwrap() - s["bounds_px"][0].as_f64().unwrap();
    let ratio = width(&right) / width(&with("fov_not_halved"));
    assert!(
        (2.5..3.5).contains(&ratio),
        "tan(60°)/tan(30°) = 3, found {ratio}"
    );
    for mistake in close2gl::core::Mistake::ALL {
        assert_eq!(
            with(mistake.name())["triangles_in"],
            12,
            "{}",
            mistake.name()
        );
    }
}

/// Every command's help names its modes, and bench's exclusive modes are refused together
/// (clap's own error, exit code 2) before anything runs.
#[test]
fn help_names_every_mode_and_bench_refuses_two_at_once() {
    let help = |args: &[&str]| {
        let out = close2gl(args);
        assert!(out.status.success(), "{args:?}");
        String::from_utf8_lossy(&out.stdout).into_owned()
    };
    let top = help(&["--help"]);
    for (command, modes) in [
        ("bench", &["--raster", "--grid", "--fill", "--load"][..]),
        ("inspect", &["--triangle", "--pixel"]),
        ("grade", &["--submissions"]),
    ] {
        let line = top
            .lines()
            .find(|l| l.trim_start().starts_with(command))
            .unwrap_or_else(|| panic!("{command} in {top}"));
        for mode in modes {
            assert!(
                line.contains(mode),
                "close2gl --help: {command} names {mode}: {line}"
            );
            assert!(
                help(&[command, "--help"]).contains(mode),
                "{command} --help: {mode}"
            );
        }
    }
    for refused in [
        &["bench", "--raster", "--fill"][..],
        &["bench", "--fill", "--load", "assets/cube.in"],
        &["bench", "--grid"],
        &["bench", "--raster", "--grid", "box"],
    ] {
        let out = close2gl(refused);
        assert_eq!(out.status.code(), Some(2), "{refused:?}");
    }
}

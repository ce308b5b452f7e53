//! The pipeline inspector, headless: a scene with one triangle of each fate gets exactly those
//! fates from `inspect --triangle`, from `stats` and from the `Fates` resource of a headless
//! World; the reference's matrices equal Close2GL's; and the pixel probe agrees with the GPU's
//! own ID pass where the two views agree, and names what simple clipping removed.

use std::path::PathBuf;
use std::process::{Command, Output};
use std::sync::OnceLock;

use close2gl::core::{
    Camera, Fates, Mesh, PipelineSettings, RecordFates, Scene, SoftwareFrame, Viewport,
};
use close2gl::raster::SoftwareRasterizer;
use close2gl::raster::coverage_probe::{Drawn, PixelOutcome, PixelProbe, probe};
use close2gl_gpu::{Gpu, OffscreenPlugin, probe_reference, render_offscreen};
use serde_json::Value;

/// One triangle per fate, seen from the origin looking down -z (90° both ways, near 1, far 10,
/// 100×100 pixels: at z = -5 a world unit is 10 pixels).
const SCENE: &str = "\
v -1 -1 2\nv 1 -1 2\nv 0 1 2
v -4 2 -5\nv -2 2 -5\nv -0.3 0.4 -0.5
v -9 0 -5\nv -7 0 -5\nv -8 1 -5
v 7 0 -5\nv 9 0 -5\nv 8 1 -5
v 0 -9 -5\nv 1 -9 -5\nv 0.5 -8 -5
v 0 7 -5\nv 1 7 -5\nv 0.5 8 -5
v -1 -1 -15\nv 1 -1 -15\nv 0 1 -15
v 2 2 -5\nv 2 4 -5\nv 4 2 -5
v -4 -2 -5\nv 0 -2 -5\nv -2 -2.00001 -5
v -2.94 -1.06 -5\nv -2.94 -1.09 -5\nv -2.91 -1.06 -5
v 1 -3 -4\nv 3.5 -3 -4\nv 2.25 -0.5 -4
v 2.88 -3.84 -6\nv 3.84 -3.84 -6\nv 3.36 -3 -6
v -4 -4 -5\nv -2 -4 -5\nv -3 -3 -5
v 4 -1 -5\nv 6 -1 -5\nv 5 0.5 -5
";

/// Each triangle's expected fate with the software rasterizer, and its planes.
const FATES: [(&str, &[&str]); 14] = [
    ("clipped", &[]), // behind the eye: checked apart (every plane test fails at once)
    ("cut", &["near"]),
    ("clipped", &["left"]),
    ("clipped", &["right"]),
    ("clipped", &["bottom"]),
    ("clipped", &["top"]),
    ("clipped", &["far"]),
    ("culled", &[]),
    ("zero_area", &[]),
    ("no_pixels", &[]), // smaller than a pixel, between centres
    ("drawn", &[]),     // in front of the next one
    ("hidden", &[]),
    ("drawn", &[]),
    ("cut", &["right"]),
];

const VIEW: [&str; 12] = [
    "--size",
    "100x100",
    "--set",
    "camera.position=[0, 0, 0]",
    "--set",
    "camera.target=[0, 0, -1]",
    "--set",
    "camera.near=1",
    "--set",
    "camera.far=10",
    "--set",
    "render.close2gl_raster=software",
];
const SIZE: Viewport = Viewport {
    width: 100,
    height: 100,
};
const FOV: [&str; 4] = ["--set", "camera.hfov=90", "--set", "camera.vfov=90"];

/// The scene as an OBJ file, written once for all the tests (which run in parallel).
fn scene_file() -> PathBuf {
    static FILE: OnceLock<PathBuf> = OnceLock::new();
    FILE.get_or_init(|| {
        // In the build's own scratch folder: the file is shared by the tests for the process.
        let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR")).join("inspector");
        std::fs::create_dir_all(&dir).expect("temp dir");
        let path = dir.join("fates.obj");
        let faces: String = (0..14)
            .map(|t| format!("f {} {} {}\n", 3 * t + 1, 3 * t + 2, 3 * t + 3))
            .collect();
        std::fs::write(&path, format!("{SCENE}{faces}")).expect("write the scene");
        path
    })
    .clone()
}

fn close2gl(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .env_remove("WAYLAND_DISPLAY")
        .output()
        .expect("the binary runs")
}

fn json(command: &str, extra: &[&str]) -> Value {
    let model = scene_file();
    let model = model.to_str().expect("a UTF-8 path");
    let args = [&[command, model][..], &VIEW, &FOV, extra].concat();
    let out = close2gl(&args);
    assert!(
        out.status.success(),
        "{args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("one JSON object")
}

fn names(value: &Value) -> Vec<&str> {
    let list = value.as_array().expect("a list");
    list.iter().map(|v| v.as_str().expect("a name")).collect()
}

#[test]
fn inspect_names_each_triangles_fate_and_planes() {
    for (index, (fate, planes)) in FATES.iter().enumerate() {
        let j = json("inspect", &["--triangle", &index.to_string()]);
        assert_eq!(j["triangle"], index, "{j}");
        assert_eq!(j["fate"], *fate, "triangle {index}: {j}");
        if index == 0 {
            assert_eq!(j["behind_eye"], true, "{j}");
            assert!(names(&j["planes"]).contains(&"near"), "{j}");
        } else {
            assert_eq!(names(&j["planes"]), *planes, "triangle {index}: {j}");
        }
    }
}

#[test]
fn inspect_shows_the_near_cut_step_by_step() {
    let j = json("inspect", &["--triangle", "1"]);
    let steps = j["clip_steps"].as_array().expect("steps");
    assert_eq!(steps.len(), 1, "{j}");
    assert_eq!(steps[0]["plane"], "near");
    // One corner behind the near plane: the triangle becomes a quad, every vertex on or in
    // front of it (z >= -w), and the window has its four corners.
    let quad = steps[0]["polygon"].as_array().expect("polygon");
    assert_eq!(quad.len(), 4, "{j}");
    for p in quad {
        let p: [f32; 4] = serde_json::from_value(p.clone()).expect("x, y, z, w");
        assert!(p[2] >= -p[3] - 1e-5, "{p:?} is behind the near plane");
    }
    assert_eq!(j["window"].as_array().map(Vec::len), Some(4), "{j}");
    assert!(j["signed_area"].as_f64().is_some_and(|a| a < 0.0), "{j}");
}

/// Glam's look-at and perspective against Close2GL's own M and P: equal to 1e-5 (f32 rounding
/// of the same formulas; P compared after the depth range's remap to wgpu's 0..1).
#[test]
fn the_reference_matrices_equal_close2gls() {
    let j = json("inspect", &["--triangle", "12"]);
    let difference = &j["matrices"]["max_difference"];
    for which in ["view", "projection"] {
        let d = difference[which].as_f64().expect("a number");
        assert!(d <= 1e-5, "{which}: {d}");
    }
    assert_eq!(
        j["matrices"]["V"][1],
        serde_json::json!([0.0, -50.0, 0.0, 50.0])
    );
}

#[test]
fn inspect_rejects_a_triangle_out_of_range_and_a_pixel_off_the_view() {
    let model = scene_file();
    let model = model.to_str().expect("a UTF-8 path");
    for question in [["--triangle", "14"], ["--pixel", "100,3"], ["--pixel", "x"]] {
        let out = close2gl(&[&["inspect", model][..], &VIEW, &question].concat());
        assert_eq!(out.status.code(), Some(2), "{question:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(err.contains(question[0]), "{err}");
    }
}

#[test]
fn stats_counts_each_fate() {
    let s = json("stats", &[]);
    let fates = &s["fates"];
    let expected = [
        ("drawn", 2),
        ("cut", 2),
        ("clipped", 6),
        ("culled", 1),
        ("zero_area", 1),
        ("no_pixels", 1),
        ("hidden", 1),
    ];
    for (name, count) in expected {
        assert_eq!(fates[name], count, "{name}: {s}");
    }
    // With the GPU drawing Close2GL's view, nobody can tell no_pixels or hidden.
    let gpu = json("stats", &["--set", "render.close2gl_raster=gpu"]);
    assert_eq!(
        (
            gpu["fates"]["no_pixels"].as_u64(),
            gpu["fates"]["hidden"].as_u64()
        ),
        (Some(0), Some(0))
    );
    assert_eq!(gpu["fates"]["drawn"], 4, "{gpu}");
}

#[test]
fn render_reports_the_same_fates_as_stats() {
    let out = scene_file().with_file_name("render");
    let render = json("render", &["--out", out.to_str().expect("UTF-8")]);
    assert_eq!(render["fates"], json("stats", &[])["fates"], "{render}");
}

/// The scene as a headless World, fates recorded.
fn world_app(extra: &[&str]) -> close2gl::core::App {
    let model = scene_file();
    let sets: Vec<String> = [&VIEW[2..], &FOV[..], extra]
        .concat()
        .chunks(2)
        .map(|pair| pair[1].to_string())
        .collect();
    let mut config = close2gl::config::load(None, &sets).expect("the settings");
    config.model = close2gl::core::ModelSource::parse(model.to_str().expect("UTF-8"));
    let mut app = close2gl::build_app(&config, SIZE).expect("the scene");
    app.world_mut().resource_mut::<RecordFates>().0 = true;
    app.update();
    app
}

#[test]
fn the_fates_resource_holds_each_triangles_fate() {
    let app = world_app(&[]);
    let fates = app.world().resource::<Fates>();
    assert_eq!(fates.triangles.len(), 14);
    for (index, (fate, _)) in FATES.iter().enumerate() {
        assert_eq!(
            fates.triangles[index].kind.name(),
            *fate,
            "triangle {index}"
        );
    }
    assert!(fates.triangles[0].behind_eye);
    assert!(
        fates.triangles[7].signed_area > 0.0,
        "a back face: clockwise on screen"
    );
}

/// The scene both views draw, and the pieces the probes need.
struct Probed {
    app: close2gl::core::App,
    gpu: Gpu,
    mesh: Mesh,
    camera: Camera,
    settings: PipelineSettings,
}

fn probed(extra: &[&str]) -> Probed {
    let mut app = world_app(extra);
    let gpu = Gpu::headless(close2gl_gpu::wgpu::Backends::PRIMARY).expect("a GPU adapter");
    app.add_plugins(OffscreenPlugin(gpu.clone()));
    let world = app.world_mut();
    let mesh = world.query::<&Mesh>().single(world).expect("mesh").clone();
    let camera = *world.query::<&Camera>().single(world).expect("camera");
    let settings = *world.resource::<PipelineSettings>();
    Probed {
        app,
        gpu,
        mesh,
        camera,
        settings,
    }
}

impl Probed {
    /// Close2GL's probe, its winner from the software rasterizer's id buffer.
    fn close2gl(&self, x: u32, y: u32) -> PixelProbe {
        self.close2gl_probe(x, y, true)
    }

    /// Close2GL's probe; with `from_rasterizer` false, its winner worked out by the probe
    /// itself (as when the GPU draws Close2GL's 2D buffer).
    fn close2gl_probe(&self, x: u32, y: u32, from_rasterizer: bool) -> PixelProbe {
        let world = self.app.world();
        let scene = Scene {
            mesh: &self.mesh,
            camera: &self.camera,
            pipeline: &self.settings,
            viewport: SIZE,
        };
        let drawn = Drawn {
            rasterizer: world.resource::<SoftwareRasterizer>(),
            image: world.resource::<SoftwareFrame>(),
        };
        let fates = world.resource::<Fates>();
        probe(scene, fates, (x, y), from_rasterizer.then_some(drawn))
    }

    fn reference(&self, x: u32, y: u32) -> Option<u32> {
        let scene = Scene {
            mesh: &self.mesh,
            camera: &self.camera,
            pipeline: &self.settings,
            viewport: SIZE,
        };
        probe_reference(&self.gpu, scene, (x, y))
            .expect("the reference probe")
            .map(|hit| hit.triangle)
    }
}

#[test]
fn the_probes_winners_agree_where_the_views_agree() {
    let mut p = probed(&[]);
    let snapshot = render_offscreen(&mut p.app).expect("both views");
    let (mut compared, mut covered) = (0, 0);
    // Every third pixel: the reference's ID pass draws the whole view for each probe.
    for y in (1..100).step_by(3) {
        for x in (1..100).step_by(3) {
            let (r, c) = (
                snapshot.reference.pixel(x, y),
                snapshot.close2gl.pixel(x, y),
            );
            if r != c {
                continue;
            }
            compared += 1;
            let close2gl = p.close2gl(x, y);
            covered += usize::from(close2gl.triangle.is_some());
            assert_eq!(
                close2gl.triangle,
                p.reference(x, y),
                "pixel {x},{y}: {close2gl:?}"
            );
        }
    }
    assert!(
        covered > 20 && compared > 1000,
        "{covered} covered of {compared}"
    );
}

#[test]
fn the_probe_names_what_simple_clipping_removed() {
    // Triangle 13 straddles the right border: simple clipping drops it, the GPU draws it.
    let p = probed(&["--set", "render.clipping=simple"]);
    let (x, y) = (95, 57);
    assert_eq!(p.reference(x, y), Some(13));
    let close2gl = p.close2gl(x, y);
    assert_eq!(close2gl.triangle, None, "{close2gl:?}");
    let candidate = close2gl.candidates.iter().find(|c| c.triangle == 13);
    assert_eq!(
        candidate.map(|c| c.outcome),
        Some(PixelOutcome::Clipped),
        "{close2gl:?}"
    );
    // And where triangle 10 hides 11, the probe says who lost the depth test.
    let hidden = p.close2gl(78, 80);
    let outcomes: Vec<_> = hidden
        .candidates
        .iter()
        .map(|c| (c.triangle, c.outcome))
        .collect();
    assert_eq!(
        outcomes,
        [(10, PixelOutcome::Won), (11, PixelOutcome::Depth)]
    );
}

#[test]
fn the_probes_own_winner_is_the_rasterizers() {
    let p = probed(&[]);
    let mut covered = 0;
    for (x, y) in (0..100).flat_map(|y| (0..100).map(move |x| (x, y))) {
        let (drawn, computed) = (p.close2gl(x, y), p.close2gl_probe(x, y, false));
        assert_eq!(
            computed.triangle, drawn.triangle,
            "pixel {x},{y}: {computed:?}"
        );
        covered += usize::from(drawn.triangle.is_some());
    }
    assert!(covered > 300, "{covered}");
}

/// Two triangles sharing a diagonal through pixel centres: on the diagonal, one draws the
/// centre and the top-left rule gives it away from the other, which the probe says.
#[test]
fn the_probe_names_the_fill_rule_on_a_shared_edge() {
    let square =
        "v -2.95 2.95 -5\nv -2.95 0.95 -5\nv -0.95 0.95 -5\nv -0.95 2.95 -5\nf 1 2 3\nf 1 3 4\n";
    let path = scene_file().with_file_name("square.obj");
    std::fs::write(&path, square).expect("write the square");
    let model = path.to_str().expect("UTF-8");
    let args = [&["inspect", model][..], &VIEW, &FOV, &["--pixel", "30,30"]].concat();
    let out = close2gl(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let j: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let mut outcomes: Vec<&str> = j["close2gl"]["candidates"]
        .as_array()
        .expect("candidates")
        .iter()
        .map(|c| c["outcome"].as_str().expect("an outcome"))
        .collect();
    outcomes.sort();
    assert_eq!(outcomes, ["fill_rule", "won"], "{j}");
    assert_eq!(j["agree"], true, "{j}");
}

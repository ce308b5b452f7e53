//! `check` on `examples/raster/raster.c`, the rasterizer assignment in one C program, run as a
//! real process: built right, in double and in float, it agrees with nothing named on every
//! bundled model in every shading, every texture filter, and three window sizes; built with each
//! catalogue mistake, check names that mistake on a scene that shows it (the table of
//! docs/checking.md), and with the pairs docs/checking.md lists, both.

use std::path::{Path, PathBuf};
use std::process::Command;

use close2gl_check::raster::{check_raster, report};
use close2gl_core::RasterMistake;
use close2gl_testkit::TempDir;
use close2gl_testkit::student::{asset, compile_raster, mistake_flag, repository};
use close2gl_trace_format::read_raster_frame;
use rayon::prelude::*;

fn examples() -> PathBuf {
    repository().join("examples/raster")
}

/// A sample scene of `examples/raster/` with its `window` line replaced (when given) and its
/// files named by absolute paths, written into `dir`.
fn scene(dir: &Path, name: &str, window: Option<(u32, u32)>) -> PathBuf {
    let text =
        std::fs::read_to_string(examples().join(format!("{name}.scene"))).expect("a sample scene");
    let lines: Vec<String> = (text.lines())
        .map(
            |line| match line.split_whitespace().collect::<Vec<_>>()[..] {
                ["window", _, _] if window.is_some() => {
                    let (w, h) = window.unwrap_or_default();
                    format!("window {w} {h}")
                }
                [key @ ("model" | "texture"), path] => {
                    format!("{key} {}", examples().join(path).display())
                }
                _ => line.to_string(),
            },
        )
        .collect();
    let size = window.map_or(String::new(), |(w, h)| format!("_{w}x{h}"));
    let path = dir.join(format!("{name}{size}.scene"));
    std::fs::write(&path, lines.join("\n") + "\n").expect("write a scene");
    path
}

/// A scene of a bundled model, framed, in `shading` (and textured with the sample checkerboard
/// with `filter`, when given).
fn model_scene(dir: &Path, model: &str, shading: &str, filter: Option<&str>) -> PathBuf {
    let mut text = format!(
        "close2gl-scene 1\nmodel {}\nwindow 128 96\ncamera framed\norbit u 0.3\nshading {shading}\nbackground 0.1 0.1 0.2\n",
        asset(model).display()
    );
    if let Some(filter) = filter {
        let texture = examples().join("checker.ppm");
        text += &format!("texture {}\nfilter {filter}\n", texture.display());
    }
    let path = dir.join(format!(
        "{model}_{shading}_{}.scene",
        filter.unwrap_or("plain")
    ));
    std::fs::write(&path, text).expect("write a scene");
    path
}

/// Runs `program` on `scene`; the report's verdict and names.
fn run(program: &Path, scene: &Path, dir: &Path) -> (bool, Vec<&'static str>, String) {
    let name = format!(
        "{}.{}.trace",
        program
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or("program"),
        scene
            .file_stem()
            .and_then(|n| n.to_str())
            .unwrap_or("scene")
    );
    let trace = dir.join(name);
    let status = Command::new(program)
        .arg(scene)
        .arg(&trace)
        .status()
        .expect("run raster");
    assert!(
        status.success(),
        "{} {}: {status}",
        program.display(),
        scene.display()
    );
    let frame = read_raster_frame(&trace).unwrap_or_else(|e| panic!("{e}"));
    let checked = check_raster(&frame);
    let text = report::text(&checked, &trace.display().to_string());
    (checked.agrees(), checked.mistakes(), text)
}

#[test]
fn the_right_program_agrees_everywhere_in_double_and_in_float() {
    let dir = TempDir::new("raster-right");
    let builds = [
        compile_raster(&dir.0, "raster", &[]),
        compile_raster(&dir.0, "raster-float", &["-DRASTER_FLOAT"]),
    ];
    let mut scenes = Vec::new();
    for name in [
        "square",
        "twice",
        "cube",
        "knot",
        "knot_far_light",
        "floor_nearest",
        "floor_bilinear",
        "floor_trilinear",
    ] {
        scenes.push(scene(&dir.0, name, None));
    }
    for size in [(61, 47), (200, 150), (320, 240)] {
        scenes.push(scene(&dir.0, "knot", Some(size)));
        scenes.push(scene(&dir.0, "floor_trilinear", Some(size)));
    }
    for model in ["cube.in", "knot.obj", "far_away.in", "textured_cube.in"] {
        for shading in ["none", "gouraud_ad", "gouraud_ads", "phong"] {
            scenes.push(model_scene(&dir.0, model, shading, None));
        }
    }
    for filter in ["nearest", "bilinear", "trilinear"] {
        scenes.push(model_scene(
            &dir.0,
            "textured_cube.in",
            "phong",
            Some(filter),
        ));
    }
    let runs: Vec<(&PathBuf, &PathBuf)> = builds
        .iter()
        .flat_map(|b| scenes.iter().map(move |s| (b, s)))
        .collect();
    let wrong: Vec<String> = (runs.par_iter())
        .filter_map(|(build, scene)| {
            let (agrees, named, text) = run(build, scene, &dir.0);
            (!agrees || !named.is_empty()).then_some(text)
        })
        .collect();
    assert!(
        wrong.is_empty(),
        "the right program did not agree:\n{}",
        wrong.join("\n")
    );
}

/// The sample scene that shows each mistake (docs/checking.md's table).
fn showing(m: RasterMistake) -> &'static str {
    use RasterMistake as M;
    match m {
        M::FillRuleInclusive | M::FillRuleExclusive => "square",
        M::NoAttenuation => "knot_far_light",
        M::NearestRounds => "floor_nearest",
        M::NoWrapBlack | M::LodAbsolute | M::PhongAffine | M::ViewportEdgeSkipped => {
            "floor_trilinear"
        }
        M::NormalNotRenormalized | M::NoSpecular | M::ViewerAtInfinity | M::ColourNotClamped => {
            "knot"
        }
        _ => "cube",
    }
}

#[test]
fn each_mistake_build_is_named_alone_and_in_the_listed_pairs() {
    let dir = TempDir::new("raster-mistakes");
    let mut runs: Vec<(Vec<RasterMistake>, &str)> = RasterMistake::catalogue()
        .iter()
        .map(|&m| (vec![m], showing(m)))
        .collect();
    use RasterMistake as M;
    runs.extend([
        (vec![M::DepthPerspective, M::UvAffine], "floor_trilinear"),
        (vec![M::TNotFlipped, M::ChannelsSwapped], "cube"),
        (vec![M::LightInWorld, M::NoSpecular], "knot"),
        (vec![M::PhongAffine, M::LodOneAxis], "floor_trilinear"),
    ]);
    let missed: Vec<String> = (runs.par_iter())
        .filter_map(|(mistakes, scene_name)| {
            let flags: Vec<String> = mistakes.iter().map(|m| mistake_flag(m.name())).collect();
            let flags: Vec<&str> = flags.iter().map(String::as_str).collect();
            let names: Vec<&str> = mistakes.iter().map(|m| m.name()).collect();
            let program = compile_raster(&dir.0, &format!("raster-{}", names.join("-")), &flags);
            let scene = scene(&dir.0, scene_name, None);
            let (agrees, named, text) = run(&program, &scene, &dir.0);
            let all_named = names.iter().all(|n| named.contains(n));
            (agrees || !all_named)
                .then(|| format!("{} on {scene_name}:\n{text}", names.join(" + ")))
        })
        .collect();
    assert!(missed.is_empty(), "not named:\n{}", missed.join("\n"));
}

//! `close2gl grade --rubric` on the rasterizer assignment: `examples/raster/raster.c` built right
//! and with catalogue mistakes, run in the sandbox on `assets/rubrics/rasterizer/`'s scenes. The right
//! program scores 200; each mistake build scores what was written below before it was ever
//! graded (each mistake costs the lines whose stages it belongs to, on the scenes that show it);
//! a teacher's edited rubric changes the points as written.

use std::path::{Path, PathBuf};
use std::process::Command;

use close2gl::core::RasterMistake;
use close2gl_check::raster::rubric::Rubric;
use close2gl_testkit::TempDir;
use close2gl_testkit::student::{compile_raster, mistake_flag, repository};
use serde_json::Value;

fn rubric() -> PathBuf {
    repository().join("assets/rubrics/rasterizer/rubric.toml")
}

/// `close2gl grade --rubric RUBRIC --run 'PROGRAM {scene} {trace}' --json`: the JSON.
fn grade(rubric: &Path, program: &Path) -> Value {
    let output = Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .args(["grade", "--json", "--rubric"])
        .arg(rubric)
        .arg("--run")
        .arg(format!("{} {{scene}} {{trace}}", program.display()))
        .output()
        .expect("run close2gl grade");
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).expect("grade's JSON")
}

/// The lines that lost points, as `id=points`, sorted; and the total.
fn lost(grade: &Value) -> (Vec<String>, u64) {
    let lines = grade["lines"].as_array().expect("lines");
    let mut lost: Vec<String> = (lines.iter())
        .filter(|l| l["points"] != l["max"])
        .map(|l| format!("{}={}", l["id"].as_str().unwrap_or("?"), l["points"]))
        .collect();
    lost.sort();
    (lost, grade["total"].as_u64().unwrap_or(0))
}

#[test]
fn the_right_program_scores_200_and_each_mistake_what_was_written_first() {
    let dir = TempDir::new("grade-raster");
    // Written before grading, in three sittings (the first four; the next six; the other 29):
    // the lines each build loses (their stages are the mistake's), and the total. 29 of the 39
    // held; the ten that did not are corrected to what grade gave, each with its prediction
    // and why it was wrong beside it (in every case a scene the prediction thought would show
    // the mistake, or would not; never a line outside the mistake's stages).
    let expected: &[(&str, &[&str], u64)] = &[
        ("", &[], 200),
        (
            "depth_perspective",
            &["resize=0", "synchronized=1", "zbuffer=10"],
            151,
        ),
        (
            "uv_affine",
            &[
                "resize=7",
                "synchronized=9",
                "texture_bilinear=0",
                "texture_nearest=0",
                "texture_trilinear=0",
            ],
            121,
        ),
        (
            "fill_rule_inclusive",
            &["coverage=16", "synchronized=13"],
            189,
        ),
        // The floors reach the last column, the knot_phong and knot_flat knots the top row.
        (
            "viewport_edge_skipped",
            &["coverage=16", "resize=0", "synchronized=7"],
            168,
        ),
        // Wherever triangles overlap: the cubes (culling off), the knots, the equal squares.
        // predicted zbuffer=0 synchronized=5 (172); twice passes: "less or equal", a legal rule, draws the equal second square too.
        (
            "no_depth_test",
            &["resize=7", "synchronized=6", "zbuffer=10"],
            163,
        ),
        // Phong's pixels and Gouraud ADS's corners (cube_gouraud_ads, floor_gouraud).
        // predicted gouraud=8 synchronized=10 (145); floor_gouraud's corners are far from a highlight.
        (
            "blinn_phong",
            &["gouraud=16", "phong=0", "resize=7", "synchronized=11"],
            154,
        ),
        // Every textured scene.
        (
            "t_not_flipped",
            &[
                "resize=7",
                "synchronized=9",
                "texture_bilinear=0",
                "texture_nearest=0",
                "texture_trilinear=0",
            ],
            121,
        ),
        // Everywhere red and blue differ (not the white knots on black, nor twice): output costs
        // only the lines about everything.
        ("channels_swapped", &["resize=7", "synchronized=3"], 180),
        // Every depth buffer.
        (
            "depth_ndc",
            &["resize=0", "synchronized=0", "zbuffer=0"],
            140,
        ),
        // Exact ties only where corners sit on pixel centres: the square and the twice square.
        (
            "fill_rule_exclusive",
            &["coverage=16", "synchronized=13"],
            189,
        ),
        // Every scene moves or loses pixels.
        // predicted coverage=0 synchronized=0 (145); the square moved half a pixel covers the same centres, its edges then through them.
        (
            "pixel_corner_samples",
            &["coverage=8", "resize=0", "synchronized=1"],
            154,
        ),
        (
            "vertices_rounded",
            &["coverage=0", "resize=0", "synchronized=0"],
            145,
        ),
        // predicted coverage=0 synchronized=0 (145); the square truncated to whole pixels covers the same 47 × 47 centres.
        (
            "vertices_truncated",
            &["coverage=8", "resize=0", "synchronized=1"],
            154,
        ),
        (
            "bounding_box_short",
            &["coverage=0", "resize=0", "synchronized=0"],
            145,
        ),
        // Depth mistakes show in every depth buffer, and cost only the lines about depth.
        (
            "depth_cleared_to_zero",
            &["resize=0", "synchronized=0", "zbuffer=0"],
            140,
        ),
        (
            "farthest_wins",
            &["resize=0", "synchronized=0", "zbuffer=0"],
            140,
        ),
        (
            "depth_not_written",
            &["resize=0", "synchronized=0", "zbuffer=0"],
            140,
        ),
        // Large slanted Gouraud triangles: the floor and the cube.
        ("colour_affine", &["gouraud=8", "synchronized=13"], 181),
        // The Phong cube's flat faces (its position, not its normal); the knot's are too small.
        ("phong_affine", &["phong=12", "synchronized=14"], 186),
        // Every scene with a varying: Gouraud, Phong, textures (not the flat ones, nor twice).
        (
            "weights_rotated",
            &[
                "gouraud=0",
                "phong=0",
                "resize=0",
                "synchronized=3",
                "texture_bilinear=0",
                "texture_nearest=0",
                "texture_trilinear=0",
            ],
            58,
        ),
        (
            "no_interpolation",
            &[
                "gouraud=0",
                "phong=0",
                "resize=0",
                "synchronized=3",
                "texture_bilinear=0",
                "texture_nearest=0",
                "texture_trilinear=0",
            ],
            58,
        ),
        // The knot's smooth normals, per pixel.
        (
            "normal_not_renormalized",
            &["phong=12", "resize=7", "synchronized=13"],
            177,
        ),
        // Every lit scene (the far light's corners too: their tolerance is tight).
        (
            "light_in_world",
            &["gouraud=0", "phong=0", "resize=7", "synchronized=8"],
            135,
        ),
        // The specular term: Phong's pixels, Gouraud ADS's corners.
        // predicted gouraud=8 phong=0 synchronized=10 (145); no lit corner is near a highlight, nor the Phong cube's faces.
        (
            "no_specular",
            &["phong=12", "resize=7", "synchronized=13"],
            177,
        ),
        // Faces turned from the light: the cubes and the knots.
        // predicted phong=0 (145); the Phong cube shows no face turned from its light.
        (
            "diffuse_unclamped",
            &["gouraud=8", "phong=12", "resize=7", "synchronized=10"],
            157,
        ),
        // predicted gouraud=16 synchronized=11 (154); floor_gouraud shows it too.
        (
            "specular_unclamped",
            &["gouraud=8", "phong=0", "resize=7", "synchronized=10"],
            145,
        ),
        // Only the far light attenuates.
        ("no_attenuation", &["gouraud=16", "synchronized=14"], 190),
        // predicted gouraud=8 phong=0 synchronized=10 (145); as no_specular: the corners and the cube's faces hold no highlight.
        (
            "viewer_at_infinity",
            &["phong=12", "resize=7", "synchronized=13"],
            177,
        ),
        // The texture lines' own scenes.
        (
            "nearest_rounds",
            &["synchronized=13", "texture_nearest=0"],
            178,
        ),
        (
            "bilinear_no_half_texel",
            &[
                "resize=7",
                "synchronized=11",
                "texture_bilinear=0",
                "texture_trilinear=0",
            ],
            143,
        ),
        // Coordinates beyond [0, 1]: the floors; clamping shows on the cube's edges too.
        (
            "no_wrap_black",
            &[
                "resize=7",
                "synchronized=11",
                "texture_bilinear=0",
                "texture_nearest=10",
                "texture_trilinear=12",
            ],
            145,
        ),
        // predicted texture_nearest=0 synchronized=9 (121); nearest on the cube never samples its edge texels.
        (
            "clamp_not_repeat",
            &[
                "resize=7",
                "synchronized=10",
                "texture_bilinear=0",
                "texture_nearest=10",
                "texture_trilinear=0",
            ],
            132,
        ),
        // Magnified only near the floor's camera.
        // predicted texture_trilinear=12 synchronized=13 (177); the cube is magnified in places too.
        (
            "lod_absolute",
            &["resize=7", "synchronized=12", "texture_trilinear=0"],
            164,
        ),
        (
            "lod_one_axis",
            &["resize=7", "synchronized=12", "texture_trilinear=0"],
            164,
        ),
        (
            "lod_unscaled",
            &["resize=7", "synchronized=12", "texture_trilinear=0"],
            164,
        ),
        (
            "mip_nearest_level",
            &["resize=7", "synchronized=12", "texture_trilinear=0"],
            164,
        ),
        // Upside down: all but the two symmetric squares; output costs the lines about everything.
        ("rows_bottom_first", &["resize=0", "synchronized=1"], 171),
        // Above 1: Phong's white knot, the near-lit squares.
        ("colour_not_clamped", &["resize=7", "synchronized=12"], 189),
    ];
    let text = std::fs::read_to_string(rubric()).expect("the bundled rubric");
    let parsed = Rubric::parse(&text, "rubric.toml").expect("the bundled rubric reads");
    let mut wrong = Vec::new();
    for &(mistake, lines, total) in expected {
        let flags = match mistake {
            "" => Vec::new(),
            m => vec![mistake_flag(m)],
        };
        let flags: Vec<&str> = flags.iter().map(String::as_str).collect();
        let program = compile_raster(&dir.0, &format!("raster-{mistake}"), &flags);
        let graded = grade(&rubric(), &program);
        let (lost, got) = lost(&graded);
        let lines: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
        if lost != lines || got != total {
            wrong.push(format!(
                "{mistake}: expected {lines:?} = {total}, graded {lost:?} = {got}\n{graded:#}"
            ));
        }
        // Whatever the prediction: a mistake costs only the lines about its stage.
        let stage = RasterMistake::from_name(mistake).map(RasterMistake::stage);
        for id in lost.iter().filter_map(|l| l.split('=').next()) {
            let line = parsed
                .lines
                .iter()
                .find(|l| l.id == id)
                .expect("a rubric line");
            if let Some(stage) = stage.filter(|s| !line.stages.contains(s)) {
                wrong.push(format!("{mistake} ({}) cost {id}", stage.name()));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn a_teachers_edited_rubric_changes_the_points_as_written() {
    let dir = TempDir::new("grade-raster-edited");
    let scenes = dir.0.join("scenes");
    std::fs::create_dir_all(&scenes).expect("a scenes folder");
    let bundled = repository().join("assets/rubrics/rasterizer/scenes");
    for entry in std::fs::read_dir(&bundled).expect("the bundled scenes") {
        let path = entry.expect("a scene").path();
        let text = std::fs::read_to_string(&path).expect("a scene's text");
        // The copy names its model and texture by absolute paths.
        let text: Vec<String> = (text.lines())
            .map(|l| match l.split_whitespace().collect::<Vec<_>>()[..] {
                [key @ ("model" | "texture"), file] => {
                    format!("{key} {}", bundled.join(file).display())
                }
                _ => l.to_string(),
            })
            .collect();
        std::fs::write(
            scenes.join(path.file_name().expect("a name")),
            text.join("\n"),
        )
        .expect("copy");
    }
    let edited = std::fs::read_to_string(rubric())
        .expect("the bundled rubric")
        .replace(
            "points = 30\nstages = [\"depth\"]",
            "points = 50\nstages = [\"depth\"]",
        );
    std::fs::write(dir.0.join("rubric.toml"), edited).expect("the edited rubric");
    let program = compile_raster(
        &dir.0,
        "raster",
        &[mistake_flag("depth_perspective").as_str()],
    );
    let graded = grade(&dir.0.join("rubric.toml"), &program);
    assert_eq!(graded["max"], 220);
    let zbuffer = &graded["lines"][1];
    assert_eq!(
        (
            zbuffer["id"].as_str(),
            zbuffer["max"].as_u64(),
            zbuffer["points"].as_u64()
        ),
        (Some("zbuffer"), Some(50), Some(16))
    );
}

/// The `expect-grade [-DVARIANT]: 200 | LINE=POINTS ...` lines of a corpus program's header, as
/// (flags, the lines that lose points, sorted).
fn expected_grades(program: &Path) -> Vec<(Vec<String>, Vec<String>)> {
    let text = std::fs::read_to_string(program).expect("a corpus program");
    (text.lines())
        .filter_map(|line| {
            line.trim_start_matches([' ', '/', '*', '#'])
                .strip_prefix("expect-grade")
        })
        .map(|rest| {
            let (flags, points) = rest
                .split_once(':')
                .expect("'expect-grade [FLAGS]: POINTS'");
            let flags = flags.split_whitespace().map(String::from).collect();
            let mut lost: Vec<String> = (points.split_whitespace())
                .filter(|w| *w != "200")
                .map(String::from)
                .collect();
            lost.sort();
            (flags, lost)
        })
        .collect()
}

#[test]
fn the_rasterizer_corpus_scores_what_its_headers_say() {
    let dir = TempDir::new("grade-raster-corpus");
    let examples = repository().join("examples");
    let corpus = examples.join("corpus/raster");
    let include: Vec<String> = ["trace", "raster", "corpus/raster"]
        .iter()
        .map(|p| format!("-I{}", examples.join(p).display()))
        .collect();
    let numpy = Command::new("/usr/bin/python3")
        .args(["-c", "import numpy"])
        .status();
    let mut wrong = Vec::new();
    for name in ["c_scanline.c", "cpp_barycentric.cpp", "py_numpy.py"] {
        let source = corpus.join(name);
        if name.ends_with(".py") && !numpy.as_ref().is_ok_and(|s| s.success()) {
            eprintln!("skipping {name}: /usr/bin/python3 has no numpy (CI installs python3-numpy)");
            continue;
        }
        for (flags, lost) in expected_grades(&source) {
            let mut all: Vec<&str> = include.iter().map(String::as_str).collect();
            all.extend(flags.iter().map(String::as_str));
            let out = dir.0.join(format!("{name}{}", flags.concat()));
            let command = match name.rsplit('.').next() {
                Some("c") => format!(
                    "{} {{scene}} {{trace}}",
                    close2gl_testkit::student::compile_c(&source, &out, &all).display()
                ),
                Some("cpp") => format!(
                    "{} {{scene}} {{trace}}",
                    close2gl_testkit::student::compile_cpp(&source, &out, &all).display()
                ),
                _ => {
                    let path = ["trace", "raster", "corpus/raster"]
                        .map(|p| examples.join(p).display().to_string())
                        .join(":");
                    format!(
                        "/usr/bin/env PYTHONPATH={path} /usr/bin/python3 {} {{scene}} {{trace}} {}",
                        source.display(),
                        flags.join(" ")
                    )
                }
            };
            let output = Command::new(env!("CARGO_BIN_EXE_close2gl"))
                .args(["grade", "--json", "--time-limit", "60", "--rubric"])
                .arg(rubric())
                .arg("--allow-read")
                .arg(&examples)
                .args(["--run", &command])
                .output()
                .expect("run close2gl grade");
            let graded: Value = serde_json::from_slice(&output.stdout)
                .unwrap_or_else(|_| panic!("{}", String::from_utf8_lossy(&output.stderr)));
            let (got, _) = self::lost(&graded);
            if got != lost {
                wrong.push(format!(
                    "{name} {flags:?}: expected {lost:?}, graded {got:?}"
                ));
            }
        }
    }
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn a_class_grades_into_a_csv_a_row_per_submission() {
    let dir = TempDir::new("grade-raster-class");
    let class = dir.0.join("class");
    for (name, flags) in [
        ("ana", vec![]),
        ("bo", vec![mistake_flag("depth_perspective")]),
    ] {
        std::fs::create_dir_all(class.join(name)).expect("a submission's folder");
        let flags: Vec<&str> = flags.iter().map(String::as_str).collect();
        compile_raster(&class.join(name), "raster", &flags);
    }
    let output = Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .args(["grade", "--rubric"])
        .arg(rubric())
        .args(["--run", "{dir}/raster {scene} {trace}", "--submissions"])
        .arg(&class)
        .output()
        .expect("run close2gl grade");
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let csv = std::fs::read_to_string(class.join("grades.csv")).expect("grades.csv");
    let rows: Vec<&str> = csv.lines().collect();
    assert_eq!(
        rows[0],
        "submission,coverage,zbuffer,gouraud,phong,texture_nearest,texture_bilinear,texture_trilinear,resize,synchronized,total"
    );
    assert_eq!(rows[1], "ana,25,30,25,25,20,20,25,15,15,200");
    assert_eq!(rows[2], "bo,25,10,25,25,20,20,25,0,1,151");
}

//! `close2gl grade` as a teacher meets it: the student program of `examples/trace/` compiled
//! with the system's C compiler (correct, with each catalogue mistake, turning the other way
//! round, in float32, drawing fans), hostile programs, and a class of thirty submissions. The
//! binary runs as a process, with `TMPDIR` pointing into the test's own directory so that what
//! its runs leave behind can be seen.
//!
//! What each build should lose is written down here from the rubric's rules (which line judges
//! which stage, which scenes show which stage) and checked against what grade says, line by
//! line and point by point; the cube keeps the runs short (one scene per mode, six moves, ...).

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};
use std::time::{Duration, Instant};

use close2gl::core::Mistake;
use close2gl_testkit::TempDir;
use close2gl_testkit::student::{asset, compile_c, compile_pipeline, mistake_flag, repository};
use serde_json::Value;

/// Runs `close2gl grade ARGS` with TMPDIR = `tmp`; its output and how long it took.
fn grade(args: &[&str], tmp: &Path) -> (Output, Duration) {
    std::fs::create_dir_all(tmp).expect("make TMPDIR");
    let started = Instant::now();
    let output = Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .arg("grade")
        .args(args)
        .env("TMPDIR", tmp)
        .output()
        .expect("run close2gl grade");
    (output, started.elapsed())
}

/// `grade --json` of `program` on `models`; its JSON.
fn grade_json(program: &Path, models: &[&str], dir: &Path) -> Value {
    let command = format!("'{}' {{scene}} {{trace}}", program.display());
    let mut args = vec!["--run", &command, "--json", "--jobs", "2"];
    let models: Vec<String> = models
        .iter()
        .map(|m| asset(m).display().to_string())
        .collect();
    for model in &models {
        args.extend(["--model", model.as_str()]);
    }
    let (output, _) = grade(&args, &dir.join("tmp"));
    assert!(
        output.status.success(),
        "grade failed: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).expect("grade --json prints JSON")
}

fn line<'a>(grade: &'a Value, id: &str) -> &'a Value {
    let lines = grade["lines"].as_array().expect("lines");
    lines
        .iter()
        .find(|l| l["id"] == id)
        .expect("every line is there")
}

const LINES: [&str; 12] = [
    "points",
    "wireframe",
    "solid",
    "translation",
    "lookat_translation",
    "rotation",
    "culling",
    "hfov",
    "vfov",
    "simple_clipping",
    "resize",
    "synchronized",
];

/// A mistake that changes M, P, V, the camera or the clip coordinates in every scene: its
/// frame is never close2gl's, so every scene fails `synchronized`.
fn every_frame(m: Mistake) -> bool {
    use Mistake::*;
    matches!(
        m,
        FovNotHalved
            | FovInDegrees
            | ModelviewTransposed
            | TranslationSign
            | LeftHanded
            | ProductOrder
            | DepthRowSign
            | ViewportYFlipped
            | ViewportFullScale
    )
}

/// Whether mistake `m` fails `line` in the cube's scene `name` (the id after `cube/`).
fn fails_on_cube(m: Mistake, line: &str, name: &str) -> bool {
    use Mistake::*;
    // What the 2D output shows from the framed camera (equal fovs, culling off, all in view).
    let picture = every_frame(m) && m != DepthRowSign;
    let fov = matches!(m, FovNotHalved | FovInDegrees | FovsSwapped | ProductOrder);
    // Clipping mistakes show where the cube reaches outside the view volume: the clipping
    // scenes (divide_before_clip only where a corner is before near or behind the eye), and
    // from inside it.
    let clipping = match m {
        NoClipping => name.starts_with("clipping-"),
        DivideBeforeClip => name == "clipping-near" || name == "clipping-behind-eye",
        _ => false,
    };
    let inside = name.ends_with("-inside");
    let culling = match m {
        CullingInverted => name.starts_with("culling-") && !name.contains("-off-"),
        // From inside with cw every face in view is front: drawing them all is right there.
        NeverCulls => {
            name.starts_with("culling-") && !name.contains("-off-") && name != "culling-cw-inside"
        }
        // Counter-clockwise front whatever is declared: wrong only where cw is.
        CullingIgnoresFrontFace => name.starts_with("culling-cw-"),
        // Only a side face seen from outside has n square to its normal, which the view-axis
        // test keeps and ccw culls; with cw both keep it, and from inside it is clipped.
        CullingByViewAxis => name == "culling-ccw-outside",
        // The cube's file normals are its windings': the two tests agree.
        _ => false,
    };
    match line {
        "points" | "wireframe" | "solid" => picture,
        "translation" => matches!(
            m,
            ModelviewTransposed | TranslationUnrotated | TranslationSign | LeftHanded
        ),
        "lookat_translation" | "rotation" => m == LeftHanded,
        "culling" => culling,
        "hfov" => fov || m == AspectFromAngles,
        "vfov" => fov,
        "simple_clipping" => clipping,
        "resize" => matches!(m, ViewportYFlipped | ViewportFullScale),
        "synchronized" => {
            every_frame(m)
                || culling
                || clipping
                || (matches!(m, NoClipping | DivideBeforeClip) && inside)
                || (matches!(m, FovsSwapped | AspectFromAngles) && name.starts_with("fov-"))
                || (m == TranslationUnrotated && is_motion(name))
        }
        _ => unreachable!("no line {line}"),
    }
}

/// The motion scenes start from the turned camera, where -c is not (-c·u, -c·v, -c·n).
fn is_motion(name: &str) -> bool {
    ["translation-", "lookat_translation-", "rotation-"]
        .iter()
        .any(|p| name.starts_with(p))
}

/// Each line's expected points and scenes passed for a build with `mistakes`, on the cube's
/// scenes as `grade` lists them.
fn expected_on_cube(mistakes: &[Mistake], scenes: &Value) -> Vec<(u64, u64)> {
    let scenes = scenes.as_array().expect("scenes");
    LINES
        .iter()
        .map(|&line| {
            let names: Vec<&str> = scenes
                .iter()
                .filter(|s| s["lines"].get(line).is_some())
                .map(|s| s["id"].as_str().unwrap_or("").trim_start_matches("cube/"))
                .collect();
            let passed = names
                .iter()
                .filter(|n| !mistakes.iter().any(|&m| fails_on_cube(m, line, n)))
                .count() as u64;
            let max = match line {
                "points" | "wireframe" | "solid" | "simple_clipping" => 10,
                "translation" | "hfov" | "vfov" | "resize" => 15,
                "lookat_translation" => 20,
                "culling" | "synchronized" => 25,
                _ => 30,
            };
            (max * passed / names.len() as u64, passed)
        })
        .collect()
}

/// Asserts every line's points and passed scenes are as expected; their total.
fn assert_lines(grade: &Value, expected: &[(u64, u64)], build: &str) -> u64 {
    for (id, (points, passed)) in LINES.iter().zip(expected) {
        let line = line(grade, id);
        assert_eq!(
            (line["points"].as_u64(), line["passed"].as_u64()),
            (Some(*points), Some(*passed)),
            "{build}: line {id}: {line:#}"
        );
    }
    expected.iter().map(|(points, _)| points).sum()
}

#[test]
fn the_correct_program_scores_200_on_the_bundled_models() {
    let dir = TempDir::new("grade_correct");
    let program = compile_pipeline(&dir, "pipeline", &[]);
    let command = format!("'{}' {{scene}} {{trace}}", program.display());
    let (output, elapsed) = grade(&["--run", &command, "--jobs", "2"], &dir.join("tmp"));
    let table = String::from_utf8_lossy(&output.stdout);
    eprintln!("{table}graded in {elapsed:?}");
    assert!(output.status.success());
    assert!(
        table.contains("total                                    200/200"),
        "{table}"
    );
    assert!(table.contains("Synchronized with the reference            25/25   156/156"));
}

#[test]
fn each_mistake_loses_exactly_its_lines_and_is_named() {
    let dir = TempDir::new("grade_mistakes");
    for &mistake in &Mistake::ALL[1..] {
        let name = mistake.name();
        let program = compile_pipeline(&dir, name, &[&mistake_flag(name)]);
        let grade = grade_json(&program, &["cube.in"], &dir);
        if mistake == Mistake::CullingByFileNormals {
            assert_eq!(
                grade["total"], 200,
                "the cube's file normals are its windings'"
            );
            continue;
        }
        let expected = expected_on_cube(&[mistake], &grade["scenes"]);
        let total = assert_lines(&grade, &expected, name);
        assert_eq!(grade["total"].as_u64(), Some(total));
        assert!(total < 200, "{name} costs points");
        for id in LINES {
            let line = line(&grade, id);
            let named: Vec<&str> = line["mistakes"]
                .as_array()
                .map(|m| m.iter().filter_map(Value::as_str).collect())
                .unwrap_or_default();
            let lost = line["points"] != line["max"];
            assert!(
                !lost || named.contains(&name),
                "{name}: line {id} names {named:?}"
            );
        }
    }
}

#[test]
fn a_teachers_edited_geometry_rubric_changes_the_points_as_written() {
    let dir = TempDir::new("grade_rubric_file");
    let bundled = repository().join("assets/rubrics/geometry/rubric.toml");
    let edited = std::fs::read_to_string(&bundled)
        .expect("the bundled rubric")
        .replace(
            "title = \"Backface culling\"\npoints = 25",
            "title = \"Culling\"\npoints = 40",
        );
    let rubric = dir.join("rubric.toml");
    std::fs::write(&rubric, edited).expect("write the edited rubric");
    let program = compile_pipeline(&dir, "inverted", &[&mistake_flag("culling_inverted")]);
    let command = format!("'{}' {{scene}} {{trace}}", program.display());
    let cube = asset("cube.in").display().to_string();
    let args = [
        "--run",
        &command,
        "--json",
        "--model",
        &cube,
        "--rubric",
        path(&rubric),
    ];
    let (output, _) = grade(&args, &dir.join("tmp"));
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let graded: Value = serde_json::from_slice(&output.stdout).expect("JSON");
    assert_eq!(graded["max"], 215, "the rubric's total");
    let culling = line(&graded, "culling");
    assert_eq!(
        (culling["max"].as_u64(), culling["title"].as_str()),
        (Some(40), Some("Culling"))
    );
    // The bundled default grades the same program out of 25 for culling.
    let default = grade_json(&program, &["cube.in"], &dir);
    let lost = |g: &Value, max: u64| max - line(g, "culling")["points"].as_u64().unwrap_or(0);
    assert!(
        lost(&default, 25) > 0,
        "inverted culling costs culling points"
    );
    let share = |g: &Value, max: f64| line(g, "culling")["points"].as_f64().unwrap_or(0.0) / max;
    assert!(
        (share(&graded, 40.0) - share(&default, 25.0)).abs() < 0.05,
        "the same scenes pass"
    );
}

#[test]
fn file_normals_are_caught_on_the_knot_whose_corner_normals_are_not_its_faces() {
    let dir = TempDir::new("grade_file_normals");
    let flag = mistake_flag("culling_by_file_normals");
    let program = compile_pipeline(&dir, "pipeline", &[&flag]);
    let grade = grade_json(&program, &["knot.obj"], &dir);
    let lost: Vec<&str> = LINES
        .iter()
        .copied()
        .filter(|id| line(&grade, id)["points"] != line(&grade, id)["max"])
        .collect();
    assert_eq!(lost, ["culling", "synchronized"]);
    let failures: BTreeSet<&str> = line(&grade, "culling")["failures"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|f| f["scene"].as_str())
        .collect();
    // Culling on: where the test decides; off: nothing to decide.
    let on: BTreeSet<&str> = ["ccw-outside", "cw-outside", "ccw-inside", "cw-inside"]
        .iter()
        .map(|s| match *s {
            "ccw-outside" => "knot/culling-ccw-outside",
            "cw-outside" => "knot/culling-cw-outside",
            "ccw-inside" => "knot/culling-ccw-inside",
            _ => "knot/culling-cw-inside",
        })
        .collect();
    assert_eq!(failures, on);
    assert_eq!(
        line(&grade, "culling")["mistakes"][0],
        "culling_by_file_normals"
    );
}

#[test]
fn turning_the_other_way_round_keeps_the_rotation_points_and_says_so() {
    let dir = TempDir::new("grade_clockwise");
    let program = compile_pipeline(&dir, "pipeline", &["-DROTATE_CLOCKWISE"]);
    let grade = grade_json(&program, &["cube.in", "far_away.in"], &dir);
    assert_eq!(grade["total"], 200);
    let rotation = line(&grade, "rotation");
    assert_eq!(rotation["points"], 30);
    assert_eq!(
        rotation["accepted"][0],
        "the other way round from the right-hand rule"
    );
}

#[test]
fn float32_and_fans_score_200_on_every_bundled_model() {
    let dir = TempDir::new("grade_variants");
    for flag in ["-DCLOSE2GL_FLOAT", "-DFAN"] {
        let program = compile_pipeline(&dir, "pipeline", &[flag]);
        let models = ["cube.in", "far_away.in", "knot.obj", "textured_cube.in"];
        let grade = grade_json(&program, &models, &dir);
        assert_eq!(grade["total"], 200, "{flag}: {:#}", grade["lines"]);
    }
}

/// Thirty submissions: the correct program, the three variants, each catalogue mistake, and
/// nine pairs, graded as a class on the cube; every row of grades.csv is what the rules say,
/// and a second run writes the very same file.
#[test]
fn a_class_of_thirty_grades_into_the_expected_csv() {
    use Mistake::*;
    let dir = TempDir::new("grade_class");
    let class = dir.join("class");
    let mut builds: Vec<(String, Vec<&str>, Vec<Mistake>)> = vec![
        ("correct".into(), vec![], vec![]),
        ("clockwise".into(), vec!["-DROTATE_CLOCKWISE"], vec![]),
        ("float".into(), vec!["-DCLOSE2GL_FLOAT"], vec![]),
        ("fan".into(), vec!["-DFAN"], vec![]),
    ];
    let flags: Vec<String> = Mistake::ALL[1..]
        .iter()
        .map(|m| mistake_flag(m.name()))
        .collect();
    for (m, flag) in Mistake::ALL[1..].iter().zip(&flags) {
        builds.push((m.name().into(), vec![flag.as_str()], vec![*m]));
    }
    let pairs = [
        (FovNotHalved, CullingInverted),
        (AspectFromAngles, NoClipping),
        (TranslationUnrotated, ViewportFullScale),
        (FovsSwapped, CullingByViewAxis),
        (DepthRowSign, DivideBeforeClip),
        (LeftHanded, FovInDegrees),
        (ViewportYFlipped, CullingInverted),
    ];
    let index = |m: Mistake| Mistake::ALL[1..].iter().position(|&x| x == m).unwrap_or(0);
    for (a, b) in pairs {
        let name = format!("{}+{}", a.name(), b.name());
        builds.push((
            name,
            vec![flags[index(a)].as_str(), flags[index(b)].as_str()],
            vec![a, b],
        ));
    }
    assert_eq!(builds.len(), 30);
    for (name, flags, _) in &builds {
        let folder = class.join(name);
        std::fs::create_dir_all(&folder).expect("a submission's folder");
        compile_pipeline(&folder, "pipeline", flags);
    }
    let cube = asset("cube.in").display().to_string();
    let args = [
        "--submissions",
        path(&class),
        "--run",
        "{dir}/pipeline {scene} {trace}",
    ];
    let run = |tmp: &str| {
        let mut all = args.to_vec();
        all.extend(["--model", &cube, "--jobs", "2"]);
        let (output, elapsed) = grade(&all, &dir.join(tmp));
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        let csv = std::fs::read_to_string(class.join("grades.csv")).expect("grades.csv");
        (csv, elapsed)
    };
    let (csv, elapsed) = run("tmp");
    eprintln!("30 submissions on the cube graded in {elapsed:?}\n{csv}");
    // The rubric's scenes on the cube, as one program's JSON lists them.
    let listing = grade_json(&class.join("correct/pipeline"), &["cube.in"], &dir);
    let mut rows = csv.lines();
    let header = rows.next().unwrap_or("");
    assert_eq!(header, format!("submission,{},total", LINES.join(",")));
    let mut sorted = builds.clone();
    sorted.sort_by(|a, b| a.0.cmp(&b.0));
    for ((name, _, mistakes), row) in sorted.iter().zip(rows) {
        let expected = expected_on_cube(mistakes, &listing["scenes"]);
        let points: Vec<String> = expected.iter().map(|(p, _)| p.to_string()).collect();
        let total: u64 = expected.iter().map(|(p, _)| p).sum();
        assert_eq!(
            row,
            format!("{name},{},{total}", points.join(",")),
            "{name}"
        );
        assert!(class.join(format!("{name}.html")).is_file());
    }
    let (again, _) = run("tmp2");
    assert_eq!(again, csv, "the same submissions give the same CSV");
}

fn path(p: &Path) -> &str {
    p.to_str().expect("a UTF-8 test path")
}

#[test]
fn bad_arguments_are_one_line_errors_with_exit_2() {
    let dir = TempDir::new("grade_arguments");
    let empty = dir.join("empty");
    std::fs::create_dir_all(&empty).expect("an empty class");
    let missing = dir.join("no-such-model.in");
    let cases: [(&[&str], &str); 5] = [
        (&["--run", "'unterminated"], "unterminated quote"),
        (
            &["--run", "x", "--jobs", "0"],
            "--jobs: expected at least 1",
        ),
        (
            &["--run", "x", "--time-limit", "0"],
            "--time-limit: expected seconds",
        ),
        (
            &["--run", "x", "--model", path(&missing)],
            "no-such-model.in",
        ),
        (&["--run", "x", "--submissions", path(&empty)], "found none"),
    ];
    for (args, says) in cases {
        let (output, _) = grade(args, &dir.join("tmp"));
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert_eq!(output.status.code(), Some(2), "{args:?}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{args:?}: {stderr}");
        assert!(stderr.contains(says), "{args:?}: {stderr}");
    }
}

// ---- hostile programs ------------------------------------------------------------------------

/// A hostile program, compiled from C like the student's; it gets `SCENE TRACE` as any
/// program does.
fn hostile(dir: &Path, name: &str, body: &str) -> PathBuf {
    let source = dir.join(format!("{name}.c"));
    let prelude = "#include <signal.h>\n#include <stdio.h>\n#include <stdlib.h>\n\
                   #include <string.h>\n#include <unistd.h>\n";
    std::fs::write(&source, format!("{prelude}{body}\n")).expect("write the source");
    compile_c(
        &source,
        &dir.join(name),
        &["-D_DEFAULT_SOURCE", "-Wno-unused-parameter"],
    )
}

/// The cube's scenes, a second each, two at a time.
const TIME_LIMIT: f64 = 1.0;
const JOBS: f64 = 2.0;

/// Grades `program` on the cube; asserts every scene failed with a reason `reason` accepts,
/// that grading took at most twice the time limit times the scenes over the jobs (and a few
/// seconds to start), that no process of the program is left and that its temporary
/// directories are gone.
fn grade_hostile(name: &str, body: &str, reason: impl Fn(&str) -> bool) {
    let dir = TempDir::new(&format!("grade_hostile_{name}"));
    let program = hostile(&dir, name, body);
    let command = format!("'{}' {{scene}} {{trace}}", program.display());
    let cube = asset("cube.in").display().to_string();
    let tmp = dir.join("tmp");
    let (output, elapsed) = grade(
        &[
            "--run",
            &command,
            "--json",
            "--jobs",
            "2",
            "--time-limit",
            "1",
            "--model",
            &cube,
        ],
        &tmp,
    );
    assert!(
        output.status.success(),
        "{}",
        String::from_utf8_lossy(&output.stderr)
    );
    let grade: Value = serde_json::from_slice(&output.stdout).expect("JSON");
    assert_eq!(grade["total"], 0);
    let scenes = grade["scenes"].as_array().expect("scenes");
    for scene in scenes {
        let why = scene["run_failure"].as_str().unwrap_or("");
        assert!(reason(why), "{name}: {}: {why:?}", scene["id"]);
    }
    let bound = 2.0 * scenes.len() as f64 * TIME_LIMIT / JOBS + 5.0;
    eprintln!(
        "{name}: {} scenes in {elapsed:?} (bound {bound} s)",
        scenes.len()
    );
    assert!(elapsed.as_secs_f64() < bound, "{name}: {elapsed:?}");
    assert_eq!(
        running(&program),
        Vec::<i32>::new(),
        "{name}: processes left"
    );
    let left: Vec<_> = std::fs::read_dir(&tmp).expect("TMPDIR").flatten().collect();
    assert!(left.is_empty(), "{name}: left in TMPDIR: {left:?}");
}

/// The pids of processes running `program` (their command line's first word is its path; the
/// grader's own holds it later, in its --run).
fn running(program: &Path) -> Vec<i32> {
    let first_word = program.as_os_str().as_encoded_bytes();
    std::fs::read_dir("/proc")
        .expect("/proc")
        .flatten()
        .filter_map(|entry| {
            let pid: i32 = entry.file_name().to_str()?.parse().ok()?;
            let cmdline = std::fs::read(entry.path().join("cmdline")).ok()?;
            let state = std::fs::read_to_string(entry.path().join("stat")).ok()?;
            let zombie = state.rsplit(')').next()?.trim_start().starts_with('Z');
            let found = cmdline.split(|&b| b == 0).next() == Some(first_word);
            (found && !zombie).then_some(pid)
        })
        .collect()
}

#[test]
fn a_program_that_sleeps_forever_times_out_in_every_scene() {
    grade_hostile("sleeps", "int main(void) { for (;;) pause(); }", |why| {
        why.starts_with("timed out after 1")
    });
}

#[test]
fn a_program_that_aborts_is_marked_sigabrt() {
    grade_hostile("aborts", "int main(void) { abort(); }", |why| {
        why.starts_with("killed by SIGABRT after")
    });
}

#[test]
fn random_bytes_for_a_trace_are_not_a_trace() {
    let body = r#"int main(int argc, char **argv) {
        FILE *f = fopen(argv[2], "wb");
        srand(7);
        for (int i = 0; i < 4096; i++) fputc(rand() & 255, f);
        return fclose(f) != 0;
    }"#;
    grade_hostile("random", body, |why| why.starts_with("its trace:"));
}

#[test]
fn a_child_that_calls_setsid_and_sleeps_is_killed_with_its_parent() {
    let body = r#"int main(void) {
        if (fork() == 0) { setsid(); for (;;) pause(); }
        return 0;
    }"#;
    grade_hostile("setsid", body, |why| why.starts_with("it wrote no trace"));
}

#[test]
fn endless_allocation_fails_inside_the_program() {
    let body = r#"int main(void) {
        for (long mib = 0;; mib++)
            if (!malloc(1 << 20)) { fprintf(stderr, "out of memory after %ld MiB\n", mib); return 4; }
    }"#;
    grade_hostile("allocates", body, |why| {
        why.starts_with("exited with status 4\nout of memory after")
    });
}

#[test]
fn a_trace_written_without_end_stops_at_the_file_size_limit() {
    let body = r#"int main(int argc, char **argv) {
        static char block[1 << 16];
        FILE *f = fopen(argv[2], "wb");
        memset(block, 'x', sizeof block);
        for (;;) fwrite(block, 1, sizeof block, f);
    }"#;
    grade_hostile("writes", body, |why| {
        why.starts_with("killed by SIGXFSZ after")
    });
}

#[test]
fn ctrl_c_stops_grading_and_leaves_nothing() {
    let dir = TempDir::new("grade_interrupt");
    let program = hostile(&dir, "sleeps", "int main(void) { for (;;) pause(); }");
    let command = format!("'{}' {{scene}} {{trace}}", program.display());
    let tmp = dir.join("tmp");
    std::fs::create_dir_all(&tmp).expect("TMPDIR");
    let html = dir.join("report.html");
    let mut child = Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .args([
            "grade",
            "--run",
            &command,
            "--jobs",
            "2",
            "--html",
            path(&html),
        ])
        .env("TMPDIR", &tmp)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("start grade");
    // Long enough for both jobs to have started their sleepers.
    std::thread::sleep(Duration::from_millis(1500));
    assert_eq!(running(&program).len(), 2, "two scenes under way");
    let kill = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status();
    assert!(kill.is_ok_and(|s| s.success()));
    let started = Instant::now();
    let status = child.wait().expect("grade ends");
    assert_eq!(status.code(), Some(130));
    assert!(
        started.elapsed() < Duration::from_secs(3),
        "{:?}",
        started.elapsed()
    );
    assert_eq!(running(&program), Vec::<i32>::new());
    assert_eq!(std::fs::read_dir(&tmp).map(Iterator::count).ok(), Some(0));
    assert!(!html.exists(), "an interrupted grade writes no report");
}

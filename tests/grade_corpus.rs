//! `close2gl grade` on the corpus of `examples/corpus/`: each program, and each of its bug
//! variants, built with the system's compilers (or started with python3) and graded as a
//! process on the cube. What each build should score was written in its header
//! (`expect-grade` lines) from the rubric's rules before grade was ever run on it; grade must
//! give exactly those points, line by line.
//!
//! The correct programs are the output styles students write, each of which must score
//! 200/200: window pixels y up (`cpp_glm`) and y down (`c_rowmajor`), the assignment's
//! `0 1 0 1` with full clipping (`py_fullclip`), NDC without a V (`py_ndc`, `c_ndc_nearfar`)
//! and with one (`c_ndc_nearfar -DIDENTITY_V`), x and y clipping left to the GPU
//! (`clipping simple near_far`: `py_ndc`, `c_ndc_nearfar`).

use std::path::{Path, PathBuf};
use std::process::Command;

use close2gl_testkit::TempDir;
use close2gl_testkit::student::{
    asset, compile_c, compile_cpp, compile_pipeline, corpus_programs, repository,
};
use serde_json::Value;

/// One `expect-grade` line: a build of a program and the points each line should get.
#[derive(Debug)]
struct Expected {
    program: PathBuf,
    line_no: usize,
    flags: Vec<String>,
    /// Lines that lose points, with their points; every other line keeps its maximum.
    points: Vec<(String, u64)>,
}

fn corpus() -> PathBuf {
    repository().join("examples/corpus")
}

/// Every `expect-grade cube` line of every program of the corpus.
fn expectations() -> Vec<Expected> {
    let programs = corpus_programs();
    let mut all = Vec::new();
    for program in programs {
        let text = std::fs::read_to_string(&program).expect("read a corpus program");
        for (i, line) in text.lines().enumerate() {
            let line = line.trim_start_matches([' ', '*', '/']);
            if let Some(rest) = line.strip_prefix("expect-grade ") {
                let where_ = format!("{}:{}", program.display(), i + 1);
                all.push(parse(&program, i + 1, rest).unwrap_or_else(|| {
                    panic!("{where_}: expected 'expect-grade cube [FLAG ...]: 200|LINE=POINTS ...'")
                }));
            }
        }
    }
    all
}

/// `cube [FLAG ...]: 200` or `cube [FLAG ...]: LINE=POINTS ...`.
fn parse(program: &Path, line_no: usize, rest: &str) -> Option<Expected> {
    let (head, body) = rest.split_once(':')?;
    let mut words = head.split_whitespace();
    if words.next()? != "cube" {
        return None;
    }
    let flags: Vec<String> = words.map(str::to_string).collect();
    let body = body.trim();
    let points = if body == "200" {
        Vec::new()
    } else {
        let pairs = body.split_whitespace().map(|pair| {
            let (line, points) = pair.split_once('=')?;
            Some((line.to_string(), points.parse().ok()?))
        });
        pairs.collect::<Option<Vec<_>>>()?
    };
    Some(Expected {
        program: program.to_path_buf(),
        line_no,
        flags,
        points,
    })
}

/// The `--run` command line for a build: a compiled program, or python3 with the helper and
/// the loader on its path (grade passes on only PATH, HOME and LANG, so through `env`).
fn run_command(expected: &Expected, dir: &Path) -> String {
    let include = [repository().join("examples/trace"), corpus()];
    let flags: Vec<&str> = expected.flags.iter().map(String::as_str).collect();
    let stem = expected
        .program
        .file_stem()
        .and_then(|s| s.to_str())
        .expect("a name");
    let out = dir.join(format!("{stem}{}", flags.concat().replace(['-', '='], "_")));
    let mut all: Vec<String> = include
        .iter()
        .map(|p| format!("-I{}", p.display()))
        .collect();
    all.extend(expected.flags.iter().cloned());
    let all: Vec<&str> = all.iter().map(String::as_str).collect();
    let quoted = |p: &Path| format!("'{}'", p.display());
    match expected.program.extension().and_then(|e| e.to_str()) {
        Some("c") => format!(
            "{} {{scene}} {{trace}}",
            quoted(&compile_c(&expected.program, &out, &all))
        ),
        Some("cpp") => format!(
            "{} {{scene}} {{trace}}",
            quoted(&compile_cpp(&expected.program, &out, &all))
        ),
        _ => format!(
            "env 'PYTHONPATH={}:{}' python3 {} {{scene}} {{trace}} {}",
            include[0].display(),
            include[1].display(),
            quoted(&expected.program),
            flags.join(" ")
        ),
    }
}

/// `grade --json --jobs 2` of `command` on the cube.
fn graded(command: &str, dir: &Path) -> Value {
    let tmp = dir.join("tmp");
    std::fs::create_dir_all(&tmp).expect("make TMPDIR");
    let model = asset("cube.in").display().to_string();
    // The Python programs import the helpers from examples/trace, a folder their command does
    // not name: the course's shared library folder, which the sandbox reads when told to.
    let helpers = repository().join("examples/trace").display().to_string();
    let output = Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .args([
            "grade",
            "--run",
            command,
            "--json",
            "--jobs",
            "2",
            "--model",
            &model,
            "--allow-read",
            &helpers,
        ])
        .env("TMPDIR", &tmp)
        .output()
        .expect("run close2gl grade");
    assert!(
        output.status.success(),
        "grade failed: {}",
        String::from_utf8_lossy(&output.stderr)
    );
    serde_json::from_slice(&output.stdout).expect("grade --json prints JSON")
}

/// The lines where grade's points are not the expected ones: `(build, line, expected, found,
/// grade's first reason)`.
fn mismatches(expected: &Expected, grade: &Value) -> Vec<String> {
    let lines = grade["lines"].as_array().expect("lines");
    let mut wrong = Vec::new();
    for line in lines {
        let id = line["id"].as_str().expect("id");
        let found = line["points"].as_u64().expect("points");
        let want = expected
            .points
            .iter()
            .find(|(l, _)| l == id)
            .map_or_else(|| line["max"].as_u64().expect("max"), |&(_, p)| p);
        if found != want {
            let reason = &line["failures"][0]["reason"];
            wrong.push(format!(
                "{}:{} {}: {id} expected {want}, grade gave {found} ({reason})",
                expected.program.display(),
                expected.line_no,
                expected.flags.join(" ")
            ));
        }
    }
    wrong
}

/// A line names a mistake only with the number of its failing scenes that name it, never one
/// that none names; its unexplained scenes are those that name none of its mistakes.
fn false_names(expected: &Expected, grade: &Value) -> Vec<String> {
    let scenes = grade["scenes"].as_array().expect("scenes");
    let named_in = |scene: &str| -> Vec<Value> {
        let scene = scenes.iter().find(|s| s["id"] == scene);
        scene.map_or(Vec::new(), |s| {
            s["mistakes"].as_array().expect("mistakes").clone()
        })
    };
    let mut wrong = Vec::new();
    let build = format!(
        "{}:{} {}",
        expected.program.display(),
        expected.line_no,
        expected.flags.join(" ")
    );
    for line in grade["lines"].as_array().expect("lines") {
        let failing: Vec<Vec<Value>> = line["failures"]
            .as_array()
            .expect("failures")
            .iter()
            .map(|f| named_in(f["scene"].as_str().expect("scene")))
            .collect();
        let mistakes = line["mistakes"].as_array().expect("mistakes");
        for mistake in mistakes {
            let naming = failing
                .iter()
                .filter(|names| names.contains(mistake))
                .count();
            let said = line["explained"][mistake.as_str().unwrap_or_default()].as_u64();
            if naming == 0 || said != Some(naming as u64) {
                wrong.push(format!(
                    "{build}: {} names {mistake} for {said:?} scenes; {naming} of its failing \
                     scenes name it",
                    line["id"]
                ));
            }
        }
        let unexplained = failing
            .iter()
            .filter(|names| !mistakes.iter().any(|m| names.contains(m)))
            .count();
        if line["unexplained"].as_u64() != Some(unexplained as u64) {
            wrong.push(format!(
                "{build}: {} says {} unexplained, {unexplained} name none of its mistakes",
                line["id"], line["unexplained"]
            ));
        }
    }
    wrong
}

#[test]
fn every_corpus_build_scores_what_its_header_expects_and_names_no_mistake_falsely() {
    let dir = TempDir::new("grade_corpus");
    let all = expectations();
    assert!(
        all.len() >= 17,
        "every corpus build has its expect-grade line"
    );
    let wrong: Vec<String> = all
        .iter()
        .flat_map(|e| {
            let grade = graded(&run_command(e, &dir), &dir);
            [mismatches(e, &grade), false_names(e, &grade)].concat()
        })
        .collect();
    assert!(wrong.is_empty(), "{}", wrong.join("\n"));
}

#[test]
fn a_line_names_each_mistake_with_the_scenes_it_explains() {
    // Its culling switch inverts counter-clockwise culling and never culls clockwise: the
    // culling line's four failing scenes are two of each; neither explains them all, and a
    // line once named neither ("unexplained").
    let dir = TempDir::new("grade_corpus_mixup");
    let program = corpus().join("c_rowmajor.c");
    let expected = expectations()
        .into_iter()
        .find(|e| e.program == program && e.flags == ["-DCULL_SWITCH_MIXUP"])
        .expect("c_rowmajor's -DCULL_SWITCH_MIXUP build");
    let grade = graded(&run_command(&expected, &dir), &dir);
    let culling = grade["lines"]
        .as_array()
        .and_then(|lines| lines.iter().find(|l| l["id"] == "culling"))
        .expect("the culling line");
    assert_eq!(culling["explained"]["culling_inverted"], 2, "{culling:#}");
    assert_eq!(culling["explained"]["never_culls"], 2, "{culling:#}");
    assert_eq!(culling["unexplained"], 0, "{culling:#}");
    let causes: Vec<&str> = grade["to_fix"]
        .as_array()
        .into_iter()
        .flatten()
        .filter_map(|bug| bug["cause"].as_str())
        .collect();
    assert!(
        causes.iter().any(|c| c.contains("culling_inverted")),
        "{causes:?}"
    );
}

#[test]
fn expect_grade_lines_that_do_not_read_are_refused() {
    let program = Path::new("x.c");
    assert!(parse(program, 1, "cube: 200").is_some());
    assert!(parse(program, 1, "cube -DX: culling=12 synchronized=23").is_some());
    assert!(parse(program, 1, "knot: 200").is_none());
    assert!(parse(program, 1, "cube: culling").is_none());
    assert!(parse(program, 1, "cube 200").is_none());
}

// The fairness of one style, against the rubric's promise that honesty never costs:
// `c_aspect.c` takes its horizontal extent from the window's aspect (gluPerspective's habit):
// asked hfov = vfov = 60° in a 640×480 window, it draws with hfov 75.18°. Honest
// (`-DWRITE_USED_HFOV`) it says so in its trace; as it is, it writes the scene's 60.

/// The ids of the lines that lost points.
fn lost(grade: &Value) -> Vec<String> {
    let lines = grade["lines"].as_array().expect("lines");
    lines
        .iter()
        .filter(|l| l["points"] != l["max"])
        .map(|l| l["id"].as_str().expect("id").to_string())
        .collect()
}

#[test]
fn honesty_never_costs_and_a_window_aspect_projection_costs_only_its_lines() {
    let dir = TempDir::new("grade_fairness");
    let command = |program: PathBuf| format!("'{}' {{scene}} {{trace}}", program.display());
    let correct = graded(&command(compile_pipeline(&dir, "pipeline", &[])), &dir);
    let aspect = |flags: &[&str]| {
        let source = corpus().join("c_aspect.c");
        let include = format!("-I{}", repository().join("examples/trace").display());
        let out = dir.join(format!(
            "c_aspect{}",
            flags.concat().replace(['-', '='], "_")
        ));
        let all: Vec<&str> = [include.as_str()]
            .into_iter()
            .chain(flags.iter().copied())
            .collect();
        command(compile_c(&source, &out, &all))
    };
    let honest = graded(&aspect(&["-DWRITE_USED_HFOV"]), &dir);
    let dishonest = graded(&aspect(&[]), &dir);
    assert_eq!(correct["total"], 200, "{correct:#}");
    let total = |g: &Value| g["total"].as_u64().expect("total");
    assert!(
        total(&honest) >= total(&dishonest),
        "honest {} < dishonest {}",
        total(&honest),
        total(&dishonest)
    );
    // The horizontal field of view is wrong, and so are the pictures (the mode lines and
    // synchronized); culling, clipping, the moves, vfov and resize are judged on the program's
    // own geometry, and keep their points.
    for grade in [&honest, &dishonest] {
        let lost = lost(grade);
        assert!(lost.iter().any(|l| l == "hfov"), "{lost:?}");
        for line in &lost {
            assert!(
                ["points", "wireframe", "solid", "hfov", "synchronized"].contains(&line.as_str()),
                "lost {line}: {:#}",
                grade["lines"]
            );
        }
    }
    // The report leads with what to fix.
    assert!(!honest["to_fix"].as_array().expect("to_fix").is_empty());
}

#[test]
fn a_program_that_draws_nothing_is_one_bug_to_fix_not_one_per_line() {
    let dir = TempDir::new("grade_one_bug");
    let draws_nothing = expectations()
        .into_iter()
        .find(|e| e.program.ends_with("py_ndc.py") && e.flags == ["-DDRAWS_NOTHING"])
        .expect("py_ndc.py has an expect-grade line for -DDRAWS_NOTHING");
    let grade = graded(&run_command(&draws_nothing, &dir), &dir);
    let bugs = grade["to_fix"].as_array().expect("to_fix");
    // Every line it lost is one bug: drawing nothing, where check first finds it different.
    assert_eq!(bugs.len(), 1, "{bugs:#?}");
    let lost = lost(&grade);
    let costs = bugs[0]["lines"].as_array().expect("lines");
    assert_eq!(costs.len(), lost.len(), "{bugs:#?}");
    assert!(
        bugs[0]["example"]
            .as_str()
            .is_some_and(|e| e.contains("the trace drew nothing")),
        "{bugs:#?}"
    );
}

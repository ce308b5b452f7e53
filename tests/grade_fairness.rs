//! `close2gl grade` is fair: a mistake costs only the lines it is about, and an honest trace
//! never scores below a dishonest one. The programs are the corpus's (examples/corpus), built
//! with the system's C compiler and graded as processes on the cube.
//!
//! `c_aspect.c` takes its horizontal extent from the window's aspect (gluPerspective's habit):
//! asked hfov = vfov = 60° in a 640×480 window, it draws with hfov 75.18°. Honest
//! (`-DWRITE_USED_HFOV`) it says so in its trace; as it is, it writes the scene's 60.

use std::path::{Path, PathBuf};
use std::process::Command;

use close2gl_testkit::TempDir;
use close2gl_testkit::student::{asset, compile_c, compile_pipeline, repository};
use serde_json::Value;

fn corpus_program(dir: &Path, name: &str, flags: &[&str]) -> PathBuf {
    let source = repository()
        .join("examples/corpus")
        .join(format!("{name}.c"));
    let include = format!("-I{}", repository().join("examples/trace").display());
    let mut all = vec![include.as_str()];
    all.extend(flags);
    let out = dir.join(format!("{name}{}", flags.concat().replace(['-', '='], "_")));
    compile_c(&source, &out, &all)
}

/// `grade --json` of `program` on the cube.
fn graded(program: &Path, dir: &Path) -> Value {
    let command = format!("'{}' {{scene}} {{trace}}", program.display());
    let model = asset("cube.in").display().to_string();
    let tmp = dir.join("tmp");
    std::fs::create_dir_all(&tmp).expect("make TMPDIR");
    let output = Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .args([
            "grade", "--run", &command, "--json", "--jobs", "2", "--model", &model,
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
    let correct = graded(&compile_pipeline(&dir, "pipeline", &[]), &dir);
    let honest = graded(
        &corpus_program(&dir, "c_aspect", &["-DWRITE_USED_HFOV"]),
        &dir,
    );
    let dishonest = graded(&corpus_program(&dir, "c_aspect", &[]), &dir);
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

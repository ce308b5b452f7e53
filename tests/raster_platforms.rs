//! The rasterizer assignment's grade (`grade --rubric`) where teachers grade, as the geometry's
//! is (`platforms.rs`): `examples/raster/raster.c` built right and with `no_specular`, graded
//! into Gradescope's results.json, GitHub Classroom's `result=`, the page, `--line`, and a
//! class's Moodle and Canvas CSVs; each agreeing with the grade's own `--json`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use close2gl_testkit::TempDir;
use close2gl_testkit::student::{compile_raster, mistake_flag, repository};
use serde_json::Value;

mod platform_rules;
use platform_rules::{
    assert_gradescope_format, assert_line_answers, classroom_result, reporter_points,
};

const MISTAKE: &str = "no_specular";

fn rubric() -> PathBuf {
    repository().join("assets/rubrics/rasterizer/rubric.toml")
}

/// `close2gl grade --rubric RUBRIC --run COMMAND ARGS...`, with `$GITHUB_OUTPUT` at `output`.
fn grade(command: &str, args: &[&str], output: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .args(["grade", "--jobs", "2", "--rubric"])
        .arg(rubric())
        .args(["--run", command])
        .args(args)
        .env("GITHUB_OUTPUT", output)
        .output()
        .expect("run close2gl grade")
}

fn program_command(program: &Path) -> String {
    format!("'{}' {{scene}} {{trace}}", program.display())
}

/// The program graded with `--json --gradescope --html` and then with `--classroom`: the
/// JSON, results.json, the page and the reporter's result.
fn every_output(dir: &Path, program: &Path) -> (Value, Value, String, Value) {
    let (results, page, github) = (dir.join("results"), dir.join("page.html"), dir.join("out"));
    let command = program_command(program);
    let (results_arg, page_arg) = (results.display().to_string(), page.display().to_string());
    let json = grade(
        &command,
        &["--json", "--gradescope", &results_arg, "--html", &page_arg],
        &github,
    );
    assert!(
        json.status.success(),
        "{}",
        String::from_utf8_lossy(&json.stderr)
    );
    let classroom = grade(&command, &["--classroom"], &github);
    assert!(classroom.status.success());
    let read = |path: PathBuf| std::fs::read_to_string(path).expect("a file grade wrote");
    (
        serde_json::from_slice(&json.stdout).expect("grade's JSON"),
        serde_json::from_str(&read(results.join("results.json"))).expect("results.json"),
        read(page),
        classroom_result(&github),
    )
}

/// Gradescope has a test per rubric line, numbered by its id, with the line's points and max
/// as `--json` gives them; its score and the reporter's are the JSON's total.
fn assert_agree(json: &Value, results: &Value, classroom: &Value) {
    assert_gradescope_format(results);
    assert_eq!(results["score"], json["total"], "{results:#}");
    let tests = results["tests"].as_array().expect("tests");
    for line in json["lines"].as_array().expect("lines") {
        let test = (tests.iter())
            .find(|t| t["number"] == line["id"])
            .unwrap_or_else(|| panic!("a test for {}", line["id"]));
        assert_eq!(
            (&test["score"], &test["max_score"]),
            (&line["points"], &line["max"])
        );
        assert_eq!(test["name"], line["title"]);
    }
    let total = json["total"].as_u64();
    assert_eq!(Some(reporter_points(classroom)), total.map(|t| (t, 200)));
}

#[test]
fn gradescope_classroom_and_the_page_carry_the_rasterizer_grade() {
    let dir = TempDir::new("raster-platforms");
    let right = compile_raster(&dir.0, "right", &[]);
    let (json, results, _, classroom) = every_output(&dir.0.join("right-out"), &right);
    assert_eq!(json["total"], 200);
    assert_agree(&json, &results, &classroom);
    assert_eq!(classroom["status"], "pass");
    let mistaken = compile_raster(&dir.0, "mistaken", &[mistake_flag(MISTAKE).as_str()]);
    let (json, results, page, classroom) = every_output(&dir.0.join("mistaken-out"), &mistaken);
    assert!(json["total"].as_u64() < Some(200), "{json:#}");
    assert_agree(&json, &results, &classroom);
    assert_eq!(classroom["status"], "fail");
    // The line is visible with the mistake named; the scene's file is not.
    let tests = results["tests"].as_array().expect("tests");
    let numbered = |number: &str| tests.iter().find(|t| t["number"] == number).expect(number);
    let phong = numbered("phong");
    assert!(
        phong["output"]
            .as_str()
            .unwrap_or_default()
            .contains(MISTAKE),
        "{phong}"
    );
    let details = numbered("phong.details");
    assert_eq!(details["visibility"], "hidden");
    assert!(
        details["output"]
            .as_str()
            .unwrap_or_default()
            .contains("the scene file")
    );
    for line in json["lines"].as_array().expect("lines") {
        let title = line["title"].as_str().unwrap_or_default();
        assert!(page.contains(title), "the page lacks {title}");
    }
    assert!(page.contains(MISTAKE) && page.contains("<h3 id=\"knot_phong\">"));
}

#[test]
fn one_line_scores_alone_and_fails_when_it_lost_points() {
    let dir = TempDir::new("raster-platforms-line");
    let out = dir.0.join("out");
    let right = program_command(&compile_raster(&dir.0, "right", &[]));
    let passed = grade(&right, &["--line", "phong"], &out);
    let mistaken = compile_raster(&dir.0, "mistaken", &[mistake_flag(MISTAKE).as_str()]);
    let failed = grade(&program_command(&mistaken), &["--line", "phong"], &out);
    assert_line_answers(&passed, &failed, "phong", 25, MISTAKE);
    for (args, error) in [
        (
            &["--line", "culling"][..],
            "--line culling: expected one of coverage, zbuffer",
        ),
        (&["--model", "cube.in"][..], "--model: "),
    ] {
        let refused = grade(&right, args, &out);
        assert_eq!(refused.status.code(), Some(2));
        let stderr = String::from_utf8_lossy(&refused.stderr);
        assert!(stderr.contains(error), "{stderr}");
    }
}

#[test]
fn a_class_imports_into_moodle_and_canvas_with_a_page_each() {
    let dir = TempDir::new("raster-platforms-class");
    let class = dir.0.join("class");
    for (folder, flags) in [("ana", vec![]), ("bo", vec![mistake_flag(MISTAKE)])] {
        std::fs::create_dir_all(class.join(folder)).expect("a submission");
        let flags: Vec<&str> = flags.iter().map(String::as_str).collect();
        compile_raster(&class.join(folder), "raster", &flags);
    }
    let students = dir.0.join("students.csv");
    std::fs::write(&students, "ana,ana@uni.edu,Ana Lima\n").expect("the mapping");
    let class_arg = class.display().to_string();
    let students_arg = students.display().to_string();
    let csv = |format: &str| {
        let args = [
            "--submissions",
            &class_arg,
            "--csv-format",
            format,
            "--students",
        ];
        let args = [&args[..], &[&students_arg, "--assignment", "Raster (7)"]].concat();
        let output = grade("{dir}/raster {scene} {trace}", &args, &dir.0.join("out"));
        assert!(
            output.status.success(),
            "{}",
            String::from_utf8_lossy(&output.stderr)
        );
        std::fs::read_to_string(class.join("grades.csv")).expect("grades.csv")
    };
    let moodle = csv("moodle");
    let rows: Vec<&str> = moodle.lines().collect();
    assert!(
        rows[0].starts_with(
            "Identifier,Full name,\"Triangle traversal, pixel centres and the fill rule (close2gl)\","
        ),
        "{moodle}"
    );
    assert!(rows[0].ends_with(",Total (close2gl)"), "{moodle}");
    assert!(rows[1].starts_with("ana@uni.edu,Ana Lima,") && rows[1].ends_with(",200"));
    let bo = rows[2].rsplit(',').next().unwrap_or_default().to_string();
    assert!(rows[2].starts_with("bo,,") && bo != "200", "{moodle}");
    let canvas = csv("canvas");
    let expected = format!(
        "Student,ID,SIS User ID,SIS Login ID,Section,Raster (7)\n\
         \x20   Points Possible,,,,,200\n\
         Ana Lima,,,ana@uni.edu,,200\n\
         bo,,,bo,,{bo}\n"
    );
    assert_eq!(canvas, expected);
    let page = std::fs::read_to_string(class.join("bo.html")).expect("bo's page");
    assert!(page.contains(MISTAKE) && page.contains(&format!("{bo}/200")));
}

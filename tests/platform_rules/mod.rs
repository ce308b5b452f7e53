//! What the platforms require of close2gl's files, shared by the tests of both assignments'
//! grades (`platforms.rs`, `raster_platforms.rs`): Gradescope's rules for results.json, and
//! GitHub Classroom's grading reporter's reading of a step's `result`.

use std::path::Path;
use std::process::Output;

use base64::Engine;
use base64::engine::general_purpose::STANDARD;
use serde_json::Value;

/// Gradescope's rules for results.json: each test has a name, a score and a max_score
/// (numbers, the score at most the max), a visibility Gradescope knows; the total is the
/// tests' sum; output and execution_time are there.
pub fn assert_gradescope_format(results: &Value) {
    let visibilities = ["hidden", "after_due_date", "after_published", "visible"];
    let tests = results["tests"].as_array().expect("tests");
    let mut sum = 0.0;
    for test in tests {
        assert!(test["name"].is_string(), "{test}");
        let (score, max) = (test["score"].as_f64(), test["max_score"].as_f64());
        assert!(score.is_some() && max.is_some() && score <= max, "{test}");
        sum += score.unwrap_or_default();
        let visibility = test["visibility"].as_str().unwrap_or_default();
        assert!(visibilities.contains(&visibility), "{test}");
        assert!(test["output"].is_string(), "{test}");
    }
    assert_eq!(results["score"].as_f64(), Some(sum));
    assert!(results["execution_time"].is_number());
    assert!(results["output"].is_string());
    assert!(visibilities.contains(&results["stdout_visibility"].as_str().unwrap_or_default()));
}

/// The `result=` a step appended to the `$GITHUB_OUTPUT` file at `path`, decoded as the
/// grading reporter decodes it (base64, then JSON).
pub fn classroom_result(path: &Path) -> Value {
    let outputs = std::fs::read_to_string(path).expect("$GITHUB_OUTPUT");
    let encoded = outputs
        .lines()
        .find_map(|l| l.strip_prefix("result="))
        .expect("a result= line");
    let json = STANDARD.decode(encoded).expect("base64");
    serde_json::from_slice(&json).expect("JSON")
}

/// The grading reporter's sums: the points are the tests' scores, the maximum max_score.
pub fn reporter_points(result: &Value) -> (u64, u64) {
    let tests = result["tests"].as_array().expect("tests");
    let score = tests
        .iter()
        .map(|t| t["score"].as_u64().expect("score"))
        .sum();
    (score, result["max_score"].as_u64().expect("max_score"))
}

/// `grade --line ID`'s two answers: for a program that lost nothing, `ID: MAX/MAX` and exit
/// status 0; for one that lost points, one line naming `mistake`, and exit status 1.
pub fn assert_line_answers(passed: &Output, failed: &Output, id: &str, max: u32, mistake: &str) {
    assert_eq!(passed.status.code(), Some(0));
    assert_eq!(
        String::from_utf8_lossy(&passed.stdout),
        format!("{id}: {max}/{max}\n")
    );
    assert_eq!(failed.status.code(), Some(1));
    let summary = String::from_utf8_lossy(&failed.stdout);
    assert!(
        summary.starts_with(&format!("{id}: ")) && summary.contains(mistake),
        "{summary}"
    );
    assert_eq!(summary.lines().count(), 1, "{summary}");
}

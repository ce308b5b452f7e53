//! `close2gl check` as a user meets it, on traces from the student program of `examples/trace`:
//! exit 0 when the trace agrees, 1 when it differs (with the JSON report's binding keys and the
//! pictures of --out), 2 with a one-line, line-numbered error for a trace that lies.

use std::path::Path;
use std::process::{Command, Output};

use close2gl_testkit::TempDir;
use close2gl_testkit::student::{asset, compile_pipeline, mistake_flag};
use serde_json::Value;

fn check(model: &Path, trace: &Path, more: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .arg("check")
        .arg(model)
        .arg(trace)
        .args(more)
        .output()
        .expect("the binary runs")
}

/// A trace of the cube from `program` (built with `flags`), framed, clipped simply, culled.
fn cube_trace(dir: &TempDir, flags: &[&str]) -> std::path::PathBuf {
    let name = format!("pipeline{}", flags.join(""));
    let program = compile_pipeline(dir, &name, flags);
    let scene = dir.write(
        "cube.scene",
        format!(
            "close2gl-scene 1\nmodel {}\nwindow 320 240\ncamera framed\nculling ccw\n",
            asset("cube.in").display()
        )
        .as_bytes(),
    );
    let trace = dir.join(format!("{name}.trace"));
    let status = Command::new(program).arg(&scene).arg(&trace).status();
    assert!(status.expect("runs").success());
    trace
}

#[test]
fn a_correct_trace_agrees_and_a_mistaken_one_names_its_mistake() {
    let dir = TempDir::new("check_command");
    let cube = asset("cube.in");
    let correct = check(&cube, &cube_trace(&dir, &[]), &[]);
    assert_eq!(
        correct.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&correct.stdout)
    );
    let mistaken = cube_trace(&dir, &[&mistake_flag("fov_not_halved")]);
    let out_dir = dir.join("out");
    let differs = check(
        &cube,
        &mistaken,
        &["--json", "--out", &out_dir.display().to_string()],
    );
    assert_eq!(differs.status.code(), Some(1));
    let report: Value = serde_json::from_slice(&differs.stdout).expect("one JSON object");
    assert_eq!(report["agree"], false);
    assert_eq!(report["first_difference"]["stage"], "P");
    assert_eq!(report["mistakes"], serde_json::json!(["fov_not_halved"]));
    assert_eq!(report["stages"]["camera"]["status"], "agree");
    assert_eq!(report["stages"]["P"]["status"], "differs");
    assert!(report["triangles"].is_object());
    for file in [
        "close2gl.png",
        "trace.png",
        "difference.png",
        "report.txt",
        "report.json",
    ] {
        assert!(out_dir.join(file).is_file(), "--out wrote no {file}");
    }
}

/// Each lie, the line it is on, and what the error must say.
#[test]
fn traces_that_lie_stop_with_a_line_numbered_error() {
    let dir = TempDir::new("check_lies");
    let cube = asset("cube.in");
    let good = std::fs::read_to_string(cube_trace(&dir, &[])).expect("read");
    let lines: Vec<&str> = good.lines().collect();
    let tri = lines
        .iter()
        .position(|l| l.starts_with("tri "))
        .expect("a tri line");
    let with = |f: &dyn Fn(&mut Vec<String>)| {
        let mut l: Vec<String> = lines.iter().map(|s| s.to_string()).collect();
        f(&mut l);
        l.join("\n") + "\n"
    };
    let cut = |l: &mut Vec<String>| {
        l.truncate(tri + 1);
        let half = l[tri].len() / 2;
        l[tri].truncate(half);
    };
    let nan = |l: &mut Vec<String>| {
        let mut words: Vec<&str> = l[tri].split_whitespace().collect();
        words[2] = "nan";
        l[tri] = words.join(" ");
    };
    let out_of_range = |l: &mut Vec<String>| {
        let rest: Vec<&str> = l[tri].split_whitespace().skip(2).collect();
        l[tri] = format!("tri 12 {}", rest.join(" "));
    };
    let no_camera = |l: &mut Vec<String>| l.retain(|s| !s.starts_with("camera u"));
    let unknown = |l: &mut Vec<String>| l.insert(1, "colour 1 0 0".into());
    let version = |l: &mut Vec<String>| l[0] = "close2gl-trace 2".into();
    let count = |l: &mut Vec<String>| {
        let i = l
            .iter()
            .position(|s| s.starts_with("triangles"))
            .expect("triangles line");
        l[i] = "triangles 13".into();
    };
    let repeated = |l: &mut Vec<String>| {
        let line = l[tri].clone();
        l.splice(tri..tri, std::iter::repeat_n(line, 64));
        // The helper's count would no longer match: that is another error.
        l.retain(|s| !s.starts_with("drawn "));
    };
    let cases: [(&str, String, &str); 8] = [
        ("truncated", with(&cut), "expected"),
        ("nan", with(&nan), "expected"),
        ("index out of range", with(&out_of_range), "below 12"),
        ("no camera", with(&no_camera), "camera u"),
        ("unknown key", with(&unknown), "colour"),
        ("wrong version", with(&version), "close2gl-trace 1"),
        ("triangle count", with(&count), "triangles 12"),
        ("one triangle drawn 65 times", with(&repeated), "at most 64"),
    ];
    for (name, text, says) in cases {
        let trace = dir.write("lie.trace", text.as_bytes());
        let out = check(&cube, &trace, &[]);
        let stderr = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(2), "{name}: {stderr}");
        assert_eq!(stderr.lines().count(), 1, "{name}: one line: {stderr}");
        let prefix = format!("close2gl: {}:", trace.display());
        let line = stderr
            .strip_prefix(&prefix)
            .unwrap_or_else(|| panic!("{name}: {stderr}"));
        let number: String = line.chars().take_while(char::is_ascii_digit).collect();
        assert!(
            number.parse::<usize>().is_ok_and(|n| n > 0),
            "{name}: no line number: {stderr}"
        );
        assert!(
            stderr.contains(says),
            "{name}: {stderr} does not say {says}"
        );
        assert!(out.stdout.is_empty(), "{name}: nothing half-reported");
    }
}

/// `close2gl check ARGS...`.
fn close2gl_check(args: &[&std::ffi::OsStr]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .arg("check")
        .args(args)
        .output()
        .expect("run close2gl check")
}

#[test]
fn a_raster_trace_alone_is_checked_probed_and_pictured() {
    let dir = TempDir::new("check-raster");
    let traces: Vec<_> = [
        ("right", vec![]),
        ("swapped", vec!["-DMISTAKE_CHANNELS_SWAPPED"]),
    ]
    .into_iter()
    .map(|(name, flags)| {
        close2gl_testkit::student::raster_trace(&dir.0, name, &flags, "square.scene")
    })
    .collect();
    let right = close2gl_check(&[traces[0].as_os_str()]);
    assert_eq!(
        right.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&right.stdout)
    );
    assert!(String::from_utf8_lossy(&right.stdout).contains("agrees"));
    let out = dir.0.join("pictures");
    let swapped = close2gl_check(&[traces[1].as_os_str(), "--out".as_ref(), out.as_os_str()]);
    let text = String::from_utf8_lossy(&swapped.stdout);
    assert_eq!(swapped.status.code(), Some(1), "{text}");
    assert!(text.contains("channels_swapped (output)"), "{text}");
    for picture in ["yours", "close2gl", "coverage", "depth", "colour"] {
        assert!(
            out.join(format!("{picture}.png")).is_file(),
            "{picture}.png"
        );
    }
    let probe = close2gl_check(&[
        traces[1].as_os_str(),
        "--pixel".as_ref(),
        "30".as_ref(),
        "30".as_ref(),
    ]);
    let text = String::from_utf8_lossy(&probe.stdout);
    assert!(
        text.starts_with("pixel (30, 30): yours colour") && text.contains("close2gl: colour"),
        "{text}"
    );
    // A geometry trace alone is not a raster trace: a one-line error, exit 2.
    let geometry = dir.0.join("geometry.trace");
    std::fs::write(&geometry, "close2gl-trace 1\n").expect("write");
    let wrong = close2gl_check(&[geometry.as_os_str()]);
    assert_eq!(wrong.status.code(), Some(2));
    let error = String::from_utf8_lossy(&wrong.stderr);
    assert!(
        error.contains("expected a raster trace ('close2gl-raster 1')"),
        "{error}"
    );
}

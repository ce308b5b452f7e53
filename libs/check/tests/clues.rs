//! check's clues on whole traces: a trace whose M rows are close2gl's scaled by cos 25° (the
//! camera's pitch) is told so; a trace that leaves out one triangle is told its size and place;
//! the camera stage counts the seven facts it checks, and no stage of any trace says more differ
//! than it checked; the grader's translation line says how far the camera moved and what
//! happened to its axes.

// The format's strategies for any trace its reader can produce: one copy, the format's.
#[path = "../../trace_format/tests/common/mod.rs"]
mod common;

use close2gl_check::rubric::{self, LineId};
use close2gl_check::{self as check, Stage, Status, report};
use close2gl_core::{Mesh, ModelSource, PrimitiveParams};
use close2gl_pipeline::mistakes::Mistakes;
use close2gl_pipeline::program::{ProgramCamera, System2d, given};
use close2gl_testkit::student::asset;
use close2gl_trace_format::{CameraLines, Motion, SceneCamera, parse_trace};
use glam::{DMat4, DVec3};
use proptest::prelude::*;

fn cube() -> Mesh {
    let source = ModelSource::File(asset("cube.in"));
    let loaded = close2gl_model::load(&source, &PrimitiveParams::default());
    loaded.expect("the bundled cube").mesh
}

/// A camera 6 units from the cube, pitched 25° (looking down at it from above).
fn pitched() -> ProgramCamera {
    let (s, c) = 25f64.to_radians().sin_cos();
    let n = DVec3::new(0.0, s, c);
    ProgramCamera {
        position: 6.0 * n,
        u: DVec3::X,
        v: n.cross(DVec3::X),
        n,
        hfov: 60.0,
        vfov: 46.0,
        near: 1.0,
        far: 20.0,
    }
}

/// The text of a trace of `camera` in a 640 × 480 window, `0 640 0 480`, with matrices `m`,
/// `p`, `v` (rows as the format writes them) and `more` lines after them.
fn trace_text(camera: &ProgramCamera, [m, p, v]: [DMat4; 3], more: &str) -> String {
    let vec = |a: DVec3| format!("{} {} {}", a.x, a.y, a.z);
    let matrix = |name: &str, m: DMat4| {
        let rows: Vec<String> = m.transpose().to_cols_array().map(|x| x.to_string()).into();
        format!("matrix {name} {}\n", rows.join(" "))
    };
    format!(
        "close2gl-trace 1\nwindow 640 480\northo2d 0 640 0 480\ncamera position {}\ncamera u \
         {}\ncamera v {}\ncamera n {}\ncamera hfov {}\ncamera vfov {}\ncamera near {}\ncamera \
         far {}\n{}{}{}{more}",
        vec(camera.position),
        vec(camera.u),
        vec(camera.v),
        vec(camera.n),
        camera.hfov,
        camera.vfov,
        camera.near,
        camera.far,
        matrix("M", m),
        matrix("P", p),
        matrix("V", v),
    )
}

/// OpenGL's window coordinates of a 640 × 480 window: `ortho2d 0 640 0 480`.
const GL_WINDOW: System2d = System2d {
    left: 0.0,
    right: 640.0,
    bottom: 0.0,
    top: 480.0,
};

/// close2gl's own M, P and V for `camera` in a 640 × 480 window with y up.
fn ours(camera: &ProgramCamera) -> [DMat4; 3] {
    [
        given::modelview(camera, Mistakes::NONE),
        given::projection(camera, Mistakes::NONE),
        given::viewport(&GL_WINDOW, Mistakes::NONE),
    ]
}

/// `m` with its first three rows times `k`: the rows of a camera whose axes are `k` long.
fn rows_scaled(m: DMat4, k: f64) -> DMat4 {
    let mut rows = m.transpose().to_cols_array_2d();
    rows[..3].iter_mut().flatten().for_each(|x| *x *= k);
    DMat4::from_cols_array_2d(&rows).transpose()
}

#[test]
fn m_rows_scaled_by_the_cosine_of_the_pitch_are_named() {
    let camera = pitched();
    let [m, p, v] = ours(&camera);
    let k = 25f64.to_radians().cos() as f32;
    let text = trace_text(&camera, [rows_scaled(m, f64::from(k)), p, v], "end\n");
    let trace = parse_trace(&text, "scaled.trace").expect("a valid trace");
    let report = check::check(&cube(), &trace).expect("it fits the cube");
    let text = report::text(&report, "scaled.trace");
    let clue = "rows 1, 2 and 3 of M are 0.9063 of close2gl's (= cos 25°, the pitch)";
    assert!(text.contains(&format!("      {clue}\n")), "{text}");
    assert_eq!(report.comparison.stage(Stage::M).details[0], clue);
    let unexplained = report.unexplained.as_deref().unwrap_or_default();
    assert!(unexplained.contains(clue), "{unexplained}");
    assert_eq!(report.comparison.stage(Stage::P).status, Status::Agree);
}

#[test]
fn a_p_entry_three_quarters_of_ours_is_named_and_a_right_trace_has_no_clue() {
    let camera = pitched();
    let [m, mut p, v] = ours(&camera);
    let agreeing = parse_trace(&trace_text(&camera, [m, p, v], "end\n"), "t").expect("valid");
    let report = check::check(&cube(), &agreeing).expect("fits");
    assert!(report.agrees() && report.comparison.stage(Stage::P).details.is_empty());
    p.x_axis.x *= 0.75;
    let trace = parse_trace(&trace_text(&camera, [m, p, v], "end\n"), "t").expect("valid");
    let report = check::check(&cube(), &trace).expect("fits");
    assert_eq!(
        report.comparison.stage(Stage::P).details,
        [
            "P[0][0] (row 1, column 1) is 0.7500 of close2gl's (= 3/4 = 480/640, the window's height/width)",
            "P[0][0] (row 1, column 1): expected 1.7321, found 1.2990"
        ]
    );
}

#[test]
fn a_triangle_left_out_is_told_its_size_and_place() {
    let (camera, mesh) = (pitched(), cube());
    let probe = parse_trace(&trace_text(&camera, ours(&camera), ""), "t").expect("valid");
    let frame = check::program_for(&probe, Mistakes::NONE).frame(&mesh);
    let drawn: Vec<usize> = (0..frame.len()).filter(|&t| frame[t].drawn()).collect();
    let tris: String = drawn[1..]
        .iter()
        .map(|&t| {
            let corners: Vec<String> = frame[t]
                .polygon
                .iter()
                .map(|p| format!("{} {}", p.x, p.y))
                .collect();
            format!("tri {t} {}\n", corners.join(" "))
        })
        .collect();
    let text = trace_text(&camera, ours(&camera), &format!("{tris}end\n"));
    let trace = parse_trace(&text, "t").expect("valid");
    let report = check::check(&mesh, &trace).expect("fits");
    let unexplained = report.unexplained.unwrap_or_default();
    assert!(
        unexplained.starts_with("no catalogue mistake explains it: 1 triangle ")
            && unexplained.contains(" px², longest edge ")
            && unexplained.contains("·near in front of the eye (near = 1.0)")
            && unexplained.ends_with("it does not touch the view volume's border"),
        "{unexplained}"
    );
}

/// The camera stage of a trace of `camera` (no matrices: only the axes are checked).
fn camera_stage(camera: &ProgramCamera) -> (String, usize, usize) {
    let text = trace_text(camera, ours(camera), "end\n");
    let trace = parse_trace(&text, "t").expect("valid");
    let report = check::check(&cube(), &trace).expect("fits");
    let stage = report.comparison.stage(Stage::Camera);
    let line = report::text(&report, "t")
        .lines()
        .find(|l| l.starts_with("  camera"))
        .unwrap_or_default()
        .to_string();
    (line, stage.checked, stage.differing)
}

#[test]
fn the_camera_stage_counts_its_seven_facts() {
    let mut camera = pitched();
    let (line, checked, differing) = camera_stage(&camera);
    assert_eq!((checked, differing), (7, 0), "{line}");
    assert!(line.ends_with("7 checked, 0 differ"), "{line}");
    camera.u = -camera.u * 0.9;
    let (line, checked, differing) = camera_stage(&camera);
    assert_eq!(
        (checked, differing),
        (7, 2),
        "u's length and the handedness: {line}"
    );
    camera.v *= 2.0;
    camera.n = camera.u + camera.n;
    let (_, checked, differing) = camera_stage(&camera);
    assert_eq!(checked, 7);
    assert!((4..=7).contains(&differing), "{differing} of 7");
}

/// The grader's translation verdict on the cube's `move n +` scene, for a trace whose camera
/// ended at `moved` (times the asked move) with axes `axes` (the scene's, changed).
fn translation(moved: f64, axes: impl Fn([DVec3; 3]) -> [DVec3; 3]) -> rubric::Verdict {
    let mesh = cube();
    let scenes = rubric::scenes("cube", "cube.in", &mesh);
    let scene = scenes
        .iter()
        .find(|s| s.id == "cube/translation-move-n+")
        .expect("the rubric moves along n");
    let (SceneCamera::Given(start), [Motion::Move(_, d)]) =
        (&scene.scene.camera, scene.scene.motions.as_slice())
    else {
        panic!("a given camera and one move");
    };
    let [u, v, n] = axes([start.u, start.v, start.n]);
    let camera = CameraLines {
        position: start.position + moved * d * start.n,
        u,
        v,
        n,
        ..*start
    };
    let text = trace_text(&camera, ours(&camera), "end\n");
    let trace = parse_trace(&text, "t").expect("valid");
    let report = check::compare_only(&mesh, &trace).expect("fits");
    let verdicts = rubric::judge(scene, &mesh, &trace, &report);
    let (_, verdict) = verdicts
        .into_iter()
        .find(|(line, _)| *line == LineId::Translation)
        .expect("the translation line");
    verdict
}

#[test]
fn a_move_tells_how_far_it_went_and_what_its_axes_did() {
    let c = 25f64.to_radians().cos();
    let short = translation(c, |axes| axes);
    assert!(
        !short.passed
            && short
                .detail
                .ends_with("(it moved 0.9063 of the asked distance (= cos 25°, the pitch))"),
        "{}",
        short.detail
    );
    let shorter_u = translation(1.0, |[u, v, n]| [u * c, v, n]);
    assert_eq!(
        shorter_u.detail,
        "u is 0.9063 long (= cos 25°, the pitch), not unit; the move did not turn it"
    );
    let left = translation(1.0, |[u, v, n]| [-u, v, n]);
    assert!(
        left.detail
            .starts_with("the axes are left-handed from the scene's start: u = n × v = "),
        "{}",
        left.detail
    );
    let back = translation(-1.0, |axes| axes);
    assert!(
        back.detail
            .ends_with("(it moved the asked distance the other way)"),
        "{}",
        back.detail
    );
    assert!(translation(1.0, |axes| axes).passed);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Any trace that fits the cube, its clues included: no panic, and no stage counts more
    /// differences than checks (the camera's once said "1 checked, 2 differ").
    #[test]
    fn no_stage_differs_more_than_it_checked(trace in common::trace()) {
        let mut trace = trace;
        trace.triangles = None;
        trace.clip.retain(|c| c.triangle < 12);
        trace.pieces.retain(|p| p.triangle < 12);
        let Ok(report) = check::check(&cube(), &trace) else {
            return Ok(());
        };
        for stage in &report.comparison.stages {
            prop_assert!(stage.differing <= stage.checked, "{stage:?}");
        }
    }
}

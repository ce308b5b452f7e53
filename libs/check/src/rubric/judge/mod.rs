//! How each line judges one scene's trace, on what the line is about and nothing else:
//!
//! - every line: the trace declares what the scene set (window, culling, clipping `simple` or
//!   the better `full`), and, in a scene without motions, the camera stands where the scene put
//!   it (position, v and n: a left-handed u is the camera stage's to find); the view volume
//!   only where a line is about it (hfov and vfov for the pictures and their lines, near and
//!   far for clipping, all for `synchronized`): the camera a trace declares is the one judged;
//! - `points`, `wireframe`, `solid`: the trace's mode, and its 2D output (check's camera,
//!   clipping, culling and window stages);
//! - `translation`: the final camera moved along its own axis by the amount, axes unchanged,
//!   and check's M; `lookat_translation`: the final camera looks from the look-at point, moved
//!   the asked way by about the amount (straight or along an arc); `rotation`: the final axes
//!   turned by the angle, by the right-hand rule or the other way round;
//! - `culling`, `simple_clipping`: check's stage recomputed on the program's own geometry
//!   ([`own_input`](crate::own_input)), so that a wrong matrix costs its own line, not
//!   these; clipping takes the program's culling as given (what it left out inside the volume
//!   is what culling with some front face leaves out);
//! - `hfov`, `vfov`: P's first (second) row, and the width (height) in NDC of what the program
//!   drew against close2gl's with the program's own M;
//! - `resize`: check's V, and where the 2D output lands (the window stage) from the program's
//!   own clip coordinates through the declared viewport;
//! - `synchronized`: the whole frame, every stage check compares.
//!
//! The motion lines' judgments are in `camera.rs`, those on the frame in `frame.rs`.

mod drawn;
mod final_camera;

use close2gl_core::{FrontFace, Mesh};
use close2gl_pipeline::program::{ClipRule, Program, TriangleOutcome, WindingSpace};
use close2gl_trace_format::{
    CameraLines, SceneCamera, SceneFile, Trace, clipping_name, culling_name,
};
use glam::DVec3;

use super::lines::LineId;
use super::scenes::RubricScene;
use crate::declared::program_for;
use crate::report::Report;
use crate::vocabulary::{Comparison, Stage, StageResult, Status};
use crate::words::number;
pub use final_camera::Turn;
pub(crate) use final_camera::settle_rotations;

/// How far a unit axis may be from the expected one: far above float32 rounding, far below
/// any real mistake.
const AXIS: f64 = 1e-4;
/// A position's tolerance, as a fraction of its distance from the origin and of the motion.
const POSITION: f64 = 1e-5;

/// One line's judgment of one scene: passed or not, and why (or, for a pass, what was
/// accepted: "an arc around the look-at point"; empty when there is nothing to say).
#[derive(Clone, Debug, PartialEq)]
pub struct Verdict {
    pub passed: bool,
    pub detail: String,
    /// For a rotation that passed: which way it turned.
    pub turn: Option<Turn>,
}

impl Verdict {
    fn pass(detail: impl Into<String>) -> Self {
        Self {
            passed: true,
            detail: detail.into(),
            turn: None,
        }
    }

    pub fn fail(detail: impl Into<String>) -> Self {
        Self {
            passed: false,
            detail: detail.into(),
            turn: None,
        }
    }
}

/// Every line of `scene` judged on `trace`; `report` is check's comparison of the trace
/// ([`check::compare_only`](crate::compare_only)).
pub fn judge(
    scene: &RubricScene,
    mesh: &Mesh,
    trace: &Trace,
    report: &Report,
) -> Vec<(LineId, Verdict)> {
    let SceneCamera::Given(start) = scene.scene.camera else {
        let why = "a rubric scene gives its camera";
        return scene
            .lines
            .iter()
            .map(|&l| (l, Verdict::fail(why)))
            .collect();
    };
    let judge = Judge {
        scene: &scene.scene,
        start,
        mesh,
        trace,
        report,
        ours: program_for(trace, close2gl_pipeline::mistakes::Mistakes::NONE),
    };
    let lines = scene.lines.iter();
    lines.map(|&line| (line, judge.line(line))).collect()
}

struct Judge<'a> {
    scene: &'a SceneFile,
    start: CameraLines,
    mesh: &'a Mesh,
    trace: &'a Trace,
    report: &'a Report,
    /// close2gl's program for the trace's camera and settings.
    ours: Program,
}

impl Judge<'_> {
    fn line(&self, line: LineId) -> Verdict {
        let mode = matches!(line, LineId::Points | LineId::Wireframe | LineId::Solid);
        if let Err(why) = self
            .declared(mode)
            .and_then(|()| self.volume_declared(line))
        {
            return Verdict::fail(why);
        }
        if self.scene.motions.is_empty()
            && let Err(why) = self.pose_kept()
        {
            return Verdict::fail(why);
        }
        match line {
            LineId::Points | LineId::Wireframe | LineId::Solid => self.output_right(),
            LineId::Translation => self.translation(),
            LineId::LookatTranslation => self.orbit(),
            LineId::Rotation => self.rotation(),
            LineId::Culling => self.own_stages(&[Stage::Culling], true),
            LineId::SimpleClipping => self.clipping(),
            LineId::Hfov => self.fov(0),
            LineId::Vfov => self.fov(1),
            LineId::Resize => self.resize(),
            LineId::Synchronized => self.synchronized(),
        }
    }

    /// The trace declares what the scene set.
    fn declared(&self, mode: bool) -> Result<(), String> {
        let (scene, trace) = (self.scene, self.trace);
        if trace.window != scene.window {
            return Err(format!(
                "its window is {}x{}, the scene's {}x{}",
                trace.window.0, trace.window.1, scene.window.0, scene.window.1
            ));
        }
        if on_screen(trace) != scene.culling {
            return Err(format!(
                "it declares culling {}, the scene culling {}",
                culling_name(trace.culling),
                culling_name(scene.culling)
            ));
        }
        // Full clipping does more than the assignment's simple clipping asks: accepted.
        let clipping_ok = trace.clipping == scene.clipping
            || (scene.clipping == ClipRule::Simple && trace.clipping == ClipRule::Full);
        if !clipping_ok {
            return Err(format!(
                "it declares clipping {}, the scene clipping {}",
                clipping_name(trace.clipping),
                clipping_name(scene.clipping)
            ));
        }
        if mode && trace.mode != scene.mode {
            let name = |m: Option<close2gl_core::RenderMode>| m.map_or("none", |m| m.name());
            return Err(format!(
                "its mode is {}, the scene's {}",
                name(trace.mode),
                name(scene.mode)
            ));
        }
        Ok(())
    }

    /// The view volume the trace declares is the scene's, as far as `line` is about it: the
    /// trace's camera is the one judged, so a program that says honestly which hfov it drew
    /// with loses the lines about that hfov (hfov, the pictures, synchronized) and no more; one
    /// that says the scene's and drew with another is caught by its P or its output.
    fn volume_declared(&self, line: LineId) -> Result<(), String> {
        let (s, t) = (&self.start, &self.trace.camera);
        let all = [
            ("hfov", s.hfov, t.hfov),
            ("vfov", s.vfov, t.vfov),
            ("near", s.near, t.near),
            ("far", s.far, t.far),
        ];
        let about: &[usize] = match line {
            LineId::Points | LineId::Wireframe | LineId::Solid => &[0, 1],
            LineId::Hfov => &[0],
            LineId::Vfov => &[1],
            LineId::SimpleClipping => &[2, 3],
            LineId::Synchronized => &[0, 1, 2, 3],
            _ => &[],
        };
        for &(name, want, found) in about.iter().map(|&i| &all[i]) {
            if (want - found).abs() > POSITION * want.abs() {
                return Err(format!(
                    "it drew with its camera's {name} {}, the scene asks {}",
                    number(found),
                    number(want)
                ));
            }
        }
        Ok(())
    }

    /// The camera stands where the scene put it: position, v and n (what places the view
    /// volume; a mirrored u is the camera stage's to report).
    fn pose_kept(&self) -> Result<(), String> {
        let (s, t) = (&self.start, &self.trace.camera);
        let tolerance = POSITION * (s.position.length() + 1.0);
        let off = [
            ("position", s.position, t.position, tolerance),
            ("v", s.v, t.v, AXIS),
            ("n", s.n, t.n, AXIS),
        ]
        .into_iter()
        .find(|(_, want, found, tolerance)| want.distance(*found) > *tolerance);
        match off {
            Some((name, want, found, _)) => Err(format!(
                "its camera is not the scene's: {name} expected {}, found {}",
                vec3(want),
                vec3(found)
            )),
            None => Ok(()),
        }
    }
}

/// The front face a trace declares, as seen on screen: `culling cw window` in a 2D system whose
/// numbers run mirrored on screen (y down: `ortho2d 0 W H 0`) is the scene's `ccw`.
fn on_screen(trace: &Trace) -> Option<FrontFace> {
    let o = trace.ortho2d;
    let mirrored = (o.right - o.left) * (o.top - o.bottom) < 0.0;
    match (trace.culling, trace.winding, mirrored) {
        (Some(FrontFace::Ccw), Some(WindingSpace::Window), true) => Some(FrontFace::Cw),
        (Some(FrontFace::Cw), Some(WindingSpace::Window), true) => Some(FrontFace::Ccw),
        (culling, _, _) => culling,
    }
}

/// A trace that drew nothing: right when `expected` draws nothing either (everything culled
/// or outside), a failure saying how much `whose` pipeline draws otherwise.
fn drew_nothing(expected: &[TriangleOutcome], whose: &str) -> Verdict {
    match expected.iter().filter(|o| o.drawn()).count() {
        0 => Verdict::pass(""),
        n => Verdict::fail(format!("it drew nothing, where {whose} {n} triangles")),
    }
}

/// Each stage agrees; a stage the trace leaves out fails (a line that is judged on M, P or V
/// needs the trace to give it).
fn stages_agree(comparison: &Comparison, stages: &[Stage]) -> Verdict {
    for &stage in stages {
        let verdict = required(comparison.stage(stage));
        if !verdict.passed {
            return verdict;
        }
    }
    Verdict::pass("")
}

/// A stage that must have been checked, and agree.
fn required(result: &StageResult) -> Verdict {
    match result.status {
        Status::NotChecked => Verdict::fail(format!(
            "{}: {}",
            result.stage.name(),
            result.note.as_deref().unwrap_or("not checked")
        )),
        _ => stage_verdict(result),
    }
}

/// A stage that differs fails with its first detail; one not checked passes (synchronized
/// judges what the trace gives).
fn stage_verdict(result: &StageResult) -> Verdict {
    match result.status {
        Status::Differs => Verdict::fail(format!(
            "{}: {} ({} of {} differ)",
            result.stage.name(),
            result.details.first().map_or("", String::as_str),
            result.differing,
            result.checked
        )),
        _ => Verdict::pass(""),
    }
}

fn vec3(p: DVec3) -> String {
    format!("({}, {}, {})", number(p.x), number(p.y), number(p.z))
}

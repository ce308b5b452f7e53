//! The lines judged on the frame: the modes' 2D output, culling and clipping on the program's
//! own geometry, the fields of view, resizing, and the whole frame for `synchronized`.

use close2gl_core::FrontFace;
use close2gl_pipeline::program::{CullRule, Program, TriangleOutcome};
use glam::{DMat4, DVec2};

use super::{Judge, Verdict, drew_nothing, required, stage_verdict, stages_agree};
use crate::clues;
use crate::compare::{self, matrices};
use crate::own_input::own_program;
use crate::vocabulary::{Kind, Stage};
use crate::words::number;

/// How far a frame's width in NDC (where the window is 2 wide) may be off.
const WIDTH: f64 = 1e-3;

impl Judge<'_> {
    /// The 2D output agrees with close2gl's, as a picture: the camera, clipping, culling and
    /// window stages of the whole chain from the camera (not on the program's own matrices,
    /// which check's report judges by: a picture drawn with a wrong P is a wrong picture).
    pub(super) fn output_right(&self) -> Verdict {
        let stages = [
            Stage::Camera,
            Stage::Clipping,
            Stage::Culling,
            Stage::Window,
        ];
        let whole = compare::compare(&self.ours, self.mesh, self.trace, &self.report.expected);
        stages_agree(&whole, &stages)
    }
    /// Stages of check recomputed on the program's own geometry (own V: `own_viewport`).
    pub(super) fn own_stages(&self, stages: &[Stage], own_viewport: bool) -> Verdict {
        let program = own_program(&self.ours, self.mesh, self.trace, own_viewport);
        let expected = program.frame(self.mesh);
        if self.trace.pieces.is_empty() {
            return drew_nothing(&expected, "its own clip coordinates show");
        }
        let comparison = compare::compare(&program, self.mesh, self.trace, &expected);
        stages_agree(&comparison, stages)
    }

    /// Clipping on the program's own geometry, its culling taken as given: what it left out
    /// inside the view volume must be what culling with some front face (the declared one, or
    /// either) leaves out, so that a culling bug (culling with culling off, everything culled
    /// in a scene seen from inside) costs the culling line and not this one, while a program
    /// that drops what no culling drops (or draws nothing at all) still fails it.
    pub(super) fn clipping(&self) -> Verdict {
        let program = own_program(&self.ours, self.mesh, self.trace, true);
        if !self.trace.gives_output() {
            return drew_nothing(&program.frame(self.mesh), "its own clip coordinates show");
        }
        let declared = self.clipping_with(&program);
        if declared.passed {
            return declared;
        }
        // Only a trace that fails with its declared culling is tried with either front face.
        [FrontFace::Ccw, FrontFace::Cw]
            .into_iter()
            .map(|front| {
                let mut culling = program;
                culling.declared.culling = Some(front);
                culling.cull = CullRule::Winding(front);
                self.clipping_with(&culling)
            })
            .find(|v| v.passed)
            .unwrap_or(declared)
    }

    /// Clipping as `program` culls: its clipping stage agrees, and nothing inside the view
    /// volume that it draws was left out.
    fn clipping_with(&self, program: &Program) -> Verdict {
        let comparison =
            compare::compare(program, self.mesh, self.trace, &program.frame(self.mesh));
        let verdict = stages_agree(&comparison, &[Stage::Clipping]);
        let left_out = comparison
            .triangles
            .iter()
            .any(|(kind, _)| matches!(kind, Kind::InsideNotDrawn | Kind::FrontCulled));
        match left_out && verdict.passed {
            true => stage_verdict(comparison.stage(Stage::Culling)),
            false => verdict,
        }
    }

    /// hfov (row 0) or vfov (row 1): P's row, and the frame's width (height) in NDC.
    pub(super) fn fov(&self, row: usize) -> Verdict {
        let mut p = matrices::matrix(Stage::P, self.ours.p, self.trace.p, &[row]);
        clues::add_matrix_clue(&mut p, self.ours.p, self.trace, &[row]);
        let p = required(&p);
        if !p.passed {
            return p;
        }
        let mut expected = self.ours;
        if let Some(m) = self.trace.m {
            expected.m = m;
            expected.clip_matrix = expected.p * m;
        }
        let ours = extent(
            expected
                .frame(self.mesh)
                .iter()
                .flat_map(|o: &TriangleOutcome| o.polygon.iter().copied()),
            self.ours.v,
            row,
        );
        let own_v = self
            .trace
            .v
            .filter(|v| v.col(row)[row].abs() > 0.0)
            .unwrap_or(self.ours.v);
        let theirs = extent(
            self.trace
                .pieces
                .iter()
                .flat_map(|p| p.corners.iter().copied()),
            own_v,
            row,
        );
        let (side, fov) = match row {
            0 => ("wide", self.start.hfov),
            _ => ("high", self.start.vfov),
        };
        match (theirs, ours) {
            (None, None) => Verdict::pass(""),
            (Some(t), Some(o)) if (t - o).abs() <= WIDTH + WIDTH * o + self.pixels(row, 2.0) => {
                Verdict::pass("")
            }
            (t, o) => Verdict::fail(format!(
                "what it drew is {} {side} in NDC, close2gl's {} (a field of view of {})",
                t.map_or("nothing".into(), number),
                o.map_or("nothing".into(), number),
                number(fov)
            )),
        }
    }

    /// `n` pixels of the window along NDC axis `row`, in NDC (where the window is 2 wide): a
    /// program that rounds its corners to whole pixels (the window stage's business) changes
    /// what it drew by that much, whatever its field of view.
    fn pixels(&self, row: usize, n: f64) -> f64 {
        let (w, h) = self.trace.window;
        let size = if row == 0 { w } else { h };
        2.0 * n / f64::from(size)
    }

    /// V where the trace gives it, and where the 2D output lands through the declared
    /// viewport. V is optional: a program that does not write it (one whose output is NDC,
    /// `ortho2d -1 1 -1 1`, where the GPU does the viewport, or one that never built a
    /// matrix for it) is judged on where its output lands.
    pub(super) fn resize(&self) -> Verdict {
        if self.trace.v.is_some() {
            let v = stage_verdict(self.report.comparison.stage(Stage::V));
            if !v.passed {
                return v;
            }
        }
        self.own_stages(&[Stage::Window], false)
    }

    /// Every stage check compares agrees; a trace that drew nothing agrees only where close2gl
    /// draws nothing either.
    pub(super) fn synchronized(&self) -> Verdict {
        if let Some(stage) = self.report.comparison.first_difference() {
            return stage_verdict(stage);
        }
        match self.trace.pieces.is_empty() {
            true => drew_nothing(&self.report.expected, "close2gl draws"),
            false => Verdict::pass(""),
        }
    }
}

/// The width of `points` (in a 2D system whose viewport is `v`) along NDC axis `row`.
fn extent(points: impl Iterator<Item = DVec2>, v: DMat4, row: usize) -> Option<f64> {
    let (scale, offset) = (v.col(row)[row], v.col(3)[row]);
    let (low, high) = points
        .map(|p| (p[row] - offset) / scale)
        .filter(|x| x.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(l, h), x| {
            (l.min(x), h.max(x))
        });
    (low <= high).then_some(high - low)
}

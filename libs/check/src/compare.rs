//! One program's frame (close2gl's, or close2gl's with mistakes) against a trace, stage by stage
//! in the pipeline's order. What the trace leaves out is not checked; what it gives is checked
//! within tolerances a float32 program meets (docs/checking.md, "Tolerances").

use close2gl_core::{FateKind, Mesh, Mistake};
use close2gl_pipeline::program::{Outcome, Program};
use close2gl_trace_format::Trace;
use glam::{DMat4, DVec2, DVec4};

use close2gl_pipeline::rounding::{self, BOUND, PRINTED, clip_error, clip_terms};

use super::own_input::own_program;
use super::region;

/// The stages, in the pipeline's order, by the names scripts read.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Stage {
    Camera,
    M,
    P,
    V,
    Clip,
    Clipping,
    Culling,
    Window,
    Depth,
}

impl Stage {
    pub const ALL: [Stage; 9] = [
        Stage::Camera,
        Stage::M,
        Stage::P,
        Stage::V,
        Stage::Clip,
        Stage::Clipping,
        Stage::Culling,
        Stage::Window,
        Stage::Depth,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Stage::Camera => "camera",
            Stage::M => "M",
            Stage::P => "P",
            Stage::V => "V",
            Stage::Clip => "clip",
            Stage::Clipping => "clipping",
            Stage::Culling => "culling",
            Stage::Window => "window",
            Stage::Depth => "depth",
        }
    }
}

/// A way one mesh triangle can disagree, each belonging to one stage.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum Kind {
    /// Its clip coordinates differ.
    ClipCoordinates,
    /// close2gl removed it whole and a corner is at or behind the eye; the trace drew it.
    DrawnBehindEye,
    /// close2gl removed it whole (outside the volume); the trace drew it.
    DrawnOutside,
    /// close2gl drew it (cut or whole, culling off or front-facing); the trace drew nothing.
    NotDrawn,
    /// Inside the volume and front-facing; the trace drew nothing.
    FrontCulled,
    /// Inside the volume and back-facing (culled by close2gl); the trace drew it.
    BackDrawn,
    /// Inside the volume with culling off; the trace drew nothing (it culls anyway, or drops
    /// triangles by a rule of its own).
    InsideNotDrawn,
    /// Both drew it, in different places or shapes.
    Moved,
    /// Both drew it in the same place, at different depths.
    Depth,
}

impl Kind {
    pub fn name(self) -> &'static str {
        match self {
            Kind::ClipCoordinates => "clip_coordinates",
            Kind::DrawnBehindEye => "drawn_behind_eye",
            Kind::DrawnOutside => "drawn_outside",
            Kind::NotDrawn => "not_drawn",
            Kind::FrontCulled => "front_culled",
            Kind::BackDrawn => "back_drawn",
            Kind::InsideNotDrawn => "inside_not_drawn",
            Kind::Moved => "moved",
            Kind::Depth => "depth",
        }
    }

    pub fn stage(self) -> Stage {
        match self {
            Kind::ClipCoordinates => Stage::Clip,
            Kind::DrawnBehindEye | Kind::DrawnOutside | Kind::NotDrawn => Stage::Clipping,
            Kind::FrontCulled | Kind::BackDrawn | Kind::InsideNotDrawn => Stage::Culling,
            Kind::Moved => Stage::Window,
            Kind::Depth => Stage::Depth,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    Agree,
    Differs,
    NotChecked,
}

impl Status {
    pub fn name(self) -> &'static str {
        match self {
            Status::Agree => "agree",
            Status::Differs => "differs",
            Status::NotChecked => "not_checked",
        }
    }
}

/// One stage's verdict: how many items it checked, how many differ, and the first differences
/// in words.
#[derive(Clone, Debug, PartialEq)]
pub struct StageResult {
    pub stage: Stage,
    pub status: Status,
    pub checked: usize,
    pub differing: usize,
    /// Up to [`MAX_DETAILS`] lines, in order.
    pub details: Vec<String>,
    /// Why it was not checked, when it was not.
    pub note: Option<String>,
}

/// The most lines of detail a stage keeps.
pub const MAX_DETAILS: usize = 20;

impl StageResult {
    fn new(stage: Stage) -> Self {
        Self {
            stage,
            status: Status::NotChecked,
            checked: 0,
            differing: 0,
            details: Vec::new(),
            note: None,
        }
    }

    fn not_checked(stage: Stage, note: &str) -> Self {
        Self {
            note: Some(note.into()),
            ..Self::new(stage)
        }
    }

    fn differ(&mut self, detail: impl FnOnce() -> String) {
        self.differing += 1;
        if self.details.len() < MAX_DETAILS {
            self.details.push(detail());
        }
    }

    fn finish(mut self) -> Self {
        self.status = match self.differing {
            0 => Status::Agree,
            _ => Status::Differs,
        };
        self
    }

    /// Its status in a few words, as the viewer's panel lists the stages: `not checked`,
    /// `agrees (N)`, `K of N differ`.
    pub fn in_brief(&self) -> String {
        match self.status {
            Status::NotChecked => "not checked".to_string(),
            Status::Agree => format!("agrees ({})", self.checked),
            Status::Differs => format!("{} of {} differ", self.differing, self.checked),
        }
    }
}

/// Every stage's verdict, and the triangles that disagree by kind (all of them, in order).
#[derive(Clone, Debug, PartialEq)]
pub struct Comparison {
    pub stages: Vec<StageResult>,
    pub triangles: Vec<(Kind, Vec<usize>)>,
}

impl Comparison {
    /// Whether everything the trace gives agrees.
    pub fn agrees(&self) -> bool {
        self.stages.iter().all(|s| s.status != Status::Differs)
    }

    /// The first stage that differs.
    pub fn first_difference(&self) -> Option<&StageResult> {
        self.stages.iter().find(|s| s.status == Status::Differs)
    }

    pub fn stage(&self, stage: Stage) -> &StageResult {
        &self.stages[stage as usize]
    }

    /// The triangles that disagree in `kind`.
    pub fn of_kind(&self, kind: Kind) -> &[usize] {
        self.triangles
            .iter()
            .find(|(k, _)| *k == kind)
            .map_or(&[], |(_, t)| t)
    }
}

/// How far apart unit axes may be from unit length or square to each other: a float32
/// program's axes after many turns drift by far less (it renormalises, or the camera stage
/// is where it shows).
const AXES: f64 = 1e-3;

/// Compares `trace` with what `program` computes for `mesh` (`expected`: its frame), the whole
/// chain from the camera. The trace's triangle indices must be the mesh's (checked when the
/// trace was read).
pub fn compare(program: &Program, mesh: &Mesh, trace: &Trace, expected: &[Outcome]) -> Comparison {
    compare_stages([program, program, program], mesh, trace, expected)
}

/// Compares `trace` with `program`, each stage on the program's own input to it: the clip
/// coordinates against its own P·M (when it gives both), clipping, culling and the window from
/// its own clip coordinates and V ([`own_program`]). Two independent bugs then show at once,
/// each at its stage, rather than the first hiding the second under its consequences.
pub fn compare_own_input(program: &Program, mesh: &Mesh, trace: &Trace) -> Comparison {
    let own = own_program(program, mesh, trace, true);
    let expected = own.frame(mesh);
    let mut own_product = *program;
    if let Some((p, m)) = trace.p.zip(trace.m) {
        own_product.clip_matrix = p * m;
    }
    compare_stages([program, &own_product, &own], mesh, trace, &expected)
}

/// The stages in order: the camera and the matrices against `matrices`, the clip coordinates
/// against `clip`'s, the 2D output against `output`'s frame, `expected`.
fn compare_stages(
    [matrices_of, clip_of, output]: [&Program; 3],
    mesh: &Mesh,
    trace: &Trace,
    expected: &[Outcome],
) -> Comparison {
    let mut triangles: Vec<(Kind, Vec<usize>)> = Vec::new();
    let mut mark = |kind: Kind, t: usize| match triangles.iter_mut().find(|(k, _)| *k == kind) {
        Some((_, list)) => list.push(t),
        None => triangles.push((kind, vec![t])),
    };
    let mut stages = vec![camera(matrices_of, trace)];
    stages.extend(matrices(matrices_of, trace));
    stages.push(clip(clip_of, mesh, trace, &mut mark));
    stages.extend(drawn(output, trace, expected, &mut mark));
    triangles.sort_by_key(|(kind, _)| *kind);
    Comparison { stages, triangles }
}

/// The M, P and V stages (V's depth row is not compared: the format leaves it to the program).
pub(super) fn matrices(program: &Program, trace: &Trace) -> [StageResult; 3] {
    [
        matrix(Stage::M, program.m, trace.m, ALL_ROWS),
        matrix(Stage::P, program.p, trace.p, ALL_ROWS),
        matrix(Stage::V, program.v, trace.v, V_ROWS),
    ]
}

/// The rows of M and P compared, and of V (its third, for depth, is the program's own).
pub(super) const ALL_ROWS: &[usize] = &[0, 1, 2, 3];
pub(super) const V_ROWS: &[usize] = &[0, 1, 3];

pub(super) fn camera(program: &Program, trace: &Trace) -> StageResult {
    let mut result = StageResult::new(Stage::Camera);
    // Three lengths, three right angles and the handedness: each can differ once.
    result.checked = 7;
    let c = &trace.camera;
    for (name, axis) in [("u", c.u), ("v", c.v), ("n", c.n)] {
        let length = axis.length();
        if (length - 1.0).abs() > AXES {
            result.differ(|| format!("{name} is not unit length: |{name}| = {length:.6}"));
        }
    }
    for (name, a, b) in [("u·v", c.u, c.v), ("u·n", c.u, c.n), ("v·n", c.v, c.n)] {
        let dot = a.dot(b) / (a.length() * b.length());
        if dot.abs() > AXES {
            result.differ(|| format!("the axes are not square to each other: {name} = {dot:.6}"));
        }
    }
    let handedness = c.u.cross(c.v).dot(c.n);
    let left_expected = program.mistakes.has(Mistake::LeftHanded);
    if (handedness < 0.0) != left_expected {
        result.differ(|| match left_expected {
            true => format!("the axes are right-handed: (u × v)·n = {handedness:.6}"),
            false => format!(
                "the axes are left-handed: (u × v)·n = {handedness:.6} (u points to the \
                 camera's left: u = n × v instead of v × n)"
            ),
        });
    }
    result.finish()
}

/// A matrix stage: entries of the given rows, each within [`BOUND`] of its size and of the
/// matrix's (rounding in float32 scales with both), and what printing it adds.
pub fn matrix(stage: Stage, expected: DMat4, found: Option<DMat4>, rows: &[usize]) -> StageResult {
    let Some(found) = found else {
        let note = format!("the trace has no 'matrix {}' line", stage.name());
        return StageResult::not_checked(stage, &note);
    };
    let mut result = StageResult::new(stage);
    let largest = expected
        .to_cols_array()
        .iter()
        .fold(0.0f64, |a, b| a.max(b.abs()));
    for &row in rows {
        for column in 0..4 {
            let (e, f) = (expected.col(column)[row], found.col(column)[row]);
            result.checked += 1;
            // An entry is computed from numbers as large as the matrix's largest (M's
            // translation sums c's terms), and printed.
            let tolerance = BOUND * (e.abs() + largest) + PRINTED;
            if !within((e - f).abs(), tolerance) {
                result.differ(|| {
                    format!(
                        "{}[{}][{}] (row {}, column {}): expected {}, found {}",
                        stage.name(),
                        row,
                        column,
                        row + 1,
                        column + 1,
                        number(e),
                        number(f)
                    )
                });
            }
        }
    }
    result.finish()
}

pub(super) fn clip(
    program: &Program,
    mesh: &Mesh,
    trace: &Trace,
    mark: &mut impl FnMut(Kind, usize),
) -> StageResult {
    if trace.clip.is_empty() {
        return StageResult::not_checked(Stage::Clip, "the trace has no 'clip' lines");
    }
    let mut result = StageResult::new(Stage::Clip);
    let a = program.clip_matrix;
    for line in &trace.clip {
        result.checked += 1;
        let t = line.triangle;
        let corners = mesh.triangles[t].map(|i| program.world(mesh, i));
        for (k, (&found, &corner)) in line.corners.iter().zip(&corners).enumerate() {
            let want = a * corner.extend(1.0);
            let error = clip_error(clip_terms(a, program.camera.position, &[corner]));
            let off = (found - want).abs();
            if (0..4).any(|i| !within(off[i], error[i] + PRINTED)) {
                mark(Kind::ClipCoordinates, t);
                result.differ(|| {
                    format!(
                        "triangle {t}, corner {k} (line {}): expected {}, found {}",
                        line.line,
                        vec4(want),
                        vec4(found)
                    )
                });
                break;
            }
        }
    }
    result.finish()
}

/// What the trace drew, by mesh triangle (indices into `trace.pieces`).
pub fn pieces_by_triangle(trace: &Trace, triangles: usize) -> Vec<Vec<usize>> {
    let mut pieces: Vec<Vec<usize>> = vec![Vec::new(); triangles];
    for (i, piece) in trace.pieces.iter().enumerate() {
        pieces[piece.triangle].push(i);
    }
    pieces
}

/// What one mesh triangle's comparison found.
pub enum TriangleVerdict {
    /// Both agree; `window`: both drew it (the window stage checked it), `depths`: how many of
    /// the trace's pieces gave depths that were checked.
    Agree { window: bool, depths: usize },
    Differs {
        kind: Kind,
        detail: String,
        window: bool,
        depths: usize,
    },
}

/// Judges mesh triangle `t`: close2gl's outcome `ours` against the trace's pieces for it.
pub fn judge_triangle(
    program: &Program,
    trace: &Trace,
    t: usize,
    ours: &Outcome,
    pieces: &[usize],
) -> TriangleVerdict {
    let theirs: Vec<&[DVec2]> = pieces
        .iter()
        .map(|&i| trace.pieces[i].corners.as_slice())
        .collect();
    let one = OneTriangle {
        program,
        trace,
        t,
        ours,
        pieces,
        theirs,
    };
    match (ours.drawn(), !one.theirs.is_empty()) {
        (true, true) => one.both_drew(),
        (true, false) => one.only_ours_drew(),
        (false, true) => one.only_theirs_drew(),
        (false, false) => AGREE,
    }
}

/// One mesh triangle as both sides drew it. What is worked out from it (visibility, the
/// trace's line) is worked out only in the branch that reads it: a triangle is judged for
/// every candidate set of mistakes.
struct OneTriangle<'a> {
    program: &'a Program,
    trace: &'a Trace,
    t: usize,
    ours: &'a Outcome,
    pieces: &'a [usize],
    theirs: Vec<&'a [DVec2]>,
}

impl OneTriangle<'_> {
    /// The trace's line of the triangle's first piece.
    fn line(&self) -> usize {
        self.pieces
            .first()
            .map_or(0, |&i| self.trace.pieces[i].line)
    }

    /// Both drew it: in the same place (the window stage), at the same depths.
    fn both_drew(&self) -> TriangleVerdict {
        let (t, ours) = (self.t, self.ours);
        if let Some(d) = region::compare(&ours.polygon, &ours.errors, &self.theirs) {
            return differs(Kind::Moved, moved(t, &d, self.line()), true, 0);
        }
        let (checked, off) = depths(ours, self.pieces, self.trace);
        match off {
            Some((found, want, line)) => differs(
                Kind::Depth,
                format!(
                    "triangle {t} (line {line}): depth expected {}, found {}",
                    number(want),
                    number(found)
                ),
                true,
                checked,
            ),
            None => TriangleVerdict::Agree {
                window: true,
                depths: checked,
            },
        }
    }

    /// close2gl drew it and the trace did not: culling's (front-facing, or inside with culling
    /// off) or clipping's; nothing when close2gl's piece is within rounding of nothing.
    fn only_ours_drew(&self) -> TriangleVerdict {
        let (t, ours) = (self.t, self.ours);
        if ours.near_a_plane || region::negligible(&ours.polygon, &ours.errors) {
            return AGREE;
        }
        let inside = ours.fate.kind == FateKind::Drawn;
        let culling_on = self.program.declared.culling.is_some();
        if inside && ours.near_edge_on {
            AGREE
        } else if inside && culling_on {
            let detail = format!(
                "triangle {t}: close2gl drew it (front-facing, inside the view volume); the \
                 trace drew nothing"
            );
            differs(Kind::FrontCulled, detail, false, 0)
        } else if inside {
            let detail = format!(
                "triangle {t}: close2gl drew it (inside the view volume, culling off); the trace \
                 drew nothing"
            );
            differs(Kind::InsideNotDrawn, detail, false, 0)
        } else {
            let detail = format!(
                "triangle {t}: close2gl {} it; the trace drew nothing",
                fate_words(ours)
            );
            differs(Kind::NotDrawn, detail, false, 0)
        }
    }

    /// The trace drew it and close2gl did not: clipping's (outside, or behind the eye) or
    /// culling's; nothing when the trace's pieces are within rounding of nothing.
    fn only_theirs_drew(&self) -> TriangleVerdict {
        let (t, ours) = (self.t, self.ours);
        let error = corner_error(self.program, ours);
        let visible = self
            .theirs
            .iter()
            .any(|q| !region::negligible(q, &vec![error; q.len()]));
        if !visible {
            return AGREE;
        }
        match ours.fate.kind {
            FateKind::Clipped if !ours.near_a_plane => {
                let kind = match ours.clip.iter().any(|c| c.w <= 0.0) {
                    true => Kind::DrawnBehindEye,
                    false => Kind::DrawnOutside,
                };
                let detail = format!(
                    "triangle {t}: close2gl {} it; the trace drew it (line {})",
                    fate_words(ours),
                    self.line()
                );
                differs(kind, detail, false, 0)
            }
            FateKind::Culled | FateKind::ZeroArea if !ours.near_edge_on => {
                let detail = format!(
                    "triangle {t}: close2gl culled it as a back face; the trace drew it (line {})",
                    self.line()
                );
                differs(Kind::BackDrawn, detail, false, 0)
            }
            _ => AGREE,
        }
    }
}

fn differs(kind: Kind, detail: String, window: bool, depths: usize) -> TriangleVerdict {
    TriangleVerdict::Differs {
        kind,
        detail,
        window,
        depths,
    }
}

const AGREE: TriangleVerdict = TriangleVerdict::Agree {
    window: false,
    depths: 0,
};

/// The clipping, culling, window and depth stages, from what each side drew per triangle.
fn drawn(
    program: &Program,
    trace: &Trace,
    expected: &[Outcome],
    mark: &mut impl FnMut(Kind, usize),
) -> [StageResult; 4] {
    if !trace.gives_output() {
        let note = "the trace has no 'tri', 'poly', 'drawn' or 'clip' lines";
        return [Stage::Clipping, Stage::Culling, Stage::Window, Stage::Depth]
            .map(|s| StageResult::not_checked(s, note));
    }
    let pieces = pieces_by_triangle(trace, expected.len());
    let mut stages =
        [Stage::Clipping, Stage::Culling, Stage::Window, Stage::Depth].map(StageResult::new);
    stages[0].checked = expected.len();
    stages[1].checked = expected.len();
    if trace.pieces.is_empty() && trace.drawn.is_none() {
        stages[0].note = Some(
            "the trace gives clip coordinates and no 'tri' or 'poly' line: compared as a \
             program that drew nothing ('drawn 0' says so)"
                .into(),
        );
    }
    for (t, ours) in expected.iter().enumerate() {
        let (window, depths) = match judge_triangle(program, trace, t, ours, &pieces[t]) {
            TriangleVerdict::Agree { window, depths } => (window, depths),
            TriangleVerdict::Differs {
                kind,
                detail,
                window,
                depths,
            } => {
                mark(kind, t);
                stages[kind.stage() as usize - Stage::Clipping as usize].differ(|| detail);
                (window, depths)
            }
        };
        stages[2].checked += usize::from(window);
        stages[3].checked += depths;
    }
    let [clipping, culling, window, mut depth] = stages;
    if depth.checked == 0 {
        depth.note = Some(match trace.pieces.iter().any(|p| p.depths.is_some()) {
            true => "no triangle with depths was drawn where close2gl draws it".into(),
            false => "the trace's 'tri' and 'poly' lines give no depth".into(),
        });
        return [clipping.finish(), culling.finish(), window.finish(), depth];
    }
    [
        clipping.finish(),
        culling.finish(),
        window.finish(),
        depth.finish(),
    ]
}

/// How far a float32 program may put the corners of a triangle close2gl did not draw: the
/// largest error of its corners in front of the eye (those behind it are not placed at all).
fn corner_error(program: &Program, ours: &Outcome) -> f64 {
    ours.clip
        .iter()
        .filter(|c| c.w > 0.0)
        .map(|&c| {
            let p = (program.v * (c / c.w)).truncate().truncate();
            rounding::window_error(program.v, ours.terms, c, p)
        })
        .fold(rounding::PRINTED, f64::max)
}

/// How many of the trace's pieces for this triangle give depths, and the first depth that is
/// off, with close2gl's depth at that corner and the trace's line.
fn depths(ours: &Outcome, pieces: &[usize], trace: &Trace) -> (usize, Option<(f64, f64, usize)>) {
    let (mut checked, mut first) = (0, None);
    for &i in pieces {
        let piece = &trace.pieces[i];
        let Some(found) = &piece.depths else {
            continue;
        };
        checked += 1;
        for (q, &z) in piece.corners.iter().zip(found) {
            let nearest = (0..ours.polygon.len()).min_by(|&a, &b| {
                let d = |i: usize| ours.polygon[i].distance(*q);
                d(a).total_cmp(&d(b))
            });
            if let Some(i) = nearest
                && ours.polygon[i].distance(*q) <= ours.errors[i]
                && !within((z - ours.depths[i]).abs(), ours.depth_errors[i])
                && first.is_none()
            {
                first = Some((z, ours.depths[i], piece.line));
            }
        }
    }
    (checked, first)
}

fn moved(t: usize, d: &region::RegionDifference, line: usize) -> String {
    match d.corner {
        (Some(want), Some(found)) => format!(
            "triangle {t} (line {line}): a corner expected at {}, the nearest drawn is {}",
            vec2(want),
            vec2(found)
        ),
        (Some(want), None) => format!(
            "triangle {t} (line {line}): no corner drawn near {}",
            vec2(want)
        ),
        (None, Some(found)) => format!(
            "triangle {t} (line {line}): a corner drawn at {}, outside close2gl's polygon",
            vec2(found)
        ),
        (None, None) => format!(
            "triangle {t} (line {line}): covers {} square units, close2gl's polygon {}",
            number(d.found_area),
            number(d.expected_area)
        ),
    }
}

/// What close2gl did with a triangle, in words.
pub fn fate_words(outcome: &Outcome) -> String {
    let planes: Vec<&str> = close2gl_core::ClipPlane::in_outcode(outcome.fate.planes)
        .map(|p| p.name())
        .collect();
    let behind = outcome.clip.iter().filter(|c| c.w <= 0.0).count();
    match outcome.fate.kind {
        FateKind::Drawn => "drew".into(),
        FateKind::Cut => format!("cut (by {}) and drew", planes.join(", ")),
        FateKind::Clipped if behind > 0 => format!(
            "clipped ({}; {behind} corner{} behind the eye)",
            planes.join(", "),
            if behind == 1 { "" } else { "s" }
        ),
        FateKind::Clipped => format!("clipped (outside {})", planes.join(", ")),
        FateKind::Culled => "culled as a back face".into(),
        FateKind::ZeroArea => "culled (no area)".into(),
        FateKind::NoPixels | FateKind::Hidden => "drew".into(),
    }
}

/// Whether a difference is within its tolerance; a NaN never is (a `nan` the reader let through
/// would otherwise agree with everything).
fn within(difference: f64, tolerance: f64) -> bool {
    difference <= tolerance
}

pub fn number(x: f64) -> String {
    match x.abs() {
        a if a != 0.0 && !(1e-3..1e6).contains(&a) => format!("{x:.4e}"),
        _ => format!("{x:.4}"),
    }
}

fn vec2(p: DVec2) -> String {
    format!("({}, {})", number(p.x), number(p.y))
}

fn vec4(p: DVec4) -> String {
    format!(
        "({}, {}, {}, {})",
        number(p.x),
        number(p.y),
        number(p.z),
        number(p.w)
    )
}

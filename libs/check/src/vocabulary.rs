//! The words a comparison is written in: the stages in the pipeline's order ([`Stage`]), the
//! ways one mesh triangle can disagree, each belonging to one stage ([`Kind`]), a stage's
//! verdict ([`StageResult`]) and the whole comparison's ([`Comparison`]). Every stage's
//! comparison (`compare/`), the diagnosis, the reports and the rubric read and write these.

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
    pub(crate) fn new(stage: Stage) -> Self {
        Self {
            stage,
            status: Status::NotChecked,
            checked: 0,
            differing: 0,
            details: Vec::new(),
            note: None,
        }
    }

    pub(crate) fn not_checked(stage: Stage, note: &str) -> Self {
        Self {
            note: Some(note.into()),
            ..Self::new(stage)
        }
    }

    pub(crate) fn differ(&mut self, detail: impl FnOnce() -> String) {
        self.differing += 1;
        if self.details.len() < MAX_DETAILS {
            self.details.push(detail());
        }
    }

    pub(crate) fn finish(mut self) -> Self {
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

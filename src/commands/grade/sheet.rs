//! A grade in the one shape every writer for teachers reads (the page, Gradescope, GitHub
//! Classroom, the gradebook CSV, `--line`), whichever assignment made it: the geometry grade
//! (`graded.rs`) and the rasterizer's (`raster_sheet.rs`) each fill one, so that each writer
//! is written once.

/// What "to fix first" says when nothing is to fix.
pub const NOTHING_TO_FIX: &str = "to fix: nothing, every line passed";

/// One program's grade.
pub struct Sheet {
    /// The rubric's lines, in its order.
    pub lines: Vec<SheetLine>,
    pub total: u32,
    /// What the rubric is worth.
    pub max: u32,
    /// "To fix first", a line of text each.
    pub to_fix: Vec<String>,
    /// The scenes that failed some line, in the rubric's order.
    pub failing: Vec<FailingScene>,
    /// The difference picture's colours with what each means; none when the scenes have no
    /// such picture.
    pub legend: Vec<(&'static str, [u8; 4])>,
}

/// One rubric line scored.
pub struct SheetLine {
    /// Its id (`culling`, `zbuffer`), as `--line` and `--json` name it.
    pub id: String,
    pub title: String,
    pub points: u32,
    pub max: u32,
    pub passed: usize,
    pub scenes: usize,
    /// The mistakes named, in words ("never_culls: 4 of 4 failing scenes"); empty when none.
    pub mistakes: String,
    /// What its passing scenes had to say (a legal choice accepted), each once.
    pub notes: Vec<String>,
    /// The failing scenes by name, with why each failed the line.
    pub failures: Vec<(String, String)>,
    /// What a report says under the line: see [`evidence`].
    pub evidence: Vec<String>,
    /// The first failing scene's file: the answer key, shown only as `--details` says.
    pub scene_file: Option<String>,
}

/// A scene that failed some line, for the page.
pub struct FailingScene {
    pub id: String,
    /// The lines it failed (id) and why.
    pub lines: Vec<(String, String)>,
    /// Captioned PNG pictures (close2gl's, the program's, the difference); maybe none.
    pub pictures: Vec<(&'static str, Vec<u8>)>,
    /// Check's report as text, when the program's output could be checked.
    pub check: Option<String>,
    pub scene_text: String,
}

impl SheetLine {
    pub fn full(&self) -> bool {
        self.points == self.max
    }
}

/// What a report says under a failing line: its first failing scene, why, check's first
/// difference when it says more, and the mistakes named (words of
/// `close2gl_check::rubric::score::mistakes_in_words`).
pub fn evidence(
    first: Option<(&str, &str)>,
    difference: Option<&str>,
    mistakes: &str,
) -> Vec<String> {
    let Some((scene, why)) = first else {
        return Vec::new();
    };
    let mut lines = vec![format!("first failing scene: {scene}")];
    lines.extend(why.lines().map(|l| format!("  {l}")));
    if let Some(difference) = difference.filter(|d| !why.contains(d)) {
        lines.push(format!("  check's first difference: {difference}"));
    }
    if !mistakes.is_empty() {
        lines.push(format!("  mistakes named: {mistakes}"));
    }
    lines
}

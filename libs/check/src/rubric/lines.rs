//! The assignment's rubric: twelve lines and their points, 200 in all, in the rubric's order,
//! by the ids reports and scripts read (binding).

/// One line of the rubric.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum LineId {
    Points,
    Wireframe,
    Solid,
    Translation,
    LookatTranslation,
    Rotation,
    Culling,
    Hfov,
    Vfov,
    SimpleClipping,
    Resize,
    Synchronized,
}

use close2gl_core::Mistake;

impl LineId {
    /// In the rubric's order.
    pub const ALL: [LineId; 12] = [
        LineId::Points,
        LineId::Wireframe,
        LineId::Solid,
        LineId::Translation,
        LineId::LookatTranslation,
        LineId::Rotation,
        LineId::Culling,
        LineId::Hfov,
        LineId::Vfov,
        LineId::SimpleClipping,
        LineId::Resize,
        LineId::Synchronized,
    ];

    /// The id reports and scripts read.
    pub fn id(self) -> &'static str {
        match self {
            LineId::Points => "points",
            LineId::Wireframe => "wireframe",
            LineId::Solid => "solid",
            LineId::Translation => "translation",
            LineId::LookatTranslation => "lookat_translation",
            LineId::Rotation => "rotation",
            LineId::Culling => "culling",
            LineId::Hfov => "hfov",
            LineId::Vfov => "vfov",
            LineId::SimpleClipping => "simple_clipping",
            LineId::Resize => "resize",
            LineId::Synchronized => "synchronized",
        }
    }

    /// The line as the assignment words it.
    pub fn title(self) -> &'static str {
        match self {
            LineId::Points => "Points",
            LineId::Wireframe => "Wireframe",
            LineId::Solid => "Solid",
            LineId::Translation => "Translation",
            LineId::LookatTranslation => "Translation keeping the look-at point",
            LineId::Rotation => "Rotation",
            LineId::Culling => "Backface culling",
            LineId::Hfov => "Change hfov",
            LineId::Vfov => "Change vfov",
            LineId::SimpleClipping => "Simple clipping",
            LineId::Resize => "Works after resize",
            LineId::Synchronized => "Synchronized with the reference",
        }
    }

    /// The line's points.
    pub fn max_points(self) -> u32 {
        match self {
            LineId::Points | LineId::Wireframe | LineId::Solid | LineId::SimpleClipping => 10,
            LineId::Translation | LineId::Hfov | LineId::Vfov | LineId::Resize => 15,
            LineId::LookatTranslation => 20,
            LineId::Culling | LineId::Synchronized => 25,
            LineId::Rotation => 30,
        }
    }

    /// The catalogue mistakes this line's own stage can show, the ones a failing scene's
    /// diagnosis is reported under it by; `None`: any (the line sees the whole frame).
    pub fn stage_mistakes(self) -> Option<&'static [Mistake]> {
        use Mistake as M;
        match self {
            LineId::Points | LineId::Wireframe | LineId::Solid | LineId::Synchronized => None,
            LineId::Translation => Some(&[
                M::ModelviewTransposed,
                M::TranslationUnrotated,
                M::TranslationSign,
                M::LeftHanded,
            ]),
            LineId::LookatTranslation | LineId::Rotation => Some(&[M::LeftHanded]),
            LineId::Culling => Some(&[
                M::CullingInverted,
                M::CullingByFileNormals,
                M::CullingByViewAxis,
                M::NeverCulls,
                M::CullingIgnoresFrontFace,
            ]),
            LineId::Hfov | LineId::Vfov => Some(&[
                M::FovNotHalved,
                M::FovInDegrees,
                M::FovsSwapped,
                M::AspectFromAngles,
                M::ProductOrder,
            ]),
            LineId::SimpleClipping => Some(&[M::DivideBeforeClip, M::NoClipping]),
            LineId::Resize => Some(&[M::ViewportYFlipped, M::ViewportFullScale]),
        }
    }
}

/// What each line is worth and what it is called, as a rubric file says
/// (`assets/rubrics/geometry/rubric.toml`); the assignment's 200 points by default. The lines
/// themselves, their scenes and judgments are close2gl's.
#[derive(Clone, Debug, PartialEq)]
pub struct LinePoints(Vec<(LineId, String, u32)>);

impl Default for LinePoints {
    fn default() -> Self {
        let lines = LineId::ALL
            .iter()
            .map(|&l| (l, l.title().to_string(), l.max_points()));
        LinePoints(lines.collect())
    }
}

impl LinePoints {
    /// The rubric in `text` (`assignment = "geometry"`, a `[[line]]` with `id`, `title` and
    /// `points` for each of the twelve lines); `file` labels its errors.
    pub fn parse(text: &str, file: &str) -> Result<LinePoints, String> {
        let mut read: Vec<(LineId, String, u32)> = Vec::new();
        for (key, line) in super::file::lines(text, file, "geometry")? {
            let (id, title, points) =
                super::file::head(&line, &key, file, &["id", "title", "points"])?;
            let ids: Vec<&str> = LineId::ALL.iter().map(|l| l.id()).collect();
            let found = LineId::ALL.iter().find(|l| l.id() == id);
            let line = found.ok_or_else(|| {
                format!(
                    "{file}: {key}.id: expected one of {}, found '{id}'",
                    ids.join(", ")
                )
            })?;
            if read.iter().any(|(l, _, _)| l == line) {
                return Err(format!(
                    "{file}: {key}.id: expected each line once, found '{id}' again"
                ));
            }
            read.push((*line, title, points));
        }
        if let Some(missing) = LineId::ALL
            .iter()
            .find(|l| !read.iter().any(|(r, _, _)| r == *l))
        {
            return Err(format!(
                "{file}: line: expected a [[line]] for '{}'",
                missing.id()
            ));
        }
        read.sort_by_key(|(line, _, _)| *line);
        Ok(LinePoints(read))
    }

    /// The line's points.
    pub fn max(&self, line: LineId) -> u32 {
        self.0
            .iter()
            .find(|(l, _, _)| *l == line)
            .map_or(0, |(_, _, p)| *p)
    }

    /// The line's title.
    pub fn title(&self, line: LineId) -> &str {
        self.0
            .iter()
            .find(|(l, _, _)| *l == line)
            .map_or("", |(_, t, _)| t)
    }

    /// What the whole rubric is worth.
    pub fn total(&self) -> u32 {
        self.0.iter().map(|(_, _, p)| p).sum()
    }

    /// The points for `passed` of `scenes` of `line`: its points shared out evenly over its
    /// scenes, rounded down (so a line with every scene passed has all its points).
    pub fn points(&self, line: LineId, passed: usize, scenes: usize) -> u32 {
        match scenes {
            0 => 0,
            _ => (u64::from(self.max(line)) * passed as u64 / scenes as u64) as u32,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lines_add_up_to_the_assignments_200() {
        let total: u32 = LineId::ALL.iter().map(|l| l.max_points()).sum();
        assert_eq!(total, 200);
    }

    #[test]
    fn points_are_shared_out_and_rounded_down() {
        let points = LinePoints::default();
        assert_eq!(points.points(LineId::Rotation, 24, 24), 30);
        assert_eq!(points.points(LineId::Rotation, 23, 24), 28);
        assert_eq!(points.points(LineId::Translation, 1, 24), 0);
        assert_eq!(points.points(LineId::Translation, 0, 0), 0);
    }

    #[test]
    fn the_bundled_rubric_file_is_the_assignments_and_an_edit_changes_it() {
        let bundled = include_str!("../../../../assets/rubrics/geometry/rubric.toml");
        let points = LinePoints::parse(bundled, "rubric.toml").expect("the bundled rubric");
        assert_eq!(points, LinePoints::default());
        let edited = bundled.replace("points = 25\n", "points = 50\n");
        let edited = LinePoints::parse(&edited, "rubric.toml").expect("an edited rubric");
        assert_eq!((edited.max(LineId::Culling), edited.total()), (50, 250));
        let dropped = bundled.replace("id = \"vfov\"", "id = \"hfov\"");
        let error = LinePoints::parse(&dropped, "r.toml").unwrap_err();
        assert_eq!(
            error,
            "r.toml: line[9].id: expected each line once, found 'hfov' again"
        );
    }
}

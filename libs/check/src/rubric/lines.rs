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

/// What the whole rubric is worth.
pub const MAX_TOTAL: u32 = 200;

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

    /// The points for `passed` of `scenes`: the line's points shared out evenly over its
    /// scenes, rounded down (so a line with every scene passed has all its points).
    pub fn points(self, passed: usize, scenes: usize) -> u32 {
        match scenes {
            0 => 0,
            _ => (u64::from(self.max_points()) * passed as u64 / scenes as u64) as u32,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_lines_add_up_to_the_assignments_200() {
        let total: u32 = LineId::ALL.iter().map(|l| l.max_points()).sum();
        assert_eq!(total, MAX_TOTAL);
    }

    #[test]
    fn points_are_shared_out_and_rounded_down() {
        assert_eq!(LineId::Rotation.points(24, 24), 30);
        assert_eq!(LineId::Rotation.points(23, 24), 28);
        assert_eq!(LineId::Translation.points(1, 24), 0);
        assert_eq!(LineId::Translation.points(0, 0), 0);
    }
}

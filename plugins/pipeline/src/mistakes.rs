//! The classic mistakes of the assignment, as data: a set of them ([`Mistakes`]), which two a
//! program can make at once, and M, P and V as a program with those mistakes builds them. The
//! program that runs them, triangle by triangle, is [`crate::program`].
//!
//! Where a mistake's one-line meaning leaves a choice open, `trace-format.md` pins it; the
//! comments below quote those choices.

use close2gl_core::Mistake;
use glam::{DMat4, DVec3};

use crate::program::given::{ProgramCamera, System2d};
/// A set of mistakes (at most a few at once: diagnosis tries each one and each pair).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct Mistakes(u32);

impl Mistakes {
    pub const NONE: Mistakes = Mistakes(0);

    pub fn one(mistake: Mistake) -> Self {
        Self::NONE.with(mistake)
    }

    /// This set and `mistake` (`Mistake::None` adds nothing).
    pub fn with(self, mistake: Mistake) -> Self {
        match mistake {
            Mistake::None => self,
            m => Mistakes(self.0 | 1 << m as u32),
        }
    }

    pub fn has(self, mistake: Mistake) -> bool {
        mistake != Mistake::None && self.0 & (1 << mistake as u32) != 0
    }

    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The mistakes in the set, in the catalogue's order.
    pub fn iter(self) -> impl Iterator<Item = Mistake> {
        Mistake::ALL.iter().copied().filter(move |&m| self.has(m))
    }

    /// The catalogue's ids, joined with " + " ("none" for the empty set).
    pub fn names(self) -> String {
        let names: Vec<&str> = self.iter().map(Mistake::name).collect();
        match names.is_empty() {
            true => "none".into(),
            false => names.join(" + "),
        }
    }

    /// Every mistake alone, then every pair that can be made at once (two culling rules that
    /// each replace the winding test, or two clipping rules, cannot).
    pub fn singles_and_pairs() -> Vec<Mistakes> {
        let all = &Mistake::ALL[1..];
        let mut sets: Vec<Mistakes> = all.iter().map(|&m| Mistakes::one(m)).collect();
        for (i, &a) in all.iter().enumerate() {
            for &b in &all[i + 1..] {
                if !excludes(a, b) {
                    sets.push(Mistakes::one(a).with(b));
                }
            }
        }
        sets
    }
}

/// Two mistakes that each replace the same decision, so that no program makes both: the test
/// that decides a back face, the front winding, or the clipping rule. A program that never
/// culls makes no other culling mistake.
fn excludes(a: Mistake, b: Mistake) -> bool {
    use Mistake::{
        CullingByFileNormals, CullingByViewAxis, CullingIgnoresFrontFace, CullingInverted,
        DivideBeforeClip, NeverCulls, NoClipping,
    };
    let replaces = |m: Mistake| match m {
        CullingByFileNormals | CullingByViewAxis => 1,
        DivideBeforeClip | NoClipping => 2,
        CullingInverted | CullingIgnoresFrontFace => 3,
        _ => 0,
    };
    let culling = |m: Mistake| replaces(m) == 1 || replaces(m) == 3;
    (replaces(a) != 0 && replaces(a) == replaces(b))
        || (a == NeverCulls && culling(b))
        || (b == NeverCulls && culling(a))
}

/// A matrix from its rows, so the code reads like the printed matrices.
pub fn from_rows(rows: [[f64; 4]; 4]) -> DMat4 {
    DMat4::from_cols_array_2d(&rows).transpose()
}

/// M: rows u, v, n and the translation −c·(u, v, n); or what the mistakes make of it.
pub fn modelview(camera: &ProgramCamera, mistakes: Mistakes) -> DMat4 {
    let (u, v, n, c) = (camera.u, camera.v, camera.n, camera.position);
    let mut t = match mistakes.has(Mistake::TranslationUnrotated) {
        true => -c,
        false => DVec3::new(-c.dot(u), -c.dot(v), -c.dot(n)),
    };
    if mistakes.has(Mistake::TranslationSign) {
        t = -t;
    }
    let m = from_rows([
        [u.x, u.y, u.z, t.x],
        [v.x, v.y, v.z, t.y],
        [n.x, n.y, n.z, t.z],
        [0.0, 0.0, 0.0, 1.0],
    ]);
    match mistakes.has(Mistake::ModelviewTransposed) {
        true => m.transpose(),
        false => m,
    }
}

/// P: glFrustum for right = near·tan(hfov/2), top = near·tan(vfov/2); or what the mistakes
/// make of those extents and of the depth row.
pub fn projection(camera: &ProgramCamera, mistakes: Mistakes) -> DMat4 {
    use Mistake::{AspectFromAngles, DepthRowSign, FovInDegrees, FovNotHalved, FovsSwapped};
    let (h, v) = match mistakes.has(FovsSwapped) {
        true => (camera.vfov, camera.hfov),
        false => (camera.hfov, camera.vfov),
    };
    let angle = |degrees: f64| {
        let radians = match mistakes.has(FovInDegrees) {
            true => degrees,
            false => degrees.to_radians(),
        };
        match mistakes.has(FovNotHalved) {
            true => radians,
            false => radians * 0.5,
        }
    };
    let (near, far) = (camera.near, camera.far);
    let top = near * angle(v).tan();
    let right = match mistakes.has(AspectFromAngles) {
        true => top * h / v,
        false => near * angle(h).tan(),
    };
    let depth = match mistakes.has(DepthRowSign) {
        true => -1.0,
        false => 1.0,
    };
    from_rows([
        [near / right, 0.0, 0.0, 0.0],
        [0.0, near / top, 0.0, 0.0],
        [
            0.0,
            0.0,
            depth * -(far + near) / (far - near),
            depth * -2.0 * far * near / (far - near),
        ],
        [0.0, 0.0, -1.0, 0.0],
    ])
}

/// V: NDC onto the 2D system, x' = x·(R−L)/2 + (R+L)/2, y' = y·(T−B)/2 + (T+B)/2, and depth
/// onto 0..1; or what the mistakes make of the scales.
pub fn viewport(system: &System2d, mistakes: Mistakes) -> DMat4 {
    let half = match mistakes.has(Mistake::ViewportFullScale) {
        true => 1.0,
        false => 0.5,
    };
    let flip = match mistakes.has(Mistake::ViewportYFlipped) {
        true => -1.0,
        false => 1.0,
    };
    let System2d {
        left,
        right,
        bottom,
        top,
    } = *system;
    from_rows([
        [(right - left) * half, 0.0, 0.0, (right + left) / 2.0],
        [0.0, flip * (top - bottom) * half, 0.0, (top + bottom) / 2.0],
        [0.0, 0.0, 0.5, 0.5],
        [0.0, 0.0, 0.0, 1.0],
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn pairs_leave_out_two_rules_for_one_decision() {
        let sets = Mistakes::singles_and_pairs();
        let singles = Mistake::ALL.len() - 1;
        let both = |a, b| Mistakes::one(a).with(b);
        assert!(!sets.contains(&both(Mistake::DivideBeforeClip, Mistake::NoClipping)));
        assert!(!sets.contains(&both(
            Mistake::CullingByFileNormals,
            Mistake::CullingByViewAxis
        )));
        assert!(!sets.contains(&both(Mistake::NeverCulls, Mistake::CullingInverted)));
        assert!(sets.contains(&both(Mistake::FovNotHalved, Mistake::CullingInverted)));
        assert!(sets.contains(&both(Mistake::NeverCulls, Mistake::LeftHanded)));
        // Three pairs of rules for one decision, and never culling with four culling rules.
        assert_eq!(sets.len(), singles + singles * (singles - 1) / 2 - 3 - 4);
    }
}

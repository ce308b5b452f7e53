//! The classic mistakes of the assignment, as data: a set of them ([`Mistakes`]) and which two a
//! program can make at once. What they make of M, P and V is written in the matrices themselves
//! ([`crate::matrices`]); the program that runs them, triangle by triangle, is
//! [`crate::program`].
//!
//! Where a mistake's one-line meaning leaves a choice open, `trace-format.md` pins it; the
//! comments below quote those choices.

use close2gl_core::Mistake;

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

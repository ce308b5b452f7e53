//! Naming what a rasterizer did: first the legal rules it chose (the tie rule, the 8-bit
//! conversion, the depth function) that reproduce it best, then, when those do not reproduce
//! every fact, the catalogue's mistakes that do, alone or in pairs. A mistake that cannot show in
//! this frame (a texture filter's mistake with no texture) is not tried, so never named.

use close2gl_core::{
    ByteConversion, DepthFunction, RasterMistake as M, RasterMistakes, RasterRules, RasterStage,
    Shading, TextureFilter, TieRule,
};
use rayon::prelude::*;

use super::band::Band;
use super::facts::{Allowance, Facts, compare};
use close2gl_trace_format::RasterFrame;

use super::input::Redraw;

/// A drawing held against the trace: its rules, mistakes and facts.
#[derive(Clone, Copy, Debug)]
pub struct Attempt {
    pub rules: RasterRules,
    pub mistakes: RasterMistakes,
    pub facts: Facts,
}

/// What the search found.
#[derive(Clone, Debug)]
pub struct Diagnosis {
    /// close2gl's own rules and no mistake.
    pub reference: Attempt,
    /// The legal rules that reproduce the trace best, without mistakes.
    pub legal: Attempt,
    /// Every set of mistakes that reproduces every fact, with the legal rules.
    pub named: Vec<Attempt>,
    /// When none does: the mistakes that come closest, each alone.
    pub nearest: Vec<Attempt>,
}

/// The context every attempt is drawn and judged in.
pub struct Judge<'a> {
    pub input: &'a RasterFrame,
    pub redraw: Redraw<'a>,
    pub ties: Vec<bool>,
    /// The bytes the background may be written as (`facts::backgrounds`).
    pub background: Vec<[u8; 4]>,
    pub allowance: Allowance,
    /// Where a pair is tried before the whole frame.
    pub band: Band,
}

impl Judge<'_> {
    pub fn attempt(&self, rules: RasterRules, mistakes: RasterMistakes) -> Attempt {
        let drawn = self.redraw.draw(rules, mistakes);
        let rows = 0..self.input.trace.window.1;
        let facts = compare(self.input, &drawn, &self.ties, &self.background, rows);
        Attempt {
            rules,
            mistakes,
            facts,
        }
    }

    /// The attempt drawn in the band alone: its facts are the band's.
    fn attempt_in_band(&self, rules: RasterRules, mistakes: RasterMistakes) -> Attempt {
        let rows = &self.band.rows;
        let drawn = self.redraw.draw_band(rules, mistakes, rows);
        let facts = compare(
            self.input,
            &drawn,
            &self.ties,
            &self.background,
            rows.clone(),
        );
        Attempt {
            rules,
            mistakes,
            facts,
        }
    }

    /// Of attempts drawn in the band, those that reproduce every fact when drawn whole (only
    /// those the band does not rule out are).
    fn reproducing(&self, in_band: &[Attempt], legal: &Attempt) -> Vec<Attempt> {
        (in_band.par_iter())
            .filter(|a| self.band.could_agree(&a.facts, self.allowance))
            .map(|a| self.attempt(a.rules, a.mistakes))
            .filter(|a| self.reproduces(a, legal))
            .collect()
    }

    fn agrees(&self, attempt: &Attempt) -> bool {
        attempt.facts.agree(self.allowance)
    }

    /// Whether a mistaken drawing reproduces the trace where close2gl's rules (`legal`) do not:
    /// within the tolerance where they are outside it; exactly where they are only within it (a
    /// texture's tolerance would otherwise hide a mistake that changes few pixels).
    fn reproduces(&self, attempt: &Attempt, legal: &Attempt) -> bool {
        self.agrees(attempt) && (!self.agrees(legal) || attempt.facts.exact())
    }

    /// The search.
    pub fn diagnose(&self) -> Diagnosis {
        let (reference, legal, closest) = self.legal_rules();
        let mut diagnosis = Diagnosis {
            reference,
            legal,
            named: Vec::new(),
            nearest: Vec::new(),
        };
        if self.agrees(&legal) && legal.facts.exact() {
            return diagnosis;
        }
        // A mistake made under close2gl's own rules, or else under the legal rules that come
        // closest (a program may choose another tie rule and make a mistake too).
        let mut tried = Vec::new();
        for rules in [legal.rules, closest.rules] {
            if tried.contains(&rules) {
                continue;
            }
            tried.push(rules);
            diagnosis = self.mistakes(diagnosis, rules);
            if !diagnosis.named.is_empty() {
                break;
            }
        }
        diagnosis
    }

    /// The mistakes that reproduce every fact under `rules`: each alone, else pairs of those
    /// that come closer alone. Each set is drawn in the band first, which orders them and rules
    /// most out; only the others are drawn whole.
    fn mistakes(&self, mut diagnosis: Diagnosis, rules: RasterRules) -> Diagnosis {
        let legal = diagnosis.legal;
        let start = (self
            .attempt_in_band(legal.rules, RasterMistakes::NONE)
            .facts)
            .distance();
        let singles: Vec<Attempt> = (self.candidates().par_iter())
            .map(|&m| self.attempt_in_band(rules, RasterMistakes::one(m)))
            .collect();
        diagnosis.named = self.reproducing(&singles, &legal);
        if !diagnosis.named.is_empty() {
            return diagnosis;
        }
        let mut closer: Vec<Attempt> = (singles.iter())
            .filter(|a| a.facts.distance() < start)
            .copied()
            .collect();
        closer.sort_by_key(|a| a.facts.distance());
        closer.truncate(8);
        // Pairs of those that come closer alone, and the closest three with any other: a mistake
        // that one frame shows everywhere (channels swapped) hides how close another comes.
        let mut pairs: Vec<RasterMistakes> = Vec::new();
        for (i, a) in closer.iter().enumerate() {
            let others = match i < 3 {
                true => singles.iter().collect::<Vec<_>>(),
                false => closer[i + 1..].iter().collect(),
            };
            for b in others {
                let set = (a.mistakes.iter()).fold(b.mistakes, |s, m| s.with(m));
                if set != a.mistakes && !pairs.contains(&set) {
                    pairs.push(set);
                }
            }
        }
        let pairs: Vec<Attempt> = (pairs.par_iter())
            .map(|&set| self.attempt_in_band(rules, set))
            .collect();
        diagnosis.named = self.reproducing(&pairs, &legal);
        if diagnosis.named.is_empty() && diagnosis.nearest.is_empty() {
            // Told with the whole frame's facts.
            let mut nearest: Vec<Attempt> = (closer[..closer.len().min(3)].par_iter())
                .map(|a| self.attempt(a.rules, a.mistakes))
                .collect();
            nearest.sort_by_key(|a| a.facts.distance());
            diagnosis.nearest = nearest;
        }
        diagnosis
    }

    /// close2gl's own rules without mistakes; the legal rules the program uses (those that
    /// reproduce every fact, closest to its exact colours; close2gl's own when none does); and
    /// the legal rules that come closest, whether or not they reproduce it. Each choice is tried
    /// only where its facts differ: another tie rule where coverage does, truncation where a
    /// colour is not exactly alike, "less or equal" where depth or colour does.
    fn legal_rules(&self) -> (Attempt, Attempt, Attempt) {
        let reference = self.attempt(RasterRules::default(), RasterMistakes::NONE);
        let mut closest = reference;
        let key = |a: &Attempt| (a.facts.distance(), a.facts.inexact);
        let choose = |choices: Vec<RasterRules>, closest: &mut Attempt| {
            let attempts: Vec<Attempt> = (choices.par_iter())
                .map(|&rules| self.attempt(rules, RasterMistakes::NONE))
                .collect();
            for attempt in attempts {
                if key(&attempt) < key(closest) {
                    *closest = attempt;
                }
            }
        };
        if closest.facts.coverage.differing > 0 {
            let ties = TieRule::ALL.iter().skip(1);
            let rules = ties
                .map(|&tie| RasterRules {
                    tie,
                    ..closest.rules
                })
                .collect();
            choose(rules, &mut closest);
        }
        if closest.facts.inexact > 0 {
            let rules = RasterRules {
                conversion: ByteConversion::Truncate,
                ..closest.rules
            };
            choose(vec![rules], &mut closest);
        }
        if closest.facts.depth.differing + closest.facts.colour.differing > 0 {
            let rules = RasterRules {
                depth: DepthFunction::LessEqual,
                ..closest.rules
            };
            choose(vec![rules], &mut closest);
        }
        let legal = match self.agrees(&closest) {
            true => closest,
            false => reference,
        };
        (reference, legal, closest)
    }

    /// The catalogue's mistakes that can show in this frame.
    pub fn candidates(&self) -> Vec<M> {
        let (frame, shading) = (self.input, self.input.trace.shading);
        (M::catalogue().iter().copied())
            .filter(|&m| can_show(m, shading, frame.filter(), frame.depth.is_some()))
            .collect()
    }
}

/// Whether mistake `m` can change a frame drawn with `shading` and `filter` (None: untextured);
/// `depth`: whether the trace gives its depth buffer.
pub fn can_show(m: M, shading: Shading, filter: Option<TextureFilter>, depth: bool) -> bool {
    use TextureFilter::{Bilinear, Nearest, Trilinear};
    let lit_per_pixel = shading == Shading::Phong;
    match m {
        M::DepthNdc => depth,
        M::ColourAffine => shading.per_vertex(),
        M::PhongAffine | M::NormalNotRenormalized => lit_per_pixel,
        // Gouraud's corners carry the program's own lit colours: its lighting is judged there.
        _ if m.stage() == RasterStage::Shading => lit_per_pixel,
        M::UvAffine | M::TNotFlipped | M::NoWrapBlack | M::ClampNotRepeat => filter.is_some(),
        M::NearestRounds => filter == Some(Nearest),
        M::BilinearNoHalfTexel => matches!(filter, Some(Bilinear | Trilinear)),
        M::LodAbsolute | M::LodOneAxis | M::LodUnscaled | M::MipNearestLevel => {
            filter == Some(Trilinear)
        }
        M::WeightsRotated | M::NoInterpolation => shading != Shading::None || filter.is_some(),
        _ => true,
    }
}

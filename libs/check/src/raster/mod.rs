//! check for the second assignment: a student's own rasterizer, judged on its own input. The
//! trace's triangles, with the values the program gave each corner, are drawn again by
//! close2gl's textbook rasterizer ([`input`]) and the program's buffers held against that
//! drawing ([`facts`]): coverage, depth, colour, and for Gouraud the lighting at each corner
//! ([`corners`]). When they differ, [`diagnose`] finds the legal rules the program chose and the
//! catalogue's mistakes that reproduce every fact; [`report`] writes it for a person and a
//! script, [`pictures`] as images of the stage that differs; [`probe`] answers for one pixel.

pub mod band;
pub mod corners;
pub mod diagnose;
pub mod facts;
pub mod input;
pub mod pictures;
pub mod probe;
pub mod report;
pub mod rubric;

use close2gl_core::{RasterMistakes, RasterRules};
use close2gl_trace_format::RasterFrame;

use band::Band;
use corners::CornerFacts;
use diagnose::{Diagnosis, Judge};
use facts::Allowance;
use input::Redraw;

/// What check found about a raster trace.
#[derive(Clone, Debug)]
pub struct RasterReport {
    pub diagnosis: Diagnosis,
    /// Gouraud's lighting at the corners (None when not judged).
    pub corners: Option<CornerFacts>,
    pub allowance: Allowance,
}

impl RasterReport {
    /// Whether the program agrees with close2gl under legal rules: every fact reproduced, no
    /// mistake reproducing it better, and every corner lit alike.
    pub fn agrees(&self) -> bool {
        self.diagnosis.legal.facts.agree(self.allowance)
            && self.diagnosis.named.is_empty()
            && self.corners.as_ref().is_none_or(|c| c.differing == 0)
    }

    /// The catalogue ids named (the pixels' and the corners'), each once, in catalogue order.
    pub fn mistakes(&self) -> Vec<&'static str> {
        let pixels = self.diagnosis.named.iter().map(|a| a.mistakes);
        let corners = self.corners.iter().flat_map(|c| c.named.iter().copied());
        let all = pixels.fold(RasterMistakes::NONE, |all, set| {
            set.iter().fold(all, |a, m| a.with(m))
        });
        let all = corners.fold(all, |all, m| all.with(m));
        all.iter().map(|m| m.name()).collect()
    }

    /// The legal rules the program was found to use.
    pub fn rules(&self) -> RasterRules {
        self.diagnosis.legal.rules
    }
}

/// Checks `frame`: the judge, ready for the search and for probes.
pub fn judge(frame: &RasterFrame) -> Judge<'_> {
    let background = facts::backgrounds(frame.trace.background);
    Judge {
        input: frame,
        redraw: Redraw::new(frame),
        ties: facts::ties(frame),
        band: Band::new(frame, &background),
        background,
        allowance: Allowance::for_texture(frame.filter()),
    }
}

/// Checks `frame` whole.
pub fn check_raster(frame: &RasterFrame) -> RasterReport {
    judge(frame).report()
}

impl Judge<'_> {
    /// What the judge finds in its frame (for a caller that draws with it afterwards).
    pub fn report(&self) -> RasterReport {
        RasterReport {
            diagnosis: self.diagnose(),
            corners: corners::judge(self.input, &self.redraw),
            allowance: self.allowance,
        }
    }
}

//! A band of the picture to try a drawing on before the whole frame. A set of mistakes that
//! reproduces every fact reproduces them in any band too, and a drawing of an eighth of the rows
//! costs about an eighth of a frame; so the search draws each mistake and pair in the band, and
//! the whole frame only for those the band cannot rule out. The band is where the program drew
//! the most (where a mistake has the most pixels to show in).

use std::ops::Range;

use close2gl_trace_format::RasterFrame;

use super::facts::{Allowance, Facts, Tally, background_like};

/// The fewest rows a band has (the whole picture when it has fewer).
const FEWEST_ROWS: u32 = 16;

/// The rows tried first, and how many pixels the program drew in the whole picture.
#[derive(Clone, Debug)]
pub struct Band {
    pub rows: Range<u32>,
    /// The program's pixels that are not its background: at most this many colours are compared
    /// in the whole frame.
    drawn: usize,
}

impl Band {
    /// The eighth of `frame`'s rows (starting on an even row, so that texturing's 2×2 quads are
    /// whole) where the program drew the most pixels that are not `background`.
    pub fn new(frame: &RasterFrame, background: &[[u8; 4]]) -> Band {
        let image = &frame.framebuffer;
        let (width, height) = (image.width as usize, image.height);
        let per_row: Vec<usize> = (image.pixels.chunks(width.max(1)))
            .map(|row| {
                (row.iter())
                    .filter(|&&p| !background_like(p, background).0)
                    .count()
            })
            .collect();
        let rows = match height <= FEWEST_ROWS {
            true => height,
            false => (height / 8).max(FEWEST_ROWS) & !1,
        };
        let drawn_in = |first: u32| -> usize {
            per_row[first as usize..(first + rows) as usize]
                .iter()
                .sum()
        };
        let first = (0..=height.saturating_sub(rows))
            .step_by(2)
            .max_by_key(|&first| drawn_in(first))
            .unwrap_or(0);
        Band {
            rows: first..(first + rows).min(height),
            drawn: per_row.iter().sum(),
        }
    }

    /// Whether a drawing whose facts in the band are `facts` could still reproduce every fact of
    /// the frame within `allowance`: coverage and depth must agree everywhere, and no more
    /// colours may differ than the whole frame's share allows.
    pub fn could_agree(&self, facts: &Facts, allowance: Allowance) -> bool {
        let colour = Tally {
            compared: self.drawn,
            differing: facts.colour.differing,
            first: None,
        };
        facts.coverage.differing == 0 && facts.depth.differing == 0 && allowance.allows(&colour)
    }
}

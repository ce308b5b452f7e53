//! The assignment's rubric as scenes and judgments, for `close2gl grade`: the twelve lines and
//! their points ([`lines`]), the scenes each line is judged on for one model
//! ([`scenes`](mod@scenes)), what close2gl expects of a camera after a scene's motions
//! ([`expected_motion`]), how each line judges a scene's trace ([`judge`](mod@judge)), and
//! the judged scenes added up into the lines' points ([`score`]). Running the programs and
//! writing the reports is the command's.

pub mod expected_motion;
pub mod file;
pub mod judge;
pub mod lines;
pub mod scenes;
pub mod score;

pub use judge::{Turn, Verdict, judge};
pub use lines::{LineId, LinePoints};
pub use scenes::{RubricScene, scenes};
pub use score::{Judged, LineScore, NamedMistake, Score};

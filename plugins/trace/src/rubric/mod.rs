//! The assignment's rubric as scenes and judgments, for `close2gl grade`: the twelve lines and
//! their points ([`lines`]), the scenes each line is judged on for one model
//! ([`scenes`](mod@scenes)), what close2gl expects of a camera after a scene's motions
//! ([`expected_motion`]), the program's own geometry that later stages are judged on ([`own`]), and how
//! each line judges a scene's trace ([`judge`](mod@judge)). Running the programs and writing the
//! reports is the command's.

pub mod expected_motion;
pub mod judge;
pub mod lines;
pub mod scenes;

pub use judge::{Turn, Verdict, judge, settle_rotations};
pub use lines::{LineId, MAX_TOTAL};
pub use scenes::{RubricScene, scenes};

//! Breaking a valid file at random, for the property tests that read it with a loader's fast
//! reader and its line reader and expect the same outcome from both.

use proptest::prelude::*;

/// Where to break a file and how: at a fraction of its length, so many bytes taken out and
/// these put in.
pub(crate) type Cut = (f64, usize, &'static [u8]);

/// One to three cuts, each putting in one of `inserted`.
pub(crate) fn cuts(
    inserted: impl Strategy<Value = &'static [u8]>,
) -> impl Strategy<Value = Vec<Cut>> {
    prop::collection::vec((0.0f64..1.0, 0usize..3, inserted), 1..4)
}

/// `text` with `cuts` made in turn.
pub(crate) fn damaged(text: String, cuts: Vec<Cut>) -> Vec<u8> {
    let mut bytes = text.into_bytes();
    for (at, removed, inserted) in cuts {
        let at = (at * bytes.len() as f64) as usize;
        let end = (at + removed).min(bytes.len());
        bytes.splice(at..end, inserted.iter().copied());
    }
    bytes
}

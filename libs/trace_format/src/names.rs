//! The words the files spell their switches with. Culling and clipping are the pipeline's own
//! values (`Option<FrontFace>`, [`ClipRule`]), named here because the words are the format's;
//! [`Axis`] is a [`NamedEnum`] like the config's. One list of values and one name for each
//! read and write them all, so that the writer cannot spell them differently.

use close2gl_core::declaration::ClipRule;
use close2gl_core::{FrontFace, NamedEnum};

use super::Axis;

/// What a `culling` line can say, in the order its shape lists them: `off|ccw|cw`.
pub const CULLINGS: [Option<FrontFace>; 3] = [None, Some(FrontFace::Ccw), Some(FrontFace::Cw)];

/// What a `clipping` line can say, in the order its shape lists them: `simple|full|none`.
pub const CLIPPINGS: [ClipRule; 3] = [ClipRule::Simple, ClipRule::Full, ClipRule::Nothing];

/// `culling`'s word: `off`, or the front face (`glFrontFace`, as seen on screen) by its name.
pub fn culling_name(culling: Option<FrontFace>) -> &'static str {
    culling.map_or("off", FrontFace::name)
}

/// `clipping`'s word for what the program did with triangles reaching outside the view volume.
pub fn clipping_name(clip: ClipRule) -> &'static str {
    match clip {
        ClipRule::Simple => "simple",
        ClipRule::Full => "full",
        ClipRule::Nothing => "none",
    }
}

impl NamedEnum for Axis {
    const ALL: &'static [Self] = &[Self::U, Self::V, Self::N];

    fn name(self) -> &'static str {
        match self {
            Self::U => "u",
            Self::V => "v",
            Self::N => "n",
        }
    }
}

/// The value of `all` that `name` spells `word`.
pub(crate) fn from_word<T: Copy>(all: &[T], name: fn(T) -> &'static str, word: &str) -> Option<T> {
    all.iter().copied().find(|&v| name(v) == word)
}

/// The names of `all` as a line's shape spells a choice: `off|ccw|cw`.
pub(crate) fn choices<T: Copy>(all: &[T], name: fn(T) -> &'static str) -> String {
    let names: Vec<&str> = all.iter().map(|&v| name(v)).collect();
    names.join("|")
}

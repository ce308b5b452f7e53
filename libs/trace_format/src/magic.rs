//! The first line of either file: which of the two formats it is, and which version.

use super::syntax::{FormatError, Line};

/// The version of both formats this crate reads and writes.
const VERSION: &str = "1";

#[derive(Clone, Copy, PartialEq, Eq)]
pub(crate) enum Format {
    Trace,
    Scene,
    Raster,
}

impl Format {
    /// The first field of the first line: `close2gl-trace` or `close2gl-scene`.
    fn word(self) -> &'static str {
        match self {
            Self::Trace => "close2gl-trace",
            Self::Scene => "close2gl-scene",
            Self::Raster => "close2gl-raster",
        }
    }

    pub(crate) fn noun(self) -> &'static str {
        match self {
            Self::Trace => "trace",
            Self::Scene => "scene",
            Self::Raster => "raster trace",
        }
    }

    /// The whole first line, as the writer writes it.
    pub(crate) fn magic(self) -> String {
        format!("{} {VERSION}", self.word())
    }

    /// The format whose first word is `word`.
    fn of_word(word: &str) -> Option<Self> {
        [Self::Trace, Self::Scene, Self::Raster]
            .into_iter()
            .find(|f| f.word() == word)
    }
}

/// Checks that `first`, the first record of the file, is `format`'s magic and version. An
/// error says why when the line is close: another version, or another of the formats (a grader
/// who passes the scene where the program's trace belongs).
pub(crate) fn check_magic(
    first: Option<&Line>,
    format: Format,
    file: &str,
    last_line: usize,
) -> Result<(), FormatError> {
    let magic = format!("'{}'", format.magic());
    let Some(line) = first else {
        let message = format!("expected {magic}, found end of file");
        return Err(FormatError::new(file, last_line, message));
    };
    match line.fields[..] {
        [word, VERSION] if word == format.word() => Ok(()),
        [word, _] if word == format.word() => {
            let mut error = line.expected(&magic);
            error.message += &format!(" (this close2gl reads version {VERSION})");
            Err(error)
        }
        [word, ..] if word != format.word() && Format::of_word(word).is_some() => {
            let mut error = line.expected(&magic);
            let other = Format::of_word(word).map_or("", Format::noun);
            error.message += &format!(" (a {other} file, not a {})", format.noun());
            Err(error)
        }
        _ => Err(line.expected(&magic)),
    }
}

//! What both formats share below their keys: lines, comments, fields, the spelling of numbers,
//! and the one shape every error has (`my.trace:12: expected '...', found '...'`).

use std::fmt;

/// A file that does not read, at the line that shows it. `line` is 1-based; 0 when the fault is
/// the file's as a whole (it cannot be read, or is too big).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FormatError {
    pub file: String,
    pub line: usize,
    pub message: String,
}

impl fmt::Display for FormatError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}:{}: {}", self.file, self.line, self.message)
    }
}

impl std::error::Error for FormatError {}

impl FormatError {
    pub(crate) fn new(file: &str, line: usize, message: String) -> Self {
        Self {
            file: file.to_string(),
            line,
            message,
        }
    }
}

/// The most fields a line keeps: the longest record, `poly T K` with 3·64 numbers, and one more
/// so that a longer line still fails its count. A hostile line of a billion fields then costs
/// no more memory than a good one.
const MAX_FIELDS: usize = 3 + 3 * super::MAX_POLY_CORNERS + 1;

/// `expected <what>, found '<found>'` at `file:line`.
pub(crate) fn expected(file: &str, line: usize, what: &str, found: &str) -> FormatError {
    let message = format!("expected {what}, found '{}'", close2gl_core::excerpt(found));
    FormatError::new(file, line, message)
}

/// One record: a line that is not blank once its comment is gone.
pub(crate) struct Line<'a> {
    pub(crate) file: &'a str,
    pub(crate) number: usize,
    /// The line without its comment and the blanks around it: what an error quotes.
    pub(crate) text: &'a str,
    /// At most [`MAX_FIELDS`]; the first is the key.
    pub(crate) fields: Vec<&'a str>,
}

/// The records of `text`, numbered as an editor numbers its lines (`\n` ends a line; the `\r` of
/// `\r\n` is a blank). A leading byte-order mark (Windows editors write one) is skipped.
pub(crate) fn records<'a>(text: &'a str, file: &'a str) -> impl Iterator<Item = Line<'a>> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    text.split('\n').enumerate().filter_map(move |(i, raw)| {
        let content = raw.split_once('#').map_or(raw, |(before, _)| before);
        let text = content.trim_matches(is_blank);
        let fields: Vec<&str> = text
            .split(is_blank)
            .filter(|f| !f.is_empty())
            .take(MAX_FIELDS)
            .collect();
        (!fields.is_empty()).then_some(Line {
            file,
            number: i + 1,
            text,
            fields,
        })
    })
}

/// The number of the file's last line: where an error about what the file lacks points.
pub(crate) fn last_line(text: &str) -> usize {
    text.lines().count().max(1)
}

/// Spaces and tabs separate fields; so does a `\r`, as in the C reader (`c2g_split`): it ends a
/// `\r\n` line, and a stray one inside a line must not become part of a field, where a model
/// name ending in it would not survive being written out and read back.
fn is_blank(c: char) -> bool {
    c == ' ' || c == '\t' || c == '\r'
}

impl Line<'_> {
    pub(crate) fn key(&self) -> &str {
        self.fields[0]
    }

    /// `expected <what>, found '<this line>'`.
    pub(crate) fn expected(&self, what: &str) -> FormatError {
        expected(self.file, self.number, what, self.text)
    }

    /// `expected '<shape>', found '<this line>'`: the line is not of the form its key needs.
    pub(crate) fn wrong_shape(&self, shape: &str) -> FormatError {
        self.expected(&format!("'{shape}'"))
    }

    /// Checks that the line has exactly `count` fields, key included.
    pub(crate) fn expect_fields(&self, count: usize, shape: &str) -> Result<(), FormatError> {
        if self.fields.len() == count {
            Ok(())
        } else {
            Err(self.wrong_shape(shape))
        }
    }

    /// Field `i` as a number; `name` is what `shape` calls it.
    pub(crate) fn number(&self, i: usize, name: &str, shape: &str) -> Result<f64, FormatError> {
        let word = self.fields[i];
        parse_number(word).map_err(|what| {
            let what = format!("{what} for {name} in '{shape}'");
            expected(self.file, self.number, &what, word)
        })
    }

    /// Fields `start..` as numbers; `name(k)` is what `shape` calls the k-th of them.
    pub(crate) fn numbers(
        &self,
        start: usize,
        shape: &str,
        name: impl Fn(usize) -> String,
    ) -> Result<Vec<f64>, FormatError> {
        (start..self.fields.len())
            .map(|i| self.number(i, &name(i - start), shape))
            .collect()
    }

    /// `KEY A B C`: the three numbers, named in errors as `shape` names them after the key.
    pub(crate) fn three(&self, shape: &str) -> Result<[f64; 3], FormatError> {
        self.expect_fields(4, shape)?;
        let names: Vec<&str> = shape.split(' ').skip(1).collect();
        let xyz = self.numbers(1, shape, |k| names[k].to_string())?;
        Ok([xyz[0], xyz[1], xyz[2]])
    }

    /// Field `i` as a count or an index: a non-negative integer, no fraction, no exponent.
    pub(crate) fn integer(&self, i: usize, name: &str, shape: &str) -> Result<usize, FormatError> {
        let word = self.fields[i];
        parse_integer(word).map_err(|what| {
            let what = format!("{what} for {name} in '{shape}'");
            expected(self.file, self.number, &what, word)
        })
    }
}

/// A number as C's `%d`, `%f`, `%e` or `%g` print it: an optional sign, digits with an optional
/// fraction (`1.` and `.5` too), an optional exponent. `nan`, `inf`, hex and Rust-only spellings
/// are refused before `str::parse` sees them, and so is a number too big for an `f64`.
fn parse_number(word: &str) -> Result<f64, &'static str> {
    if !is_decimal(word.as_bytes()) {
        return Err("a number");
    }
    match word.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        _ => Err("a finite number"),
    }
}

fn is_decimal(b: &[u8]) -> bool {
    let mut i = usize::from(matches!(b.first(), Some(b'+' | b'-')));
    let whole = digits(b, &mut i);
    let mut fraction = 0;
    if b.get(i) == Some(&b'.') {
        i += 1;
        fraction = digits(b, &mut i);
    }
    if whole + fraction == 0 {
        return false;
    }
    if matches!(b.get(i), Some(b'e' | b'E')) {
        i += 1;
        i += usize::from(matches!(b.get(i), Some(b'+' | b'-')));
        if digits(b, &mut i) == 0 {
            return false;
        }
    }
    i == b.len()
}

/// Skips the ASCII digits at `*i`; returns how many there were.
fn digits(b: &[u8], i: &mut usize) -> usize {
    let start = *i;
    while b.get(*i).is_some_and(u8::is_ascii_digit) {
        *i += 1;
    }
    *i - start
}

/// `%d` or `%u` of a non-negative value (a `+` sign allowed, as `%+d` prints it).
fn parse_integer(word: &str) -> Result<usize, &'static str> {
    let digits = word.strip_prefix('+').unwrap_or(word);
    if digits.is_empty() || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return Err("a non-negative integer");
    }
    digits
        .parse()
        .map_err(|_| "an integer of at most 18446744073709551615")
}

/// A value and the line that gave it, so that a second line for its key can name the first.
pub(crate) type Slot<T> = Option<(T, usize)>;

/// Fills `slot` from `line`; a key given twice is an error at the second line.
pub(crate) fn set_once<T>(
    slot: &mut Slot<T>,
    value: T,
    line: &Line,
    key: &str,
) -> Result<(), FormatError> {
    if let Some((_, first)) = slot {
        return Err(line.expected(&format!("one '{key}' line (the first is line {first})")));
    }
    *slot = Some((value, line.number));
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_are_what_printf_prints_and_nothing_else() {
        for word in [
            "1", "-0.5", "1e-3", "2.5E+02", "+3", "1.", ".5", "-.5e1", "007", "0.000000",
        ] {
            let x = parse_number(word);
            assert_eq!(x, Ok(word.parse().unwrap()), "{word}");
        }
        for word in [
            "", "+", "-", ".", "e5", "1e", "1e+", "1.2.3", "nan", "NaN", "inf", "-inf", "infinity",
            "0x10", "1_0", "1,5", "١", "1e5x", "--1", "+-1", "1 ",
        ] {
            assert_eq!(parse_number(word), Err("a number"), "{word:?}");
        }
        assert_eq!(parse_number("1e999"), Err("a finite number"));
        assert_eq!(parse_number("-1e999"), Err("a finite number"));
    }

    #[test]
    fn integers_have_no_sign_fraction_or_exponent() {
        assert_eq!(parse_integer("0"), Ok(0));
        assert_eq!(parse_integer("+12"), Ok(12));
        for word in ["-1", "-0", "1.0", "1e3", "", "+", "x"] {
            assert_eq!(parse_integer(word), Err("a non-negative integer"), "{word}");
        }
        assert!(parse_integer("99999999999999999999").is_err());
    }

    #[test]
    fn records_drop_comments_blanks_and_line_ends_and_keep_numbers() {
        let text = "\u{feff}# head\r\n\r\n  a\t b  # c\r\n#\nd";
        let lines: Vec<_> = records(text, "f")
            .map(|l| (l.number, l.text, l.fields))
            .collect();
        assert_eq!(
            lines,
            vec![(3, "a\t b", vec!["a", "b"]), (5, "d", vec!["d"])]
        );
        assert_eq!(last_line(text), 5);
        assert_eq!(last_line(""), 1);
    }

    #[test]
    fn a_line_of_endless_fields_keeps_only_enough_to_fail() {
        let text = "tri 0".to_string() + &" 1".repeat(100_000);
        let line = records(&text, "f").next().unwrap();
        assert_eq!(line.fields.len(), MAX_FIELDS);
        let error = line.wrong_shape("tri T x0 y0 x1 y1 x2 y2");
        assert!(error.message.ends_with("…'"), "{error}");
    }
}

//! What tobj reads: the file's lines, each checked first with its number and handed on only if
//! the loader uses it. tobj's errors name no line, it takes `inf` and NaN for numbers, and its
//! index arithmetic overflows on references far out of range (a panic in a debug build), so
//! every record it reads has passed these checks: numbers finite, w not zero, each face corner
//! naming records that come before it. What the loader does not use is not handed on: `l`
//! (tobj makes a triangle of `l a b c`), `usemtl` and `mtllib` (materials are not read, the app
//! draws in one chosen colour; tobj refuses a `usemtl` without a name), a `v` record's colour
//! (tobj refuses a face on a vertex without one when another has one), comments, `s`, `p`, ...

use std::io::{self, BufRead, Read};

use crate::diagnostics::expected;
use crate::line_reader::Lines;

/// The form a face must have, as errors quote it.
const FACE: &str = "f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...";

/// The three kinds of numbered records a face corner refers to, in the order of `v/vt/vn`.
#[derive(Clone, Copy, PartialEq)]
enum Element {
    Position,
    Texcoord,
    Normal,
}

impl Element {
    const ALL: [Element; 3] = [Element::Position, Element::Texcoord, Element::Normal];

    fn from_keyword(keyword: &str) -> Option<Self> {
        match keyword {
            "v" => Some(Element::Position),
            "vt" => Some(Element::Texcoord),
            "vn" => Some(Element::Normal),
            _ => None,
        }
    }

    fn keyword(self) -> &'static str {
        ["v", "vt", "vn"][self as usize]
    }

    /// How many numbers the record starts with, and its form as errors quote it.
    fn record(self) -> (usize, &'static str) {
        match self {
            Element::Position => (3, "v x y z [w]"),
            Element::Texcoord => (2, "vt u v"),
            Element::Normal => (3, "vn x y z"),
        }
    }
}

/// Why a line is refused: the form it should have had, and more when there is more to say.
struct Refusal {
    what: &'static str,
    why: Option<String>,
}

impl Refusal {
    fn form(what: &'static str) -> Self {
        Self { what, why: None }
    }

    fn because(what: &'static str, why: impl Into<String>) -> Self {
        Self {
            what,
            why: Some(why.into()),
        }
    }
}

/// The checked lines of a file, as a reader for tobj: one line at a time, each ending in `\n`.
/// Reading stops at the first line refused (or that cannot be read); tobj then fails with a
/// read error that has lost the message, which [`Checked::into_error`] keeps.
pub(super) struct Checked<'l, R> {
    lines: Lines<'l, R>,
    /// How many `v`, `vt` and `vn` records the lines handed on so far hold.
    seen: [usize; 3],
    line: Vec<u8>,
    /// How much of `line` tobj has consumed.
    at: usize,
    error: Option<String>,
}

impl<'l, R: BufRead> Checked<'l, R> {
    pub(super) fn new(lines: Lines<'l, R>) -> Self {
        Self {
            lines,
            seen: [0; 3],
            line: Vec::new(),
            at: 0,
            error: None,
        }
    }

    /// Why reading stopped before the end of the file, if it did: `path:line: expected ...`.
    pub(super) fn into_error(self) -> Option<String> {
        self.error
    }

    /// Fills `line` with the next line tobj is to read; leaves it empty at the end of the file.
    fn next(&mut self) -> Result<(), String> {
        let label = self.lines.label();
        while let Some((number, line)) = self.lines.next_line()? {
            let handed = check(line, &mut self.seen).map_err(|refusal| {
                let message = expected(label, number, refusal.what, Some(line));
                match refusal.why {
                    Some(why) => format!("{message} ({why})"),
                    None => message,
                }
            })?;
            if let Some(text) = handed {
                self.line.extend_from_slice(text.as_bytes());
                self.line.push(b'\n');
                return Ok(());
            }
        }
        Ok(())
    }
}

impl<R: BufRead> BufRead for Checked<'_, R> {
    fn fill_buf(&mut self) -> io::Result<&[u8]> {
        if self.error.is_none() && self.at == self.line.len() {
            self.line.clear();
            self.at = 0;
            if let Err(error) = self.next() {
                self.error = Some(error);
            }
        }
        match &self.error {
            Some(error) => Err(io::Error::other(error.clone())),
            None => Ok(&self.line[self.at..]),
        }
    }

    fn consume(&mut self, amount: usize) {
        self.at = (self.at + amount).min(self.line.len());
    }
}

impl<R: BufRead> Read for Checked<'_, R> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let available = self.fill_buf()?;
        let n = available.len().min(buf.len());
        buf[..n].copy_from_slice(&available[..n]);
        self.consume(n);
        Ok(n)
    }
}

/// The part of `line` tobj is to read (`None`: none of it), or why the line is refused. `seen`
/// counts the `v`, `vt` and `vn` records so far. Words are split and numbers read as tobj splits
/// and reads them (`split_whitespace`, `str::parse`); keywords are case-sensitive.
fn check<'t>(line: &'t str, seen: &mut [usize; 3]) -> Result<Option<&'t str>, Refusal> {
    let mut words = line.split_whitespace();
    let Some(keyword) = words.next() else {
        return Ok(None);
    };
    if let Some(element) = Element::from_keyword(keyword) {
        let (count, what) = element.record();
        let mut end = numbers(&mut words, count, line, what)?;
        if element == Element::Position {
            end = w(words, line, end)?;
        }
        seen[element as usize] += 1;
        return Ok(Some(&line[..end]));
    }
    match keyword {
        "f" => {
            face(words, seen)?;
            Ok(Some(line))
        }
        // Objects and groups: tobj keeps each apart, and gives it texture coordinates and
        // normals only if all its corners name them.
        "o" | "g" => Ok(Some(line)),
        _ => Ok(None),
    }
}

/// Where `word`, a slice of `line`, ends in it.
fn end_in(line: &str, word: &str) -> usize {
    word.as_ptr() as usize - line.as_ptr() as usize + word.len()
}

/// Checks that the next `count` words are finite numbers; returns where the last ends in `line`.
fn numbers<'t>(
    words: &mut impl Iterator<Item = &'t str>,
    count: usize,
    line: &'t str,
    what: &'static str,
) -> Result<usize, Refusal> {
    let mut end = 0;
    let mut finite = true;
    for _ in 0..count {
        let word = words.next().ok_or(Refusal::form(what))?;
        let x: f32 = word.parse().map_err(|_| Refusal::form(what))?;
        finite &= x.is_finite();
        end = end_in(line, word);
    }
    if !finite {
        return Err(Refusal::because(what, "numbers must be finite"));
    }
    Ok(end)
}

/// What follows a `v` record's position: nothing, a w (a nonzero finite number, by which tobj
/// divides the position), or three words of a colour (an extension some exporters write, not
/// handed on). Returns where the part tobj reads ends in `line`, the position ending at `end`.
fn w<'t>(
    mut words: impl Iterator<Item = &'t str>,
    line: &'t str,
    end: usize,
) -> Result<usize, Refusal> {
    const WHAT: &str = "v x y z [w]";
    let rest: [Option<&str>; 4] = std::array::from_fn(|_| words.next());
    match rest {
        [None, ..] | [Some(_), Some(_), Some(_), None] => Ok(end),
        [Some(w), None, ..] => match w.parse::<f32>() {
            Ok(0.0) => Err(Refusal::because(WHAT, "w must not be zero")),
            Ok(x) if x.is_finite() => Ok(end_in(line, w)),
            Ok(_) => Err(Refusal::because(WHAT, "numbers must be finite")),
            Err(_) => Err(Refusal::form(WHAT)),
        },
        _ => Err(Refusal::form(WHAT)),
    }
}

/// Checks a face's corners: at least three, each `v`, `v/vt`, `v//vn` or `v/vt/vn`, each
/// reference naming a record before the face, counted from 1 or back from -1. A corner's
/// references are checked as they are read, so that the first thing wrong is the one reported.
fn face<'t>(words: impl Iterator<Item = &'t str>, seen: &[usize; 3]) -> Result<(), Refusal> {
    let mut corners = 0;
    for word in words {
        let mut parts = word.split('/');
        for element in Element::ALL {
            let Some(part) = parts.next() else { break };
            if part.is_empty() {
                // `v//vn` leaves out the texture coordinate; the position is never optional.
                match element {
                    Element::Position => return Err(Refusal::form(FACE)),
                    _ => continue,
                }
            }
            let reference: isize = part.parse().map_err(|_| Refusal::form(FACE))?;
            let count = seen[element as usize];
            if reference == 0 || reference.unsigned_abs() > count {
                let keyword = element.keyword();
                let why = format!(
                    "{keyword} index {reference} refers to no record: the file has {count}"
                );
                return Err(Refusal::because(FACE, why));
            }
        }
        if parts.next().is_some() {
            return Err(Refusal::form(FACE));
        }
        corners += 1;
    }
    if corners < 3 {
        return Err(Refusal::form(FACE));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What tobj reads of `line` after `records` of each kind, or the refusal's words.
    fn handed(line: &str, records: usize) -> Result<Option<&str>, (&'static str, Option<String>)> {
        check(line, &mut [records; 3]).map_err(|r| (r.what, r.why))
    }

    #[test]
    fn records_are_handed_on_without_what_the_loader_does_not_use() {
        assert_eq!(handed("v 2 4 6 2\r", 0), Ok(Some("v 2 4 6 2")));
        assert_eq!(handed(" v\t2 4 6 0.5 0.5 x", 0), Ok(Some(" v\t2 4 6")));
        assert_eq!(handed("vt 0.5 1 0 extra", 0), Ok(Some("vt 0.5 1")));
        assert_eq!(
            handed("f 1 2/1 3//1 +1/-1/1", 3),
            Ok(Some("f 1 2/1 3//1 +1/-1/1"))
        );
        assert_eq!(handed("o a b", 0), Ok(Some("o a b")));
        for line in [
            "",
            "# v 1",
            "s off",
            "l 1 2 3",
            "p 1",
            "usemtl",
            "mtllib a.mtl",
            "V 1 2 3",
        ] {
            assert_eq!(handed(line, 3), Ok(None), "{line:?}");
        }
    }

    #[test]
    fn a_w_must_be_a_nonzero_finite_number() {
        let form = "v x y z [w]";
        let refused = |why: Option<&str>| Err((form, why.map(String::from)));
        assert_eq!(handed("v 1 2 3 -0", 0), refused(Some("w must not be zero")));
        assert_eq!(
            handed("v 1 2 3 inf", 0),
            refused(Some("numbers must be finite"))
        );
        for line in [
            "v 1 2 3 w",
            "v 1 2 3 1 1",
            "v 1 2 3 1 1 1 1",
            "v 1 nan x",
            "v 1 2",
        ] {
            assert_eq!(handed(line, 0), refused(None), "{line:?}");
        }
    }

    #[test]
    fn faces_name_records_before_them_in_every_corner_form() {
        let refused = |why: Option<&str>| Err((FACE, why.map(String::from)));
        for line in [
            "f 1 2",
            "f 1 2 x",
            "f 1 2 /3",
            "f 1 2 3////",
            "f 1 2 3/1/1/1",
            "f 1 2 --3",
        ] {
            assert_eq!(handed(line, 3), refused(None), "{line:?}");
        }
        let why = "vt index -4 refers to no record: the file has 3";
        assert_eq!(handed("f 1/-4 2 3", 3), refused(Some(why)));
        let why = "v index 2 refers to no record: the file has 1";
        assert_eq!(
            handed("f 1 2 3", 1),
            refused(Some(why)),
            "records after the face"
        );
    }

    #[test]
    fn the_reader_counts_records_and_stops_at_the_first_refused_line() {
        let text = "v 0 0 0\n# x\nf 1 1 1\nf 2 1 1\nv 1 1 1\n";
        let mut checked = Checked::new(Lines::new(text.as_bytes(), "m.obj"));
        let mut read = String::new();
        assert!(checked.read_to_string(&mut read).is_err());
        assert_eq!(read, "v 0 0 0\nf 1 1 1\n");
        assert_eq!(
            checked.into_error().as_deref(),
            Some(
                "m.obj:4: expected 'f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...', found 'f 2 1 1' \
                 (v index 2 refers to no record: the file has 1)"
            )
        );
    }
}

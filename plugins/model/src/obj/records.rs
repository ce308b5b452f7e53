//! The checks every OBJ record passes on its way to tobj. tobj's errors name no line, and its
//! index arithmetic overflows on wild references (a panic), so each line it reads has been
//! checked first, with its number: numbers finite, faces referencing records that exist.

use std::io::BufRead;

use crate::diagnostics::expected;
use crate::lines::Lines;

/// The file's numbered records: how many of each it has (counted in a first pass), and how many
/// the checking pass has met so far.
pub(super) struct Records<'l> {
    label: &'l str,
    totals: [usize; 3],
    seen: [usize; 3],
}

impl<'l> Records<'l> {
    /// Counts the positions, texture coordinates and normals of the file `lines` reads.
    pub(super) fn count<R: BufRead>(mut lines: Lines<'l, R>) -> Result<Self, String> {
        let mut totals = [0usize; 3];
        while let Some((_, line)) = lines.next_line()? {
            if let Some(kind) = line
                .split_whitespace()
                .next()
                .and_then(Element::from_keyword)
            {
                totals[kind as usize] += 1;
            }
        }
        Ok(Self {
            label: lines.label(),
            totals,
            seen: [0; 3],
        })
    }

    /// Checks the file's next line, `line` numbered `number`.
    pub(super) fn check(&mut self, number: usize, line: &str) -> Result<(), String> {
        let error = |what: &str, why: Option<String>| {
            let message = expected(self.label, number, what, Some(line));
            match why {
                Some(why) => format!("{message} ({why})"),
                None => message,
            }
        };
        let mut words = line.split_whitespace();
        let keyword = words.next().unwrap_or_default();
        if let Some(kind) = Element::from_keyword(keyword) {
            let (count, what) = kind.record();
            let numbers: Vec<f32> = words.take(count).map_while(|w| w.parse().ok()).collect();
            if numbers.len() < count {
                return Err(error(what, None));
            }
            if !numbers.iter().all(|x| x.is_finite()) {
                return Err(error(what, Some("numbers must be finite".into())));
            }
            self.seen[kind as usize] += 1;
        } else if keyword == "f" || keyword == "l" {
            // tobj reads `l` records as faces too.
            let (minimum, what) = if keyword == "f" {
                (3, "f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...")
            } else {
                (2, "l v[/vt] v[/vt] ...")
            };
            let mut corners = 0;
            for word in words {
                check_corner(word, &self.totals, &self.seen).map_err(|why| error(what, why))?;
                corners += 1;
            }
            if corners < minimum {
                return Err(error(what, None));
            }
        }
        Ok(())
    }

    /// After the last line: the checking pass met the records the counting pass counted. A file
    /// rewritten between the two could otherwise hand tobj a reference past its end.
    pub(super) fn finish(&self) -> Result<(), String> {
        if self.seen == self.totals {
            return Ok(());
        }
        Err(format!(
            "{}: the file changed while it was read: load it again",
            self.label
        ))
    }
}

/// The three kinds of numbered records a face corner refers to, in the order of `v/vt/vn`.
#[derive(Clone, Copy)]
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

    /// How many numbers the record must start with, and its form.
    fn record(self) -> (usize, &'static str) {
        match self {
            Element::Position => (3, "v x y z [w]"),
            Element::Texcoord => (2, "vt u v"),
            Element::Normal => (3, "vn x y z"),
        }
    }
}

/// Checks one `v[/vt][/vn]` face corner; the error says why, when there is more to say than
/// the expected form.
fn check_corner(word: &str, totals: &[usize; 3], seen: &[usize; 3]) -> Result<(), Option<String>> {
    let mut parts = word.split('/');
    for kind in Element::ALL {
        let Some(part) = parts.next() else { break };
        if part.is_empty() {
            // `v//vn` leaves out the texture coordinate; the position is never optional.
            match kind {
                Element::Position => return Err(None),
                _ => continue,
            }
        }
        let index: isize = part.parse().map_err(|_| None)?;
        let (total, before) = (totals[kind as usize], seen[kind as usize]);
        let exists = match index {
            0 => false,
            i if i > 0 => i.unsigned_abs() <= total,
            i => i.unsigned_abs() <= before,
        };
        if !exists {
            return Err(Some(format!(
                "{} index {index} refers to no record: the file has {total}",
                kind.keyword()
            )));
        }
    }
    match parts.next() {
        Some(_) => Err(None),
        None => Ok(()),
    }
}

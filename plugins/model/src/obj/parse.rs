//! One OBJ line read into what it means: a position, texture coordinate or normal (numbers read
//! and checked), a face (its corners read by [`face`] once the caller knows how to resolve their
//! references), or nothing the loader keeps; or why the line is refused, in the words of the
//! one-line error (`crate::diagnostics::expected`) that names it.

use glam::{Vec2, Vec3};

use crate::decimal::parse_f32;

/// A corner's missing texture coordinate or normal.
pub(super) const NONE: u32 = u32::MAX;

/// The largest index a reference may come to: [`NONE`] and the one below it mark what a corner
/// lacks and what no corner has named.
pub(super) const MAX_INDEX: u32 = NONE - 2;

/// The form a face must have, as errors quote it.
const FACE: &str = "f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...";

/// The three kinds of numbered records a face corner refers to, in the order of `v/vt/vn`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Element {
    Position,
    Texcoord,
    Normal,
}

impl Element {
    pub(super) const ALL: [Element; 3] = [Element::Position, Element::Texcoord, Element::Normal];

    pub(super) fn from_keyword(keyword: &[u8]) -> Option<Self> {
        match keyword {
            b"v" => Some(Element::Position),
            b"vt" => Some(Element::Texcoord),
            b"vn" => Some(Element::Normal),
            _ => None,
        }
    }

    pub(super) fn keyword(self) -> &'static str {
        ["v", "vt", "vn"][self as usize]
    }

    /// The record's form, as errors quote it.
    fn form(self) -> &'static str {
        ["v x y z [w]", "vt u v", "vn x y z"][self as usize]
    }
}

/// What a line means to the loader, whose words `W` gives.
pub(super) enum Record<W> {
    Position(Vec3),
    Texcoord(Vec2),
    Normal(Vec3),
    /// A face's corner words, for [`face`].
    Face(W),
    /// Blank lines, comments, and records the loader does not use: `o`, `g`, `s`, `l`, `p`,
    /// `usemtl`, `mtllib`, ... (materials are not read: the app draws in one chosen colour).
    Other,
}

/// Why a line is refused: the form it should have had, and more when there is more to say.
#[derive(Debug, PartialEq)]
pub(super) struct Refusal {
    pub(super) what: &'static str,
    pub(super) why: Option<String>,
}

impl Refusal {
    /// A face refused, for the reason [`face`] gives.
    pub(super) fn face(why: Option<String>) -> Self {
        Self { what: FACE, why }
    }

    fn new(what: &'static str, why: Option<&str>) -> Self {
        Self {
            what,
            why: why.map(String::from),
        }
    }
}

/// The record `words` (a line's words, see `crate::words`) make. Keywords are case-sensitive,
/// as in the format and in tobj, which this loader replaced; a word after the numbers a `vt` or
/// `vn` needs is ignored (a `vt`'s optional w, for one).
pub(super) fn record<'l, W: Iterator<Item = &'l [u8]>>(mut words: W) -> Result<Record<W>, Refusal> {
    let Some(keyword) = words.next() else {
        return Ok(Record::Other);
    };
    if keyword == b"f" {
        return Ok(Record::Face(words));
    }
    let Some(element) = Element::from_keyword(keyword) else {
        return Ok(Record::Other);
    };
    let what = element.form();
    Ok(match element {
        Element::Position => {
            let [x, y, z] = numbers(&mut words, what)?;
            Record::Position(Vec3::new(x, y, z) / w(words, what)?)
        }
        Element::Texcoord => Record::Texcoord(Vec2::from_array(numbers(&mut words, what)?)),
        Element::Normal => Record::Normal(Vec3::from_array(numbers(&mut words, what)?)),
    })
}

/// The next `N` words as finite numbers.
fn numbers<'l, const N: usize>(
    words: &mut impl Iterator<Item = &'l [u8]>,
    what: &'static str,
) -> Result<[f32; N], Refusal> {
    let mut numbers = [0.0; N];
    for x in &mut numbers {
        *x = words
            .next()
            .and_then(parse_f32)
            .ok_or(Refusal::new(what, None))?;
    }
    if numbers.iter().all(|x| x.is_finite()) {
        Ok(numbers)
    } else {
        Err(Refusal::new(what, Some("numbers must be finite")))
    }
}

/// What a `v` record's position is divided by: its w, or 1 without one. Three words after the
/// position are a colour (an extension some exporters write), which is ignored.
fn w<'l>(mut words: impl Iterator<Item = &'l [u8]>, what: &'static str) -> Result<f32, Refusal> {
    let rest: [Option<&[u8]>; 4] = std::array::from_fn(|_| words.next());
    match rest {
        [None, ..] | [Some(_), Some(_), Some(_), None] => Ok(1.0),
        [Some(w), None, ..] => match parse_f32(w) {
            Some(0.0) => Err(Refusal::new(what, Some("w must not be zero"))),
            Some(w) if w.is_finite() => Ok(w),
            Some(_) => Err(Refusal::new(what, Some("numbers must be finite"))),
            None => Err(Refusal::new(what, None)),
        },
        _ => Err(Refusal::new(what, None)),
    }
}

/// Reads a face's corners into `corners` (cleared first), each as the `[v, vt, vn]` indices
/// `resolve` makes of the file's 1-based or negative (counted back) references, [`NONE`] for a
/// missing texture coordinate or normal. `resolve(element, reference, corner)` is told which
/// corner of the face it resolves for; its error, if it refuses, is why the face is refused
/// (`None`: the face is not of the form). A face needs three corners.
pub(super) fn face<'l, E>(
    words: impl Iterator<Item = &'l [u8]>,
    mut resolve: impl FnMut(Element, i64, usize) -> Result<u32, E>,
    corners: &mut Vec<[u32; 3]>,
) -> Result<(), Option<E>> {
    corners.clear();
    for word in words {
        let at = corners.len();
        corners.push(parse_corner(word, |element, reference| {
            resolve(element, reference, at)
        })?);
    }
    if corners.len() < 3 {
        return Err(None);
    }
    Ok(())
}

/// One `v`, `v/vt`, `v//vn` or `v/vt/vn` corner. Each reference is resolved as soon as it is
/// read, so that the first thing wrong in the corner is the one reported.
fn parse_corner<E>(
    word: &[u8],
    mut resolve: impl FnMut(Element, i64) -> Result<u32, E>,
) -> Result<[u32; 3], Option<E>> {
    let mut corner = [NONE; 3];
    let mut rest = Some(word);
    for element in Element::ALL {
        let Some(part) = rest else { break };
        let (reference, after) = parse_reference(part);
        rest = after;
        match reference {
            Reference::Empty if element == Element::Position => return Err(None),
            Reference::Empty => {}
            Reference::Bad => return Err(None),
            Reference::Index(i) => corner[element as usize] = resolve(element, i).map_err(Some)?,
        }
    }
    match rest {
        Some(_) => Err(None),
        None => Ok(corner),
    }
}

/// One part of a corner, up to its `/`.
enum Reference {
    Empty,
    /// Not a number that fits.
    Bad,
    Index(i64),
}

/// The reference `part` starts with, read as `str::parse::<i64>` reads it (an optional sign and
/// decimal digits) up to the first `/`, and what follows that `/`, if there is one: split and
/// read in one go.
fn parse_reference(part: &[u8]) -> (Reference, Option<&[u8]>) {
    let end = part.iter().position(|&b| b == b'/');
    let (digits, rest) = match end {
        Some(end) => (&part[..end], Some(&part[end + 1..])),
        None => (part, None),
    };
    let reference = match digits {
        [] => Reference::Empty,
        digits => number(digits).map_or(Reference::Bad, Reference::Index),
    };
    (reference, rest)
}

/// A reference as `str::parse::<i64>` reads it: an optional sign and decimal digits, `None` when
/// it does not fit.
fn number(part: &[u8]) -> Option<i64> {
    let (negative, digits) = match part.first()? {
        b'-' => (true, &part[1..]),
        b'+' => (false, &part[1..]),
        _ => (false, part),
    };
    if digits.is_empty() {
        return None;
    }
    // Up to 18 digits cannot overflow: the common case needs no checks.
    if digits.len() <= 18 {
        let mut n: i64 = 0;
        for &b in digits {
            let digit = b.wrapping_sub(b'0');
            if digit > 9 {
                return None;
            }
            n = n * 10 + i64::from(digit);
        }
        return Some(if negative { -n } else { n });
    }
    let mut n: i64 = 0;
    for &b in digits {
        let digit = i64::from(b.wrapping_sub(b'0'));
        if digit > 9 {
            return None;
        }
        n = n.checked_mul(10)?;
        // Negative numbers are built downwards, so that i64::MIN reads too.
        n = if negative {
            n.checked_sub(digit)?
        } else {
            n.checked_add(digit)?
        };
    }
    Some(n)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::words::LineWords;
    use proptest::prelude::*;

    fn read(line: &str) -> Result<String, Refusal> {
        Ok(match record(LineWords::new(line))? {
            Record::Position(p) => format!("v {p}"),
            Record::Texcoord(t) => format!("vt {t}"),
            Record::Normal(n) => format!("vn {n}"),
            Record::Face(words) => {
                let mut corners = Vec::new();
                face(
                    words,
                    |_, i, _| Ok::<_, String>((i + 10) as u32),
                    &mut corners,
                )
                .map_err(Refusal::face)?;
                format!("f {corners:?}")
            }
            Record::Other => "other".into(),
        })
    }

    fn refused(what: &'static str, why: Option<&str>) -> Result<String, Refusal> {
        Err(Refusal::new(what, why))
    }

    #[test]
    fn positions_are_divided_by_w_and_colours_ignored() {
        assert_eq!(read("v 2 4 6 2"), Ok("v [1, 2, 3]".into()));
        assert_eq!(read(" v\t2 4 6 \r"), Ok("v [2, 4, 6]".into()));
        assert_eq!(read("v 2 4 6 0.5 0.5 x"), Ok("v [2, 4, 6]".into()));
        let form = "v x y z [w]";
        assert_eq!(read("v 1 2 3 0"), refused(form, Some("w must not be zero")));
        assert_eq!(
            read("v 1 2 3 -0"),
            refused(form, Some("w must not be zero"))
        );
        assert_eq!(
            read("v 1 2 3 inf"),
            refused(form, Some("numbers must be finite"))
        );
        assert_eq!(read("v 1 2 3 w"), refused(form, None));
        assert_eq!(read("v 1 2 3 1 1"), refused(form, None));
        assert_eq!(read("v 1 2 3 1 1 1 1"), refused(form, None));
        assert_eq!(read("v 1 nan x"), refused(form, None));
    }

    #[test]
    fn unknown_and_unused_records_are_skipped() {
        for line in [
            "", "# v 1", "o a b", "g", "s off", "l 1 2", "p 1", "usemtl", "V 1 2 3",
        ] {
            assert_eq!(read(line), Ok("other".into()), "{line:?}");
        }
    }

    #[test]
    fn corners_take_every_form_and_refuse_the_rest() {
        assert_eq!(
            read("f 1 2/3 4//5 6/7/8 +9 -1"),
            Ok(format!(
                "f {:?}",
                [
                    [11, NONE, NONE],
                    [12, 13, NONE],
                    [14, NONE, 15],
                    [16, 17, 18],
                    [19, NONE, NONE],
                    [9, NONE, NONE]
                ]
            ))
        );
        for line in [
            "f 1 2",
            "f 1 2 x",
            "f 1 2 /3",
            "f 1 2 3////",
            "f 1 2 3/4/5/6",
            "f 1 2 --3",
        ] {
            assert_eq!(read(line), refused(FACE, None), "{line:?}");
        }
    }

    /// Any digits, the words around `i64`'s ends, and junk.
    const REFERENCES: &str = "[-+]?[0-9]{0,22}|[-+0-9a]{0,4}|-?9223372036854775[0-9]{3}";

    proptest! {
        #[test]
        fn references_read_as_str_parse_reads_them(word in REFERENCES) {
            prop_assert_eq!(number(word.as_bytes()), word.parse::<i64>().ok());
        }
    }
}

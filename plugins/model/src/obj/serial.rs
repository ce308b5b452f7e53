//! The reference reader: an OBJ file line by line, each line checked with its number, so that
//! the first thing wrong is reported where it is (`path:line: expected '<form>', found
//! '<line>' (why)`). Two passes, since a face may name a record further on: the first counts the
//! records, the second reads them. The file's text is never held whole. Used when the fast
//! reader ([`super::blocks`]) gives up.

use std::io::BufRead;

use super::faces::Geometry;
use super::parse::{self, Element, MAX_INDEX, Record, Refusal};
use crate::diagnostics::expected;
use crate::lines::Lines;
use crate::words::LineWords;

/// Reads the file each `pass()` reads from its start.
pub(super) fn read<'l, R: BufRead>(
    mut pass: impl FnMut() -> Result<Lines<'l, R>, String>,
) -> Result<Geometry, String> {
    let totals = count(pass()?)?;
    let mut lines = pass()?;
    let label = lines.label();
    let mut geometry = Geometry::default();
    let mut corners = Vec::new();
    while let Some((number, line)) = lines.next_line()? {
        let refused = |refusal: Refusal| {
            let message = expected(label, number, refusal.what, Some(line));
            match refusal.why {
                Some(why) => format!("{message} ({why})"),
                None => message,
            }
        };
        match parse::record(LineWords::new(line)).map_err(refused)? {
            Record::Position(p) => geometry.positions.push(p),
            Record::Texcoord(t) => geometry.texcoords.push(t),
            Record::Normal(n) => geometry.normals.push(n),
            Record::Face(words) => {
                let seen = geometry.counts();
                let resolve = |element, reference, _| resolve(element, reference, totals, seen);
                parse::face(words, resolve, &mut corners)
                    .map_err(|why| refused(Refusal::face(why)))?;
                geometry.face(&corners);
            }
            Record::Other => {}
        }
    }
    // A file rewritten between the passes could otherwise leave a face naming a record past
    // its end.
    if geometry.counts() != totals {
        return Err(format!(
            "{label}: the file changed while it was read: load it again"
        ));
    }
    Ok(geometry)
}

/// How many `v`, `vt` and `vn` records the file `lines` reads holds.
fn count<R: BufRead>(mut lines: Lines<R>) -> Result<[usize; 3], String> {
    let mut totals = [0; 3];
    while let Some((_, line)) = lines.next_line()? {
        if let Some(element) = LineWords::new(line).next().and_then(Element::from_keyword) {
            totals[element as usize] += 1;
        }
    }
    Ok(totals)
}

/// The index `reference` comes to in a face that follows `seen` records of the file's `totals`:
/// from 1 up to the file's count, or from -1 back to its first record before the face.
fn resolve(
    element: Element,
    reference: i64,
    totals: [usize; 3],
    seen: [usize; 3],
) -> Result<u32, String> {
    let (total, before) = (
        totals[element as usize] as u64,
        seen[element as usize] as u64,
    );
    let magnitude = reference.unsigned_abs();
    let index = match reference.signum() {
        1 if magnitude <= total => magnitude - 1,
        -1 if magnitude <= before => before - magnitude,
        _ => {
            return Err(format!(
                "{} index {reference} refers to no record: the file has {total}",
                element.keyword()
            ));
        }
    };
    u32::try_from(index)
        .ok()
        .filter(|&i| i <= MAX_INDEX)
        .ok_or_else(|| {
            format!(
                "{} index {reference} is more than 32-bit indices can address",
                element.keyword()
            )
        })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_that_loses_records_between_the_passes_is_refused() {
        // The face names position 3, which the first pass counted and the second never meets.
        let mut passes = ["v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "f 1 2 3\n"].into_iter();
        let pass = || {
            Ok(Lines::new(
                passes.next().expect("two passes").as_bytes(),
                "m.obj",
            ))
        };
        assert_eq!(
            read(pass).err().as_deref(),
            Some("m.obj: the file changed while it was read: load it again")
        );
    }

    #[test]
    fn faces_may_name_records_further_on() {
        let text = "f 1/1 2/1 3/1\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n";
        let geometry = read(|| Ok(Lines::new(text.as_bytes(), "m.obj"))).unwrap();
        assert_eq!(geometry.triangles.len(), 1);
    }
}

//! The fast way through an OBJ file, in one pass: read in blocks (see
//! `in_parallel::block_bytes`), each cut at line ends into pieces parsed on all cores at once,
//! the pieces joined in file order while the next block is parsed. It takes only files that
//! hold nothing wrong, and reads them as the line reader ([`super::serial`]) does; at the first
//! doubt (a bad record, a reference to nothing or to a record further on than the end of its
//! piece, an over-long line) it gives up, and the file is read again line by line, whose error,
//! line and all, is the one reported.

use std::io::Read;

use close2gl_core::limits::MAX_LINE_BYTES;
use glam::{Vec2, Vec3};

use super::faces::Geometry;
use super::parse::{self, Element, MAX_INDEX, NONE, Record};
use crate::in_parallel::fill;
use crate::words::{LineWords, Words};

/// Reads the file `reader` reads, about `block` bytes at a time: its geometry, or `None` when
/// it must be read line by line instead. `Err` only when reading fails.
pub(super) fn read<R: Read>(
    mut reader: R,
    block: usize,
    label: &str,
) -> Result<Option<Geometry>, String> {
    // Pieces smaller than a core's share, so that a core done early takes another.
    let pieces = 4 * rayon::current_num_threads();
    let mut geometry = Geometry::default();
    let mut text = Vec::new();
    let mut parsed: Vec<Option<Piece>> = Vec::new();
    let mut want = block;
    loop {
        let ended = fill(&mut reader, &mut text, want, label)?;
        let end = match text.iter().rposition(|&b| b == b'\n') {
            _ if ended => text.len(),
            Some(newline) => newline + 1,
            // A line longer than the limit: the line reader says so, without holding it.
            None if text.len() > MAX_LINE_BYTES => return Ok(None),
            None => {
                // Geometric growth, so that a long line costs linear time.
                want = text.len() + block.max(text.len());
                continue;
            }
        };
        want = block;
        let (joined, next) = rayon::join(
            || join(&mut geometry, std::mem::take(&mut parsed)),
            || parse_block(&text[..end], pieces),
        );
        if !joined {
            return Ok(None);
        }
        parsed = next;
        text.drain(..end);
        if ended {
            break;
        }
    }
    Ok(join(&mut geometry, parsed).then_some(geometry))
}

/// The parsed pieces of one block, in file order.
fn parse_block(text: &[u8], pieces: usize) -> Vec<Option<Piece>> {
    use rayon::prelude::*;
    cuts(text, pieces)
        .par_iter()
        .map(|&(start, end)| parse_piece(&text[start..end]))
        .collect()
}

/// `text` cut into about `pieces` runs of whole lines.
fn cuts(text: &[u8], pieces: usize) -> Vec<(usize, usize)> {
    let mut cuts = Vec::with_capacity(pieces);
    let mut start = 0;
    for k in 1..pieces {
        let from = (text.len() * k / pieces).max(start);
        let Some(newline) = text[from..].iter().position(|&b| b == b'\n') else {
            break;
        };
        let end = from + newline + 1;
        cuts.push((start, end));
        start = end;
    }
    cuts.push((start, text.len()));
    cuts
}

/// What a run of lines holds, ready to join the file's geometry once the records before it are
/// known.
#[derive(Default)]
struct Piece {
    positions: Vec<Vec3>,
    texcoords: Vec<Vec2>,
    normals: Vec<Vec3>,
    /// Every face's `[v, vt, vn]` corners, one face after another.
    corners: Vec<[u32; 3]>,
    /// How many corners each face has.
    faces: Vec<u32>,
    /// The references that count back, which depend on the records before the piece.
    back: Vec<Back>,
}

/// A negative reference: the index it comes to, counted from the piece's first record of its
/// kind (negative when it reaches before the piece).
struct Back {
    corner: usize,
    element: Element,
    index: i64,
}

/// The records and faces of a run of whole lines, or `None` if any line is wrong.
fn parse_piece(text: &[u8]) -> Option<Piece> {
    // Nearly always: then no line needs a look of its own.
    let ascii = text.is_ascii();
    let mut piece = Piece::default();
    let mut corners = Vec::new();
    for line in text.split(|&b| b == b'\n') {
        if line.len() > MAX_LINE_BYTES {
            return None;
        }
        if ascii || line.is_ascii() {
            piece.line(Words(line), &mut corners)?;
        } else {
            piece.line(LineWords::new(&String::from_utf8_lossy(line)), &mut corners)?;
        }
    }
    Some(piece)
}

impl Piece {
    /// Adds the record of the line whose words are `words`; `corners` is room to read a face.
    fn line<'l>(
        &mut self,
        words: impl Iterator<Item = &'l [u8]>,
        corners: &mut Vec<[u32; 3]>,
    ) -> Option<()> {
        match parse::record(words).ok()? {
            Record::Position(p) => self.positions.push(p),
            Record::Texcoord(t) => self.texcoords.push(t),
            Record::Normal(n) => self.normals.push(n),
            Record::Face(words) => self.face(words, corners)?,
            Record::Other => {}
        }
        Some(())
    }

    /// Adds the face of `words`, read through `corners`.
    fn face<'l>(
        &mut self,
        words: impl Iterator<Item = &'l [u8]>,
        corners: &mut Vec<[u32; 3]>,
    ) -> Option<()> {
        let counts = [
            self.positions.len(),
            self.texcoords.len(),
            self.normals.len(),
        ];
        let start = self.corners.len();
        let back = &mut self.back;
        let resolve = |element: Element, reference: i64, corner: usize| {
            if reference > 0 {
                return index(reference - 1).ok_or(());
            }
            if reference == 0 {
                return Err(());
            }
            back.push(Back {
                corner: start + corner,
                element,
                index: counts[element as usize] as i64 + reference,
            });
            Ok(0)
        };
        parse::face(words, resolve, corners).ok()?;
        self.corners.extend_from_slice(corners);
        self.faces.push(corners.len() as u32);
        Some(())
    }
}

/// `index` if a corner can hold it.
fn index(index: i64) -> Option<u32> {
    u32::try_from(index).ok().filter(|&i| i <= MAX_INDEX)
}

/// Adds the pieces to the geometry in order; false if a piece was not taken whole or does not
/// join (a reference to nothing, or to a record the line reader must count first).
fn join(geometry: &mut Geometry, pieces: Vec<Option<Piece>>) -> bool {
    pieces
        .into_iter()
        .all(|piece| piece.is_some_and(|piece| join_piece(geometry, piece)))
}

/// Adds one piece, its negative references resolved now that the records before it are known.
fn join_piece(geometry: &mut Geometry, mut piece: Piece) -> bool {
    let before = geometry.counts();
    for back in &piece.back {
        let element = back.element as usize;
        let Some(index) = index(before[element] as i64 + back.index) else {
            return false;
        };
        piece.corners[back.corner][element] = index;
    }
    geometry.positions.extend(piece.positions);
    geometry.texcoords.extend(piece.texcoords);
    geometry.normals.extend(piece.normals);
    let counts = geometry.counts();
    let exists = |corner: &[u32; 3]| {
        (corner.iter().zip(counts)).all(|(&i, count)| i == NONE || (i as usize) < count)
    };
    let mut start = 0;
    for &n in &piece.faces {
        let corners = &piece.corners[start..start + n as usize];
        if !corners.iter().all(exists) {
            return false;
        }
        geometry.face(corners);
        start += n as usize;
    }
    true
}

#[cfg(test)]
mod tests;

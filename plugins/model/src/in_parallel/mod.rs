//! The triangles of a `.in` file read on all cores. The body is read in blocks; each block ends
//! where a `v0` record starts and is cut, at `v0` records too, into pieces (four per core); the
//! pieces are parsed at once and their triangles joined in file order, the mesh of one block
//! being built while the next block is parsed. Only files whose every record is right are taken
//! this way: a piece with anything the line-by-line reader might refuse or read differently
//! (a bad record, a misplaced one, a byte outside ASCII, an over-long line) makes the whole file
//! go back to that reader, whose error, line and all, is then the one reported.

use std::io::Read;

use close2gl_core::limits::MAX_LINE_BYTES;

use crate::decimal::parse_f32;
use crate::in_triangles::{Body, FileTriangle, Orientation, VERTEX_TAGS, VertexLayout};
use crate::mesh_builder::Corner;
use crate::words::{Words, is_space, trim};
use glam::Vec3;

/// Bytes read at a time for each core: large enough that the cores' start and join are nothing
/// beside the parse, small enough that the text held stays small beside the mesh.
const BLOCK_BYTES_PER_CORE: usize = 1 << 20;

/// Bytes read at a time: [`BLOCK_BYTES_PER_CORE`] for each core.
pub(crate) fn block_bytes() -> usize {
    BLOCK_BYTES_PER_CORE * rayon::current_num_threads()
}

/// Reads the triangles that follow the header from `reader` into `body`, about `block` bytes
/// at a time: the body, or `None` when the file must be read line by line instead. `Err` only
/// when reading fails.
pub(crate) fn read_body<R: Read>(
    mut reader: R,
    layout: &VertexLayout,
    mut body: Body,
    block: usize,
    label: &str,
) -> Result<Option<Body>, String> {
    // Pieces smaller than a core's share, so that a core done early takes another.
    let pieces = 4 * rayon::current_num_threads();
    let mut text = Vec::new();
    let mut parsed: Vec<Option<Piece>> = Vec::new();
    let mut want = block;
    loop {
        let ended = fill(&mut reader, &mut text, want, label)?;
        let Some(end) = block_end(&text, ended) else {
            if text.len() > block + 4 * (MAX_LINE_BYTES + 1) {
                return Ok(None); // No v0 record in sight: let the line reader say why.
            }
            // Geometric growth, so that a long run without records costs linear time.
            want = text.len() + block.max(text.len());
            continue;
        };
        want = block;
        let (joined, next) = rayon::join(
            || join(&mut body, std::mem::take(&mut parsed)),
            || parse_block(&text[..end], layout, pieces),
        );
        if !joined? {
            return Ok(None);
        }
        parsed = next;
        text.drain(..end);
        if ended && text.is_empty() {
            break;
        }
    }
    let whole = join(&mut body, parsed)?;
    Ok((whole && body.triangles > 0).then_some(body))
}

/// Reads until `text` holds `want` bytes or the file ends; whether it ended.
pub(crate) fn fill(
    reader: &mut impl Read,
    text: &mut Vec<u8>,
    want: usize,
    label: &str,
) -> Result<bool, String> {
    let want = want.saturating_sub(text.len()).max(1);
    // Exactly, or `read_to_end` would double the block's room.
    text.reserve_exact(want);
    let want = want as u64;
    let read = reader
        .take(want)
        .read_to_end(text)
        .map_err(|e| format!("{label}: cannot read: {e}"))?;
    Ok((read as u64) < want)
}

/// Where the text read so far can be cut: the start of its last `v0` record (after the first
/// line), or its end once the file has ended. `None` when more must be read first.
fn block_end(text: &[u8], ended: bool) -> Option<usize> {
    if ended {
        return Some(text.len());
    }
    let mut end = text.len();
    while let Some(newline) = text[..end].iter().rposition(|&b| b == b'\n') {
        if starts_v0(&text[newline + 1..]) {
            return Some(newline + 1);
        }
        end = newline;
    }
    None
}

/// The parsed pieces of one block, in file order.
fn parse_block(text: &[u8], layout: &VertexLayout, pieces: usize) -> Vec<Option<Piece>> {
    use rayon::prelude::*;
    cuts(text, pieces)
        .par_iter()
        .map(|&(start, end)| parse_piece(&text[start..end], layout))
        .collect()
}

/// `text` cut into about `pieces` runs of lines, each but the first starting at a `v0` record.
fn cuts(text: &[u8], pieces: usize) -> Vec<(usize, usize)> {
    let mut cuts = Vec::with_capacity(pieces);
    let mut start = 0;
    for k in 1..pieces {
        let Some(end) = next_v0(text, (text.len() * k / pieces).max(start + 1)) else {
            break;
        };
        cuts.push((start, end));
        start = end;
    }
    cuts.push((start, text.len()));
    cuts
}

/// The start of the first `v0` record on a line starting after `from`.
fn next_v0(text: &[u8], from: usize) -> Option<usize> {
    let mut at = from.min(text.len());
    loop {
        let newline = at + text[at..].iter().position(|&b| b == b'\n')?;
        at = newline + 1;
        if starts_v0(&text[at..]) {
            return Some(at);
        }
    }
}

/// Whether the line `text` begins with is a `v0` record.
fn starts_v0(text: &[u8]) -> bool {
    let start = text
        .iter()
        .position(|&b| b == b'\n' || !is_space(b))
        .unwrap_or(text.len());
    text.get(start..start + 3)
        .is_some_and(|w| w[..2].eq_ignore_ascii_case(b"v0") && is_space(w[2]))
}

/// The triangles of one piece, oriented and made corners, and what orienting them corrected.
struct Piece {
    /// Each triangle's corners and the file's face normal.
    triangles: Vec<([Corner; 3], Vec3)>,
    orientation: Orientation,
}

/// Adds the pieces' triangles to the mesh in order; false if a piece was not taken whole.
fn join(body: &mut Body, pieces: Vec<Option<Piece>>) -> Result<bool, String> {
    for piece in pieces {
        let Some(piece) = piece else {
            return Ok(false);
        };
        body.orientation.absorb(&piece.orientation);
        for (corners, face_normal) in &piece.triangles {
            body.add_corners(corners, *face_normal)?;
        }
    }
    Ok(true)
}

/// The triangles of a run of whole records, or `None` if any is not exactly what the line
/// reader takes (see the module docs).
fn parse_piece(text: &[u8], layout: &VertexLayout) -> Option<Piece> {
    if !text.is_ascii() {
        return None;
    }
    let mut piece = Piece {
        triangles: Vec::with_capacity(text.len() / 128),
        orientation: Orientation::default(),
    };
    let mut records = Records::new(text);
    while let Some(first) = records.next()? {
        let mut triangle = FileTriangle::default();
        let mut numbers = [0.0; 9];
        for (k, tag) in VERTEX_TAGS.into_iter().enumerate() {
            let record = if k == 0 { first } else { records.next()?? };
            let v = read_numbers(record, &[tag], layout.counts, &mut numbers)?;
            if !layout.is_material(v[6]) {
                return None;
            }
            triangle.set_corner(k, v);
        }
        let face = read_numbers(records.next()??, &["face", "normal"], &[3], &mut numbers)?;
        triangle.set_face_normal(face);
        let face_normal = triangle.face_normal();
        piece
            .triangles
            .push((piece.orientation.orient(triangle).corners(), face_normal));
    }
    Some(piece)
}

/// The non-blank lines of a piece, trimmed.
struct Records<'t> {
    lines: std::slice::Split<'t, u8, fn(&u8) -> bool>,
}

impl<'t> Records<'t> {
    fn new(text: &'t [u8]) -> Self {
        let newline: fn(&u8) -> bool = |&b| b == b'\n';
        Self {
            lines: text.split(newline),
        }
    }

    /// The next non-blank line; `Some(None)` at the end, `None` for a line the line reader
    /// refuses as too long.
    fn next(&mut self) -> Option<Option<&'t [u8]>> {
        for line in self.lines.by_ref() {
            if line.len() > MAX_LINE_BYTES {
                return None;
            }
            let trimmed = trim(line);
            if !trimmed.is_empty() {
                return Some(Some(trimmed));
            }
        }
        Some(None)
    }
}

/// The numbers of a `keywords n1 n2 ...` record with one of `counts` numbers, all finite, as
/// the line reader reads them.
fn read_numbers<'n>(
    record: &[u8],
    keywords: &[&str],
    counts: &[usize],
    numbers: &'n mut [f32; 9],
) -> Option<&'n [f32]> {
    let mut words = Words(record);
    for keyword in keywords {
        if !words.next()?.eq_ignore_ascii_case(keyword.as_bytes()) {
            return None;
        }
    }
    let mut count = 0;
    for word in words {
        let x = parse_f32(word).filter(|x| x.is_finite())?;
        *numbers.get_mut(count)? = x;
        count += 1;
    }
    counts.contains(&count).then_some(&numbers[..count])
}

#[cfg(test)]
mod tests;

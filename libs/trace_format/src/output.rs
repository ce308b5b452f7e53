//! The trace lines that record the program's work rather than its settings: its matrices and,
//! per mesh triangle, the clip coordinates and the 2D pieces it drew.

use glam::{DMat4, DVec2, DVec4};

use super::MAX_POLY_CORNERS;
use super::syntax::{FormatError, Line};

/// `clip T`: mesh triangle T's corners in clip coordinates, before clipping.
#[derive(Clone, Debug, PartialEq)]
pub struct ClipLine {
    pub triangle: usize,
    pub corners: [DVec4; 3],
    /// Where it was written, for a checker's messages.
    pub line: usize,
}

/// A `tri` (3 corners) or `poly` (K corners) line: a 2D polygon drawn for mesh triangle T, in
/// the `ortho2d` system, with each corner's NDC depth when the program gave them.
#[derive(Clone, Debug, PartialEq)]
pub struct Piece {
    pub triangle: usize,
    pub corners: Vec<DVec2>,
    /// One per corner, or none.
    pub depths: Option<Vec<f64>>,
    pub line: usize,
}

const MATRIX: &str = "matrix M|P|V|model m00 m01 m02 m03 m10 … m33";
const CLIP: &str = "clip T x0 y0 z0 w0 x1 y1 z1 w1 x2 y2 z2 w2";
const TRI: &str = "tri T x0 y0 x1 y1 x2 y2";
const TRI_DEPTHS: &str = "tri T x0 y0 z0 x1 y1 z1 x2 y2 z2";
const POLY: &str = "poly T K x0 y0 x1 y1 …";

/// The matrices a trace may give, in the order of [`matrix`]'s index (`model`: the model
/// matrix applied before M, an addition within version 1).
pub(crate) const MATRIX_NAMES: [&str; 4] = ["M", "P", "V", "model"];

/// `matrix NAME` + 16 numbers, row by row: the index of NAME in [`MATRIX_NAMES`] and the
/// matrix (glam's are column-major, so the rows are read as columns and transposed).
pub(crate) fn matrix(line: &Line) -> Result<(usize, DMat4), FormatError> {
    line.expect_fields(18, MATRIX)?;
    let Some(which) = MATRIX_NAMES.iter().position(|&m| m == line.fields[1]) else {
        return Err(line.wrong_shape(MATRIX));
    };
    let numbers = line.numbers(2, MATRIX, |k| format!("m{}{}", k / 4, k % 4))?;
    let mut rows = [0.0; 16];
    rows.copy_from_slice(&numbers);
    Ok((which, DMat4::from_cols_array(&rows).transpose()))
}

/// `clip T` + three corners `x y z w`.
pub(crate) fn clip(line: &Line) -> Result<ClipLine, FormatError> {
    line.expect_fields(14, CLIP)?;
    let triangle = line.integer(1, "T", CLIP)?;
    let numbers = line.numbers(2, CLIP, |k| coordinate(k, 4))?;
    let corner = |i: usize| DVec4::from_slice(&numbers[4 * i..]);
    Ok(ClipLine {
        triangle,
        corners: [corner(0), corner(1), corner(2)],
        line: line.number,
    })
}

/// `tri T` + three corners `x y`, or `x y z` with their depths.
pub(crate) fn tri(line: &Line) -> Result<Piece, FormatError> {
    let (shape, per_corner) = match line.fields.len().saturating_sub(2) {
        6 => (TRI, 2),
        9 => (TRI_DEPTHS, 3),
        n if n < 6 => return Err(line.wrong_shape(TRI)),
        _ => return Err(line.wrong_shape(TRI_DEPTHS)),
    };
    let triangle = line.integer(1, "T", shape)?;
    piece(line, triangle, 2, per_corner, shape)
}

/// `poly T K` + K corners `x y`, or `x y z` with their depths.
pub(crate) fn poly(line: &Line) -> Result<Piece, FormatError> {
    if line.fields.len() < 3 {
        return Err(line.wrong_shape(POLY));
    }
    let triangle = line.integer(1, "T", POLY)?;
    let k = line.integer(2, "K", POLY)?;
    if !(3..=MAX_POLY_CORNERS).contains(&k) {
        let what = format!("'{POLY}' with K in 3..={MAX_POLY_CORNERS}");
        return Err(line.expected(&what));
    }
    let per_corner = match line.fields.len() - 3 {
        n if n == 2 * k => 2,
        n if n == 3 * k => 3,
        _ => {
            let (two, three) = (2 * k, 3 * k);
            let what = format!("'poly T K' and {two} or {three} numbers (2K or 3K for K = {k})");
            return Err(line.expected(&what));
        }
    };
    piece(line, triangle, 3, per_corner, POLY)
}

/// The corners from field `start` on, `per_corner` numbers each (the third a depth).
fn piece(
    line: &Line,
    triangle: usize,
    start: usize,
    per_corner: usize,
    shape: &str,
) -> Result<Piece, FormatError> {
    let numbers = line.numbers(start, shape, |k| coordinate(k, per_corner))?;
    let corners = numbers.chunks_exact(per_corner);
    Ok(Piece {
        triangle,
        corners: corners.clone().map(|c| DVec2::new(c[0], c[1])).collect(),
        depths: (per_corner == 3).then(|| corners.map(|c| c[2]).collect()),
        line: line.number,
    })
}

/// What a shape calls the k-th number of a list of corners: `x0 y0 z0 w0 x1 …`.
fn coordinate(k: usize, per_corner: usize) -> String {
    format!("{}{}", ["x", "y", "z", "w"][k % per_corner], k / per_corner)
}

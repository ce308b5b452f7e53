//! Wavefront `.obj` files, read by a parser of our own: positions (`v x y z [w]`), texture
//! coordinates and normals, faces in all four corner forms with negative (counted back)
//! references, polygons cut into fans; every object merged into one mesh, one vertex per
//! distinct (position, normal, texture coordinate); smooth (area-weighted) normals where the
//! file gives none. Materials, groups, lines and points are skipped: the app draws triangles in
//! one chosen colour. The file is read in one pass on all cores (`blocks`); one with anything
//! wrong is read again line by line (`serial`), whose error names the file and line.

mod blocks;
mod faces;
mod mesh;
mod normals;
mod numbering;
mod parse;
mod positions;
mod serial;

use std::io::{BufReader, Read};

use crate::lines::Lines;
use crate::{LoadedModel, file_stem, in_parallel};
use faces::Geometry;

/// Parses the text of a `.obj` file; `label` names the file in messages.
pub fn parse_obj(text: &str, label: &str) -> Result<LoadedModel, String> {
    read_obj(|| Ok(text.as_bytes()), label)
}

/// Reads an OBJ file from the start of each `open()`: once, unless it must be read again line
/// by line to say what is wrong with it (twice more, then). The text is read in blocks, never
/// held whole: memory follows the mesh, not the file.
pub(crate) fn read_obj<R: Read>(
    open: impl Fn() -> Result<R, String>,
    label: &str,
) -> Result<LoadedModel, String> {
    read_obj_blocks(open, label, in_parallel::block_bytes())
}

/// [`read_obj`] reading `block` bytes at a time (the tests use tiny blocks).
fn read_obj_blocks<R: Read>(
    open: impl Fn() -> Result<R, String>,
    label: &str,
    block: usize,
) -> Result<LoadedModel, String> {
    let geometry = match blocks::read(open()?, block, label)? {
        Some(geometry) => geometry,
        None => serial::read(|| Ok(Lines::new(BufReader::new(open()?), label)))?,
    };
    model(geometry, label)
}

/// The model a file's geometry makes.
fn model(geometry: Geometry, label: &str) -> Result<LoadedModel, String> {
    let mesh = mesh::build(geometry, file_stem(label)).map_err(|e| format!("{label}: {e}"))?;
    // A `v x y z w` with a tiny w can push a finite position to infinity.
    mesh.validate().map_err(|e| format!("{label}: {e}"))?;
    Ok(LoadedModel {
        mesh,
        warnings: Vec::new(),
    })
}

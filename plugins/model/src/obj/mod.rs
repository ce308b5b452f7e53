//! Wavefront `.obj` files, read by tobj: positions (`v x y z [w]`), texture coordinates and
//! normals, faces in all four corner forms with negative (counted back) references, polygons cut
//! into fans from their first corner. Every line is checked on its way to tobj (`checks`), so
//! that what is wrong is reported at its line (`path:line: expected '<form>', found '<line>'`);
//! the file is read once, a line at a time, through the caller's reader (its progress and its
//! cancel). tobj's objects are merged into one mesh (`merge`), one vertex per distinct (position,
//! normal, texture coordinate), with smooth (area-weighted) normals where the file gives none.
//! Materials, groups, lines and points are skipped: the app draws triangles in one chosen colour.

mod checks;
mod merge;

use std::io::{BufReader, Read};

use crate::line_reader::Lines;
use crate::{LoadedModel, file_stem};
use checks::Checked;

/// Parses the text of a `.obj` file; `label` names the file in messages.
pub fn parse_obj(text: &str, label: &str) -> Result<LoadedModel, String> {
    read_obj(text.as_bytes(), label)
}

/// Reads an OBJ file from `reader`, a line at a time: memory follows the mesh (and tobj's copy
/// of the file's records), not the file's text.
pub(crate) fn read_obj<R: Read>(reader: R, label: &str) -> Result<LoadedModel, String> {
    let options = tobj::LoadOptions {
        // A polygon becomes a fan from its first corner, in the file's winding.
        triangulate: true,
        // One index per corner, a vertex per distinct `v/vt/vn`: what the mesh builder takes.
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let mut checked = Checked::new(Lines::new(BufReader::new(reader), label));
    // `mtllib` never reaches tobj, so it never asks for a material file.
    let loaded = tobj::load_obj_buf(&mut checked, &options, |_| Ok(Default::default()));
    if let Some(error) = checked.into_error() {
        return Err(error);
    }
    let (models, _) =
        loaded.map_err(|e| format!("{label}: not a readable .obj file: tobj says {e}"))?;
    let mesh = merge::build(&models, file_stem(label)).map_err(|e| format!("{label}: {e}"))?;
    // A `v x y z w` with a tiny w can push a finite position to infinity.
    mesh.validate().map_err(|e| format!("{label}: {e}"))?;
    Ok(LoadedModel {
        mesh,
        warnings: Vec::new(),
    })
}

//! Big model files written on the spot, for the tests of loading them (memory, progress, the
//! background load): nobody keeps a 200 MB file in the repository.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::Path;

/// What [`write_grid_in`] or [`write_grid_obj`] wrote.
#[derive(Clone, Copy, Debug)]
pub struct GridFile {
    pub bytes: u64,
    pub triangles: usize,
    /// Distinct corners: what the loaded mesh holds, each shared by up to six triangles.
    pub vertices: usize,
}

impl GridFile {
    /// Bytes of the loaded mesh's own arrays: a position and a normal per vertex, three 32-bit
    /// indices per triangle (no texture coordinates).
    pub fn mesh_bytes(&self) -> u64 {
        (self.vertices * 2 * 12 + self.triangles * 12) as u64
    }
}

/// Writes a course `.in` file of a flat `side` × `side` grid of unit squares, two triangles
/// each, facing +z: about 160 bytes a triangle, so `side` = 800 gives some 200 MB.
pub fn write_grid_in(path: &Path, name: &str, side: usize) -> std::io::Result<GridFile> {
    let mut out = BufWriter::new(File::create(path)?);
    writeln!(out, "Object name = {name}")?;
    writeln!(out, "# triangles = {}", 2 * side * side)?;
    writeln!(out, "Material count = 1")?;
    writeln!(out, "ambient color 0.2 0.2 0.2")?;
    writeln!(out, "diffuse color 0.8 0.8 0.8")?;
    writeln!(out, "specular color 0.0 0.0 0.0")?;
    writeln!(out, "material shine 1.0")?;
    writeln!(
        out,
        "-- 3*[pos(x,y,z) normal(x,y,z) color_index] face_normal(x,y,z)"
    )?;
    for corners in grid_triangles(side) {
        // Whole numbers written as a course file writes reals (and much faster than formatting
        // floats in a debug build).
        for (k, (x, y)) in corners.into_iter().enumerate() {
            writeln!(out, "v{k} {x}.000000 {y}.000000 0.000000 0.0 0.0 1.0 0")?;
        }
        writeln!(out, "face normal 0.0 0.0 1.0")?;
    }
    finish(out, path, side)
}

/// Writes a Wavefront `.obj` file of the same grid as [`write_grid_in`]: each corner once (`v`),
/// then the faces by index, with no normals, so the loader computes smooth ones. About 25
/// bytes a triangle: `side` = 800 gives some 33 MB.
pub fn write_grid_obj(path: &Path, name: &str, side: usize) -> std::io::Result<GridFile> {
    let mut out = BufWriter::new(File::create(path)?);
    writeln!(out, "o {name}")?;
    for y in 0..=side {
        for x in 0..=side {
            writeln!(out, "v {x} {y} 0")?;
        }
    }
    // OBJ indices count from 1.
    let index = |(x, y): (usize, usize)| y * (side + 1) + x + 1;
    for [a, b, c] in grid_triangles(side) {
        writeln!(out, "f {} {} {}", index(a), index(b), index(c))?;
    }
    finish(out, path, side)
}

/// The grid's triangles, counter-clockwise seen from +z, as corners (x, y): two per unit square.
fn grid_triangles(side: usize) -> impl Iterator<Item = [(usize, usize); 3]> {
    (0..side).flat_map(move |y| {
        (0..side).flat_map(move |x| {
            [
                [(x, y), (x + 1, y), (x + 1, y + 1)],
                [(x, y), (x + 1, y + 1), (x, y + 1)],
            ]
        })
    })
}

fn finish(mut out: BufWriter<File>, path: &Path, side: usize) -> std::io::Result<GridFile> {
    out.flush()?;
    Ok(GridFile {
        bytes: std::fs::metadata(path)?.len(),
        triangles: 2 * side * side,
        vertices: (side + 1) * (side + 1),
    })
}

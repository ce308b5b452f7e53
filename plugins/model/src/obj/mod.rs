//! Wavefront `.obj` files through tobj: triangulated, single-indexed, every object merged into
//! one mesh; smooth (area-weighted) normals where the file gives none. Materials are not read:
//! the app draws in one chosen colour.

mod records;

use std::collections::HashMap;
use std::io::BufRead;

use glam::{Vec2, Vec3};

use crate::lines::Lines;
use crate::mesh_builder::MeshBuilder;
use crate::{LoadedModel, file_stem};
use records::Records;

/// One triangle corner as tobj gives it.
#[derive(Clone, Copy)]
struct Corner {
    position: Vec3,
    normal: Option<Vec3>,
    uv: Option<Vec2>,
}

/// The triangles of one tobj object, corner by corner.
fn corners(mesh: &tobj::Mesh) -> impl Iterator<Item = [Corner; 3]> + '_ {
    let position = |i: u32| Vec3::from_slice(&mesh.positions[3 * i as usize..]);
    // tobj gives one normal per vertex only when every corner of the object named one.
    let has_normals = mesh.normals.len() == mesh.positions.len();
    let normal =
        move |i: u32| has_normals.then(|| Vec3::from_slice(&mesh.normals[3 * i as usize..]));
    // The same for texture coordinates (`vt`).
    let has_uvs = mesh.texcoords.len() / 2 == mesh.positions.len() / 3;
    let uv = move |i: u32| has_uvs.then(|| Vec2::from_slice(&mesh.texcoords[2 * i as usize..]));
    mesh.indices.chunks_exact(3).map(move |t| {
        [t[0], t[1], t[2]].map(|i| Corner {
            position: position(i),
            normal: normal(i),
            uv: uv(i),
        })
    })
}

/// Parses the text of a `.obj` file; `label` names the file in messages.
pub fn parse_obj(text: &str, label: &str) -> Result<LoadedModel, String> {
    read_obj(|| Ok(Lines::new(text.as_bytes(), label)), label)
}

/// Reads an OBJ file in two passes, each from a fresh `pass()` over its lines: the first counts
/// the records, the second checks each line (see [`Records`]) as it hands it to tobj. The file's
/// text is never held whole: memory follows the mesh, not the file.
pub(crate) fn read_obj<'l, R: BufRead>(
    mut pass: impl FnMut() -> Result<Lines<'l, R>, String>,
    label: &str,
) -> Result<LoadedModel, String> {
    let mut records = Records::count(pass()?)?;
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let mut checked = pass()?.into_reader(|number, line| records.check(number, line));
    let loaded = tobj::load_obj_buf(&mut checked, &options, |_| Ok(Default::default()));
    // A line the checks refused stops tobj with a read error that has lost the message.
    if let Some(error) = checked.into_error() {
        return Err(error);
    }
    records.finish()?;
    let (models, _) =
        loaded.map_err(|e| format!("{label}: not a readable .obj file: tobj says {e}"))?;
    let triangles = || models.iter().flat_map(|m| corners(&m.mesh));
    if triangles().next().is_none() {
        return Err(format!(
            "{label}: no triangles (faces need at least 3 vertices)"
        ));
    }

    let smooth = smooth_normals(triangles());
    let mut builder = MeshBuilder::new(file_stem(label));
    for triangle in triangles() {
        let mut corners = [0; 3];
        for (k, c) in triangle.iter().enumerate() {
            let normal = c
                .normal
                .and_then(Vec3::try_normalize)
                .or_else(|| smooth.get(&position_key(c.position)).copied())
                .unwrap_or(Vec3::Z);
            corners[k] = builder.vertex(c.position, normal, c.uv)?;
        }
        builder.triangle(corners);
    }
    let mesh = builder.finish();
    // A `v x y z w` with a tiny w can push a finite position to infinity.
    mesh.validate().map_err(|e| format!("{label}: {e}"))?;
    Ok(LoadedModel {
        mesh,
        warnings: Vec::new(),
    })
}

fn position_key(p: Vec3) -> [u32; 3] {
    (p + 0.0).to_array().map(f32::to_bits)
}

/// Area-weighted vertex normals, per distinct position: the unnormalised cross product of each
/// triangle is its normal times twice its area, so summing them weights big faces more. Keyed by
/// position (not by tobj's vertex) so that texture seams do not crease the shading. Positions
/// whose faces cancel out or have no area get no entry.
fn smooth_normals(triangles: impl Iterator<Item = [Corner; 3]>) -> HashMap<[u32; 3], Vec3> {
    let mut sums: HashMap<[u32; 3], Vec3> = HashMap::new();
    for [a, b, c] in triangles {
        let weighted = (b.position - a.position).cross(c.position - a.position);
        for corner in [a, b, c] {
            *sums.entry(position_key(corner.position)).or_default() += weighted;
        }
    }
    sums.into_iter()
        .filter_map(|(key, sum)| Some((key, sum.try_normalize()?)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_that_loses_records_between_the_passes_is_refused() {
        // The face checks its forward reference against the first pass's count; tobj, reading
        // the second pass, finds no position 1.
        let mut passes = ["v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "f 1 2 3\n"].into_iter();
        let pass = || {
            Ok(Lines::new(
                passes.next().expect("two passes").as_bytes(),
                "m.obj",
            ))
        };
        assert_eq!(
            read_obj(pass, "m.obj").err().as_deref(),
            Some("m.obj: the file changed while it was read: load it again")
        );
    }
}

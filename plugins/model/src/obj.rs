//! Wavefront `.obj` files through tobj: triangulated, single-indexed, every object merged into
//! one mesh; smooth (area-weighted) normals where the file gives none. Materials are not read:
//! the app draws in one chosen colour.

use std::collections::HashMap;
use std::io::BufReader;

use glam::{Vec2, Vec3};

use crate::diagnostics::expected;
use crate::mesh_builder::MeshBuilder;
use crate::progress::{Counted, LoadProgress};
use crate::{LoadedModel, file_stem};

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
    read_obj(text, label, &LoadProgress::default())
}

/// [`parse_obj`], counting what tobj reads into `progress`.
pub(crate) fn read_obj(
    text: &str,
    label: &str,
    progress: &LoadProgress,
) -> Result<LoadedModel, String> {
    check_records(text, label)?;
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let mut counted = BufReader::new(Counted {
        inner: text.as_bytes(),
        progress,
    });
    let (models, _) = tobj::load_obj_buf(&mut counted, &options, |_| Ok(Default::default()))
        .map_err(|e| format!("{label}: not a readable .obj file: tobj says {e}"))?;
    let triangles: Vec<[Corner; 3]> = models.iter().flat_map(|m| corners(&m.mesh)).collect();
    if triangles.is_empty() {
        return Err(format!(
            "{label}: no triangles (faces need at least 3 vertices)"
        ));
    }

    let smooth = smooth_normals(&triangles);
    let mut builder = MeshBuilder::new(file_stem(label));
    for triangle in &triangles {
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
fn smooth_normals(triangles: &[[Corner; 3]]) -> HashMap<[u32; 3], Vec3> {
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

/// tobj's errors name no line, and its index arithmetic overflows on wild references (a panic
/// in debug builds), so every record it will trust is checked here first, with line numbers:
/// numbers finite, faces referencing records that exist.
fn check_records(text: &str, label: &str) -> Result<(), String> {
    // Positive indices may point forward, negative ones count back from the record at hand.
    let totals = count_elements(text);
    let mut seen = [0usize; 3];
    for (i, line) in text.lines().enumerate() {
        let error = |what: &str, why: Option<String>| {
            let message = expected(label, i + 1, what, Some(line));
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
            seen[kind as usize] += 1;
        } else if keyword == "f" || keyword == "l" {
            // tobj reads `l` records as faces too.
            let (minimum, what) = if keyword == "f" {
                (3, "f v[/vt][/vn] v[/vt][/vn] v[/vt][/vn] ...")
            } else {
                (2, "l v[/vt] v[/vt] ...")
            };
            let mut corners = 0;
            for word in words {
                check_corner(word, &totals, &seen).map_err(|why| error(what, why))?;
                corners += 1;
            }
            if corners < minimum {
                return Err(error(what, None));
            }
        }
    }
    Ok(())
}

/// How many positions, texture coordinates and normals the file has.
fn count_elements(text: &str) -> [usize; 3] {
    let mut totals = [0usize; 3];
    for line in text.lines() {
        if let Some(kind) = line
            .split_whitespace()
            .next()
            .and_then(Element::from_keyword)
        {
            totals[kind as usize] += 1;
        }
    }
    totals
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

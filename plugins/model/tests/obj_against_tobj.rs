//! Our OBJ reader against tobj, the reader it replaced, kept as the reference: two independent
//! readers of the same files, so that their agreement means something (as glam's matrices are
//! for Close2GL's own). On generated files of the forms both read alike (positions with and
//! without w, texture coordinates, normals, the four corner forms, negative indices, polygons,
//! several objects), every triangle's corners must come out the same: positions to the bit,
//! texture coordinates to the bit, the file's normals normalised.

use close2gl_model::parse_obj;
use glam::{Vec2, Vec3};
use proptest::prelude::*;

/// How a face names its corners: `v`, `v/vt`, `v//vn` or `v/vt/vn`, by absolute or relative index.
#[derive(Clone, Copy, Debug)]
struct Form {
    uv: bool,
    normal: bool,
    relative: bool,
}

fn form() -> impl Strategy<Value = Form> {
    (any::<bool>(), any::<bool>(), any::<bool>()).prop_map(|(uv, normal, relative)| Form {
        uv,
        normal,
        relative,
    })
}

/// A file: `objects` groups of records, each with its own positions (some with w), texture
/// coordinates and normals, and faces of 3 to 6 corners over them in one form per object.
fn obj_file() -> impl Strategy<Value = String> {
    let object = (
        prop::collection::vec((-50i32..50, -50i32..50, -50i32..50, 1i32..4), 3..12),
        form(),
        prop::collection::vec(
            prop::collection::vec(any::<prop::sample::Index>(), 3..7),
            1..8,
        ),
    );
    prop::collection::vec(object, 1..4).prop_map(|objects| {
        let mut text = String::new();
        let mut total = 0usize;
        for (k, (points, form, faces)) in objects.into_iter().enumerate() {
            text += &format!("o part{k}\n");
            for &(x, y, z, w) in &points {
                // Halves and quarters: exact in f32 and in decimal, so both readers agree.
                let (x, y, z) = (x as f32 / 4.0, y as f32 / 2.0, z as f32 / 4.0);
                match w {
                    1 => text += &format!("v {x} {y} {z}\n"),
                    w => text += &format!("v {x} {y} {z} {w}\n"),
                }
                text += &format!("vt {} {}\n", (x + 20.0) / 64.0, (y + 30.0) / 64.0);
                text += &format!("vn {y} {z} {}\n", x + 0.5);
            }
            let n = points.len();
            for face in faces {
                text += "f";
                for index in face {
                    let i = index.index(n);
                    let id = match form.relative {
                        true => format!("-{}", n - i),
                        false => format!("{}", total + i + 1),
                    };
                    text += &match (form.uv, form.normal) {
                        (false, false) => format!(" {id}"),
                        (true, false) => format!(" {id}/{id}"),
                        (false, true) => format!(" {id}//{id}"),
                        (true, true) => format!(" {id}/{id}/{id}"),
                    };
                }
                text += "\n";
            }
            total += n;
        }
        text
    })
}

/// One triangle corner as a reader gives it.
#[derive(Debug, PartialEq)]
struct Corner {
    position: [u32; 3],
    uv: Option<[u32; 2]>,
    normal: Option<Vec3>,
}

fn bits3(v: Vec3) -> [u32; 3] {
    v.to_array().map(f32::to_bits)
}

fn ours(text: &str) -> Result<Vec<Corner>, String> {
    let mesh = parse_obj(text, "m.obj")?.mesh;
    Ok(mesh
        .triangles
        .iter()
        .flatten()
        .map(|&i| {
            let i = i as usize;
            Corner {
                position: bits3(mesh.positions[i]),
                uv: mesh
                    .uvs
                    .get(i)
                    .map(|uv: &Vec2| uv.to_array().map(f32::to_bits)),
                normal: Some(mesh.normals[i]),
            }
        })
        .collect())
}

fn tobj(text: &str) -> Vec<Corner> {
    let options = tobj::LoadOptions {
        triangulate: true,
        single_index: true,
        ignore_points: true,
        ignore_lines: true,
    };
    let (models, _) =
        tobj::load_obj_buf(&mut text.as_bytes(), &options, |_| Ok(Default::default()))
            .expect("tobj reads the generated file");
    let mut corners = Vec::new();
    for model in &models {
        let m = &model.mesh;
        for &i in &m.indices {
            let i = i as usize;
            let position = Vec3::from_slice(&m.positions[3 * i..]);
            corners.push(Corner {
                position: bits3(position),
                uv: (!m.texcoords.is_empty())
                    .then(|| [m.texcoords[2 * i], m.texcoords[2 * i + 1]].map(f32::to_bits)),
                normal: (!m.normals.is_empty())
                    .then(|| Vec3::from_slice(&m.normals[3 * i..]).normalize_or_zero()),
            });
        }
    }
    corners
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn our_reader_gives_the_triangles_tobj_gives(text in obj_file()) {
        let ours = ours(&text).map_err(TestCaseError::fail)?;
        let reference = tobj(&text);
        prop_assert_eq!(ours.len(), reference.len(), "triangle corners\n{}", text);
        for (k, (a, b)) in ours.iter().zip(&reference).enumerate() {
            prop_assert_eq!(a.position, b.position, "corner {}\n{}", k, text);
            // Where the file gives a normal, ours is that normal, normalised; where it gives
            // none, ours is computed (smooth) and tobj has none to compare.
            if let (Some(ours), Some(theirs)) = (a.normal, b.normal)
                && theirs != Vec3::ZERO
            {
                prop_assert!((ours - theirs).length() < 1e-6, "corner {}: {} vs {}\n{}", k, ours, theirs, text);
            }
            if b.uv.is_some() {
                prop_assert_eq!(a.uv, b.uv, "corner {}\n{}", k, text);
            }
        }
    }
}

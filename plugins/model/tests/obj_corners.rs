//! Every triangle corner of generated OBJ files, against what the generator wrote: files of
//! positions (some with w), texture coordinates, normals, faces of 3 to 6 corners in the four
//! corner forms with absolute or negative indices, several objects; each polygon a fan from its
//! first corner, in file order. Positions and texture coordinates must come out to the bit (the
//! numbers are exact in decimal and in f32), the file's normals normalised, and a corner
//! without a normal (or with a zero one) a unit smooth normal.

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

/// One triangle corner: what the generator wrote (the position divided by its w), or what the
/// loader made of it.
#[derive(Clone, Debug)]
struct Corner {
    position: Vec3,
    uv: Option<Vec2>,
    normal: Option<Vec3>,
}

/// A file: `objects` groups of records, each with its own positions (some with w), texture
/// coordinates and normals, and faces of 3 to 6 corners over them in one form per object; and
/// the corners of its triangles, polygons cut into fans from their first corner.
fn obj_file() -> impl Strategy<Value = (String, Vec<Corner>)> {
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
        let mut corners = Vec::new();
        let mut total = 0usize;
        for (k, (points, form, faces)) in objects.into_iter().enumerate() {
            text += &format!("o part{k}\n");
            let mut records = Vec::new();
            for &(x, y, z, w) in &points {
                // Halves and quarters: exact in f32 and in decimal.
                let (x, y, z) = (x as f32 / 4.0, y as f32 / 2.0, z as f32 / 4.0);
                match w {
                    1 => text += &format!("v {x} {y} {z}\n"),
                    w => text += &format!("v {x} {y} {z} {w}\n"),
                }
                let uv = Vec2::new((x + 20.0) / 64.0, (y + 30.0) / 64.0);
                let normal = Vec3::new(y, z, x + 0.5);
                text += &format!("vt {} {}\n", uv.x, uv.y);
                text += &format!("vn {} {} {}\n", normal.x, normal.y, normal.z);
                records.push(Corner {
                    position: Vec3::new(x, y, z) / w as f32,
                    uv: form.uv.then_some(uv),
                    normal: form.normal.then_some(normal),
                });
            }
            let n = points.len();
            for face in faces {
                text += "f";
                let face: Vec<usize> = face.iter().map(|index| index.index(n)).collect();
                for &i in &face {
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
                for pair in face[1..].windows(2) {
                    corners.extend([face[0], pair[0], pair[1]].map(|i| records[i].clone()));
                }
            }
            total += n;
        }
        (text, corners)
    })
}

/// The loader's triangle corners.
fn loaded(text: &str) -> Result<Vec<Corner>, String> {
    let mesh = parse_obj(text, "m.obj")?.mesh;
    Ok(mesh
        .triangles
        .iter()
        .flatten()
        .map(|&i| {
            let i = i as usize;
            Corner {
                position: mesh.positions[i],
                uv: mesh.uvs.get(i).copied(),
                normal: Some(mesh.normals[i]),
            }
        })
        .collect())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(200))]

    #[test]
    fn every_corner_is_the_one_the_file_names((text, written) in obj_file()) {
        let loaded = loaded(&text).map_err(TestCaseError::fail)?;
        prop_assert_eq!(loaded.len(), written.len(), "triangle corners\n{}", text);
        for (k, (ours, file)) in loaded.iter().zip(&written).enumerate() {
            let bits = |p: Vec3| p.to_array().map(f32::to_bits);
            prop_assert_eq!(bits(ours.position), bits(file.position), "corner {}\n{}", k, text);
            // Without a texture coordinate of its own a corner has (0, 0), or none at all when
            // no corner of the file has one.
            let uv = |uv: Option<Vec2>| uv.map(|uv| uv.to_array().map(f32::to_bits));
            let expected = file.uv.or(ours.uv.and(Some(Vec2::ZERO)));
            prop_assert_eq!(uv(ours.uv), uv(expected), "corner {}\n{}", k, text);
            let normal = ours.normal.unwrap_or_default();
            match file.normal.and_then(Vec3::try_normalize) {
                Some(theirs) => prop_assert!((normal - theirs).length() < 1e-6, "corner {}: {} vs {}\n{}", k, normal, theirs, text),
                None => prop_assert!((normal.length() - 1.0).abs() < 1e-6, "corner {}: smooth {}\n{}", k, normal, text),
            }
        }
    }
}

//! Property tests: whatever the bytes, the loaders return Ok or Err and never panic, and any
//! model they accept is whole (`Mesh::validate`) with unit normals. Arbitrary bytes rarely get
//! past the first line, so real files are also mutated the ways broken files are broken.

use close2gl_model::{LoadedModel, parse_in, parse_obj};
use proptest::prelude::*;

const TETRA: &str = include_str!("data/tetra.in");
const QUAD: &str = include_str!("data/quad_two_materials.in");
const OBJ: &str = "o pyramid
v -1 0 -1
v 1 0 -1
v 1 0 1
v -1 0 1
v 0 1 0 1
vt 0 0
vt 1 1
vn 0 1 0
f 1/1 2/2 3/1 4/2
f 4//1 3//1 5//1
f -3 -4 -1
f 2/1/1 1/2/1 5/1/1
f 1 4 5
";

fn check(result: Result<LoadedModel, String>) -> Result<(), TestCaseError> {
    match result {
        Ok(model) => {
            prop_assert_eq!(model.mesh.validate(), Ok(()));
            for n in &model.mesh.normals {
                prop_assert!((n.length() - 1.0).abs() < 1e-4, "normal {}", n);
            }
        }
        Err(message) => prop_assert!(!message.contains('\n'), "{}", message),
    }
    Ok(())
}

fn both(text: &str) -> Result<(), TestCaseError> {
    check(parse_in(text, "p.in"))?;
    check(parse_obj(text, "p.obj"))
}

#[derive(Clone, Debug)]
enum Mutation {
    DeleteLine(usize),
    DuplicateLine(usize),
    InsertLine(usize, &'static str),
    ReplaceNumber(usize, &'static str),
    Truncate(usize),
    SetByte(usize, u8),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let line = prop::sample::select(vec![
        "# triangles = 4000000000",
        "Material count = 4000000000",
        "Texture = YES",
        "Texture = NO",
        "v0 0 0 0 0 0 1 0",
        "v2 1 1 1 0 0 -1 0 0.5 0.5",
        "face normal 0 0 0",
        "ambient color 0.1 0.1 0.1",
        "f 1 2 3",
        "f -1 -2 -3",
        "f 1/-9999999999999/1 2 3",
        "f 99999999999999999999 1 2",
        "v 1e30 0 0 1e-30",
        "v 1 2 3 0",
        "vn 0 0 0",
        "vt 0",
        "o again",
        "mtllib nowhere.mtl",
        "usemtl red",
        "",
    ]);
    let number = prop::sample::select(vec![
        "nan",
        "inf",
        "-inf",
        "1e39",
        "-1e39",
        "abc",
        "",
        "4000000000",
        "-1",
        "0",
        "1e-45",
        "99999999999999999999",
        "3.5",
        "-0.000",
        "0x10",
    ]);
    prop_oneof![
        any::<usize>().prop_map(Mutation::DeleteLine),
        any::<usize>().prop_map(Mutation::DuplicateLine),
        (any::<usize>(), line).prop_map(|(at, l)| Mutation::InsertLine(at, l)),
        (any::<usize>(), number).prop_map(|(at, n)| Mutation::ReplaceNumber(at, n)),
        any::<usize>().prop_map(Mutation::Truncate),
        (any::<usize>(), any::<u8>()).prop_map(|(at, b)| Mutation::SetByte(at, b)),
    ]
}

/// Replaces the number at index `at` (modulo how many there are) with `number`.
fn replace_number(lines: &mut [String], at: usize, number: &str) {
    let numbers = lines
        .iter()
        .flat_map(|l| l.split_whitespace())
        .filter(|w| w.parse::<f64>().is_ok())
        .count();
    if numbers == 0 {
        return;
    }
    let target = at % numbers;
    let mut seen = 0;
    for line in lines {
        let words: Vec<&str> = line
            .split_whitespace()
            .map(|w| {
                let is_number = w.parse::<f64>().is_ok();
                let replace = is_number && seen == target;
                seen += usize::from(is_number);
                if replace { number } else { w }
            })
            .collect();
        *line = words.join(" ");
    }
}

fn mutate(text: &str, mutations: &[Mutation]) -> String {
    let mut text = text.to_string();
    for m in mutations {
        let mut lines: Vec<String> = text.lines().map(String::from).collect();
        let line_at = |at: usize| at % (lines.len() + 1);
        match *m {
            Mutation::DeleteLine(at) if !lines.is_empty() => {
                lines.remove(at % lines.len());
            }
            Mutation::DuplicateLine(at) if !lines.is_empty() => {
                let line = lines[at % lines.len()].clone();
                lines.insert(at % lines.len(), line);
            }
            Mutation::InsertLine(at, line) => lines.insert(line_at(at), line.to_string()),
            Mutation::ReplaceNumber(at, number) => replace_number(&mut lines, at, number),
            Mutation::Truncate(at) => {
                let mut bytes = text.into_bytes();
                bytes.truncate(at % (bytes.len() + 1));
                text = String::from_utf8_lossy(&bytes).into_owned();
                continue;
            }
            Mutation::SetByte(at, byte) if !text.is_empty() => {
                let mut bytes = text.into_bytes();
                let len = bytes.len();
                bytes[at % len] = byte;
                text = String::from_utf8_lossy(&bytes).into_owned();
                continue;
            }
            _ => {}
        }
        text = lines.join("\n");
    }
    text
}

/// Words both formats use, so random sentences of them reach past the header.
fn token_soup() -> impl Strategy<Value = String> {
    let word = prop::sample::select(vec![
        "Object name =",
        "# triangles =",
        "Material count =",
        "ambient color",
        "diffuse color",
        "specular color",
        "material shine",
        "Texture = YES",
        "--",
        "v0",
        "v1",
        "v2",
        "face normal",
        "v",
        "vn",
        "vt",
        "f",
        "o",
        "0",
        "1",
        "-1",
        "0.5",
        "1e-3",
        "nan",
        "2/1",
        "1//1",
        "-2/-1/-1",
        "4000000000",
        "\n",
        "\r\n",
        " ",
        "=",
    ]);
    prop::collection::vec(word, 0..200).prop_map(|words| words.join(" "))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    #[test]
    fn arbitrary_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..2000)) {
        both(&String::from_utf8_lossy(&bytes))?;
    }

    #[test]
    fn token_soup_never_panics(text in token_soup()) {
        both(&text)?;
    }

    #[test]
    fn mutated_in_files_never_panic(
        tetra in prop::bool::ANY,
        mutations in prop::collection::vec(mutation(), 1..5),
    ) {
        let text = mutate(if tetra { TETRA } else { QUAD }, &mutations);
        check(parse_in(&text, "m.in"))?;
    }

    #[test]
    fn mutated_obj_files_never_panic(mutations in prop::collection::vec(mutation(), 1..5)) {
        check(parse_obj(&mutate(OBJ, &mutations), "m.obj"))?;
    }
}

#[test]
fn the_unmutated_files_load() {
    parse_in(TETRA, "tetra.in").unwrap();
    parse_in(QUAD, "quad.in").unwrap();
    let obj = parse_obj(OBJ, "p.obj").unwrap();
    assert_eq!(obj.mesh.triangles.len(), 6);
}

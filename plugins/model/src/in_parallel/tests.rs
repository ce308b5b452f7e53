//! The parallel reader against the line reader: the same mesh, warnings and error, bit for bit,
//! for valid files in every layout the format allows and for the same files broken at random,
//! read in blocks small enough that every record boundary gets cut.

use std::cell::Cell;
use std::io::{BufReader, Read};

use proptest::prelude::*;

use crate::damage::{cuts, damaged};

use crate::LoadedModel;
use crate::in_format::{read_in_blocks, read_in_lines};
use crate::line_reader::Lines;
use crate::progress::{Counted, LoadProgress};

/// What a load gives, with every number's bits (`Debug` tells -0.0 from 0.0).
fn outcome(result: Result<LoadedModel, String>) -> String {
    format!("{result:?}")
}

/// The parallel reader's outcome and the line reader's, and whether the parallel reader took
/// the file itself (it opens the file twice; a third time to hand it to the line reader).
fn both(text: &[u8], block: usize) -> (String, String, bool) {
    let opened = Cell::new(0);
    let open = || {
        opened.set(opened.get() + 1);
        Ok(text)
    };
    let parallel = read_in_blocks(open, text.len() as u64, "p.in", block);
    let lines = read_in_lines(Lines::new(BufReader::new(text), "p.in"));
    (outcome(parallel), outcome(lines), opened.get() == 2)
}

/// A number as model files spell it.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        (-50i32..50).prop_map(|n| n.to_string()),
        (-50i32..50).prop_map(|n| format!("{n}.000000")),
        (-1e4f32..1e4).prop_map(|x| format!("{x:.6}")),
        (-1f32..1.0).prop_map(|x| format!("{x}")),
        (-1f32..1.0).prop_map(|x| format!("{x:e}")),
        Just("-0.000".to_string()),
        Just("1e-3".to_string()),
        Just(".5".to_string()),
    ]
}

/// A run of the spaces the format allows between fields.
fn space() -> impl Strategy<Value = &'static str> {
    prop_oneof![4 => Just(" "), 1 => Just("  "), 1 => Just("\t"), 1 => Just(" \x0b ")]
}

/// One record: its words joined by spaces, maybe indented and with trailing spaces or `\r`.
fn record(words: Vec<String>) -> impl Strategy<Value = String> {
    let gaps = prop::collection::vec(space(), words.len());
    (gaps, space(), prop_oneof![Just(""), Just(" "), Just("\r")]).prop_map(
        move |(gaps, indent, end)| {
            let mut line = if gaps[0] == "\t" {
                indent.to_string()
            } else {
                String::new()
            };
            for (k, word) in words.iter().enumerate() {
                if k > 0 {
                    line.push_str(gaps[k]);
                }
                line.push_str(word);
            }
            line + end
        },
    )
}

/// One triangle's four records, with `uv` numbers after each vertex's material.
fn triangle(materials: u32, uv: bool) -> impl Strategy<Value = Vec<String>> {
    let corner = move |tag: &'static str| {
        let numbers = prop::collection::vec(number(), if uv { 8 } else { 6 });
        (numbers, 0..materials, prop::bool::ANY).prop_flat_map(move |(mut n, m, upper)| {
            n.insert(6, m.to_string());
            let tag = if upper {
                tag.to_uppercase()
            } else {
                tag.into()
            };
            record(std::iter::once(tag).chain(n).collect())
        })
    };
    let face = prop::collection::vec(number(), 3).prop_flat_map(|n| {
        record(
            ["face".into(), "normal".into()]
                .into_iter()
                .chain(n)
                .collect(),
        )
    });
    (corner("v0"), corner("v1"), corner("v2"), face).prop_map(|(a, b, c, d)| vec![a, b, c, d])
}

/// A whole valid file: header, materials, maybe a `Texture =` line, triangles, blank lines here
/// and there, `\n` or `\r\n`, maybe no final newline.
fn file() -> impl Strategy<Value = String> {
    (1u32..3, prop::option::of(prop::bool::ANY)).prop_flat_map(|(materials, texture)| {
        let uv = texture == Some(true);
        let triangles = prop::collection::vec(triangle(materials, uv), 1..12);
        let blanks = prop::collection::vec(
            prop_oneof![6 => Just(""), 1 => Just("\n"), 1 => Just("  \n")],
            64,
        );
        (triangles, blanks, prop::bool::ANY, prop::bool::ANY).prop_map(
            move |(triangles, blanks, crlf, final_newline)| {
                let mut lines = vec![
                    "Object name = grid".to_string(),
                    format!("# triangles = {}", triangles.len()),
                    format!("Material count = {materials}"),
                ];
                for _ in 0..materials {
                    lines.extend(
                        ["ambient color 0.2 0.2 0.2", "diffuse color 0.8 0.8 0.8"]
                            .map(String::from),
                    );
                    lines.extend(["specular color 0 0 0", "material shine 1"].map(String::from));
                }
                if let Some(yes) = texture {
                    lines.push(format!("Texture = {}", if yes { "YES" } else { "no" }));
                }
                lines.push("-- the columns".into());
                let newline = if crlf { "\r\n" } else { "\n" };
                let mut text = String::new();
                for (k, line) in lines
                    .into_iter()
                    .chain(triangles.into_iter().flatten())
                    .enumerate()
                {
                    text.push_str(blanks[k % blanks.len()]);
                    text.push_str(&line);
                    text.push_str(newline);
                }
                if !final_newline {
                    text.truncate(text.len() - newline.len());
                }
                text
            },
        )
    })
}

/// Bytes that break a file in the ways real files break (and some only fuzzers find).
fn damage() -> impl Strategy<Value = &'static [u8]> {
    prop_oneof![
        Just(&b""[..]),
        Just(&b"\n"[..]),
        Just(&b" "[..]),
        Just(&b"x"[..]),
        Just(&b"v0"[..]),
        Just(&b"\nv0 1 2 3 0 0 1 0\n"[..]),
        Just(&b"nan"[..]),
        Just(&b"1e39"[..]),
        Just(&b"-"[..]),
        Just(&b"."[..]),
        Just(&b"9"[..]),
        Just(&b"\xc2\xa0"[..]),
        Just(&b"\xff"[..]),
        Just(&b"\r"[..]),
        Just(&b"\x0c"[..]),
        Just(&b"\x1f"[..]),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn valid_files_give_the_line_readers_mesh_bit_for_bit(text in file(), block in 1usize..300) {
        let (parallel, lines, taken) = both(text.as_bytes(), block);
        prop_assert!(lines.starts_with("Ok"), "{}", lines);
        prop_assert!(taken, "the parallel reader gave a valid file to the line reader");
        prop_assert_eq!(parallel, lines);
    }

    #[test]
    fn broken_files_give_the_line_readers_error_or_mesh(
        text in file(),
        cuts in cuts(damage()),
        block in 1usize..300,
    ) {
        let (parallel, lines, _) = both(&damaged(text, cuts), block);
        prop_assert_eq!(parallel, lines);
    }
}

#[test]
fn a_body_without_triangles_and_a_huge_line_go_to_the_line_reader() {
    let header = "Object name = a\n# triangles = 1\nMaterial count = 1\nambient color 0 0 0\n\
                  diffuse color 0 0 0\nspecular color 0 0 0\nmaterial shine 1\n-- c\n";
    let triangle = "v0 0 0 0 0 0 1 0\nv1 1 0 0 0 0 1 0\nv2 0 1 0 0 0 1 0\nface normal 0 0 1\n";
    let long = format!(
        "{header}{triangle}{}\n{triangle}",
        " ".repeat(close2gl_core::limits::MAX_LINE_BYTES + 1)
    );
    for text in [header.to_string(), format!("{header}\n\n"), long] {
        for block in [1, 64, 1 << 20] {
            let (parallel, lines, taken) = both(text.as_bytes(), block);
            assert!(lines.starts_with("Err") && !taken, "{lines}");
            assert_eq!(parallel, lines);
        }
    }
}

/// A header and `triangles` copies of one triangle: a body of many blocks.
fn many_triangles(triangles: usize) -> String {
    let header = "Object name = a\n# triangles = 1\nMaterial count = 1\nambient color 0 0 0\n\
                  diffuse color 0 0 0\nspecular color 0 0 0\nmaterial shine 1\n-- c\n";
    let triangle = "v0 0 0 0 0 0 1 0\nv1 1 0 0 0 0 1 0\nv2 0 1 0 0 0 1 0\nface normal 0 0 1\n";
    header.to_string() + &triangle.repeat(triangles)
}

/// Gives `text`, and cancels `progress` once `after` bytes have been read.
struct CancelAfter<'a> {
    text: &'a [u8],
    at: usize,
    after: usize,
    progress: &'a LoadProgress,
}

impl Read for CancelAfter<'_> {
    fn read(&mut self, buf: &mut [u8]) -> std::io::Result<usize> {
        if self.at >= self.after {
            self.progress.cancel();
        }
        let n = (&self.text[self.at..]).read(buf)?;
        self.at += n;
        Ok(n)
    }
}

#[test]
fn progress_reaches_the_end_and_a_cancelled_load_stops_between_blocks() {
    let text = many_triangles(20_000);
    let load = |after: usize| {
        let progress = LoadProgress::default();
        progress.set_total(text.len() as u64);
        let open = || {
            Ok(Counted {
                inner: CancelAfter {
                    text: text.as_bytes(),
                    at: 0,
                    after,
                    progress: &progress,
                },
                progress: &progress,
            })
        };
        let loaded = read_in_blocks(open, text.len() as u64, "c.in", 64 << 10)
            .map(|m| m.mesh.triangles.len());
        (loaded, progress.fraction())
    };
    assert_eq!(load(usize::MAX), (Ok(20_000), 1.0));
    let (cancelled, fraction) = load(text.len() / 3);
    assert_eq!(cancelled, Err("c.in: cannot read: cancelled".to_string()));
    assert!((0.3..0.5).contains(&fraction), "{fraction}");
}

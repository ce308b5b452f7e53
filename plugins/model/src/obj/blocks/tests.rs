//! The fast reader against the line reader: the same mesh or the same error, bit for bit, for
//! valid files of every form the loader reads and for the same files broken at random, read in
//! blocks small enough that every line gets cut.

use std::cell::Cell;
use std::io::BufReader;

use proptest::prelude::*;

use crate::damage::{cuts, damaged};

use super::super::{model, read_obj_blocks, serial};
use crate::lines::Lines;

/// The fast reader's outcome and the line reader's (`Debug` tells -0.0 from 0.0), and whether
/// the fast reader took the file itself (it opens the file once; twice more to hand it on).
fn both(text: &[u8], block: usize) -> (String, String, bool) {
    let opened = Cell::new(0);
    let open = || {
        opened.set(opened.get() + 1);
        Ok(text)
    };
    let fast = read_obj_blocks(open, "p.obj", block);
    let lines = serial::read(|| Ok(Lines::new(BufReader::new(text), "p.obj")))
        .and_then(|geometry| model(geometry, "p.obj"));
    (format!("{fast:?}"), format!("{lines:?}"), opened.get() == 1)
}

/// A number as OBJ files spell it.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        (-50i32..50).prop_map(|n| n.to_string()),
        (-1e4f32..1e4).prop_map(|x| format!("{x:.6}")),
        (-1f32..1.0).prop_map(|x| format!("{x}")),
        (-1f32..1.0).prop_map(|x| format!("{x:e}")),
        Just("-0.000".to_string()),
        Just(".5".to_string()),
    ]
}

/// Spaces between words, as files have them.
fn space() -> impl Strategy<Value = &'static str> {
    prop_oneof![6 => Just(" "), 1 => Just("  "), 1 => Just("\t"), 1 => Just(" \x0b ")]
}

/// A line of `words`, maybe indented, maybe with trailing spaces or `\r`.
fn line(words: Vec<String>) -> impl Strategy<Value = String> {
    let gaps = prop::collection::vec(space(), words.len() + 1);
    (gaps, prop_oneof![Just(""), Just(" "), Just("\r")]).prop_map(move |(gaps, end)| {
        let mut line = String::new();
        for (word, gap) in words.iter().zip(&gaps) {
            line.push_str(if line.is_empty() && gap != &" " {
                gap
            } else {
                ""
            });
            if !line.trim().is_empty() {
                line.push_str(gap);
            }
            line.push_str(word);
        }
        line + end
    })
}

/// What a line of a valid file can be, before its face's references are chosen.
#[derive(Clone, Debug)]
enum Draft {
    Record(Vec<String>),
    /// A face of this many corners, naming texture coordinates, normals, counting back.
    Face(usize, bool, bool, Vec<(bool, u32)>),
}

fn draft() -> impl Strategy<Value = Draft> {
    let numbers = |n| prop::collection::vec(number(), n);
    let record = |keyword: &'static str, n| {
        numbers(n).prop_map(move |n| Draft::Record([vec![keyword.to_string()], n].concat()))
    };
    let other = prop::sample::select(vec![
        "# a comment",
        "#v 1 2 3",
        "o thing",
        "g a b",
        "s off",
        "usemtl red",
        "mtllib a b.mtl",
        "l 1 2",
        "p 1",
        "",
        "# caf\u{e9}",
        "vp 1 2",
        "V 1 2 3",
    ])
    .prop_map(|line| Draft::Record(vec![line.to_string()]));
    let w = (number(), -3.0f32..3.0).prop_map(|(x, w)| {
        let w = if w.abs() < 0.1 { 1.0 } else { w };
        Draft::Record(vec!["v".into(), x.clone(), x.clone(), x, format!("{w}")])
    });
    let colour = numbers(6).prop_map(|n| Draft::Record([vec!["v".to_string()], n].concat()));
    let face = (
        3usize..7,
        prop::bool::ANY,
        prop::bool::ANY,
        prop::collection::vec((prop::bool::ANY, 0u32..1000), 6),
    )
        .prop_map(|(n, vt, vn, picks)| Draft::Face(n, vt, vn, picks));
    prop_oneof![
        4 => record("v", 3),
        1 => w,
        1 => colour,
        2 => record("vt", 2),
        1 => record("vt", 3),
        2 => record("vn", 3),
        2 => other,
        8 => face,
    ]
}

/// A valid file: its drafts with every face naming records before it (a face that cannot is
/// left out), joined by `\n` or `\r\n`, maybe without a final newline.
fn file() -> impl Strategy<Value = String> {
    let drafts = prop::collection::vec(draft(), 1..60);
    let words = (drafts, prop::bool::ANY).prop_map(|(drafts, slash)| {
        let mut counts = [0u32; 3];
        let mut lines = Vec::new();
        for draft in drafts {
            match draft {
                Draft::Record(words) => {
                    let keyword = ["v", "vt", "vn"].iter().position(|k| **k == words[0]);
                    if let Some(k) = keyword {
                        counts[k] += 1;
                    }
                    lines.push(words);
                }
                Draft::Face(n, vt, vn, picks) => {
                    let names = [true, vt, vn];
                    if (0..3).any(|k| names[k] && counts[k] == 0) {
                        continue;
                    }
                    let reference = |k: usize, (back, pick): (bool, u32)| {
                        let i = pick % counts[k];
                        if back {
                            format!("-{}", counts[k] - i)
                        } else {
                            format!("{}", i + 1)
                        }
                    };
                    let mut words = vec!["f".to_string()];
                    for &pick in &picks[..n] {
                        let mut corner = reference(0, pick);
                        match (vt, vn) {
                            (false, false) if slash => corner.push('/'),
                            (false, false) => {}
                            (true, false) => corner += &format!("/{}", reference(1, pick)),
                            (false, true) => corner += &format!("//{}", reference(2, pick)),
                            (true, true) => {
                                corner +=
                                    &format!("/{}/{}", reference(1, pick), reference(2, pick));
                            }
                        }
                        words.push(corner);
                    }
                    lines.push(words);
                }
            }
        }
        lines
    });
    (words, prop::bool::ANY, prop::bool::ANY).prop_flat_map(|(lines, crlf, final_newline)| {
        let lines: Vec<_> = lines.into_iter().map(line).collect();
        lines.prop_map(move |lines| {
            let newline = if crlf { "\r\n" } else { "\n" };
            let mut text = lines.join(newline);
            if final_newline {
                text.push_str(newline);
            }
            text
        })
    })
}

/// Bytes that break a file in the ways real files break (and some only fuzzers find).
fn damage() -> impl Strategy<Value = &'static [u8]> {
    prop::sample::select(vec![
        &b""[..],
        b"\n",
        b" ",
        b"/",
        b"//",
        b"-",
        b"0",
        b"9",
        b"99",
        b"-99",
        b"x",
        b"nan",
        b"1e39",
        b"\nf 1 2 3\n",
        b"\nf -1 -2 -3 -4\n",
        b"\nv 1 2 3 0\n",
        b"\nvt 0\n",
        b"\xc2\xa0",
        b"\xff",
        b"\r",
        b"\x0c",
    ])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn valid_files_give_the_line_readers_mesh_bit_for_bit(text in file(), block in 1usize..300) {
        let (fast, lines, taken) = both(text.as_bytes(), block);
        prop_assert!(taken, "the fast reader gave a valid file to the line reader: {}", lines);
        prop_assert_eq!(fast, lines);
    }

    #[test]
    fn broken_files_give_the_line_readers_error_or_mesh(
        text in file(),
        cuts in cuts(damage()),
        block in 1usize..300,
    ) {
        let (fast, lines, _) = both(&damaged(text, cuts), block);
        prop_assert_eq!(fast, lines);
    }
}

#[test]
fn references_further_on_and_huge_lines_go_to_the_line_reader() {
    let ahead = "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n";
    let long = format!(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\n{}\nf 1 2 3\n",
        " ".repeat(close2gl_core::limits::MAX_LINE_BYTES + 1)
    );
    for (text, ok) in [(ahead.to_string(), true), (long, false)] {
        for block in [1, 64, 1 << 20] {
            let (fast, lines, taken) = both(text.as_bytes(), block);
            assert!(
                lines.starts_with(if ok { "Ok" } else { "Err" }) && !taken,
                "{lines}"
            );
            assert_eq!(fast, lines);
        }
    }
}

//! No input panics either reader: random bytes, and random lines of the formats' own words and
//! numbers (which get far past the magic). What reads must write back to the same, and an error
//! is one line naming the file.

mod common;

use close2gl_trace_format::{FormatError, parse_scene, parse_trace};
use common::without_lines;
use proptest::prelude::*;

/// The words of both formats, numbers at and past every limit, and the blanks between them.
const WORDS: &[&str] = &[
    "close2gl-trace",
    "close2gl-scene",
    "1",
    "2",
    "model",
    "triangles",
    "window",
    "ortho2d",
    "camera",
    "position",
    "u",
    "v",
    "n",
    "hfov",
    "vfov",
    "near",
    "far",
    "framed",
    "culling",
    "off",
    "ccw",
    "cw",
    "clipping",
    "simple",
    "full",
    "none",
    "mode",
    "points",
    "wireframe",
    "solid",
    "matrix",
    "M",
    "P",
    "V",
    "clip",
    "tri",
    "poly",
    "end",
    "lookat",
    "move",
    "rotate",
    "orbit",
    "#",
    "0",
    "-0",
    "3",
    "4",
    "64",
    "65",
    "180",
    "16384",
    "16385",
    "-1",
    "0.5",
    ".5",
    "1.",
    "1e999",
    "1e-320",
    "nan",
    "inf",
    "0x1p3",
    "18446744073709551616",
    "\t",
    "\r",
    "\u{feff}",
    "é",
    "",
];

fn check(text: &str) -> Result<(), TestCaseError> {
    match parse_trace(text, "f") {
        Ok(trace) => {
            let back = parse_trace(&trace.to_text(), "f");
            prop_assert_eq!(back.map(without_lines), Ok(without_lines(trace)));
        }
        Err(e) => one_line(&e)?,
    }
    match parse_scene(text, "f") {
        Ok(scene) => prop_assert_eq!(parse_scene(&scene.to_text(), "f"), Ok(scene)),
        Err(e) => one_line(&e)?,
    }
    Ok(())
}

fn one_line(error: &FormatError) -> Result<(), TestCaseError> {
    let text = error.to_string();
    prop_assert!(text.starts_with("f:"), "{}", text);
    prop_assert!(!text.contains(['\n', '\r']), "{:?}", text);
    Ok(())
}

/// A file of lines of random words, most often after the right magic.
fn lines() -> impl Strategy<Value = String> {
    let line = prop::collection::vec(prop::sample::select(WORDS), 0..20).prop_map(|w| w.join(" "));
    let magic = prop::sample::select(&["close2gl-trace 1\n", "close2gl-scene 1\n", ""][..]);
    let ending = prop::sample::select(&["\n", "\r\n"][..]);
    (magic, prop::collection::vec(line, 0..30), ending)
        .prop_map(|(magic, lines, ending)| magic.to_string() + &lines.join(ending))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(2048))]

    #[test]
    fn random_bytes_do_not_panic(bytes in prop::collection::vec(any::<u8>(), 0..512)) {
        check(&String::from_utf8_lossy(&bytes))?;
    }

    #[test]
    fn random_lines_of_the_formats_words_do_not_panic(text in lines()) {
        check(&text)?;
    }

    /// A valid file with one line's words shuffled in: the deepest lines get broken too.
    #[test]
    fn a_valid_file_with_one_broken_line_does_not_panic(
        which in 0..13usize,
        words in prop::collection::vec(prop::sample::select(WORDS), 0..20),
    ) {
        let text = format!("{}tri 0 0 0 1 0 0 1\nclip 0 1 2 3 4 5 6 7 8 9 10 11 12\nend\n", common::TRACE);
        check(&common::replaced(&text, which + 1, &words.join(" ")))?;
        check(&common::replaced(common::SCENE, which % 4 + 1, &words.join(" ")))?;
    }
}

//! The code's comments keep the why and point to `docs/*.md#section` for the measured figures:
//! every such link must name a heading of that file (by the anchor GitHub makes of it), so that
//! a section renamed or moved breaks this test rather than a reader's link.

use std::fs;
use std::path::{Path, PathBuf};

/// GitHub's anchor for a heading: lower case, spaces to hyphens, other punctuation dropped.
fn anchor(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

/// The `.rs` files under `dir`, build output left out.
fn rust_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in fs::read_dir(dir).expect("a source directory") {
        let path = entry.expect("a directory entry").path();
        if path.is_dir() {
            if !path.ends_with("target") {
                rust_files(&path, out);
            }
        } else if path.extension().is_some_and(|e| e == "rs") {
            out.push(path);
        }
    }
}

/// Each link into a section of a file of `docs/` in `text`, as (its name, the anchor).
fn links(text: &str) -> Vec<(&str, &str)> {
    let word = |s: &str| s.find(|c: char| !(c.is_ascii_alphanumeric() || c == '-' || c == '_'));
    let mut found = Vec::new();
    for (at, _) in text.match_indices("docs/") {
        let rest = &text[at + "docs/".len()..];
        let name_end = word(rest).unwrap_or(rest.len());
        let Some(tail) = rest[name_end..].strip_prefix(".md#") else {
            continue;
        };
        let anchor_end = word(tail).unwrap_or(tail.len());
        found.push((&rest[..name_end], &tail[..anchor_end]));
    }
    found
}

#[test]
fn a_heading_becomes_githubs_anchor() {
    assert_eq!(
        anchor("The lighting's attenuation, and sharing the tiles between the threads"),
        "the-lightings-attenuation-and-sharing-the-tiles-between-the-threads"
    );
    assert_eq!(
        links("see docs/performance.md#textures. And docs/a.md, (docs/performance.md#loading)"),
        [("performance", "textures"), ("performance", "loading")]
    );
}

#[test]
fn every_link_from_the_code_into_the_docs_names_a_heading() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files = Vec::new();
    for dir in ["src", "plugins", "tests", "benches", "examples"] {
        rust_files(&root.join(dir), &mut files);
    }
    let mut checked = 0;
    let mut broken = Vec::new();
    for file in &files {
        let text = fs::read_to_string(file).expect("a source file");
        for (name, link) in links(&text) {
            let doc = root.join("docs").join(format!("{name}.md"));
            let headings = fs::read_to_string(&doc).unwrap_or_default();
            let found = headings
                .lines()
                .filter_map(|line| line.strip_prefix('#'))
                .any(|heading| anchor(heading.trim_start_matches('#')) == link);
            checked += 1;
            if !found {
                broken.push(format!("{}: docs/{name}.md#{link}", file.display()));
            }
        }
    }
    assert!(checked > 0, "no links found: the search is broken");
    assert!(
        broken.is_empty(),
        "links to no heading:\n{}",
        broken.join("\n")
    );
}

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

/// The extensions of the files the prose names.
const NAMED: [&str; 9] = [
    ".rs", ".wgsl", ".md", ".toml", ".c", ".h", ".py", ".cpp", ".html",
];

/// Each file name or path `text` names: a word of path characters ending in one of [`NAMED`].
fn named_files(text: &str) -> Vec<&str> {
    let path_char = |c: char| c.is_ascii_alphanumeric() || matches!(c, '_' | '-' | '.' | '/');
    text.split(|c: char| !path_char(c))
        .map(|word| word.trim_end_matches('.').trim_start_matches("./"))
        .filter(|word| {
            NAMED
                .iter()
                .any(|ext| word.ends_with(ext) && word.len() > ext.len())
        })
        .filter(|word| !placeholder(word))
        .collect()
}

/// A name that stands for the reader's own file, not one of ours: an absolute path, a path
/// with a part in capitals (`DIR/NAME.html`), `my_...`, or a relative one going up.
fn placeholder(word: &str) -> bool {
    let capitals = |part: &str| part.len() > 1 && part.chars().all(|c| c.is_ascii_uppercase());
    word.starts_with(['/', '.'])
        || word.contains("..")
        || word.starts_with("my_")
        || word.split(['/', '.']).any(capitals)
}

/// The repository's files, as paths relative to its root (build output and dependencies left out).
fn repository_files(root: &Path, dir: &Path, out: &mut Vec<String>) {
    for entry in fs::read_dir(dir).expect("a directory") {
        let path = entry.expect("a directory entry").path();
        let name = path
            .file_name()
            .and_then(|n| n.to_str())
            .unwrap_or_default();
        if path.is_dir() {
            if !matches!(name, "target" | "node_modules" | ".git" | "__pycache__") {
                repository_files(root, &path, out);
            }
        } else if let Ok(relative) = path.strip_prefix(root) {
            out.push(relative.to_string_lossy().into_owned());
        }
    }
}

/// The folder a Markdown table row is about (its first cell, `plugins/gpu`): a bare file
/// name in that row is that folder's. None: the name may be anywhere.
fn scope(root: &Path, file: &str, line: &str) -> Option<String> {
    if !file.ends_with(".md") {
        return None;
    }
    let first = line.strip_prefix("| `")?.split('`').next()?;
    let folder = first.trim_end_matches('/');
    (folder.contains('/') && root.join(folder).is_dir()).then(|| folder.to_string())
}

#[test]
fn every_file_a_comment_or_document_names_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut all = Vec::new();
    repository_files(root, root, &mut all);
    // A name with its folder must be that path (from the root, or the end of one); a bare name
    // in a table row about a folder must be in that folder.
    let exists = |name: &str, scope: Option<&str>| {
        all.iter().any(|f| {
            let at = f == name || f.ends_with(&format!("/{name}"));
            let within = match (name.contains('/'), scope) {
                (false, Some(folder)) => f.starts_with(&format!("{folder}/")),
                _ => true,
            };
            at && within
        })
    };
    let mut checked = 0;
    let mut missing = Vec::new();
    let prose = all
        .iter()
        .filter(|f| f.ends_with(".rs") || f.ends_with(".md"));
    for file in prose {
        let text = fs::read_to_string(root.join(file)).expect("a text file");
        for (i, line) in text.lines().enumerate() {
            // In Rust, the comments are the prose; in Markdown, every line.
            let prose = match file.ends_with(".rs") {
                true => line.split_once("//").map_or("", |(_, comment)| comment),
                false => line,
            };
            let scope = scope(root, file, line);
            for name in named_files(prose) {
                checked += 1;
                if !exists(name, scope.as_deref()) {
                    missing.push(format!("{file}:{}: {name}", i + 1));
                }
            }
        }
    }
    assert!(
        checked > 100,
        "only {checked} names found: the search is broken"
    );
    assert!(
        missing.is_empty(),
        "files named that do not exist where they are said to be:\n{}",
        missing.join("\n")
    );
}

#[test]
fn a_table_row_about_a_folder_scopes_its_bare_names() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let row = "| `plugins/input` | the outside view's key (`outside.rs`) |";
    assert_eq!(
        scope(root, "docs/x.md", row).as_deref(),
        Some("plugins/input")
    );
    assert_eq!(scope(root, "src/x.rs", row), None);
    assert_eq!(scope(root, "docs/x.md", "| `src/` |").as_deref(), None);
}

#[test]
fn file_names_are_found_in_prose() {
    assert_eq!(
        named_files(
            "see `stage.rs`, plugins/gpu/src/kept_faces.wgsl and docs/web.md. Not x.y, DIR/NAME.html, /home/me/a.py or my_close2gl.py"
        ),
        ["stage.rs", "plugins/gpu/src/kept_faces.wgsl", "docs/web.md"]
    );
}

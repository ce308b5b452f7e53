//! The code's comments keep the why and point to `docs/*.md#section` for the measured figures:
//! every such link must name a heading of that file (by the anchor GitHub makes of it), so that
//! a section renamed or moved breaks this test rather than a reader's link. Likewise every file
//! the comments and documents name must be where they say, and every module path the README,
//! CONTRIBUTING and `docs/` write (`close2gl_core::limits::ZERO_AREA`) must name a module, so
//! that a file renamed or moved breaks this test rather than the reader's search.

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

/// The folder a Markdown table row is about (its first cell, `plugins/gpu` or `src/`): a file
/// that row names is in that folder. None: the name may be anywhere.
fn scope(root: &Path, file: &str, line: &str) -> Option<String> {
    if !file.ends_with(".md") {
        return None;
    }
    let first = line.strip_prefix("| `")?.split('`').next()?;
    let folder = first.trim_end_matches('/');
    (first.contains('/') && root.join(folder).is_dir()).then(|| folder.to_string())
}

/// A Markdown line without its links' targets, and the targets that lead to a file of ours
/// (`[Fuzzing](reliability.md#fuzzing)`: `reliability.md`; not a web address, not an anchor).
fn links_apart(line: &str) -> (String, Vec<&str>) {
    let mut prose = String::new();
    let mut targets = Vec::new();
    let mut rest = line;
    while let Some(at) = rest.find("](") {
        prose.push_str(&rest[..at + 2]);
        rest = &rest[at + 2..];
        let end = rest.find([')', ' ']).unwrap_or(rest.len());
        let target = rest[..end].split('#').next().unwrap_or_default();
        if !target.is_empty() && !target.contains("://") {
            targets.push(target);
        }
        rest = &rest[end..];
    }
    prose.push_str(rest);
    (prose, targets)
}

#[test]
fn every_file_a_comment_or_document_names_exists() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut all = Vec::new();
    repository_files(root, root, &mut all);
    // A name is a path from the root, or the end of one, folders included as written; in a
    // table row about a folder, the end of a path in that folder.
    let exists = |name: &str, scope: Option<&str>| {
        all.iter().any(|f| {
            let within = scope.is_none_or(|folder| f.starts_with(&format!("{folder}/")));
            f == name || (f.ends_with(&format!("/{name}")) && within)
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
            // In Rust, the comments are the prose; in Markdown, every line, its links' targets
            // apart: they lead from the page's folder.
            let (prose, targets) = match file.ends_with(".rs") {
                true => (
                    line.split_once("//").map_or("", |(_, c)| c).into(),
                    Vec::new(),
                ),
                false => links_apart(line),
            };
            let folder = Path::new(file).parent().unwrap_or(Path::new(""));
            for target in targets {
                checked += 1;
                if !root.join(folder).join(target).exists() {
                    missing.push(format!("{file}:{}: {target}", i + 1));
                }
            }
            let scope = scope(root, file, line);
            for name in named_files(&prose) {
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
    assert_eq!(
        scope(root, "docs/x.md", "| `src/` |").as_deref(),
        Some("src")
    );
    assert_eq!(scope(root, "docs/x.md", "| `stats` |").as_deref(), None);
}

#[test]
fn a_links_target_is_kept_apart_from_the_prose() {
    let (prose, targets) = links_apart(
        "see [Fuzzing](reliability.md#fuzzing), [a](#here) and [b](https://example.org/page)",
    );
    assert_eq!(prose, "see [Fuzzing](), [a]() and [b]()");
    assert_eq!(targets, ["reliability.md"]);
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

/// The pages a reader starts from, whose module paths are checked: the README, CONTRIBUTING and
/// every file of `docs/`.
fn front_pages(root: &Path) -> Vec<PathBuf> {
    let mut pages = vec![root.join("README.md"), root.join("CONTRIBUTING.md")];
    for entry in fs::read_dir(root.join("docs")).expect("docs/") {
        let path = entry.expect("a directory entry").path();
        if path.extension().is_some_and(|e| e == "md") {
            pages.push(path);
        }
    }
    pages
}

/// Each module path in backticks on `line`: identifiers joined by `::` and nothing else, the
/// first a module's or a crate's (`close2gl_core::limits::ZERO_AREA`; not `App::update`, a
/// type's, nor `app.requires::<R>()`).
fn rust_paths(line: &str) -> Vec<&str> {
    let identifier = |s: &str| {
        s.starts_with(|c: char| c.is_ascii_alphabetic() || c == '_')
            && s.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
    };
    line.split('`')
        .skip(1)
        .step_by(2)
        .filter(|span| span.contains("::") && span.split("::").all(identifier))
        .filter(|span| span.starts_with(|c: char| !c.is_ascii_uppercase()))
        .collect()
}

/// A module's source file and the folder its submodules are in.
#[derive(Clone)]
struct Module {
    file: PathBuf,
    children: PathBuf,
}

impl Module {
    fn at(file: PathBuf) -> Module {
        let named_for_its_folder = file.ends_with("lib.rs") || file.ends_with("mod.rs");
        let children = match named_for_its_folder {
            true => file.parent().expect("a folder").to_path_buf(),
            false => file.with_extension(""),
        };
        Module { file, children }
    }

    /// Its submodule `name`: a file or a folder of that name among its children.
    fn child(&self, name: &str) -> Option<Module> {
        [format!("{name}.rs"), format!("{name}/mod.rs")]
            .map(|file| self.children.join(file))
            .into_iter()
            .find(|file| file.is_file())
            .map(Module::at)
    }
}

/// The workspace's crates: each package's name with its root module (`src/lib.rs`).
fn crates(root: &Path) -> Vec<(String, Module)> {
    let mut folders = vec![root.to_path_buf()];
    for group in ["plugins", "libs"] {
        for entry in fs::read_dir(root.join(group)).expect("a crate folder") {
            folders.push(entry.expect("a directory entry").path());
        }
    }
    folders
        .into_iter()
        .filter_map(|folder| {
            let manifest = fs::read_to_string(folder.join("Cargo.toml")).ok()?;
            let package = manifest.split("[package]").nth(1)?;
            let name = package.lines().find_map(|l| l.strip_prefix("name = "))?;
            let lib = folder.join("src/lib.rs");
            lib.is_file()
                .then(|| (name.trim_matches('"').to_string(), Module::at(lib)))
        })
        .collect()
}

/// Whether `file` declares `name` (as a function, constant, type, module or macro) or
/// re-exports it (in a `pub use`, or a glob that may hold it).
fn declares(file: &Path, name: &str) -> bool {
    let text = fs::read_to_string(file).expect("a source file");
    let code: String = text
        .lines()
        .map(|line| line.split("//").next().unwrap_or_default())
        .collect::<Vec<_>>()
        .join("\n");
    let words: Vec<&str> = code
        .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
        .filter(|w| !w.is_empty())
        .collect();
    const KEYWORDS: [&str; 10] = [
        "fn",
        "const",
        "static",
        "struct",
        "enum",
        "trait",
        "type",
        "union",
        "mod",
        "macro_rules",
    ];
    let defined = words
        .windows(2)
        .any(|pair| pair[1] == name && KEYWORDS.contains(&pair[0]));
    let re_exported = code.split("pub use").skip(1).any(|statement| {
        let statement = statement.split(';').next().unwrap_or_default();
        statement.contains('*')
            || statement
                .split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                .any(|w| w == name)
    });
    defined || re_exported
}

/// Whose a path's first segment is when it is none of ours: std's, a primitive type's, or a
/// package's of the lock file (`wgpu::TextureFormat`).
fn foreign_roots(root: &Path) -> Vec<String> {
    let lock = fs::read_to_string(root.join("Cargo.lock")).expect("Cargo.lock");
    let packages = lock
        .lines()
        .filter_map(|line| line.strip_prefix("name = "))
        .map(|name| name.trim_matches('"').replace('-', "_"));
    let std = [
        "std", "core", "alloc", "str", "bool", "char", "f32", "f64", "u8", "u16", "u32", "u64",
        "usize", "i8", "i16", "i32", "i64", "isize",
    ];
    std.map(String::from).into_iter().chain(packages).collect()
}

/// Why `path` (`a::b::c`) names nothing, or None when it names something. Its first segment
/// is one of our crates (`close2gl_check`, or `check` for short) or a module of one
/// (`limits`), else someone else's (`str::parse`, not checked further) or a mistake. Each
/// segment after it is a submodule (a file or a folder, or a `mod` inside the file) down to
/// the last, or to the first type: an item the module declares or re-exports.
fn unresolved(
    path: &str,
    crates: &[(String, Module)],
    modules: &[Module],
    foreign: &[String],
) -> Option<String> {
    let segments: Vec<&str> = path.split("::").collect();
    let first = segments[0];
    let starts: Vec<&Module> = crates
        .iter()
        .filter(|(name, _)| *name == first || *name == format!("close2gl_{first}"))
        .map(|(_, module)| module)
        .chain(modules.iter().filter(|m| m.children.ends_with(first)))
        .collect();
    if starts.is_empty() {
        let theirs = foreign.iter().any(|name| name == first);
        return (!theirs).then(|| format!("no crate or module {first}"));
    }
    // Said of the first reading: a crate before a module of the same name.
    let mut why = None;
    for start in starts {
        match resolve(start.clone(), &segments[1..]) {
            Ok(()) => return None,
            Err(e) => why = why.or(Some(e)),
        }
    }
    why
}

/// Follows `segments` down from `module` (the rule: [`unresolved`]).
fn resolve(mut module: Module, segments: &[&str]) -> Result<(), String> {
    for (i, &segment) in segments.iter().enumerate() {
        let a_type = segment.starts_with(|c: char| c.is_ascii_uppercase());
        if !a_type && let Some(child) = module.child(segment) {
            module = child;
            continue;
        }
        if !declares(&module.file, segment) {
            return Err(format!("no {segment} in {}", module.file.display()));
        }
        let inline_module = fs::read_to_string(&module.file)
            .expect("a source file")
            .contains(&format!("mod {segment} {{"));
        // A type's associated items and what a re-export names are not followed; an inline
        // module's items are in the same file.
        if a_type || i + 1 == segments.len() || !inline_module {
            return Ok(());
        }
    }
    Ok(())
}

#[test]
fn every_module_path_the_front_pages_write_names_a_module() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let crates = crates(root);
    let mut files = Vec::new();
    for (_, lib) in &crates {
        rust_files(&lib.children, &mut files);
    }
    let modules: Vec<Module> = files.into_iter().map(Module::at).collect();
    let foreign = foreign_roots(root);
    let mut checked = 0;
    let mut wrong = Vec::new();
    for page in front_pages(root) {
        let text = fs::read_to_string(&page).expect("a page");
        for (i, line) in text.lines().enumerate() {
            for path in rust_paths(line) {
                checked += 1;
                if let Some(why) = unresolved(path, &crates, &modules, &foreign) {
                    let page = page.strip_prefix(root).unwrap_or(&page).display();
                    let why = why.replace(&format!("{}/", root.display()), "");
                    wrong.push(format!("{page}:{}: `{path}`: {why}", i + 1));
                }
            }
        }
    }
    assert!(
        checked > 20,
        "only {checked} module paths found: the search is broken"
    );
    assert!(
        wrong.is_empty(),
        "module paths that name nothing:\n{}",
        wrong.join("\n")
    );
}

#[test]
fn module_paths_are_read_from_backticks_and_followed_down_the_files() {
    assert_eq!(
        rust_paths("`close2gl_core::limits::ZERO_AREA`, `App::update`, `app.requires::<R>()`"),
        ["close2gl_core::limits::ZERO_AREA"]
    );
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let crates = crates(root);
    let foreign = foreign_roots(root);
    let check = |path| unresolved(path, &crates, &[], &foreign);
    assert_eq!(check("close2gl_core::limits::ZERO_AREA"), None);
    assert_eq!(
        check("core::camera::PARALLEL_UP"),
        None,
        "a crate for short"
    );
    assert_eq!(check("config::load_text"), None, "re-exported");
    assert_eq!(check("str::parse"), None, "someone else's");
    assert!(
        check("close2gl_core::limit::ZERO_AREA").is_some(),
        "a module that is not"
    );
    assert!(
        check("close2gl_core::limits::ZERO_AREAS").is_some(),
        "an item that is not"
    );
    assert!(
        check("close2gl_cheque::compare").is_some(),
        "a crate that is not"
    );
    assert!(check("compare::clip").is_some(), "a module that is nowhere");
}

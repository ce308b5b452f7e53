//! What a run may read, beyond its own directory: the system's program and library folders,
//! the few files of `/etc` the dynamic loader and the C library read, and what its command
//! names: the program's folder, every folder or file's folder given as an absolute path, and
//! the interpreter that runs a script (named in the command or in the script's `#!` line) with
//! its prefix, so that a Python in a virtual environment under the user's home still runs.

use std::ffi::OsStr;
use std::io::{BufRead, BufReader, Read};
use std::path::{Path, PathBuf};

/// Read and execute: programs and their libraries (`/bin`, `/lib`, ... are links into `/usr`
/// on a merged-/usr system, folders on an older one).
pub const SYSTEM_FOLDERS: &[&str] = &["/usr", "/bin", "/sbin", "/lib", "/lib32", "/lib64"];

/// Read only, from `/etc`: the dynamic loader's cache and preload list, the time zone, and
/// the links `/usr/bin` programs go through (`cc`, `awk`, `java` are links into
/// `/etc/alternatives` on Debian). Nothing else of `/etc` (no `passwd`, no host names).
pub const SYSTEM_FILES: &[&str] = &[
    "/etc/ld.so.cache",
    "/etc/ld.so.preload",
    "/etc/localtime",
    "/etc/alternatives",
];

/// Read and write: the devices every process may use.
pub const SYSTEM_DEVICES: &[&str] = &[
    "/dev/null",
    "/dev/zero",
    "/dev/full",
    "/dev/random",
    "/dev/urandom",
];

/// The folders (or, in a folder too broad to open, the files) that `words` names: the
/// program (looked up in `path_var` when it has no slash) and its interpreter with their
/// folders and prefixes, and each absolute path among the arguments (a folder itself, a
/// file's folder: a script run by the interpreter named first). A folder is too broad when it is the user's home or holds the temporary
/// folder (where every run's directory is): then only the file is readable.
pub fn command_folders(words: &[String], path_var: &OsStr) -> Vec<PathBuf> {
    let mut folders = Vec::new();
    let Some((program, args)) = words.split_first() else {
        return folders;
    };
    if let Some(program) = find_program(program, path_var) {
        add_program(&program, path_var, &mut folders);
    }
    for arg in args.iter().map(Path::new).filter(|p| p.is_absolute()) {
        if arg.is_dir() {
            add_folder(arg, &mut folders);
        } else if arg.exists() {
            add_folder_of(arg, &mut folders);
        }
    }
    // The system's folders are readable anyway.
    folders.retain(|f| !SYSTEM_FOLDERS.iter().any(|s| f.starts_with(s)));
    folders.sort();
    folders.dedup();
    folders
}

/// `program` as the child's exec would find it: a name without a slash is looked up in
/// `path_var`'s folders; a path is taken as it is.
pub fn find_program(program: &str, path_var: &OsStr) -> Option<PathBuf> {
    if program.contains('/') {
        // A relative path is the run directory's, which the run may read anyway.
        return Some(PathBuf::from(program)).filter(|p| p.is_absolute());
    }
    std::env::split_paths(path_var)
        .map(|dir| dir.join(program))
        .find(|candidate| is_executable(candidate))
}

fn is_executable(path: &Path) -> bool {
    use std::os::unix::fs::PermissionsExt;
    path.metadata()
        .is_ok_and(|m| m.is_file() && m.permissions().mode() & 0o111 != 0)
}

/// A program, the file its links lead to, each one's folder and prefix (the folder above a
/// `bin`), a virtual environment's base interpreter (`home` in its `pyvenv.cfg`), and the
/// interpreter of its `#!` line.
fn add_program(program: &Path, path_var: &OsStr, folders: &mut Vec<PathBuf>) {
    let resolved = program.canonicalize().ok();
    for path in std::iter::once(program.to_path_buf()).chain(resolved) {
        add_folder_of(&path, folders);
        let Some(prefix) = path
            .parent()
            .filter(|p| p.ends_with("bin"))
            .and_then(Path::parent)
        else {
            continue;
        };
        // Seen already: also what stops a virtual environment whose `home` leads back to it.
        if folders.iter().any(|f| f == prefix) {
            continue;
        }
        add_folder(prefix, folders);
        if let Some(home) = venv_home(prefix) {
            add_program(&home.join("python3"), path_var, folders);
        }
    }
    if let Some(interpreter) = shebang(program, path_var) {
        // `#!` lines do not nest (the kernel runs at most a few levels): one is enough here.
        if shebang(&interpreter, path_var).is_none() {
            add_program(&interpreter, path_var, folders);
        }
    }
}

/// `home` in `prefix/pyvenv.cfg`: the folder of the Python a virtual environment was made from.
fn venv_home(prefix: &Path) -> Option<PathBuf> {
    let file = std::fs::File::open(prefix.join("pyvenv.cfg")).ok()?;
    BufReader::new(file)
        .lines()
        .map_while(Result::ok)
        .find_map(|line| {
            let (key, value) = line.split_once('=')?;
            (key.trim() == "home").then(|| PathBuf::from(value.trim()))
        })
}

/// The interpreter of a script's `#!` line; through `/usr/bin/env NAME`, NAME looked up in
/// `path_var`.
fn shebang(script: &Path, path_var: &OsStr) -> Option<PathBuf> {
    let mut head = [0u8; 256];
    let mut file = std::fs::File::open(script).ok()?;
    let read = file.read(&mut head).ok()?;
    let line = head[..read].strip_prefix(b"#!")?;
    let line = line.split(|&b| b == b'\n').next()?;
    let line = std::str::from_utf8(line).ok()?;
    let mut words = line.split_whitespace();
    let interpreter = words.next()?;
    match Path::new(interpreter).file_name() == Some(OsStr::new("env")) {
        true => find_program(words.find(|w| !w.starts_with('-'))?, path_var),
        false => Some(PathBuf::from(interpreter)),
    }
}

fn add_folder_of(file: &Path, folders: &mut Vec<PathBuf>) {
    match file.parent() {
        Some(folder) if !too_broad(folder) => add_folder(folder, folders),
        _ => folders.push(file.to_path_buf()),
    }
}

fn add_folder(folder: &Path, folders: &mut Vec<PathBuf>) {
    if !too_broad(folder) {
        folders.push(folder.to_path_buf());
    }
}

/// The user's home, and the temporary folder or any folder holding it (`/`, `/tmp`: every
/// run's directory is in it, and a run must not read another's).
fn too_broad(folder: &Path) -> bool {
    let canonical = |p: &Path| p.canonicalize().unwrap_or_else(|_| p.to_path_buf());
    let folder = canonical(folder);
    let home = std::env::var_os("HOME").map(PathBuf::from);
    home.is_some_and(|home| canonical(&home) == folder)
        || canonical(&std::env::temp_dir()).starts_with(&folder)
}

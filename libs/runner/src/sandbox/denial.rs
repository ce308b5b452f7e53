//! Telling a program the sandbox stopped from one that failed by itself. Landlock refuses with
//! `EACCES` (a file, a TCP connection) or `EPERM` (a signal, an abstract socket) and logs
//! nothing an unprivileged grader can read, so the only witness is what the program says: its
//! stderr's lines with "Permission denied" or "Operation not permitted" (the C library's and
//! Python's words for those errors). A line naming a path outside what the run may read is
//! "tried to open PATH: denied"; another such line is quoted as it is. A program that says
//! nothing, or says it in other words, is not caught: this is a hint for the report, not proof.

use std::path::{Component, Path, PathBuf};

/// The words of the errors the sandbox causes.
const DENIED: [&str; 4] = [
    "Permission denied",
    "Operation not permitted",
    "EACCES",
    "EPERM",
];

/// The first sign in `stderr` that the sandbox denied something; `allowed`: the folders the
/// run could read (a path under them was denied for another reason: permissions, or writing);
/// `dir`: the run's directory, which relative paths start from.
pub(super) fn spot(stderr: &[u8], allowed: &[PathBuf], dir: &Path) -> Option<String> {
    let text = String::from_utf8_lossy(stderr);
    let line = text
        .lines()
        .find(|l| DENIED.iter().any(|d| l.contains(d)))?;
    let outside = paths_in(line, dir).find(|path| {
        let path = Path::new(path);
        !allowed.iter().any(|a| path.starts_with(a)) && !system(path)
    });
    Some(match outside {
        Some(path) => format!("tried to open {}: denied", home_as_tilde(&path)),
        None => format!("denied: {}", line.trim()),
    })
}

/// Paths in a line: words starting with `/`, `./` or `../` (those from `dir`, `..` taken away),
/// without the quotes, colons and commas error messages put around them.
fn paths_in<'a>(line: &'a str, dir: &'a Path) -> impl Iterator<Item = String> + 'a {
    line.split(|c: char| c.is_whitespace() || c == '\'' || c == '"' || c == '`')
        .map(|word| word.trim_end_matches([':', ',', ';', ')']))
        .filter(|word| word.len() > 1 && ["/", "./", "../"].iter().any(|s| word.starts_with(s)))
        .map(|word| {
            let mut path = PathBuf::new();
            for part in dir.join(word).components() {
                match part {
                    Component::ParentDir => _ = path.pop(),
                    Component::CurDir => {}
                    part => path.push(part),
                }
            }
            path.display().to_string()
        })
}

fn system(path: &Path) -> bool {
    let under = |folders: &[&str]| folders.iter().any(|f| path.starts_with(f));
    under(super::SYSTEM_FOLDERS) || under(super::SYSTEM_FILES) || under(super::SYSTEM_DEVICES)
}

/// `/home/ana/key` as `~/key` when the user's home is `/home/ana`: shorter, and what the user
/// recognises.
fn home_as_tilde(path: &str) -> String {
    let home = std::env::var_os("HOME").map(PathBuf::from);
    match home.and_then(|h| Path::new(path).strip_prefix(&h).ok().map(Path::to_path_buf)) {
        Some(rest) if !rest.as_os_str().is_empty() => format!("~/{}", rest.display()),
        _ => path.to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_path_outside_is_named_and_one_inside_is_quoted() {
        let allowed = [PathBuf::from("/work/run")];
        let spot = |stderr: &[u8], allowed: &[PathBuf]| super::spot(stderr, allowed, &allowed[0]);
        let python = b"Traceback\nPermissionError: [Errno 13] Permission denied: '/srv/key'\n";
        assert_eq!(
            spot(python, &allowed).as_deref(),
            Some("tried to open /srv/key: denied")
        );
        let c = b"fopen /work/run/x: Permission denied\n";
        assert_eq!(
            spot(c, &allowed).as_deref(),
            Some("denied: fopen /work/run/x: Permission denied")
        );
        let signal = b"kill: Operation not permitted\n";
        assert_eq!(
            spot(signal, &allowed).as_deref(),
            Some("denied: kill: Operation not permitted")
        );
        assert_eq!(spot(b"segmentation fault\n", &allowed), None);
        let relative = b"../../srv/key: Permission denied\n";
        assert_eq!(
            spot(relative, &allowed).as_deref(),
            Some("tried to open /srv/key: denied")
        );
    }
}

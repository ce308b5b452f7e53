//! Reading a file a run wrote, as the run's own and nothing else: the grader reads as the
//! teacher, so a trace that is a link to `/proc/self/environ`, a classmate's source or a FIFO
//! must be reported for what it is, never opened. Only a regular file with no other name
//! (a hard link made elsewhere would be someone else's file) is read.

use std::fs::File;
use std::io::Read;
use std::path::Path;

use rustix::fs::{FileType, OFlags};
use rustix::io::Errno;

use crate::beneath;

/// Characters of a link's target a report quotes.
const TARGET_CHARS: usize = 200;

/// Why a run's file was not read.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum NotItsOwn {
    /// There is no such file.
    Missing,
    /// A symbolic link, with where it points (read from the link, the target never opened).
    Link(String),
    /// Something other than a regular file: "a directory", "a FIFO", "a socket", "a device".
    NotAFile(&'static str),
    /// A regular file with other names (hard links): it may be another's file.
    OtherNames(u64),
    /// Larger than the caller reads.
    TooBig(u64),
    /// It could not be read (the error's words).
    Unreadable(String),
}

impl NotItsOwn {
    /// In a report's words, the file called `what` ("its trace"): "its trace is a link to
    /// /proc/self/environ, not a file it wrote".
    pub fn describe(&self, what: &str) -> String {
        match self {
            NotItsOwn::Missing => format!("{what} is missing"),
            NotItsOwn::Link(target) => format!("{what} is a link to {target}, not a file it wrote"),
            NotItsOwn::NotAFile(kind) => format!("{what} is {kind}, not a file it wrote"),
            NotItsOwn::OtherNames(links) => format!(
                "{what} is a file with {links} names (a hard link), not a file it wrote alone"
            ),
            NotItsOwn::TooBig(size) => format!("{what} is too big to read ({size} bytes)"),
            NotItsOwn::Unreadable(why) => format!("{what} could not be read: {why}"),
        }
    }
}

/// The bytes of `name` in the run directory `dir`, read only when it is a regular file the
/// run wrote, of at most `max` bytes; never through a link.
pub(crate) fn read(dir: &Path, name: &str, max: u64) -> Result<Vec<u8>, NotItsOwn> {
    let unreadable = |e: std::io::Error| NotItsOwn::Unreadable(e.to_string());
    let dir = beneath::open_run_dir(dir).map_err(unreadable)?;
    let handle = match beneath::handle(&dir, name) {
        Err(e) if e.raw_os_error() == Some(Errno::NOENT.raw_os_error()) => {
            return Err(NotItsOwn::Missing);
        }
        handle => handle.map_err(unreadable)?,
    };
    let stat = rustix::fs::fstat(&handle).map_err(|e| unreadable(e.into()))?;
    match FileType::from_raw_mode(stat.st_mode) {
        FileType::RegularFile => {}
        FileType::Symlink => return Err(NotItsOwn::Link(target(&handle))),
        FileType::Directory => return Err(NotItsOwn::NotAFile("a directory")),
        FileType::Fifo => return Err(NotItsOwn::NotAFile("a FIFO")),
        FileType::Socket => return Err(NotItsOwn::NotAFile("a socket")),
        _ => return Err(NotItsOwn::NotAFile("a device")),
    }
    if stat.st_nlink > 1 {
        return Err(NotItsOwn::OtherNames(stat.st_nlink as u64));
    }
    let size = stat.st_size as u64;
    if size > max {
        return Err(NotItsOwn::TooBig(size));
    }
    let file = beneath::reopen(&handle, OFlags::RDONLY, 0o600).map_err(unreadable)?;
    let mut bytes = Vec::new();
    File::from(file)
        .take(max + 1)
        .read_to_end(&mut bytes)
        .map_err(unreadable)?;
    match bytes.len() as u64 > max {
        true => Err(NotItsOwn::TooBig(bytes.len() as u64)),
        false => Ok(bytes),
    }
}

/// Where the link `handle` holds points, as text a report can show (control characters
/// escaped, cut to [`TARGET_CHARS`]).
fn target(handle: &std::os::fd::OwnedFd) -> String {
    let Ok(target) = rustix::fs::readlinkat(handle, c"", Vec::new()) else {
        return "somewhere it could not say".into();
    };
    let text = String::from_utf8_lossy(target.as_bytes());
    let mut out = String::new();
    for c in text.chars().take(TARGET_CHARS) {
        match c.is_control() {
            true => out.extend(c.escape_default()),
            false => out.push(c),
        }
    }
    out
}

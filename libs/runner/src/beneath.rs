//! A run's directory as the program left it, reached without following any link it made:
//! every name is opened from its directory's descriptor with `O_NOFOLLOW`, so that a link to
//! `/proc/self/environ`, the teacher's home or a classmate's folder is seen as a link and never
//! opened, read, measured, `chmod`ed or deleted through. A directory or file the program made
//! unreadable (`chmod 000`) is given back to its owner (the grader: the program runs as the
//! same user) through a descriptor of that very object, never by its path.

use std::ffi::{CStr, CString};
use std::io;
use std::os::fd::{AsFd, AsRawFd, OwnedFd};

use rustix::fs::{AtFlags, CWD, Dir, FileType, Mode, OFlags, Stat};
use rustix::io::Errno;
use rustix::path::Arg;

/// One entry of a directory, its status read without following it.
pub(crate) struct Entry {
    pub(crate) name: CString,
    pub(crate) stat: Stat,
}

impl Entry {
    pub(crate) fn kind(&self) -> FileType {
        FileType::from_raw_mode(self.stat.st_mode)
    }
}

/// Opens the directory `name` (in `parent`; a path from the working directory with [`CWD`])
/// for listing, not through a link. One the program made unreadable is given back first.
pub(crate) fn open_dir<P: Arg + Copy>(parent: impl AsFd, name: P) -> io::Result<OwnedFd> {
    let flags = OFlags::RDONLY | OFlags::DIRECTORY | OFlags::NOFOLLOW | OFlags::CLOEXEC;
    match rustix::fs::openat(&parent, name, flags, Mode::empty()) {
        Err(Errno::ACCESS) => {
            give_back(&handle(&parent, name)?, 0o700)?;
            Ok(rustix::fs::openat(&parent, name, flags, Mode::empty())?)
        }
        opened => Ok(opened?),
    }
}

/// The run directory at `path` (made by the grader, so its own path is trusted), for listing.
pub(crate) fn open_run_dir(path: &std::path::Path) -> io::Result<OwnedFd> {
    open_dir(CWD, path)
}

/// A handle on `name` itself (`O_PATH`): a link stays a link, nothing is opened for reading.
pub(crate) fn handle<P: Arg>(parent: impl AsFd, name: P) -> io::Result<OwnedFd> {
    let flags = OFlags::PATH | OFlags::NOFOLLOW | OFlags::CLOEXEC;
    Ok(rustix::fs::openat(parent, name, flags, Mode::empty())?)
}

/// Sets the mode of the object `handle` holds (a directory or a regular file, never a link)
/// through `/proc/self/fd`, which leads to that very object whatever its path now names.
pub(crate) fn give_back(handle: &OwnedFd, mode: u32) -> io::Result<()> {
    let kind = FileType::from_raw_mode(rustix::fs::fstat(handle)?.st_mode);
    if !matches!(kind, FileType::Directory | FileType::RegularFile) {
        return Err(io::Error::other("not a directory or a file"));
    }
    let path = format!("/proc/self/fd/{}", handle.as_raw_fd());
    Ok(rustix::fs::chmod(path.as_str(), Mode::from_raw_mode(mode))?)
}

/// Reopens the object `handle` holds with `flags` (through `/proc/self/fd`: that object, not
/// what its name leads to now), giving it back to its owner with `mode` when it was taken.
pub(crate) fn reopen(handle: &OwnedFd, flags: OFlags, mode: u32) -> io::Result<OwnedFd> {
    let path = format!("/proc/self/fd/{}", handle.as_raw_fd());
    let open = || rustix::fs::open(path.as_str(), flags | OFlags::CLOEXEC, Mode::empty());
    match open() {
        Err(Errno::ACCESS) => {
            give_back(handle, mode)?;
            Ok(open()?)
        }
        opened => Ok(opened?),
    }
}

/// Each entry of the open directory `dir` but `.` and `..`; an entry removed meanwhile is
/// left out.
pub(crate) fn entries(dir: &OwnedFd) -> Vec<Entry> {
    let Ok(mut listing) = Dir::read_from(dir) else {
        return Vec::new();
    };
    let mut entries = Vec::new();
    while let Some(Ok(entry)) = listing.read() {
        let name: &CStr = entry.file_name();
        if name == c"." || name == c".." {
            continue;
        }
        if let Ok(stat) = rustix::fs::statat(dir, name, AtFlags::SYMLINK_NOFOLLOW) {
            entries.push(Entry {
                name: name.to_owned(),
                stat,
            });
        }
    }
    entries
}

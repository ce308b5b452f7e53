//! A fresh directory for one run, so that each scene starts from nothing and whatever a program
//! writes there goes away with it. Each live workspace is also listed, so that
//! [`reap_everything`](crate::reap_everything) can remove those a caller never dropped (an
//! interrupt, an early `exit`).

use std::fs::{self, DirBuilder};
use std::hash::{BuildHasher, RandomState};
use std::io::{self, ErrorKind};
use std::os::unix::fs::DirBuilderExt;
use std::path::{Path, PathBuf};
use std::sync::{Mutex, PoisonError};

use rustix::fs::{CWD, FileType};

use crate::beneath;
use crate::own_file::{self, NotItsOwn};

/// The workspaces not yet dropped.
static LIVE: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// A new, empty directory `close2gl-grade-XXXXXXXXXXXXXXXX` under [`std::env::temp_dir`],
/// readable by the user only, removed with everything in it when dropped.
#[derive(Debug)]
pub struct Workspace {
    path: PathBuf,
}

impl Workspace {
    /// Makes the directory. Its name is random, and an existing directory is never reused.
    pub fn new() -> io::Result<Self> {
        let parent = std::path::absolute(std::env::temp_dir())?;
        let mut attempts = 0;
        loop {
            let suffix = RandomState::new().hash_one(attempts);
            let path = parent.join(format!("close2gl-grade-{suffix:016x}"));
            match DirBuilder::new().mode(0o700).create(&path) {
                Ok(()) => {
                    live().push(path.clone());
                    return Ok(Self { path });
                }
                Err(e) if e.kind() == ErrorKind::AlreadyExists && attempts < 100 => attempts += 1,
                Err(e) => return Err(e),
            }
        }
    }

    /// The directory's absolute path.
    pub fn path(&self) -> &Path {
        &self.path
    }

    /// The bytes of the file `name` the program wrote here, at most `max` of them: only a
    /// regular file of its own is read, never a link, a FIFO or a device, nor a file with
    /// another name elsewhere ([`NotItsOwn`] says which it was).
    pub fn read_own(&self, name: &str, max: u64) -> Result<Vec<u8>, NotItsOwn> {
        own_file::read(&self.path, name, max)
    }
}

impl Drop for Workspace {
    fn drop(&mut self) {
        remove(&self.path);
        live().retain(|path| path != &self.path);
    }
}

/// Removes every workspace not yet dropped (their `Drop` then finds nothing to remove).
pub(crate) fn remove_live_workspaces() {
    for path in live().drain(..) {
        remove(&path);
    }
}

fn live() -> std::sync::MutexGuard<'static, Vec<PathBuf>> {
    // A panic while the list was held leaves it consistent (push, retain, drain): keep using it.
    LIVE.lock().unwrap_or_else(PoisonError::into_inner)
}

/// Removes `dir` and everything in it (the standard library's removal never follows a link).
/// A program may have made directories unreadable or unwritable (it runs as the same user);
/// then every directory is given back to its owner and the removal is tried again.
fn remove(dir: &Path) {
    match fs::remove_dir_all(dir) {
        Err(e) if e.kind() != ErrorKind::NotFound => {
            give_back_tree(dir);
            let _ = fs::remove_dir_all(dir);
        }
        _ => {}
    }
}

/// Gives `dir` and every directory below it back to their owner (read, write, search), each
/// reached from its parent's descriptor, never through a link the program made.
fn give_back_tree(dir: &Path) {
    if let Ok(root) = beneath::handle(CWD, dir) {
        let _ = beneath::give_back(&root, 0o700);
    }
    let mut pending: Vec<_> = beneath::open_run_dir(dir).into_iter().collect();
    while let Some(dir) = pending.pop() {
        let below = beneath::entries(&dir);
        for entry in below.iter().filter(|e| e.kind() == FileType::Directory) {
            let name = entry.name.as_c_str();
            if let Ok(handle) = beneath::handle(&dir, name) {
                let _ = beneath::give_back(&handle, 0o700);
            }
            pending.extend(beneath::open_dir(&dir, name).ok());
        }
    }
}

//! How much a run directory holds, measured while the program runs: `RLIMIT_FSIZE` bounds one
//! file, but a program writing many files (or many directories) would fill the disk without it.

use std::fs;
use std::os::unix::fs::{MetadataExt, PermissionsExt};
use std::path::{Path, PathBuf};

/// What one entry costs at least: an empty file or a directory still takes an inode and a block,
/// so a program making millions of empty files meets the limit too.
const MIN_ENTRY: u64 = 4096;

/// Whether `dir` holds more than `limit` bytes: each entry counts its size or its allocated
/// blocks, whichever is more (a sparse file counts its length), and at least [`MIN_ENTRY`].
/// Symbolic links are not followed. It stops walking as soon as the limit is passed.
pub(crate) fn exceeds(dir: &Path, limit: u64) -> bool {
    // A program may replace its directory by a link to another: that one is not its to count
    // (nor, below, to change the permissions of).
    if !dir.symlink_metadata().is_ok_and(|meta| meta.is_dir()) {
        return false;
    }
    let mut total = 0u64;
    let mut pending: Vec<PathBuf> = vec![dir.to_path_buf()];
    while let Some(dir) = pending.pop() {
        let Some(entries) = read_dir_fixing_permissions(&dir) else {
            continue;
        };
        for entry in entries.flatten() {
            // An entry the program deleted meanwhile has no metadata: it no longer counts.
            let Ok(meta) = entry.metadata() else { continue };
            total += meta.len().max(meta.blocks() * 512).max(MIN_ENTRY);
            if total > limit {
                return true;
            }
            if meta.is_dir() {
                pending.push(entry.path());
            }
        }
    }
    false
}

/// Lists `dir`; a directory the program made unreadable (`chmod 000`) is given back to its
/// owner (us: the program runs as the same user) and listed again, so it cannot hide files.
fn read_dir_fixing_permissions(dir: &Path) -> Option<fs::ReadDir> {
    match fs::read_dir(dir) {
        Ok(entries) => Some(entries),
        Err(e) if e.kind() == std::io::ErrorKind::PermissionDenied => {
            fs::set_permissions(dir, fs::Permissions::from_mode(0o700)).ok()?;
            fs::read_dir(dir).ok()
        }
        Err(_) => None,
    }
}

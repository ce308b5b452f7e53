//! How much a run directory holds, measured while the program runs: `RLIMIT_FSIZE` bounds one
//! file, but a program writing many files (or many directories) would fill the disk without it.

use std::path::Path;

use rustix::fs::FileType;

use crate::beneath;

/// What one entry costs at least: an empty file or a directory still takes an inode and a block,
/// so a program making millions of empty files meets the limit too.
const MIN_ENTRY: u64 = 4096;

/// Whether `dir` holds more than `limit` bytes: each entry counts its size or its allocated
/// blocks, whichever is more (a sparse file counts its length), and at least [`MIN_ENTRY`].
/// Links are counted as links, never followed (`beneath`); a directory the program made
/// unreadable is given back and counted. It stops walking as soon as the limit is passed.
pub(crate) fn exceeds(dir: &Path, limit: u64) -> bool {
    let Ok(root) = beneath::open_run_dir(dir) else {
        return false;
    };
    let mut total = 0u64;
    let mut pending = vec![root];
    while let Some(dir) = pending.pop() {
        for entry in beneath::entries(&dir) {
            let (size, blocks) = (entry.stat.st_size as u64, entry.stat.st_blocks as u64);
            total += size.max(blocks * 512).max(MIN_ENTRY);
            if total > limit {
                return true;
            }
            if entry.kind() == FileType::Directory {
                // One the program removed or replaced meanwhile is simply not counted.
                pending.extend(beneath::open_dir(&dir, entry.name.as_c_str()).ok());
            }
        }
    }
    false
}

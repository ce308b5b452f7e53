//! Opening a file the app was given by path. On the desktop that is the file system. A browser
//! has none: the web page hands the app each file it has (the bundled models, a file dropped on
//! the page or picked) with [`keep`], and opening its name finds the bytes kept. Files kept are
//! looked at first everywhere, so the desktop's tests can use the table the page uses.

use std::collections::HashMap;
use std::fs::File;
use std::io::{self, Cursor, Read, Seek, SeekFrom};
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

static KEPT: Mutex<Option<HashMap<PathBuf, Arc<[u8]>>>> = Mutex::new(None);

/// Keeps `bytes` as the file `path`: opening `path` from now on reads them (replacing any kept
/// before under that name).
pub fn keep(path: impl Into<PathBuf>, bytes: impl Into<Arc<[u8]>>) {
    let mut kept = KEPT.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    kept.get_or_insert_with(HashMap::new)
        .insert(path.into(), bytes.into());
}

fn kept(path: &Path) -> Option<Arc<[u8]>> {
    let kept = KEPT.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    kept.as_ref()?.get(path).cloned()
}

/// An open file: on disk, or kept in memory.
pub enum Opened {
    Disk(File),
    Kept(Cursor<Arc<[u8]>>),
}

/// Opens `path` for reading: the bytes kept under that name, else the file on disk. A directory
/// or a device is refused (as `ErrorKind::InvalidInput`): a loader expects a file.
pub fn open(path: &Path) -> io::Result<Opened> {
    if let Some(bytes) = kept(path) {
        return Ok(Opened::Kept(Cursor::new(bytes)));
    }
    let file = File::open(path)?;
    if !file.metadata()?.is_file() {
        return Err(io::Error::new(
            io::ErrorKind::InvalidInput,
            "a directory or device, not a file",
        ));
    }
    Ok(Opened::Disk(file))
}

impl Opened {
    /// The file's size in bytes.
    pub fn len(&self) -> io::Result<u64> {
        match self {
            Opened::Disk(file) => Ok(file.metadata()?.len()),
            Opened::Kept(cursor) => Ok(cursor.get_ref().len() as u64),
        }
    }

    pub fn is_empty(&self) -> io::Result<bool> {
        self.len().map(|len| len == 0)
    }
}

impl Read for Opened {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        match self {
            Opened::Disk(file) => file.read(buf),
            Opened::Kept(cursor) => cursor.read(buf),
        }
    }
}

impl Seek for Opened {
    fn seek(&mut self, pos: SeekFrom) -> io::Result<u64> {
        match self {
            Opened::Disk(file) => file.seek(pos),
            Opened::Kept(cursor) => cursor.seek(pos),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_kept_file_is_read_before_the_disk_and_a_directory_is_refused() {
        let name = PathBuf::from("files-test/kept.in");
        assert!(open(&name).is_err(), "not on disk, not kept yet");
        keep(name.clone(), b"1 2 3".to_vec());
        let mut text = String::new();
        let mut opened = open(&name).unwrap();
        assert_eq!(opened.len().unwrap(), 5);
        opened.read_to_string(&mut text).unwrap();
        assert_eq!(text, "1 2 3");
        opened.rewind().unwrap();
        let mut again = Vec::new();
        opened.read_to_end(&mut again).unwrap();
        assert_eq!(again, b"1 2 3");
        let dir = std::env::temp_dir();
        let error = open(&dir).err().expect("a directory is not a file");
        assert!(error.to_string().contains("not a file"), "{error}");
    }
}

//! A directory of a test's own, for the files it writes, removed when the test is done with it.

use std::path::PathBuf;

pub struct TempDir(pub PathBuf);

impl TempDir {
    /// `close2gl_<test>_<pid>` under the system's temporary directory.
    pub fn new(test: &str) -> Self {
        let path = std::env::temp_dir().join(format!("close2gl_{test}_{}", std::process::id()));
        std::fs::create_dir_all(&path).expect("temp dir");
        Self(path)
    }

    /// Writes `contents` to `name` in the directory; returns its path.
    pub fn write(&self, name: &str, contents: &[u8]) -> PathBuf {
        let path = self.0.join(name);
        std::fs::write(&path, contents).expect("write");
        path
    }
}

impl Drop for TempDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

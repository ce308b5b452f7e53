//! Reading a scene or trace file whole, with its faults as [`FormatError`]s too: a file that
//! cannot be read, one too big to be a trace (which would otherwise take the memory), and bytes
//! that are not UTF-8, named by their line.

use std::io::Read;
use std::path::Path;

use super::MAX_FILE_BYTES;
use super::syntax::FormatError;

/// The text of the file at `path` and the label its errors use: the path as given.
pub(crate) fn text(path: &Path) -> Result<(String, String), FormatError> {
    let (bytes, file) = bytes(path)?;
    Ok((decode(bytes, &file)?, file))
}

/// The bytes of the file at `path`, at most [`MAX_FILE_BYTES`] of them, and its label.
pub(crate) fn bytes(path: &Path) -> Result<(Vec<u8>, String), FormatError> {
    let file = path.display().to_string();
    let io = |e: std::io::Error| FormatError::new(&file, 0, format!("cannot read: {e}"));
    let too_big = |found: &str| {
        let message = format!("expected a file of at most 1 GiB, found {found}");
        FormatError::new(&file, 0, message)
    };
    let mut reader = close2gl_core::files::open(path).map_err(io)?;
    let size = reader.len().map_err(io)?;
    if size > MAX_FILE_BYTES {
        return Err(too_big(&format!("{size} bytes")));
    }
    // The file may grow between the look and the read, or be a device with no size: the read
    // stops one byte past the limit either way.
    let mut bytes = Vec::new();
    (&mut reader)
        .take(MAX_FILE_BYTES + 1)
        .read_to_end(&mut bytes)
        .map_err(io)?;
    if bytes.len() as u64 > MAX_FILE_BYTES {
        return Err(too_big("more"));
    }
    Ok((bytes, file))
}

/// `bytes` as text, or the line of the first byte that is not UTF-8; `file` labels the error.
pub(crate) fn decode(bytes: Vec<u8>, file: &str) -> Result<String, FormatError> {
    match String::from_utf8(bytes) {
        Ok(text) => Ok(text),
        Err(e) => {
            let at = e.utf8_error().valid_up_to();
            let bytes = e.as_bytes();
            let line = 1 + bytes[..at].iter().filter(|&&b| b == b'\n').count();
            let message = format!("expected UTF-8 text, found the byte 0x{:02x}", bytes[at]);
            Err(FormatError::new(file, line, message))
        }
    }
}

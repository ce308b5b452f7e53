//! A model file's lines, read one at a time so that a big file never sits in memory whole.

use std::io::{BufRead, Read};

use close2gl_core::limits::MAX_LINE_BYTES;

use crate::diagnostics::expected;

/// The lines of `reader`, each without its `\n` (a `\r` stays, for the parser's trim). Invalid
/// UTF-8 becomes U+FFFD, so the parser reports it at its line like any other garbage, and a
/// line longer than [`MAX_LINE_BYTES`] is an error at that line rather than an allocation as
/// large as the file.
pub(crate) struct Lines<'l, R> {
    reader: R,
    label: &'l str,
    bytes: Vec<u8>,
    text: String,
    /// 1-based number of the line in `text`; 0 before the first.
    number: usize,
    /// Bytes read so far: where the next line starts.
    offset: u64,
}

impl<'l, R: BufRead> Lines<'l, R> {
    pub(crate) fn new(reader: R, label: &'l str) -> Self {
        Self {
            reader,
            label,
            bytes: Vec::new(),
            text: String::new(),
            number: 0,
            offset: 0,
        }
    }

    /// The byte offset at which the next line starts.
    pub(crate) fn offset(&self) -> u64 {
        self.offset
    }

    pub(crate) fn label(&self) -> &'l str {
        self.label
    }

    /// The next line and its number, or `None` at the end of the file.
    pub(crate) fn next_line(&mut self) -> Result<Option<(usize, &str)>, String> {
        self.bytes.clear();
        let limit = MAX_LINE_BYTES as u64 + 1;
        let read = (&mut self.reader)
            .take(limit)
            .read_until(b'\n', &mut self.bytes)
            .map_err(|e| format!("{}: cannot read: {e}", self.label))?;
        if read == 0 {
            return Ok(None);
        }
        self.number += 1;
        self.offset += read as u64;
        let ended = self.bytes.last() == Some(&b'\n');
        if ended {
            self.bytes.pop();
        }
        self.text.clear();
        self.text.push_str(&String::from_utf8_lossy(&self.bytes));
        if !ended && self.bytes.len() > MAX_LINE_BYTES {
            let what = format!("a line of at most {MAX_LINE_BYTES} bytes");
            return Err(expected(self.label, self.number, &what, Some(&self.text)));
        }
        Ok(Some((self.number, &self.text)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn lines_keep_their_numbers_and_bad_bytes_become_replacement_characters() {
        let mut lines = Lines::new(&b"a\r\n\nb\xffc"[..], "m.in");
        assert_eq!(lines.next_line().unwrap(), Some((1, "a\r")));
        assert_eq!(lines.offset(), 3);
        assert_eq!(lines.next_line().unwrap(), Some((2, "")));
        assert_eq!(lines.offset(), 4);
        assert_eq!(lines.next_line().unwrap(), Some((3, "b\u{fffd}c")));
        assert_eq!(lines.next_line().unwrap(), None);
    }

    #[test]
    fn a_line_past_the_limit_is_an_error_at_its_line() {
        let text = format!("ok\n{}", "9".repeat(MAX_LINE_BYTES + 5));
        let mut lines = Lines::new(text.as_bytes(), "m.in");
        lines.next_line().unwrap();
        let error = lines.next_line().unwrap_err();
        assert!(
            error.starts_with("m.in:2: expected 'a line of at most 1048576 bytes', found '999"),
            "{error}"
        );
    }
}

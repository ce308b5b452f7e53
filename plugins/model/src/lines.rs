//! A model file's lines, read one at a time so that a big file never sits in memory whole.

use std::io::{self, BufRead, Read};

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

    /// The lines as a reader again, each ending in `\n`, and each passed to `check` first: what
    /// a parser of its own (tobj) reads, so that it reads only lines the checks saw and passed.
    pub(crate) fn into_reader<F>(self, check: F) -> LineReader<'l, R, F>
    where
        F: FnMut(usize, &str) -> Result<(), String>,
    {
        LineReader {
            lines: self,
            check,
            line: Vec::new(),
            at: 0,
            error: None,
        }
    }
}

/// See [`Lines::into_reader`]. Holds one line at a time.
pub(crate) struct LineReader<'l, R, F> {
    lines: Lines<'l, R>,
    check: F,
    line: Vec<u8>,
    /// How much of `line` has been consumed.
    at: usize,
    /// Why reading stopped, in the words of the checks or of [`Lines::next_line`]: the reader's
    /// own error (an `io::Error`) is all its caller's parser passes on.
    error: Option<String>,
}

impl<R, F> LineReader<'_, R, F> {
    /// Why reading stopped early, if it did.
    pub(crate) fn into_error(self) -> Option<String> {
        self.error
    }
}

impl<R: BufRead, F: FnMut(usize, &str) -> Result<(), String>> BufRead for LineReader<'_, R, F> {
    fn fill_buf(&mut self) -> io::Result<&[u8]> {
        if self.error.is_none() && self.at == self.line.len() {
            self.line.clear();
            self.at = 0;
            let next = self.lines.next_line().and_then(|line| match line {
                Some((number, text)) => (self.check)(number, text).map(|()| Some(text)),
                None => Ok(None),
            });
            match next {
                Ok(Some(text)) => {
                    self.line.extend_from_slice(text.as_bytes());
                    self.line.push(b'\n');
                }
                Ok(None) => {}
                Err(error) => self.error = Some(error),
            }
        }
        match &self.error {
            Some(error) => Err(io::Error::other(error.clone())),
            None => Ok(&self.line[self.at..]),
        }
    }

    fn consume(&mut self, amount: usize) {
        self.at = (self.at + amount).min(self.line.len());
    }
}

impl<R: BufRead, F: FnMut(usize, &str) -> Result<(), String>> Read for LineReader<'_, R, F> {
    fn read(&mut self, buf: &mut [u8]) -> io::Result<usize> {
        let available = self.fill_buf()?;
        let n = available.len().min(buf.len());
        buf[..n].copy_from_slice(&available[..n]);
        self.consume(n);
        Ok(n)
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
    fn the_reader_gives_back_the_lines_as_the_checks_saw_them() {
        let mut seen = Vec::new();
        let mut reader =
            Lines::new(&b"v 1\r\nf\xff 2\nlast"[..], "m.obj").into_reader(|n, line| {
                seen.push((n, line.to_string()));
                Ok(())
            });
        let mut text = String::new();
        reader.read_to_string(&mut text).unwrap();
        assert_eq!(text, "v 1\r\nf\u{fffd} 2\nlast\n");
        assert!(reader.into_error().is_none());
        assert_eq!(seen.len(), 3);
        assert_eq!(seen[1], (2, "f\u{fffd} 2".to_string()));
    }

    #[test]
    fn the_reader_stops_at_the_first_line_its_check_refuses_and_keeps_why() {
        let mut reader =
            Lines::new(&b"ok\nbad\nok\n"[..], "m.obj").into_reader(|n, line| match line {
                "bad" => Err(format!("m.obj:{n}: bad")),
                _ => Ok(()),
            });
        let mut text = String::new();
        let error = reader.read_to_string(&mut text).unwrap_err();
        assert_eq!(error.to_string(), "m.obj:2: bad");
        assert_eq!(text, "ok\n");
        assert_eq!(reader.into_error().as_deref(), Some("m.obj:2: bad"));
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

//! The words of a model file's lines as `str::split_whitespace` sees them, read from the bytes
//! without making a `str` of each line first.

/// The ASCII bytes `char::is_whitespace` takes for space, as `str::trim` and
/// `str::split_whitespace` do in the line readers.
pub(crate) fn is_space(b: u8) -> bool {
    matches!(b, b'\t' | b'\n' | 0x0b | 0x0c | b'\r' | b' ')
}

pub(crate) fn trim(line: &[u8]) -> &[u8] {
    let start = line
        .iter()
        .position(|&b| !is_space(b))
        .unwrap_or(line.len());
    let end = line
        .iter()
        .rposition(|&b| !is_space(b))
        .map_or(start, |i| i + 1);
    &line[start..end]
}

/// The words of ASCII text: its runs of bytes other than spaces.
pub(crate) struct Words<'t>(pub(crate) &'t [u8]);

impl<'t> Iterator for Words<'t> {
    type Item = &'t [u8];

    fn next(&mut self) -> Option<&'t [u8]> {
        let start = self.0.iter().position(|&b| !is_space(b))?;
        let rest = &self.0[start..];
        let end = rest.iter().position(|&b| is_space(b)).unwrap_or(rest.len());
        self.0 = &rest[end..];
        Some(&rest[..end])
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn words_are_split_as_split_whitespace_splits_them() {
        for line in ["", "  ", "v 1\t2 \x0b3\r"] {
            let ours: Vec<&[u8]> = Words(line.as_bytes()).collect();
            let std: Vec<&[u8]> = line.split_whitespace().map(str::as_bytes).collect();
            assert_eq!(ours, std, "{line:?}");
        }
        assert_eq!(trim(b" \tv 1\r"), b"v 1");
    }
}

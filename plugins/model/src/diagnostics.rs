//! The one shape every line-precise load error has:
//! `path:line: expected '<what>', found '<the line>'`.

use close2gl_core::excerpt;

pub(crate) fn expected(label: &str, line: usize, what: &str, found: Option<&str>) -> String {
    match found {
        Some(text) => format!(
            "{label}:{line}: expected '{what}', found '{}'",
            excerpt(text)
        ),
        None => format!("{label}:{line}: expected '{what}', found end of file"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn long_lines_are_cut_and_control_characters_replaced() {
        let line = format!("  v0 1\r\t2 {}", "9".repeat(100));
        let message = expected("m.in", 3, "v0 x", Some(&line));
        assert!(message.starts_with("m.in:3: expected 'v0 x', found 'v0 1??2 999"));
        assert!(message.ends_with("…'"));
        assert!(!message.contains('\n') && !message.contains('\r'));
    }

    #[test]
    fn end_of_file_is_named() {
        assert_eq!(
            expected("m.in", 9, "face normal nx ny nz", None),
            "m.in:9: expected 'face normal nx ny nz', found end of file"
        );
    }
}

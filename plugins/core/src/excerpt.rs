//! How a load error quotes the text it refused: one excerpt rule for every file format close2gl
//! reads (models, scenes, traces), so that their errors look alike.

/// Longest excerpt of the offending text an error quotes.
pub const EXCERPT_CHARS: usize = 60;

/// `text` trimmed, cut to a readable length, with control characters replaced, so that an error
/// stays on one line whatever bytes the file held.
pub fn excerpt(text: &str) -> String {
    let text = text.trim();
    let mut out: String = text
        .chars()
        .take(EXCERPT_CHARS)
        .map(|c| if c.is_control() { '?' } else { c })
        .collect();
    if text.chars().nth(EXCERPT_CHARS).is_some() {
        out.push('…');
    }
    out
}

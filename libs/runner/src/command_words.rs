//! The teacher's command line, as words. It is split as a POSIX shell would split it (quotes and
//! backslashes; `shlex` does it) but never given to a shell, so a scene path with spaces or a
//! student's file name with `$` in it is passed as it is, and nothing in it is expanded.

/// Splits `command` into words the way a POSIX shell does: single and double quotes, backslash
/// escapes, `#` comments. Variables, globs, pipes and redirections are not interpreted: `>`
/// is passed as a word. An unterminated quote, a trailing backslash or an empty command is an
/// error naming the command.
pub fn split_words(command: &str) -> Result<Vec<String>, String> {
    let Some(words) = shlex::split(command) else {
        return Err(format!(
            "the command `{command}` has an unterminated quote or a trailing backslash"
        ));
    };
    if words.is_empty() {
        return Err("the command is empty".to_string());
    }
    Ok(words)
}

/// Replaces every `{name}` in every word with its value, also inside a word
/// (`--out={trace}`), each word on its own: a value never becomes several words, and a value
/// that itself contains `{name}` is not substituted again. Unknown `{...}` stays as written.
pub fn substitute(words: &[String], values: &[(&str, &str)]) -> Vec<String> {
    words
        .iter()
        .map(|word| substitute_word(word, values))
        .collect()
}

fn substitute_word(word: &str, values: &[(&str, &str)]) -> String {
    let mut out = String::with_capacity(word.len());
    let mut rest = word;
    'scan: while let Some(next) = rest.chars().next() {
        for (name, value) in values {
            let after = rest
                .strip_prefix('{')
                .and_then(|r| r.strip_prefix(name))
                .and_then(|r| r.strip_prefix('}'));
            if let Some(after) = after {
                out.push_str(value);
                rest = after;
                continue 'scan;
            }
        }
        out.push(next);
        rest = &rest[next.len_utf8()..];
    }
    out
}

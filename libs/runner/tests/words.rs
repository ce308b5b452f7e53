//! The teacher's command line: split as a POSIX shell would, placeholders filled word by word.

use close2gl_runner::{split_words, substitute};

fn words(list: &[&str]) -> Vec<String> {
    list.iter().map(|word| word.to_string()).collect()
}

#[test]
fn quotes_and_escapes_split_as_a_shell_splits() {
    let split = split_words(r#"python3 'my dir/main.py' "a \"b\" c" d\ e {scene} --out={trace}"#);
    assert_eq!(
        split,
        Ok(words(&[
            "python3",
            "my dir/main.py",
            r#"a "b" c"#,
            "d e",
            "{scene}",
            "--out={trace}",
        ]))
    );
}

#[test]
fn nothing_is_expanded_or_interpreted() {
    let split = split_words("prog $HOME * > out.txt; rm -rf x");
    assert_eq!(
        split,
        Ok(words(&[
            "prog", "$HOME", "*", ">", "out.txt;", "rm", "-rf", "x"
        ]))
    );
}

#[test]
fn an_unterminated_quote_or_an_empty_command_is_an_error() {
    let error = split_words("prog 'scene.in").expect_err("unterminated quote");
    assert!(error.contains("unterminated quote"), "{error}");
    assert!(error.contains("prog 'scene.in"), "{error}");
    assert!(split_words(r"prog \").is_err());
    assert_eq!(split_words("   "), Err("the command is empty".to_string()));
}

#[test]
fn placeholders_are_replaced_inside_words_and_never_split_or_rescanned() {
    let command = words(&["prog", "{scene}", "--out={trace}", "{other}", "{{scene}}"]);
    let values = [("scene", "/tmp/a b/{trace}.in"), ("trace", "/tmp/t.json")];
    assert_eq!(
        substitute(&command, &values),
        words(&[
            "prog",
            "/tmp/a b/{trace}.in",
            "--out=/tmp/t.json",
            "{other}",
            "{/tmp/a b/{trace}.in}",
        ])
    );
}

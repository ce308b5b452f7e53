//! The scene reader (`close2gl_trace_format::parse_scene`), fed any bytes that are UTF-8 (as
//! `read_scene` hands it a file's text). It must never panic; an error is one line naming the
//! file; `\r\n` line ends change nothing, errors included; and a scene it reads writes back as
//! text that reads back to the very same scene, and to the same text again (equal texts mean
//! equal bits: `==` on floats would let -0 pass for 0).
#![no_main]

use close2gl_trace_format::parse_scene;
use libfuzzer_sys::fuzz_target;

const LABEL: &str = "fuzz.scene";

fuzz_target!(|bytes: &[u8]| {
    let Ok(text) = std::str::from_utf8(bytes) else {
        return;
    };
    let result = parse_scene(text, LABEL);
    if !text.contains('\r') {
        let crlf = parse_scene(&text.replace('\n', "\r\n"), LABEL);
        assert_eq!(crlf, result, "\\r\\n line ends change the outcome");
    }
    match result {
        Ok(scene) => {
            let written = scene.to_text();
            let back = parse_scene(&written, LABEL)
                .unwrap_or_else(|e| panic!("a scene read does not read back: {e}\n{written}"));
            assert_eq!(back, scene, "a scene read back differs");
            assert_eq!(back.to_text(), written, "a scene written twice differs");
        }
        Err(error) => {
            let message = error.to_string();
            assert!(
                message.starts_with("fuzz.scene:"),
                "an error not naming the file: {message:?}"
            );
            assert!(
                !message.contains(['\n', '\r']),
                "an error of several lines: {message:?}"
            );
        }
    }
});

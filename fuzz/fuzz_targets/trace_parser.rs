//! The trace reader (`close2gl_trace_format::parse_trace`), fed any bytes that are UTF-8 (as
//! `read_trace` hands it a file's text). It must never panic; an error is one line naming the
//! file; `\r\n` line ends change nothing, errors included; and a trace it reads writes back as
//! text that reads back to the same trace but for the line numbers, which become the written
//! text's. "The same" is judged by writing it again: every number is written in its shortest
//! round-trip spelling, so equal texts mean equal bits, where `==` on floats would let -0 pass
//! for 0.
#![no_main]

use close2gl_trace_format::parse_trace;
use libfuzzer_sys::fuzz_target;

const LABEL: &str = "fuzz.trace";

fuzz_target!(|bytes: &[u8]| {
    let Ok(text) = std::str::from_utf8(bytes) else {
        return;
    };
    let result = parse_trace(text, LABEL);
    if !text.contains('\r') {
        let crlf = parse_trace(&text.replace('\n', "\r\n"), LABEL);
        assert_eq!(crlf, result, "\\r\\n line ends change the outcome");
    }
    match result {
        Ok(trace) => {
            let written = trace.to_text();
            let back = parse_trace(&written, LABEL)
                .unwrap_or_else(|e| panic!("a trace read does not read back: {e}\n{written}"));
            assert_eq!(back.to_text(), written, "a trace read back differs");
        }
        Err(error) => {
            let message = error.to_string();
            assert!(
                message.starts_with("fuzz.trace:"),
                "an error not naming the file: {message:?}"
            );
            assert!(
                !message.contains(['\n', '\r']),
                "an error of several lines: {message:?}"
            );
        }
    }
});

//! The Wavefront `.obj` loader (the line checks, tobj, smooth normals, the mesh builder), fed
//! exactly as the app feeds it a file: any bytes, made UTF-8 with `from_utf8_lossy`, then
//! `parse_obj`. It must never panic, a mesh it accepts must be whole, and `\r\n` line ends
//! must not change the outcome.
#![no_main]

use libfuzzer_sys::fuzz_target;

fuzz_target!(|bytes: &[u8]| {
    let text = String::from_utf8_lossy(bytes);
    let parse = |text: &str| close2gl_model::parse_obj(text, "fuzz.obj");
    let result = parse(&text);
    close2gl_fuzz::check_line_ends(parse, &text, &result);
    close2gl_fuzz::check_model(result, "fuzz.obj");
});

//! The view as a link: the page's fragment holds the model and the settings, `#model=cube.in&
//! camera.hfov=45&render.clipping="simple"`, keys and values exactly as `--set` and copy as
//! command write them, each percent-encoded. `model` names a bundled model (or a primitive).

/// What a link's fragment asks for.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Link {
    /// The `model` item: a bundled model's file name, or a primitive's name.
    pub model: Option<String>,
    /// Every other item, `section.key=value`, in the link's order (for `--set`).
    pub settings: Vec<String>,
}

/// Reads a fragment (with or without its `#`). An item that is not `key=value`, or whose
/// percent-encoding is broken, is an error naming it and what was expected.
pub fn parse(fragment: &str) -> Result<Link, String> {
    let mut link = Link::default();
    let fragment = fragment.strip_prefix('#').unwrap_or(fragment);
    for (n, item) in fragment.split('&').filter(|i| !i.is_empty()).enumerate() {
        let item = decode(item).map_err(|e| format!("the link's item {}: {e}", n + 1))?;
        match item.split_once('=') {
            Some(("model", name)) if !name.is_empty() => link.model = Some(name.to_string()),
            Some((key, _)) if key.contains('.') => link.settings.push(item),
            _ => {
                return Err(format!(
                    "the link's item {} \"{item}\": expected model=NAME or section.key=value",
                    n + 1
                ));
            }
        }
    }
    Ok(link)
}

/// The fragment (without `#`) for `model` and `settings` (`("section.key", "value")` each, as
/// `close2gl_config::keys::pixel_keys` gives them).
pub fn write(model: &str, settings: &[(String, String)]) -> String {
    let mut items = vec![format!("model={}", encode(model))];
    items.extend(
        settings
            .iter()
            .map(|(key, value)| format!("{}={}", encode(key), encode(value))),
    );
    items.join("&")
}

/// Percent-encodes all but the characters a fragment keeps as they are and a reader reads
/// easily (letters, digits, `-._~` and `,`).
fn encode(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for byte in text.bytes() {
        match byte {
            b'A'..=b'Z' | b'a'..=b'z' | b'0'..=b'9' | b'-' | b'.' | b'_' | b'~' | b',' => {
                out.push(byte as char)
            }
            _ => out.push_str(&format!("%{byte:02X}")),
        }
    }
    out
}

fn decode(text: &str) -> Result<String, String> {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        match bytes[i] {
            b'%' => {
                let hex = text.get(i + 1..i + 3).filter(|h| h.len() == 2);
                let byte = hex.and_then(|h| u8::from_str_radix(h, 16).ok());
                out.push(byte.ok_or_else(|| {
                    format!(
                        "expected two hexadecimal digits after % at character {}",
                        i + 1
                    )
                })?);
                i += 3;
            }
            // A link typed by hand may say + for a space, as forms do.
            b'+' => {
                out.push(b' ');
                i += 1;
            }
            byte => {
                out.push(byte);
                i += 1;
            }
        }
    }
    String::from_utf8(out).map_err(|_| "expected UTF-8 text once decoded".to_string())
}

/// Whether the page's query (`?embed=1&test=1`, with or without `?`) sets `flag` to 1 or true.
pub fn query_flag(query: &str, flag: &str) -> bool {
    let query = query.strip_prefix('?').unwrap_or(query);
    query.split('&').any(|item| match item.split_once('=') {
        Some((key, value)) => key == flag && (value == "1" || value == "true"),
        None => item == flag,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_link_reads_back_what_was_written() {
        let settings = [
            ("camera.hfov", "45"),
            ("render.clipping", "\"simple\""),
            ("camera.position", "[0.5,-1e-7,3]"),
            ("input.orbit_left", "\"shift+a & b\""),
        ]
        .map(|(k, v)| (k.to_string(), v.to_string()));
        let fragment = write("cube.in", &settings);
        assert!(!fragment.contains(['"', '[', ' ', '#']), "{fragment}");
        assert!(
            fragment.starts_with("model=cube.in&camera.hfov=45&"),
            "{fragment}"
        );
        let link = parse(&format!("#{fragment}")).unwrap();
        assert_eq!(link.model.as_deref(), Some("cube.in"));
        let items: Vec<String> = settings.iter().map(|(k, v)| format!("{k}={v}")).collect();
        assert_eq!(link.settings, items);
    }

    #[test]
    fn a_hand_written_link_is_read_and_a_broken_one_named() {
        let link = parse("#model=torus&camera.hfov=45&render.clipping=%22simple%22").unwrap();
        assert_eq!(link.model.as_deref(), Some("torus"));
        assert_eq!(
            link.settings,
            ["camera.hfov=45", "render.clipping=\"simple\""]
        );
        assert_eq!(parse("").unwrap(), Link::default());
        let bad = parse("#model=cube.in&camera.hfov=%4").unwrap_err();
        assert!(
            bad.contains("item 2") && bad.contains("hexadecimal"),
            "{bad}"
        );
        let bad = parse("#hfov").unwrap_err();
        assert!(
            bad.contains("expected model=NAME or section.key=value"),
            "{bad}"
        );
        assert!(parse("#camera.hfov=%FF").unwrap_err().contains("UTF-8"));
    }

    #[test]
    fn query_flags() {
        assert!(query_flag("?embed=1", "embed"));
        assert!(query_flag("?test=1&embed=true", "embed"));
        assert!(query_flag("test", "test"));
        assert!(!query_flag("?embed=0", "embed"));
        assert!(!query_flag("", "embed"));
    }
}

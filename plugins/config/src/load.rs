//! Reading a config file and the `--set` overrides into a checked [`Config`](super::Config):
//! errors name the file and line, or the key, and what was expected.

use std::path::{Path, PathBuf};

use close2gl_core::limits::MAX_PIXELS;
use toml::{Table, Value};

use super::{Config, keys};

/// Reads the configuration: `file` if given, else `./config.toml` if present, else the defaults;
/// then applies each `section.key=value` override in order. Errors name the file and line or the
/// key, and what was expected there.
pub fn load(file: Option<&Path>, overrides: &[String]) -> Result<Config, String> {
    let Some(file) = file_to_read(file) else {
        // No file: the defaults, which an empty file gives as well.
        return load_text("", "", Path::new("."), overrides);
    };
    let name = file.display().to_string();
    let text = std::fs::read_to_string(&file).map_err(|e| format!("{name}: cannot read: {e}"))?;
    load_text(
        &text,
        &name,
        file.parent().unwrap_or(Path::new(".")),
        overrides,
    )
}

/// The file [`load`] reads: `file` if given, else `./config.toml` if present.
pub fn file_to_read(file: Option<&Path>) -> Option<PathBuf> {
    file.map(Path::to_path_buf).or_else(|| {
        let local = PathBuf::from("config.toml");
        local.is_file().then_some(local)
    })
}

/// What [`load`] makes of a config file's `text` and then the overrides, without reading a file:
/// `name` labels errors, `base` is where relative paths start. The fuzzer's door into the parser.
pub fn load_text(
    text: &str,
    name: &str,
    base: &Path,
    overrides: &[String],
) -> Result<Config, String> {
    let mut config = Config::default();
    // Keys, values and --set items are quoted as typed: a control character in them (a newline
    // in a quoted TOML key or in a shell argument) must not break the error's one line.
    let one_line = |e: String| e.replace(|c: char| c.is_control(), "?");
    apply_text(&mut config, text, name, base).map_err(one_line)?;
    for item in overrides {
        apply_override(&mut config, item).map_err(one_line)?;
    }
    check(&config).map_err(one_line)?;
    Ok(config)
}

fn apply_text(config: &mut Config, text: &str, name: &str, base: &Path) -> Result<(), String> {
    let table: Table = text.parse().map_err(|e: toml::de::Error| {
        let line = e
            .span()
            .map(|s| text[..s.start].lines().count().max(1))
            .unwrap_or(1);
        format!("{name}:{line}: {}", e.message())
    })?;
    for (section, body) in &table {
        let Value::Table(body) = body else {
            return Err(format!("{name}: {section}: expected a [{section}] section"));
        };
        for (key, value) in body {
            keys::set(config, section, key, value, base)
                .map_err(|e| format!("{name}: {section}.{key}: {e}"))?;
        }
    }
    Ok(())
}

/// `section.key=value`, the value parsed as TOML; a bare word is taken as a string.
fn apply_override(config: &mut Config, item: &str) -> Result<(), String> {
    let malformed = || format!("--set {item}: expected section.key=value");
    let (path, raw) = item.split_once('=').ok_or_else(malformed)?;
    let (section, key) = path.trim().split_once('.').ok_or_else(malformed)?;
    let value = format!("v = {raw}")
        .parse::<Table>()
        .ok()
        .and_then(|mut t| t.remove("v"))
        .unwrap_or_else(|| Value::String(raw.trim().to_string()));
    keys::set(config, section, key, &value, Path::new("."))
        .map_err(|e| format!("--set {section}.{key}: {e}"))
}

/// Rules that tie two keys together.
fn check(config: &Config) -> Result<(), String> {
    let camera = &config.camera;
    if let (Some(near), Some(far)) = (camera.near, camera.far)
        && near >= far
    {
        return Err(format!(
            "camera.near: expected a distance below camera.far ({far}), found {near}"
        ));
    }
    let given = [camera.u, camera.v, camera.n].iter().flatten().count();
    if given != 0 && given != 3 {
        return Err("camera.u: expected camera.u, camera.v and camera.n together".into());
    }
    if given == 3 && camera.position.is_none() {
        return Err("camera.u: expected camera.position with camera.u, v and n".into());
    }
    if let Some(pose) = camera.pose() {
        let view = pose.target - pose.position;
        if view.length_squared() == 0.0 {
            return Err("camera.target: expected a point other than camera.position".into());
        }
        if pose.basis.is_none() && view.cross(pose.up).length_squared() == 0.0 {
            return Err(
                "camera.up: expected a direction not parallel to the view direction".into(),
            );
        }
    }
    Ok(())
}

/// `WxH` → (width, height), each in 1..=[`MAX_PIXELS`].
pub fn parse_size(text: &str) -> Result<(u32, u32), String> {
    let bad =
        || format!("--size {text}: expected WIDTHxHEIGHT, each 1..={MAX_PIXELS}, e.g. 800x600");
    let (w, h) = text.split_once(['x', 'X']).ok_or_else(bad)?;
    let w: u32 = w.trim().parse().map_err(|_| bad())?;
    let h: u32 = h.trim().parse().map_err(|_| bad())?;
    if (1..=MAX_PIXELS).contains(&w) && (1..=MAX_PIXELS).contains(&h) {
        Ok((w, h))
    } else {
        Err(bad())
    }
}

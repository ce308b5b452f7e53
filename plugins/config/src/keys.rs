//! Every config key: its type, its range, where it lands in [`Config`], and how the copied
//! command writes it. One table, so that the file, `--set` overrides, the error messages and
//! copy-as-command cannot disagree.

use std::ops::RangeInclusive;
use std::path::Path;

use close2gl_core::glam::Vec3;
use close2gl_core::limits::{
    FOV_RANGE, MAX_PIXELS, MAX_SEGMENTS, MOVE_SPEED_RANGE, ROTATE_SPEED_RANGE,
};
use close2gl_core::{Action, ModelSource, NamedEnum, OutsideView, Overlay, STAGE_NAMES};
use toml::Value;

use super::Config;

/// One key of the configuration: where it lands in [`Config`] and how its value is checked (the
/// file and `--set` read it through [`set`]), and, for the keys that decide the views' pixels, how
/// the copied `close2gl render` command writes it back ([`pixel_keys`]). One table, so that
/// reading and writing cannot drift apart.
pub struct Key {
    pub section: &'static str,
    pub name: &'static str,
    read: Read,
    pub write: Write,
}

/// Stores a checked value; `base` is the directory relative paths start from.
type Read = fn(&mut Config, &Value, &Path) -> Result<(), String>;

/// Whether and how a key is written into the copied command.
#[derive(Clone, Copy)]
pub enum Write {
    /// Not a property of the views' pixels (the window, the speeds, the framing rules), or
    /// written another way (the model, as the command's argument).
    Never,
    /// Always: the pose and the lens, to the bit, so that the command's images are the view's.
    Always(fn(&Config) -> Option<String>),
    /// Only when it differs from the default, so that the line stays readable.
    IfChanged(fn(&Config) -> Option<String>),
}

macro_rules! key {
    ($section:literal . $name:literal, |$c:ident, $v:ident, $base:ident| $read:expr, $write:expr) => {
        Key {
            section: $section,
            name: $name,
            read: |$c, $v, $base| {
                $read;
                Ok(())
            },
            write: $write,
        }
    };
}

use Write::{Always, IfChanged, Never};

/// Every key but `[input]`'s, whose names are the actions' (`Action`).
pub const KEYS: &[Key] = &[
    key!("model"."path", |c, v, base| c.model = ModelSource::File(base.join(string(v)?)), Never),
    key!("model"."primitive", |c, v, _b| c.model = ModelSource::Primitive(named(v)?), Never),
    key!("model"."texture", |c, v, base| c.texture = Some(base.join(string(v)?)),
        IfChanged(|c| c.texture.as_deref().map(|t| quoted(&absolute(t).display().to_string())))),
    key!("camera"."position", |c, v, _b| c.camera.position = Some(vec3(v)?),
        Always(|c| c.camera.position.map(list3))),
    key!("camera"."target", |c, v, _b| c.camera.target = Some(vec3(v)?),
        Always(|c| c.camera.target.map(list3))),
    key!("camera"."up", |c, v, _b| c.camera.up = nonzero(vec3(v)?)?, Never),
    key!("camera"."u", |c, v, _b| c.camera.u = Some(nonzero(vec3(v)?)?),
        Always(|c| c.camera.u.map(list3))),
    key!("camera"."v", |c, v, _b| c.camera.v = Some(nonzero(vec3(v)?)?),
        Always(|c| c.camera.v.map(list3))),
    key!("camera"."n", |c, v, _b| c.camera.n = Some(nonzero(vec3(v)?)?),
        Always(|c| c.camera.n.map(list3))),
    key!("camera"."hfov", |c, v, _b| c.camera.hfov = fov(v)?,
        Always(|c| Some(exact(c.camera.hfov)))),
    key!("camera"."vfov", |c, v, _b| c.camera.vfov = fov(v)?,
        Always(|c| Some(exact(c.camera.vfov)))),
    key!("camera"."near", |c, v, _b| c.camera.near = Some(positive(v)?),
        Always(|c| c.camera.near.map(exact))),
    key!("camera"."far", |c, v, _b| c.camera.far = Some(positive(v)?),
        Always(|c| c.camera.far.map(exact))),
    key!("camera"."mode", |c, v, _b| c.camera.mode = named(v)?, Never),
    key!("camera"."move_speed", |c, v, _b| c.camera.speeds.move_speed = within(v, MOVE_SPEED_RANGE)?,
        Never),
    key!("camera"."rotate_speed", |c, v, _b| c.camera.speeds.rotate_speed = within(v, ROTATE_SPEED_RANGE)?,
        Never),
    key!("render"."mode", |c, v, _b| c.render.pipeline.mode = named(v)?,
        IfChanged(|c| name(c.render.pipeline.mode))),
    key!("render"."front_face", |c, v, _b| c.render.pipeline.front_face = named(v)?,
        IfChanged(|c| name(c.render.pipeline.front_face))),
    key!("render"."backface_culling",
        |c, v, _b| c.render.pipeline.backface_culling = boolean(v)?,
        IfChanged(|c| flag(c.render.pipeline.backface_culling))),
    key!("render"."clipping", |c, v, _b| c.render.pipeline.clipping = named(v)?,
        IfChanged(|c| name(c.render.pipeline.clipping))),
    key!("render"."color", |c, v, _b| c.render.appearance.color = color(v)?,
        IfChanged(|c| Some(list3(c.render.appearance.color)))),
    key!("render"."shading", |c, v, _b| c.render.appearance.shading = named(v)?,
        IfChanged(|c| name(c.render.appearance.shading))),
    key!("render"."background", |c, v, _b| c.render.appearance.background = color(v)?,
        IfChanged(|c| Some(list3(c.render.appearance.background)))),
    key!("render"."close2gl_raster",
        |c, v, _b| c.render.pipeline.close2gl_raster = named(v)?,
        IfChanged(|c| name(c.render.pipeline.close2gl_raster))),
    key!("render"."texture", |c, v, _b| c.render.appearance.texture = boolean(v)?,
        IfChanged(|c| flag(c.render.appearance.texture))),
    key!("render"."texture_filter",
        |c, v, _b| c.render.appearance.texture_filter = named(v)?,
        IfChanged(|c| name(c.render.appearance.texture_filter))),
    key!("render"."overlay", |c, v, _b| c.render.overlay = overlay(v)?,
        IfChanged(|c| name(c.render.overlay))),
    key!("render"."mistake", |c, v, _b| c.render.pipeline.mistake = named(v)?,
        IfChanged(|c| name(c.render.pipeline.mistake))),
    key!("render"."raster_mistake",
        |c, v, _b| c.render.appearance.raster_mistake = named(v)?,
        IfChanged(|c| name(c.render.appearance.raster_mistake))),
    key!("lighting"."light_position", |c, v, _b| c.lighting.light_position = vec3(v)?,
        IfChanged(|c| Some(list3(c.lighting.light_position)))),
    key!("lighting"."ia", |c, v, _b| c.lighting.ia = color(v)?,
        IfChanged(|c| Some(list3(c.lighting.ia)))),
    key!("lighting"."il", |c, v, _b| c.lighting.il = color(v)?,
        IfChanged(|c| Some(list3(c.lighting.il)))),
    key!("lighting"."ka", |c, v, _b| c.lighting.ka = unit(v)?,
        IfChanged(|c| Some(exact(c.lighting.ka)))),
    key!("lighting"."kd", |c, v, _b| c.lighting.kd = unit(v)?,
        IfChanged(|c| Some(exact(c.lighting.kd)))),
    key!("lighting"."ks", |c, v, _b| c.lighting.ks = unit(v)?,
        IfChanged(|c| Some(exact(c.lighting.ks)))),
    key!("lighting"."shininess", |c, v, _b| c.lighting.shininess = non_negative(v)?,
        IfChanged(|c| Some(exact(c.lighting.shininess)))),
    key!("lighting"."attenuation", |c, v, _b| c.lighting.attenuation = attenuation(v)?,
        IfChanged(|c| Some(list(&c.lighting.attenuation)))),
    key!("primitives"."box_size", |c, v, _b| c.primitives.box_size = positive_vec3(v)?,
        IfChanged(|c| Some(list3(c.primitives.box_size)))),
    key!("primitives"."sphere_radius", |c, v, _b| c.primitives.sphere_radius = positive(v)?,
        IfChanged(|c| Some(exact(c.primitives.sphere_radius)))),
    key!("primitives"."sphere_stacks", |c, v, _b| c.primitives.sphere_stacks = count(v, 2)?,
        IfChanged(|c| Some(c.primitives.sphere_stacks.to_string()))),
    key!("primitives"."sphere_slices", |c, v, _b| c.primitives.sphere_slices = count(v, 3)?,
        IfChanged(|c| Some(c.primitives.sphere_slices.to_string()))),
    key!("primitives"."torus_r0", |c, v, _b| c.primitives.torus_r0 = positive(v)?,
        IfChanged(|c| Some(exact(c.primitives.torus_r0)))),
    key!("primitives"."torus_r1", |c, v, _b| c.primitives.torus_r1 = positive(v)?,
        IfChanged(|c| Some(exact(c.primitives.torus_r1)))),
    key!("primitives"."torus_n0", |c, v, _b| c.primitives.torus_n0 = count(v, 3)?,
        IfChanged(|c| Some(c.primitives.torus_n0.to_string()))),
    key!("primitives"."torus_n1", |c, v, _b| c.primitives.torus_n1 = count(v, 3)?,
        IfChanged(|c| Some(c.primitives.torus_n1.to_string()))),
    key!("primitives"."cone_radius", |c, v, _b| c.primitives.cone_radius = positive(v)?,
        IfChanged(|c| Some(exact(c.primitives.cone_radius)))),
    key!("primitives"."cone_height", |c, v, _b| c.primitives.cone_height = positive(v)?,
        IfChanged(|c| Some(exact(c.primitives.cone_height)))),
    key!("primitives"."cone_slices", |c, v, _b| c.primitives.cone_slices = count(v, 3)?,
        IfChanged(|c| Some(c.primitives.cone_slices.to_string()))),
    key!("primitives"."cylinder_radius", |c, v, _b| c.primitives.cylinder_radius = positive(v)?,
        IfChanged(|c| Some(exact(c.primitives.cylinder_radius)))),
    key!("primitives"."cylinder_height", |c, v, _b| c.primitives.cylinder_height = positive(v)?,
        IfChanged(|c| Some(exact(c.primitives.cylinder_height)))),
    key!("primitives"."cylinder_slices", |c, v, _b| c.primitives.cylinder_slices = count(v, 3)?,
        IfChanged(|c| Some(c.primitives.cylinder_slices.to_string()))),
    key!("window"."width", |c, v, _b| c.window.width = pixels(v)?, Never),
    key!("window"."height", |c, v, _b| c.window.height = pixels(v)?, Never),
    key!("window"."layout", |c, v, _b| c.window.layout = named(v)?, Never),
    key!("outside"."show", |c, v, _b| c.outside.show = boolean(v)?,
        IfChanged(|c| flag(c.outside.show))),
    key!("outside"."stage", |c, v, _b| c.outside.stage = stage(v)?,
        IfChanged(|c| Some(exact(c.outside.stage)))),
];

/// Sets `section.key` from a TOML value. `base` is the directory relative model paths start from.
/// The error says what was expected, without the key (the caller adds file and key).
pub fn set(
    config: &mut Config,
    section: &str,
    key: &str,
    value: &Value,
    base: &Path,
) -> Result<(), String> {
    if section == "input" {
        let action = Action::from_name(key).ok_or("unknown key")?;
        let name = string(value)?;
        if name.is_empty() {
            return Err("expected a key name such as \"w\" or \"shift+p\"".into());
        }
        config.input.0.insert(action, name.to_lowercase());
        return Ok(());
    }
    let row = KEYS
        .iter()
        .find(|k| k.section == section && k.name == key)
        .ok_or("unknown key")?;
    (row.read)(config, value, base)
}

/// Every key that decides the views' pixels with its value as the configuration reads it
/// (`("camera.hfov", "60.0")`), in the table's order: the pose and the lens always, the rest where
/// they differ from the defaults; the primitives' sizes only for a primitive's own view. The model
/// is not among them: it is the command's argument. Copy as command writes each as
/// `--set key=value`.
pub fn pixel_keys(config: &Config) -> Vec<(String, String)> {
    pixel_keys_from(config, &Config::default())
}

/// [`pixel_keys`] against `base` instead of the defaults: what `--set` must change of `base` to
/// show `config` (the web page's link, whose base is its `config.toml`).
pub fn pixel_keys_from(config: &Config, base: &Config) -> Vec<(String, String)> {
    let default = base;
    let primitive = matches!(config.model, ModelSource::Primitive(_));
    KEYS.iter()
        .filter(|k| primitive || k.section != "primitives")
        .filter_map(|k| {
            let value = match k.write {
                Never => None,
                Always(write) => write(config),
                IfChanged(write) => write(config).filter(|v| Some(v) != write(default).as_ref()),
            }?;
            Some((format!("{}.{}", k.section, k.name), value))
        })
        .collect()
}

/// A number that reads back (as TOML's f64, then f32, as the config reads it) to the same
/// bits: the shortest form when that round-trips, else the f64 form, which always does.
pub fn exact(x: f32) -> String {
    let short = format!("{x:?}");
    if short.parse::<f64>().is_ok_and(|back| back as f32 == x) {
        short
    } else {
        format!("{:?}", x as f64)
    }
}

fn list(values: &[f32]) -> String {
    let items: Vec<String> = values.iter().map(|&x| exact(x)).collect();
    format!("[{}]", items.join(","))
}

fn list3(v: Vec3) -> String {
    list(&v.to_array())
}

fn name<T: NamedEnum>(value: T) -> Option<String> {
    Some(value.name().to_string())
}

fn flag(on: bool) -> Option<String> {
    Some(on.to_string())
}

/// A TOML basic string: backslashes and quotes escaped.
fn quoted(text: &str) -> String {
    format!("\"{}\"", text.replace('\\', "\\\\").replace('"', "\\\""))
}

/// The path as the command's reader's shell will find it from anywhere.
pub fn absolute(path: &Path) -> std::path::PathBuf {
    std::fs::canonicalize(path).unwrap_or_else(|_| path.to_path_buf())
}

fn number(value: &Value) -> Result<f32, String> {
    let x = match value {
        Value::Float(x) => *x,
        Value::Integer(i) => *i as f64,
        other => return Err(format!("expected a number, found {}", other.type_str())),
    };
    if x.is_finite() && x.abs() <= f32::MAX as f64 {
        Ok(x as f32)
    } else {
        Err(format!("expected a finite number, found {x}"))
    }
}

fn in_range(value: &Value, ok: impl Fn(f32) -> bool, range: &str) -> Result<f32, String> {
    let x = number(value)?;
    if ok(x) {
        Ok(x)
    } else {
        Err(format!("expected a number {range}, found {x}"))
    }
}

fn fov(value: &Value) -> Result<f32, String> {
    let range = format!("of degrees in {}..={}", FOV_RANGE.start(), FOV_RANGE.end());
    in_range(value, |x| FOV_RANGE.contains(&x), &range)
}

fn within(value: &Value, range: RangeInclusive<f32>) -> Result<f32, String> {
    let text = format!("in {}..={}", range.start(), range.end());
    in_range(value, |x| range.contains(&x), &text)
}

fn positive(value: &Value) -> Result<f32, String> {
    in_range(value, |x| x > 0.0, "> 0")
}

fn non_negative(value: &Value) -> Result<f32, String> {
    in_range(value, |x| x >= 0.0, ">= 0")
}

fn unit(value: &Value) -> Result<f32, String> {
    in_range(value, |x| (0.0..=1.0).contains(&x), "in 0..1")
}

fn integer(value: &Value, min: i64, max: i64) -> Result<u32, String> {
    match value {
        Value::Integer(i) if (min..=max).contains(i) => Ok(*i as u32),
        Value::Integer(i) => Err(format!("expected an integer in {min}..={max}, found {i}")),
        other => Err(format!("expected an integer, found {}", other.type_str())),
    }
}

fn count(value: &Value, min: i64) -> Result<u32, String> {
    integer(value, min, MAX_SEGMENTS.into())
}

fn pixels(value: &Value) -> Result<u32, String> {
    integer(value, 1, MAX_PIXELS.into())
}

fn boolean(value: &Value) -> Result<bool, String> {
    value
        .as_bool()
        .ok_or_else(|| format!("expected true or false, found {}", value.type_str()))
}

fn string(value: &Value) -> Result<&str, String> {
    value
        .as_str()
        .ok_or_else(|| format!("expected a string, found {}", value.type_str()))
}

fn named<T: NamedEnum>(value: &Value) -> Result<T, String> {
    let text = string(value)?;
    T::from_name(text).ok_or_else(|| {
        let names: Vec<String> = T::ALL.iter().map(|n| format!("\"{}\"", n.name())).collect();
        format!("expected one of {}, found \"{text}\"", names.join(", "))
    })
}

/// The overlay by name. "fates" was the fate view's name here before it had one name in the
/// config, the keys and the code; configs and recordings that say it still read.
fn overlay(value: &Value) -> Result<Overlay, String> {
    match string(value)? {
        "fates" => Ok(Overlay::FateView),
        _ => named(value),
    }
}

fn triple(
    value: &Value,
    item: impl Fn(&Value) -> Result<f32, String>,
    what: &str,
) -> Result<[f32; 3], String> {
    let wrong = || format!("expected {what}, found {value}");
    let array = value
        .as_array()
        .filter(|a| a.len() == 3)
        .ok_or_else(wrong)?;
    let mut out = [0.0; 3];
    for (slot, v) in out.iter_mut().zip(array) {
        *slot = item(v).map_err(|e| format!("{} ({e})", wrong()))?;
    }
    Ok(out)
}

/// A stage of the outside view as `--stage` gives it: a stop's name or a number.
pub fn parse_stage(text: &str) -> Result<f32, String> {
    let value = text
        .parse::<f64>()
        .map_or_else(|_| Value::String(text.into()), Value::Float);
    stage(&value)
}

/// A stage of the outside view: a number in 0..=2, or a stop's name.
fn stage(value: &Value) -> Result<f32, String> {
    let names: Vec<String> = STAGE_NAMES
        .iter()
        .map(|(n, _)| format!("\"{n}\""))
        .collect();
    let range = format!("in 0..=2 or one of {}", names.join(", "));
    match value {
        Value::String(name) => OutsideView::stage_named(name)
            .ok_or_else(|| format!("expected a number {range}, found \"{name}\"")),
        _ => in_range(
            value,
            |x| (0.0..=OutsideView::MAX_STAGE).contains(&x),
            &range,
        ),
    }
}

fn vec3(value: &Value) -> Result<Vec3, String> {
    triple(value, number, "[x, y, z]").map(Vec3::from)
}

fn positive_vec3(value: &Value) -> Result<Vec3, String> {
    triple(value, positive, "[x, y, z], each > 0").map(Vec3::from)
}

fn nonzero(v: Vec3) -> Result<Vec3, String> {
    if v.length_squared() > 0.0 {
        Ok(v)
    } else {
        Err("expected a non-zero vector".into())
    }
}

fn color(value: &Value) -> Result<Vec3, String> {
    triple(value, unit, "[r, g, b], each in 0..1").map(Vec3::from)
}

fn attenuation(value: &Value) -> Result<[f32; 3], String> {
    let a = triple(value, non_negative, "[c0, c1, c2], each >= 0")?;
    if a.iter().any(|&c| c > 0.0) {
        Ok(a)
    } else {
        Err("expected [c0, c1, c2] not all zero".into())
    }
}

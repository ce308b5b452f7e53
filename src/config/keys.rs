//! Every config key: its type, its range, and where it lands in [`Config`]. One table, so that
//! the file, `--set` overrides and the error messages cannot disagree.

use std::ops::RangeInclusive;
use std::path::Path;

use close2gl_core::glam::Vec3;
use close2gl_core::limits::{
    FOV_RANGE, MAX_PIXELS, MAX_SEGMENTS, MOVE_SPEED_RANGE, ROTATE_SPEED_RANGE,
};
use close2gl_core::{Action, ModelSource, NamedEnum, OutsideView, PrimitiveKind, STAGE_NAMES};
use toml::Value;

use super::Config;

/// Sets `section.key` from a TOML value. `base` is the directory relative model paths start from.
/// The error says what was expected, without the key (the caller adds file and key).
pub fn set(
    config: &mut Config,
    section: &str,
    key: &str,
    value: &Value,
    base: &Path,
) -> Result<(), String> {
    let c = config;
    match (section, key) {
        ("model", "path") => c.model = ModelSource::File(base.join(string(value)?)),
        ("model", "primitive") => {
            c.model = ModelSource::Primitive(named::<PrimitiveKind>(value)?);
        }
        ("model", "texture") => c.texture = Some(base.join(string(value)?)),

        ("camera", "position") => c.camera.position = Some(vec3(value)?),
        ("camera", "target") => c.camera.target = Some(vec3(value)?),
        ("camera", "up") => c.camera.up = nonzero(vec3(value)?)?,
        ("camera", "u") => c.camera.u = Some(nonzero(vec3(value)?)?),
        ("camera", "v") => c.camera.v = Some(nonzero(vec3(value)?)?),
        ("camera", "n") => c.camera.n = Some(nonzero(vec3(value)?)?),
        ("camera", "hfov") => c.camera.hfov = fov(value)?,
        ("camera", "vfov") => c.camera.vfov = fov(value)?,
        ("camera", "near") => c.camera.near = Some(positive(value)?),
        ("camera", "far") => c.camera.far = Some(positive(value)?),
        ("camera", "mode") => c.camera.mode = named(value)?,
        ("camera", "move_speed") => c.camera.speeds.move_speed = within(value, MOVE_SPEED_RANGE)?,
        ("camera", "rotate_speed") => {
            c.camera.speeds.rotate_speed = within(value, ROTATE_SPEED_RANGE)?;
        }

        ("render", "mode") => c.render.mode = named(value)?,
        ("render", "front_face") => c.render.front_face = named(value)?,
        ("render", "backface_culling") => c.render.backface_culling = boolean(value)?,
        ("render", "clipping") => c.render.clipping = named(value)?,
        ("render", "shading") => c.render.shading = named(value)?,
        ("render", "close2gl_raster") => c.render.close2gl_raster = named(value)?,
        ("render", "texture") => c.render.texture = boolean(value)?,
        ("render", "texture_filter") => c.render.texture_filter = named(value)?,
        ("render", "overlay") => c.render.overlay = named(value)?,
        ("render", "color") => c.render.color = color(value)?,
        ("render", "background") => c.render.background = color(value)?,

        ("lighting", "light_position") => c.lighting.light_position = vec3(value)?,
        ("lighting", "ia") => c.lighting.ia = color(value)?,
        ("lighting", "il") => c.lighting.il = color(value)?,
        ("lighting", "ka") => c.lighting.ka = unit(value)?,
        ("lighting", "kd") => c.lighting.kd = unit(value)?,
        ("lighting", "ks") => c.lighting.ks = unit(value)?,
        ("lighting", "shininess") => c.lighting.shininess = non_negative(value)?,
        ("lighting", "attenuation") => c.lighting.attenuation = attenuation(value)?,

        ("primitives", "box_size") => c.primitives.box_size = positive_vec3(value)?,
        ("primitives", "sphere_radius") => c.primitives.sphere_radius = positive(value)?,
        ("primitives", "sphere_stacks") => c.primitives.sphere_stacks = count(value, 2)?,
        ("primitives", "sphere_slices") => c.primitives.sphere_slices = count(value, 3)?,
        ("primitives", "torus_r0") => c.primitives.torus_r0 = positive(value)?,
        ("primitives", "torus_r1") => c.primitives.torus_r1 = positive(value)?,
        ("primitives", "torus_n0") => c.primitives.torus_n0 = count(value, 3)?,
        ("primitives", "torus_n1") => c.primitives.torus_n1 = count(value, 3)?,
        ("primitives", "cone_radius") => c.primitives.cone_radius = positive(value)?,
        ("primitives", "cone_height") => c.primitives.cone_height = positive(value)?,
        ("primitives", "cone_slices") => c.primitives.cone_slices = count(value, 3)?,
        ("primitives", "cylinder_radius") => c.primitives.cylinder_radius = positive(value)?,
        ("primitives", "cylinder_height") => c.primitives.cylinder_height = positive(value)?,
        ("primitives", "cylinder_slices") => c.primitives.cylinder_slices = count(value, 3)?,

        ("window", "width") => c.window.width = pixels(value)?,
        ("window", "height") => c.window.height = pixels(value)?,
        ("window", "layout") => c.window.layout = named(value)?,

        ("outside", "show") => c.outside.show = boolean(value)?,
        ("outside", "stage") => c.outside.stage = stage(value)?,

        ("input", action) => {
            let action = Action::from_name(action).ok_or("unknown key")?;
            let key = string(value)?;
            if key.is_empty() {
                return Err("expected a key name such as \"w\" or \"shift+p\"".into());
            }
            c.input.0.insert(action, key.to_lowercase());
        }
        _ => return Err("unknown key".into()),
    }
    Ok(())
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

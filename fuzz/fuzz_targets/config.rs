//! The configuration as the command line reads it: a config file's text (any text) and a list of
//! `--set section.key=value` overrides (real keys from `plugins/config/src/keys.rs` or made-up ones, with
//! numbers, NaN and infinities, enum names, arrays or any text as values), through
//! `close2gl_config::load_text`. It must never panic; an error is one line; a config it accepts
//! keeps every documented range, and the headless app builds from it (one frame: framing the
//! camera, the Close2GL stage and, in software mode, the rasterizer) on a small primitive.
#![no_main]

use std::fmt::Write as _;
use std::path::Path;
use std::sync::LazyLock;

use arbitrary::Arbitrary;
use close2gl_config::{Config, load_text};
use close2gl_core::glam::Vec3;
use close2gl_core::limits::{FOV_RANGE, MAX_PIXELS};
use close2gl_core::{
    Action, Camera, CameraMode, Clipping, FrontFace, ModelSource, PrimitiveKind, Rasterizer,
    RenderMode, Shading, TextureFilter, Viewport,
};
use close2gl_fuzz::Num;
use libfuzzer_sys::fuzz_target;

/// Every key of the configuration's table but `[input]`'s, as `section.name`.
static KEYS: LazyLock<Vec<String>> = LazyLock::new(|| {
    close2gl_config::keys::KEYS
        .iter()
        .map(|k| format!("{}.{}", k.section, k.name))
        .collect()
});

#[derive(Arbitrary, Debug)]
enum Key<'a> {
    Known(u8),
    Input(u8),
    Raw(&'a str),
}

#[derive(Arbitrary, Debug)]
enum Value<'a> {
    Number(Num),
    Integer(i64),
    Bool(bool),
    /// A name one of the config's enums takes.
    Name(u8),
    Triple([Num; 3]),
    Array(Vec<Num>),
    Text(&'a str),
}

#[derive(Arbitrary, Debug)]
struct Override<'a> {
    key: Key<'a>,
    value: Value<'a>,
}

/// The overrides first, so that the rest of the input is the file's text as it stands: a seed
/// is a zero byte (no overrides) and then a config file.
#[derive(Arbitrary, Debug)]
struct Input<'a> {
    overrides: Vec<Override<'a>>,
    file: &'a str,
}

fn names() -> Vec<&'static str> {
    let mut names = Vec::new();
    names.extend(PrimitiveKind::ALL.iter().map(|v| v.name()));
    names.extend(CameraMode::ALL.iter().map(|v| v.name()));
    names.extend(RenderMode::ALL.iter().map(|v| v.name()));
    names.extend(FrontFace::ALL.iter().map(|v| v.name()));
    names.extend(Clipping::ALL.iter().map(|v| v.name()));
    names.extend(Shading::ALL.iter().map(|v| v.name()));
    names.extend(Rasterizer::ALL.iter().map(|v| v.name()));
    names.extend(TextureFilter::ALL.iter().map(|v| v.name()));
    names.extend(close2gl_core::Layout::ALL.iter().map(|v| v.name()));
    names
}

/// A float as TOML writes it.
fn toml_float(x: f32) -> String {
    if x.is_nan() {
        "nan".into()
    } else if x.is_infinite() {
        if x > 0.0 { "inf" } else { "-inf" }.into()
    } else {
        format!("{x:?}")
    }
}

fn render(o: &Override, inputs: &[String], names: &[&str]) -> String {
    let mut item = match &o.key {
        Key::Known(i) => KEYS[usize::from(*i) % KEYS.len()].clone(),
        Key::Input(i) => format!("input.{}", inputs[usize::from(*i) % inputs.len()]),
        Key::Raw(text) => text.to_string(),
    };
    item.push('=');
    match &o.value {
        Value::Number(x) => item.push_str(&toml_float(x.get())),
        Value::Integer(i) => write!(item, "{i}").unwrap(),
        Value::Bool(b) => write!(item, "{b}").unwrap(),
        Value::Name(i) => item.push_str(names[usize::from(*i) % names.len()]),
        Value::Triple(v) => {
            let [a, b, c] = v.map(|x| toml_float(x.get()));
            write!(item, "[{a},{b},{c}]").unwrap();
        }
        Value::Array(v) => {
            let items: Vec<String> = v.iter().map(|x| toml_float(x.get())).collect();
            write!(item, "[{}]", items.join(",")).unwrap();
        }
        Value::Text(text) => item.push_str(text),
    }
    item
}

/// The documented ranges (README, Configuration) of a config that loaded.
fn check_ranges(config: &Config) {
    let camera = &config.camera;
    assert!(FOV_RANGE.contains(&camera.hfov), "hfov {}", camera.hfov);
    assert!(FOV_RANGE.contains(&camera.vfov), "vfov {}", camera.vfov);
    for d in [camera.near, camera.far].into_iter().flatten() {
        assert!(d.is_finite() && d > 0.0, "near/far {d}");
    }
    if let (Some(near), Some(far)) = (camera.near, camera.far) {
        assert!(near < far, "near {near} >= far {far}");
    }
    let look = config.render.appearance;
    for c in [look.color, look.background] {
        assert!(
            c.cmpge(Vec3::ZERO).all() && c.cmple(Vec3::ONE).all(),
            "colour {c}"
        );
    }
    let window = config.window;
    assert!(
        (1..=MAX_PIXELS).contains(&window.width),
        "width {}",
        window.width
    );
    assert!(
        (1..=MAX_PIXELS).contains(&window.height),
        "height {}",
        window.height
    );
    let pose = [camera.position, camera.target, camera.u, camera.v, camera.n];
    for p in pose.into_iter().flatten().chain([camera.up]) {
        assert!(p.is_finite(), "a camera vector {p}");
    }
}

/// Primitives small enough to build in every run; a bigger one is swapped for the box.
fn small_model(config: &Config) -> ModelSource {
    let p = &config.primitives;
    let quads = match config.model {
        ModelSource::Primitive(PrimitiveKind::Sphere) => p.sphere_stacks * p.sphere_slices,
        ModelSource::Primitive(PrimitiveKind::Torus) => p.torus_n0 * p.torus_n1,
        ModelSource::Primitive(PrimitiveKind::Cone) => p.cone_slices,
        ModelSource::Primitive(PrimitiveKind::Cylinder) => p.cylinder_slices,
        _ => u32::MAX,
    };
    match config.model {
        ModelSource::Primitive(kind) if quads <= 256 => ModelSource::Primitive(kind),
        _ => ModelSource::Primitive(PrimitiveKind::Box),
    }
}

fuzz_target!(|input: Input| {
    let names = names();
    let inputs: Vec<String> = Action::ALL.iter().map(|a| a.name().to_string()).collect();
    let overrides: Vec<String> = input
        .overrides
        .iter()
        .map(|o| render(o, &inputs, &names))
        .collect();
    let mut config = match load_text(input.file, "fuzz.toml", Path::new("base"), &overrides) {
        Ok(config) => config,
        Err(message) => {
            assert!(
                !message.contains(['\n', '\r']),
                "several lines: {message:?}"
            );
            return;
        }
    };
    check_ranges(&config);
    config.model = small_model(&config);
    config.texture = None;
    let viewport = Viewport {
        width: config.window.width.min(48),
        height: config.window.height.min(48),
    };
    if let Ok(mut app) = close2gl_app::build_app(&config, viewport) {
        let camera = app
            .world_mut()
            .query::<&Camera>()
            .single(app.world())
            .copied();
        if let Ok(camera) = camera {
            for axis in [camera.u, camera.v, camera.n] {
                assert!(axis.is_finite(), "the framed camera's basis {camera:?}");
            }
        }
    }
});

//! `?test=1`: the page keeps a JSON status in its `#status` element, for a test in a real browser
//! to read: how many frames were drawn, when the first was (milliseconds since navigation
//! started), the backend and adapter, the model and its triangles, the two views' coverage
//! agreement as `close2gl render` computes it, the settings shown (as the link writes them),
//! whether the panel is, and the trace shown in Close2GL's place with check's verdict on it.

use bevy_ecs::prelude::*;
use close2gl_core::{Mesh, ModelSource, ModelStatus, ToolRequests, Wake};
use close2gl_gpu::Gpu;
use close2gl_trace::view::TraceView;
use close2gl_ui::{PanelState, ViewStats};
use serde_json::{Map, Value, json};

/// Frames drawn before the views are compared: the first frames may still be settling (the
/// canvas's size arrives with the first resize).
const SETTLE_FRAMES: u64 = 3;

/// What the status counts between frames.
#[derive(Resource, Default)]
pub struct Status {
    frames: u64,
    first_frame_ms: Option<f64>,
    compared_at: Option<u64>,
}

/// `(section.key, value)` pairs as a JSON object of their values: TOML read as JSON, and a bare
/// word (a name such as `simple`, as `--set` takes it) as a string.
fn settings_json(settings: &[(String, String)]) -> Map<String, Value> {
    settings
        .iter()
        .map(|(key, value)| {
            let toml = format!("v = {value}").parse::<toml::Table>().ok();
            let value = toml
                .and_then(|t| serde_json::to_value(t.get("v")?).ok())
                .unwrap_or_else(|| Value::String(value.clone()));
            (key.clone(), value)
        })
        .collect()
}

/// After each frame drawn with the GPU: counts it, asks for the views to be compared once they
/// have settled (and again when the model changes), keeps drawing until they have been, and
/// writes the status.
pub fn write_status(world: &mut World) {
    let Some(gpu) = world.get_resource::<Gpu>().cloned() else {
        return;
    };
    let now = web_sys::window()
        .and_then(|w| w.performance())
        .map_or(0.0, |p| p.now());
    let generation = world.resource::<ModelStatus>().generation;
    let mut status = world.resource_mut::<Status>();
    status.frames += 1;
    // This system runs before the frame is drawn: the first frame is drawn when the second
    // starts.
    if status.frames == 2 {
        status.first_frame_ms = Some(now);
    }
    let frames = status.frames;
    let compare = frames >= SETTLE_FRAMES && status.compared_at != Some(generation);
    if compare {
        status.compared_at = Some(generation);
        world.resource_mut::<ToolRequests>().compare_views = true;
    }
    let agreement = world.resource::<ViewStats>().coverage_agreement;
    if agreement.is_none() || frames <= SETTLE_FRAMES + 1 {
        world.resource::<Wake>().wake();
    }
    let text = status_json(world, &gpu, agreement).to_string();
    let element = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.get_element_by_id("status"));
    if let Some(element) = element {
        element.set_text_content(Some(&text));
    }
}

fn status_json(world: &mut World, gpu: &Gpu, agreement: Option<f64>) -> Value {
    let model = match &world.resource::<ModelStatus>().source {
        Some(ModelSource::File(path)) => path.display().to_string(),
        Some(ModelSource::Primitive(kind)) => kind.name().to_string(),
        None => String::new(),
    };
    let triangles = world
        .query::<&Mesh>()
        .iter(world)
        .next()
        .map_or(0, |m| m.triangles.len());
    let settings = close2gl_config::command::of_world(world)
        .map(|config| settings_json(&close2gl_config::keys::pixel_keys(&config)))
        .unwrap_or_default();
    let panel = !world.resource::<PanelState>().hidden;
    let trace = world.get_resource::<TraceView>().and_then(|view| {
        let file = view
            .path
            .as_ref()?
            .file_name()?
            .to_string_lossy()
            .into_owned();
        let agrees = view.shown.as_ref().map(|shown| shown.report.agrees());
        Some(json!({"file": file, "agrees": agrees, "error": view.error}))
    });
    let status = world.resource::<Status>();
    let backend = match gpu.adapter.get_info().backend {
        close2gl_gpu::wgpu::Backend::BrowserWebGpu => "webgpu",
        _ => "webgl2",
    };
    json!({
        "frames": status.frames,
        "first_frame_ms": status.first_frame_ms,
        "backend": backend,
        "adapter": gpu.adapter_name(),
        "model": model,
        "triangles": triangles,
        "coverage_agreement": agreement,
        "settings": settings,
        "panel": panel,
        "trace": trace,
    })
}

//! Reading a requested trace: checked against the shown mesh, its camera asked for and its
//! switches taken.

use std::path::Path;

use bevy_ecs::prelude::*;
use close2gl_core::{Camera, CameraRequest, Mesh, Mistake, PipelineSettings, Rasterizer};
use close2gl_pipeline::program::WindingSpace;
use close2gl_trace_format::{Trace, read_trace};

use super::{Shown, TraceRequest, TraceView};

/// Serves a pending `TraceRequest` once a mesh is shown; a new mesh has the shown trace checked
/// again (or refused, when it does not fit the new model). A trace that does not read or fit
/// leaves its error in `TraceView` and the trace shown before in place. The trace's camera is
/// asked of the camera plugin, which sets it over the framing of a new model in this frame.
pub fn load_requested_trace(
    mut request: ResMut<TraceRequest>,
    mut view: ResMut<TraceView>,
    mesh: Option<Single<Ref<Mesh>>>,
    (camera, mut camera_request): (Option<Single<&Camera>>, ResMut<CameraRequest>),
    mut settings: ResMut<PipelineSettings>,
) {
    let Some(mesh) = mesh else {
        return;
    };
    if mesh.is_changed() && request.0.is_none() && view.shown.is_some() {
        request.0 = view.path.clone();
    }
    let Some(path) = request.0.take() else {
        return;
    };
    match read(&path, &mesh) {
        Ok(shown) => {
            if let Some(camera) = camera {
                camera_request.replacement = Some(trace_camera(&shown.trace, &camera, &mesh));
            }
            *settings = trace_settings(&shown.trace, *settings);
            view.taken(path);
            view.shown = Some(shown);
        }
        Err(error) => view.error = Some(error),
    }
}

fn read(path: &Path, mesh: &Mesh) -> Result<Shown, String> {
    let trace = read_trace(path).map_err(|e| e.to_string())?;
    let report = close2gl_check::check(mesh, &trace).map_err(|e| e.to_string())?;
    Ok(Shown { trace, report })
}

/// The trace's camera as the viewer's, looking at the model's centre's depth along -n.
pub fn trace_camera(trace: &Trace, camera: &Camera, mesh: &Mesh) -> Camera {
    let c = &trace.camera;
    let position = c.position.as_vec3();
    let n = c.n.as_vec3();
    let (lo, hi) = mesh.bounds();
    let depth = ((lo + hi) / 2.0 - position).dot(-n).max(c.near as f32);
    Camera {
        position,
        u: c.u.as_vec3(),
        v: c.v.as_vec3(),
        n,
        target: position - n * depth,
        hfov: c.hfov as f32,
        vfov: c.vfov as f32,
        near: c.near as f32,
        far: c.far as f32,
        mode: camera.mode,
    }
}

/// The trace's settings over `settings`: its mode, culling and clipping (its `clipping none`
/// shown as full clipping, the nearest close2gl draws), the GPU drawing the 2D output, no
/// mistake of close2gl's own.
pub fn trace_settings(trace: &Trace, settings: PipelineSettings) -> PipelineSettings {
    PipelineSettings {
        mode: trace.mode.unwrap_or(settings.mode),
        close2gl_raster: Rasterizer::Gpu,
        mistake: Mistake::None,
        ..close2gl_check::declared(trace, WindingSpace::Screen).onto(settings)
    }
}

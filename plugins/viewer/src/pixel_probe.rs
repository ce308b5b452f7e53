//! The pixel probe a Ctrl+click asks for (`InputState::probe`): which view was clicked (from the
//! layout), the pixel in that view's coordinates, and both answers for it: the reference's from
//! the GPU's ID pass, Close2GL's (winner and every candidate) from the raster crate's probe.
//! While the Close2GL view shows a program's trace, the answer also says what the trace drew
//! there and what check found of it. The answer goes to the panel ([`ProbeAnswer`]), and its
//! winner becomes the selected triangle.

use bevy_ecs::prelude::*;
use close2gl_core::Mistake;
use close2gl_core::{
    Camera, Fates, InputState, Mesh, PipelineSettings, ProbeClick, Scene, SelectedTriangle,
    Viewport,
};
use close2gl_gpu::{Gpu, ReferenceHit};
use close2gl_pipeline::mistakes::Mistakes;
use close2gl_pipeline::textbook;
use close2gl_raster::coverage_probe::{Drawn, probe};
use close2gl_trace::view::TraceView;
use close2gl_trace::view::probe::probe as trace_probe;
use close2gl_ui::ProbeAnswer;

use crate::view_layout::{Placed, Placement, View};

/// Every triangle's fate in `scene`, as Close2GL's pipeline (with its mistake, if one is set)
/// records them.
fn recorded_fates(scene: Scene<'_>) -> Fates {
    let Scene {
        mesh,
        camera,
        pipeline: settings,
        viewport,
    } = scene;
    match settings.mistake {
        Mistake::None => textbook::run_recording(mesh, camera, settings, viewport).1,
        mistake => {
            let mistakes = Mistakes::one(mistake);
            textbook::run_mistaken(mesh, camera, settings, viewport, mistakes).1
        }
    }
}

/// Answers this frame's probe click, if any, once the frame's pipeline has run.
pub fn answer(world: &mut World, gpu: &Gpu, placement: &Placement) {
    let Some(at) = world.resource::<InputState>().probe else {
        return;
    };
    let Some((placed, pixel, viewport)) = clicked_view(placement, &at) else {
        return;
    };
    let mesh = world.query::<&Mesh>().iter(world).next().cloned();
    let camera = world.query::<&Camera>().iter(world).next().copied();
    let (Some(mesh), Some(camera)) = (mesh, camera) else {
        return;
    };
    let settings = *world.resource::<PipelineSettings>();
    let scene = Scene {
        mesh: &mesh,
        camera: &camera,
        pipeline: &settings,
        viewport,
    };
    let reference = reference_answer(world, gpu, scene, pixel);
    let drawn = Drawn::last_frame(world, &settings);
    let close2gl = match world.resource::<Fates>() {
        fates if fates.triangles.len() == mesh.triangles.len() => probe(scene, fates, pixel, drawn),
        // Nothing records fates while the fate view is off: this frame's, worked out once.
        _ => probe(scene, &recorded_fates(scene), pixel, drawn),
    };
    let trace = match placed.view {
        View::Close2gl => world
            .get_resource::<TraceView>()
            .and_then(|view| trace_probe(view, pixel, viewport)),
        _ => None,
    };
    // In a trace's view, the triangle under the click is the one the trace drew there.
    let trace_triangle = trace.as_ref().and_then(|t| t.triangle).map(|t| t as u32);
    let answer = ProbeAnswer {
        view: match placed.view {
            View::Reference => "reference",
            View::Close2gl | View::Outside => "Close2GL",
        },
        reference: reference.map(|hit| hit.map(|h| (h.triangle, h.depth))),
        close2gl,
        trace: trace.map(|t| t.lines),
        click: at,
        camera,
        window: true,
    };
    let close2gl = trace_triangle.or(answer.close2gl.triangle);
    if let Some(triangle) = close2gl.or(answer.reference_triangle()) {
        world.resource_mut::<SelectedTriangle>().0 = Some(triangle);
    }
    #[cfg(target_arch = "wasm32")]
    if let Some(mut arriving) = world.get_resource_mut::<ArrivingProbe>() {
        arriving.select = close2gl.is_none();
    }
    world.insert_resource(answer);
}

/// The view the click is in, the pixel in that view's coordinates, and the views' viewport.
fn clicked_view<'a>(
    placement: &'a Placement,
    at: &ProbeClick,
) -> Option<(&'a Placed, (u32, u32), Viewport)> {
    let (viewport, x, y) = (placement.viewport?, at.at.x as u32, at.at.y as u32);
    let window = match at.close2gl_window {
        true => &placement.close2gl,
        false => &placement.main,
    };
    // The outside view is an illustration: a click there turns its camera, it probes nothing.
    let probed = |p: &&Placed| p.view != View::Outside && p.rect.contains(x, y);
    let placed = window.iter().find(probed)?;
    Some((placed, (x - placed.rect.x, y - placed.rect.y), viewport))
}

/// The reference's answer: at once on the desktop.
#[cfg(not(target_arch = "wasm32"))]
fn reference_answer(
    _world: &mut World,
    gpu: &Gpu,
    scene: Scene<'_>,
    pixel: (u32, u32),
) -> Result<Option<ReferenceHit>, String> {
    close2gl_gpu::probe_reference(gpu, scene, pixel)
}

/// In a browser the GPU cannot be waited for: the reference's answer arrives frames later
/// ([`arrive`]), and the probe says so meanwhile.
#[cfg(target_arch = "wasm32")]
fn reference_answer(
    world: &mut World,
    gpu: &Gpu,
    scene: Scene<'_>,
    pixel: (u32, u32),
) -> Result<Option<ReferenceHit>, String> {
    let probe = close2gl_gpu::start_probe(gpu, scene, pixel)?;
    world.insert_resource(ArrivingProbe {
        probe,
        select: false,
    });
    Err("on its way back from the GPU".into())
}

/// In a browser: the reference's side of the last probe, on its way back from the GPU;
/// `select` when its triangle becomes the selected one (Close2GL's side had none).
#[cfg(target_arch = "wasm32")]
#[derive(Resource)]
pub struct ArrivingProbe {
    probe: close2gl_gpu::ReferenceProbe,
    select: bool,
}

/// In a browser: puts the reference's answer into the probe's once the GPU has it. Returns
/// whether one is still on its way (the viewer draws until it has arrived).
#[cfg(target_arch = "wasm32")]
pub fn arrive(world: &mut World, gpu: &Gpu) -> bool {
    let Some(arriving) = world.get_resource::<ArrivingProbe>() else {
        return false;
    };
    let Some(reference) = arriving.probe.finish(gpu) else {
        return true;
    };
    let select = arriving.select;
    world.remove_resource::<ArrivingProbe>();
    let reference = reference.map(|hit| hit.map(|h| (h.triangle, h.depth)));
    let triangle = reference.as_ref().ok().copied().flatten().map(|(t, _)| t);
    if let Some(mut answer) = world.get_resource_mut::<ProbeAnswer>() {
        answer.reference = reference;
    }
    if let Some(triangle) = triangle.filter(|_| select) {
        world.resource_mut::<SelectedTriangle>().0 = Some(triangle);
    }
    false
}

//! The Ctrl+click probe as systems of the frame (`OutputStep::Report`, once the frame is
//! uploaded): which view the click (`InputState::probe`) is in, from the views the viewer placed
//! ([`ViewPlacement`]), and the pixel in that view's coordinates; both views' answers come from
//! the probe's one home (`close2gl_gpu::ProbedFrame`). While the Close2GL view shows a program's
//! trace, the answer also says what the trace drew there and what check found of it; while both
//! show a raster trace's fixed frame, check's probe of the trace's pixel alone answers. The answer
//! goes to the panel ([`ProbeAnswer`]), and its winner becomes the selected triangle.

use bevy_ecs::prelude::*;
use close2gl_core::{Camera, InputState, ProbeClick, SelectedTriangle, View, Viewport};
use close2gl_gpu::{Gpu, ProbedFrame, ReferenceProbe};
use close2gl_trace::view::TraceView;
use close2gl_trace::view::probe::probe as trace_probe;
use close2gl_trace::view::raster::raster_probe;
use close2gl_ui::ProbeAnswer;

use crate::placed_views::ViewPlacement;
use crate::view_layout::{Placed, Placement};

/// Answers this frame's probe click, if any.
pub fn answer_probe(
    input: Res<InputState>,
    placement: Res<ViewPlacement>,
    gpu: Res<Gpu>,
    frame: ProbedFrame,
    (trace, camera): (Option<Res<TraceView>>, Option<Single<&Camera>>),
    mut selected: ResMut<SelectedTriangle>,
    mut commands: Commands,
) {
    let Some(at) = input.probe else {
        return;
    };
    let Some((placed, pixel, viewport)) = clicked_view(&placement.0, &at) else {
        return;
    };
    let raster = trace
        .as_deref()
        .and_then(|v| raster_probe(v, pixel, viewport));
    if let Some(lines) = raster {
        let camera = camera.map(|c| **c).unwrap_or_default();
        let name = view_name(placed.view);
        commands.insert_resource(ProbeAnswer::fixed_frame(name, pixel, lines, at, camera));
        return;
    }
    let Some(answer) = frame.answer(&gpu, viewport, pixel) else {
        return;
    };
    let trace = match placed.view {
        View::Close2gl => trace.and_then(|view| trace_probe(&view, pixel, viewport)),
        _ => None,
    };
    // In a trace's view, the triangle under the click is the one the trace drew there.
    let trace_triangle = trace.as_ref().and_then(|t| t.triangle).map(|t| t as u32);
    let close2gl = trace_triangle.or(answer.close2gl.triangle);
    let reference = reference_answer(&mut commands, &gpu, answer.reference, close2gl.is_none());
    let answer = ProbeAnswer {
        view: view_name(placed.view),
        reference: reference.map(|hit| hit.map(|h| (h.triangle, h.depth))),
        close2gl: answer.close2gl,
        trace: trace.map(|t| t.lines),
        click: at,
        camera: answer.camera,
        window: true,
        fixed_frame: false,
    };
    if let Some(triangle) = close2gl.or(answer.reference_triangle()) {
        selected.0 = Some(triangle);
    }
    commands.insert_resource(answer);
}

/// The view's name in the probe's answer.
fn view_name(view: View) -> &'static str {
    match view {
        View::Reference => "reference",
        View::Close2gl | View::Outside => "Close2GL",
    }
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

type ReferenceAnswer = Result<Option<close2gl_gpu::ReferenceHit>, String>;

/// The reference's answer: at once on the desktop.
#[cfg(not(target_arch = "wasm32"))]
fn reference_answer(
    _commands: &mut Commands,
    gpu: &Gpu,
    started: Result<ReferenceProbe, String>,
    _select: bool,
) -> ReferenceAnswer {
    started?.wait(gpu)
}

/// In a browser the GPU cannot be waited for: the reference's answer arrives frames later
/// ([`arrive_probe`]), and the probe says so meanwhile; `select` when its triangle is to become
/// the selected one.
#[cfg(target_arch = "wasm32")]
fn reference_answer(
    commands: &mut Commands,
    _gpu: &Gpu,
    started: Result<ReferenceProbe, String>,
    select: bool,
) -> ReferenceAnswer {
    let probe = started?;
    commands.insert_resource(ArrivingProbe { probe, select });
    Err("on its way back from the GPU".into())
}

/// In a browser: the reference's side of the last probe, on its way back from the GPU;
/// `select` when its triangle becomes the selected one (Close2GL's side had none).
#[cfg(target_arch = "wasm32")]
#[derive(Resource)]
pub struct ArrivingProbe {
    probe: ReferenceProbe,
    select: bool,
}

/// In a browser: puts the reference's answer into the probe's once the GPU has it.
#[cfg(target_arch = "wasm32")]
pub fn arrive_probe(
    arriving: Option<Res<ArrivingProbe>>,
    gpu: Res<Gpu>,
    answer: Option<ResMut<ProbeAnswer>>,
    mut selected: ResMut<SelectedTriangle>,
    mut commands: Commands,
) {
    let Some(arriving) = arriving else {
        return;
    };
    let Some(reference) = arriving.probe.finish(&gpu) else {
        return;
    };
    commands.remove_resource::<ArrivingProbe>();
    let reference = reference.map(|hit| hit.map(|h| (h.triangle, h.depth)));
    let triangle = reference.as_ref().ok().copied().flatten().map(|(t, _)| t);
    if let Some(mut answer) = answer {
        answer.reference = reference;
    }
    if let Some(triangle) = triangle.filter(|_| arriving.select) {
        selected.0 = Some(triangle);
    }
}

/// Whether a probe's answer is still on its way back from the GPU: in a browser, where the
/// viewer draws until it has arrived.
#[cfg(target_arch = "wasm32")]
pub fn on_its_way(world: &World) -> bool {
    world.contains_resource::<ArrivingProbe>()
}

/// On the desktop the answer is waited for: it never is.
#[cfg(not(target_arch = "wasm32"))]
pub fn on_its_way(_world: &World) -> bool {
    false
}

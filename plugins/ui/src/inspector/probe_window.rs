//! The pixel probe's answer (a Ctrl+click on a view), where the user looks: a small window beside
//! the clicked pixel with both views' winners, their disagreement in plain words, Close2GL's
//! candidates and why each lost, and a button to that triangle's journey; the Inspector section
//! keeps the full record. The window says when the camera moved since, as the answer then
//! describes an older picture.

use bevy_ecs::prelude::*;
use close2gl_core::{Camera, InputState, ProbeClick, SelectedTriangle};
use close2gl_raster::coverage_probe::{PixelOutcome, PixelProbe};

use crate::legend::swatch;
use crate::state::PanelState;
use crate::view_areas::ViewArea;

/// The last pixel probe (a Ctrl+click on a view), answered by both sides: the viewer fills it.
#[derive(Resource, Clone, Debug)]
pub struct ProbeAnswer {
    /// The view clicked.
    pub view: &'static str,
    /// The GPU's ID pass: the reference's triangle and depth there (None: background), or why
    /// it could not be read.
    pub reference: Result<Option<(u32, f32)>, String>,
    /// Close2GL's winner, depth and every candidate with why it lost.
    pub close2gl: PixelProbe,
    /// While the Close2GL view shows a trace: what the trace drew there and what check says of
    /// it, in lines.
    pub trace: Option<Vec<String>>,
    /// The click, where the window opens.
    pub click: ProbeClick,
    /// The camera the answer was for: once it moves, the pixel shows something else.
    pub camera: Camera,
    /// The window beside the click shows the answer (Esc and its close button hide it).
    pub window: bool,
    /// The views show a raster trace's fixed frame: its lines alone answer (the model's
    /// winners are not what the views show, and the camera moves nothing there).
    pub fixed_frame: bool,
}

impl ProbeAnswer {
    /// The answer while the views show a raster trace's fixed frame: check's probe of the
    /// trace's pixel under the click, in `lines`, the same in either view (both show that pixel
    /// of the same frame).
    pub fn fixed_frame(
        view: &'static str,
        pixel: (u32, u32),
        lines: Vec<String>,
        click: ProbeClick,
        camera: Camera,
    ) -> ProbeAnswer {
        ProbeAnswer {
            view,
            reference: Ok(None),
            close2gl: PixelProbe {
                pixel: [pixel.0, pixel.1],
                triangle: None,
                depth: 1.0,
                color: None,
                candidates: Vec::new(),
            },
            trace: Some(lines),
            click,
            camera,
            window: true,
            fixed_frame: true,
        }
    }

    pub fn reference_triangle(&self) -> Option<u32> {
        self.reference
            .as_ref()
            .ok()
            .copied()
            .flatten()
            .map(|(t, _)| t)
    }

    /// The two winners compared, in a sentence; None while the Close2GL view shows a trace (its
    /// own lines say what it drew).
    pub fn verdict(&self) -> Option<String> {
        if self.trace.is_some() {
            return None;
        }
        let reference = match &self.reference {
            Ok(hit) => hit.map(|(t, _)| t),
            Err(e) => return Some(format!("The GPU could not answer: {e}")),
        };
        let lost = |t: u32| {
            let candidate = self.close2gl.candidates.iter().find(|c| c.triangle == t);
            candidate.map_or(String::new(), |c| {
                format!(" (triangle {t} in Close2GL: {})", why(c.outcome))
            })
        };
        Some(match (reference, self.close2gl.triangle) {
            (None, None) => "Both views show the background here.".to_string(),
            (Some(r), Some(c)) if r == c => format!("Both views drew triangle {r} here."),
            (Some(r), c) => {
                let drew = c.map_or("nothing".to_string(), |c| format!("triangle {c}"));
                format!(
                    "The views differ: the GPU drew triangle {r}, Close2GL {drew}{}.",
                    lost(r)
                )
            }
            (None, Some(c)) => {
                format!("The views differ: Close2GL drew triangle {c}, the GPU nothing.")
            }
        })
    }
}

/// Why a candidate did or did not draw the pixel, in words.
fn why(outcome: PixelOutcome) -> &'static str {
    match outcome {
        PixelOutcome::Won => "the nearest, it drew the pixel",
        PixelOutcome::Depth => "another triangle is nearer (the depth test)",
        PixelOutcome::Culled => "a back face, removed by culling",
        PixelOutcome::Clipped => "it would project here, but clipping removed it",
        PixelOutcome::FillRule => "the pixel centre is on its edge; the top-left rule gave it away",
    }
}

/// Each winner with its depth (and Close2GL's colour).
fn winners(ui: &mut egui::Ui, answer: &ProbeAnswer) {
    if answer.fixed_frame {
        return;
    }
    let winner = |hit: Option<(u32, f32)>| {
        hit.map_or("background".to_string(), |(t, d)| {
            format!("triangle {t}, depth {d:.5}")
        })
    };
    match &answer.reference {
        Ok(hit) => ui.label(format!("Reference (GPU): {}", winner(*hit))),
        Err(e) => ui.label(format!("Reference (GPU): {e}")),
    };
    let probe = &answer.close2gl;
    let close2gl = probe.triangle.map(|t| (t, probe.depth));
    ui.label(format!("Close2GL: {}", winner(close2gl)));
    if let Some([r, g, b, _]) = probe.color {
        ui.horizontal(|ui| {
            ui.label("Close2GL colour");
            swatch(ui, [r, g, b]);
        });
    }
}

/// Close2GL's candidates, each with why it lost, then the trace's lines and the verdict.
fn explanation(ui: &mut egui::Ui, answer: &ProbeAnswer) {
    for candidate in &answer.close2gl.candidates {
        ui.label(format!(
            "  triangle {} {} (depth {:.5}): {}",
            candidate.triangle,
            candidate.outcome.name(),
            candidate.depth,
            why(candidate.outcome)
        ));
    }
    for line in answer.trace.iter().flatten() {
        ui.label(line);
    }
    if let Some(verdict) = answer.verdict() {
        let differ =
            answer.reference.is_err() || answer.reference_triangle() != answer.close2gl.triangle;
        match differ {
            true => ui.colored_label(ui.visuals().warn_fg_color, verdict),
            false => ui.label(verdict),
        };
    }
}

/// The full record in the Inspector section.
pub fn record(ui: &mut egui::Ui, answer: Option<&ProbeAnswer>) {
    let Some(answer) = answer else {
        ui.weak("Ctrl+click a view to probe a pixel.");
        return;
    };
    let [x, y] = answer.close2gl.pixel;
    ui.label(format!(
        "Probe: pixel {x}, {y} (clicked on {})",
        answer.view
    ));
    winners(ui, answer);
    explanation(ui, answer);
}

/// The answer beside the clicked pixel, over the views of `area`: on the side of the click with
/// more room, kept inside the views. A click in the Close2GL window of the windows layout, which
/// has no panel to draw in, opens it in the views' corner.
pub fn probe_window(
    (InRef(ui), In(views)): (InRef<egui::Ui>, In<ViewArea>),
    answer: Option<ResMut<ProbeAnswer>>,
    input: Option<Res<InputState>>,
    cameras: Query<&Camera>,
    selected: Option<ResMut<SelectedTriangle>>,
    mut state: ResMut<PanelState>,
) {
    let Some(mut answer) = answer.filter(|a| a.window) else {
        return;
    };
    let (ctx, area) = (ui.ctx(), views.area);
    let escape = ctx.input(|i| i.key_pressed(egui::Key::Escape))
        || input.is_some_and(|i| i.pressed.iter().any(|k| k == "escape"));
    let camera = cameras.iter().next();
    let (at, pivot) = beside_click(&answer, area, ctx.pixels_per_point());
    let mut open = !escape;
    let mut journey = None;
    egui::Window::new("Probe")
        .id(egui::Id::unique("probe_window"))
        .open(&mut open)
        .collapsible(false)
        .resizable(false)
        .current_pos(at)
        .pivot(pivot)
        .constrain_to(area)
        .default_width(260.0)
        .show(ctx, |ui| {
            let [x, y] = answer.close2gl.pixel;
            ui.label(format!("Pixel {x}, {y} of the {} view", answer.view));
            if camera != Some(&answer.camera) && !answer.fixed_frame {
                ui.colored_label(
                    ui.visuals().warn_fg_color,
                    "Stale: the camera moved since this probe (Ctrl+click again).",
                );
            }
            winners(ui, &answer);
            explanation(ui, &answer);
            let triangle = answer.close2gl.triangle.or(answer.reference_triangle());
            if let Some(t) = triangle
                && ui.button(format!("Journey of triangle {t}")).clicked()
            {
                journey = Some(t);
            }
        });
    if let Some(t) = journey
        && let Some(mut selected) = selected
    {
        selected.0 = Some(t);
        state.show_journey = true;
    }
    if !open {
        answer.window = false;
    }
}

/// Where the probe window goes, and which of its corners is there: beside the click, on the
/// side with more room; in the views' corner for a click in the Close2GL window.
fn beside_click(
    answer: &ProbeAnswer,
    area: egui::Rect,
    pixels_per_point: f32,
) -> (egui::Pos2, egui::Align2) {
    let click = answer.click.at / pixels_per_point;
    match answer.click.close2gl_window {
        true => (
            area.left_top() + egui::vec2(16.0, 32.0),
            egui::Align2::LEFT_TOP,
        ),
        false if click.x > area.center().x => {
            (egui::pos2(click.x - 12.0, click.y), egui::Align2::RIGHT_TOP)
        }
        false => (egui::pos2(click.x + 12.0, click.y), egui::Align2::LEFT_TOP),
    }
}

//! The inspector section: the overlay switch, whether the views show their legends, and the
//! panel's legend (the fate view's: each fate's count, from the record Close2GL itself keeps,
//! and the colours of the reference's overlays, which the GPU answers; the live difference's
//! colours); the probe's full record; a triangle picked by index with its fate and its journey
//! as tables; the matrices M, P, V with their current numbers beside the reference's own view
//! and projection, and their largest difference.

use bevy_ecs::prelude::*;
use bevy_ecs::system::SystemParam;
use close2gl_core::glam::Mat4;
use close2gl_core::{
    Camera, ClipPlane, FateKind, Fates, Mesh, Overlay, PipelineSettings, Scene, SelectedTriangle,
    TriangleFate, Viewport, camera_matrices,
};
use close2gl_pipeline::journey::{Journey, journey};
use close2gl_pipeline::matrices;

use crate::legend::{self, swatch};
use crate::state::PanelState;

mod probe_window;
mod table;

pub use probe_window::{ProbeAnswer, probe_window};

/// What the inspector reads of the frame: the mesh and camera the pipeline drew, its viewport,
/// and the fates it recorded.
#[derive(SystemParam)]
pub struct Frame<'w, 's> {
    meshes: Query<'w, 's, &'static Mesh>,
    cameras: Query<'w, 's, &'static Camera>,
    viewport: Option<Res<'w, Viewport>>,
    fates: Option<Res<'w, Fates>>,
}

pub fn section(
    InMut(ui): InMut<egui::Ui>,
    (mut overlay, pipeline): (ResMut<Overlay>, Res<PipelineSettings>),
    mut state: ResMut<PanelState>,
    mut selected: Option<ResMut<SelectedTriangle>>,
    answer: Option<Res<ProbeAnswer>>,
    frame: Frame,
) {
    overlay_switch(ui, &mut overlay);
    legends_switch(ui, &mut state);
    match *overlay {
        Overlay::Difference => difference_legend(ui),
        _ => fates_legend(ui, frame.fates.as_deref()),
    }
    probe_window::record(ui, answer.as_deref());
    let camera = frame.cameras.iter().next();
    if let (Some(mesh), Some(camera), Some(selected)) =
        (frame.meshes.iter().next(), camera, selected.as_mut())
    {
        let viewport = frame.viewport.as_deref().copied().unwrap_or_default();
        let scene = Scene {
            mesh,
            camera,
            pipeline: &pipeline,
            viewport,
        };
        triangle(ui, scene, frame.fates.as_deref(), selected, &mut state);
    }
    egui::CollapsingHeader::new("Matrices")
        .default_open(false)
        .show(ui, |ui| {
            if let (Some(camera), Some(viewport)) = (camera, frame.viewport.as_deref()) {
                matrices_grid(ui, camera, *viewport);
            }
        });
}

fn overlay_switch(ui: &mut egui::Ui, current: &mut ResMut<Overlay>) {
    let mut shown = **current;
    ui.horizontal(|ui| {
        ui.label("Overlay");
        for &overlay in Overlay::ALL {
            ui.selectable_value(&mut shown, overlay, overlay.name());
        }
    })
    .response
    .on_hover_text(
        "fates: Close2GL's view in each triangle's fate colour (its own record), with outlines \
         of what clipping and culling removed; the reference view with the GPU's own facing \
         and depth-test answers.\ndifference: Close2GL's view replaced by where the two views \
         differ (as `close2gl render` writes diff.png); Ctrl+click any pixel to probe it.",
    );
    current.set_if_neq(shown);
}

/// The legends in the views' corners, shown unless hidden here or by their own close button.
fn legends_switch(ui: &mut egui::Ui, state: &mut PanelState) {
    let mut shown = !state.hide_legends;
    if ui.checkbox(&mut shown, "Legends in the views").changed() {
        state.hide_legends = !shown;
    }
}

/// The two halves of the fate view's legend: Close2GL's fates with their counts, and what the
/// GPU paints over the reference.
fn fates_legend(ui: &mut egui::Ui, fates: Option<&Fates>) {
    let Some(fates) = fates else {
        return;
    };
    if fates.triangles.is_empty() {
        ui.weak("No fates recorded (turn the fate view on).");
    }
    egui::Grid::new("fate_legend").show(ui, |ui| {
        for &kind in FateKind::ALL {
            swatch(ui, kind.color());
            ui.label(kind.name());
            ui.label(fates.counts.get(kind).to_string());
            ui.end_row();
        }
    });
    ui.label("Reference (the GPU's answers):");
    egui::Grid::new("reference_legend").show(ui, |ui| {
        for (kind, meaning) in legend::REFERENCE {
            swatch(ui, kind.color());
            ui.label(meaning);
            ui.end_row();
        }
    });
}

/// The live difference's colours, as `close2gl render` paints diff.png.
fn difference_legend(ui: &mut egui::Ui) {
    egui::Grid::new("difference_legend").show(ui, |ui| {
        for (color, meaning) in legend::difference() {
            swatch(ui, color);
            ui.label(meaning);
            ui.end_row();
        }
    });
}

/// The picked triangle: its fate (as recorded, with the rasterizer's verdicts, else as the
/// journey decides it) and its journey through the pipeline, every stage's numbers.
fn triangle(
    ui: &mut egui::Ui,
    scene: Scene,
    fates: Option<&Fates>,
    selected: &mut ResMut<SelectedTriangle>,
    state: &mut PanelState,
) {
    let count = scene.mesh.triangles.len();
    if count == 0 {
        return;
    }
    let Some(index) = pick_triangle(ui, selected, count) else {
        return;
    };
    let Some(journey) = journey(
        scene.mesh,
        index,
        scene.camera,
        scene.pipeline,
        scene.viewport,
    ) else {
        return;
    };
    let recorded = fates.and_then(|f| f.of(index).copied());
    fate_lines(ui, recorded.unwrap_or(journey.fate));
    let wanted = std::mem::take(&mut state.show_journey);
    let shown = egui::CollapsingHeader::new("Journey")
        .default_open(true)
        .open(wanted.then_some(true))
        .show(ui, |ui| journey_grid(ui, &journey));
    if wanted {
        shown.header_response.scroll_to_me(Some(egui::Align::TOP));
    }
}

/// The selected triangle's index (dragged or typed; the probe selects too), with a button to
/// select one when none is and to clear the selection (and its highlight in the views).
fn pick_triangle(
    ui: &mut egui::Ui,
    selected: &mut ResMut<SelectedTriangle>,
    count: usize,
) -> Option<usize> {
    let before = selected.0.map(|t| (t as usize).min(count - 1));
    let after = ui
        .horizontal(|ui| {
            let label = ui.label("Triangle");
            let Some(mut index) = before else {
                let select = ui.button("Select").clicked();
                ui.weak("or Ctrl+click a view");
                return select.then_some(0);
            };
            ui.add(egui::DragValue::new(&mut index).range(0..=count - 1))
                .labelled_by(label.id);
            ui.weak(format!("of {count}"));
            (!ui.button("Clear").clicked()).then_some(index)
        })
        .inner;
    if after != before {
        selected.0 = after.map(|i| i as u32);
    }
    after
}

fn fate_lines(ui: &mut egui::Ui, fate: TriangleFate) {
    ui.label(format!("Fate: {}", fate.kind.name()));
    let planes: Vec<&str> = ClipPlane::in_outcode(fate.planes)
        .map(ClipPlane::name)
        .collect();
    if !planes.is_empty() {
        ui.label(format!("Planes: {}", planes.join(", ")));
    }
    if fate.behind_eye {
        ui.label("Behind the eye (w <= 0 at every corner)");
    }
    if !fate.signed_area.is_nan() {
        ui.label(format!("Signed area (x2, y down): {:.3}", fate.signed_area));
    }
}

/// The journey's tables and the culling decision.
fn journey_grid(ui: &mut egui::Ui, journey: &Journey) {
    table::journey_table(ui, journey);
    let culling = journey.culling.map_or("kept", FateKind::name);
    ui.label(format!("Culling: {culling}"));
}

/// M, P and V as Close2GL builds them, the reference's view and projection (glam's), and how far
/// apart they are. P is compared in wgpu's depth range (z' = (z + w) / 2), the one the reference
/// projects to: OpenGL's -1..1 and WebGPU's 0..1 differ there by design.
fn matrices_grid(ui: &mut egui::Ui, camera: &Camera, viewport: Viewport) {
    let v = matrices::viewport(viewport.width as f32, viewport.height as f32);
    let (view, projection) = camera_matrices(camera);
    for (name, matrix) in [
        ("M (Close2GL)", matrices::modelview(camera)),
        (
            "P (Close2GL)",
            matrices::projection(camera.hfov, camera.vfov, camera.near, camera.far),
        ),
        ("V (Close2GL)", v),
        ("view (reference)", view),
        ("projection (reference)", projection),
    ] {
        table::matrix_table(ui, name, matrix);
    }
    let (dm, dp) = differences(camera);
    ui.label(format!(
        "Largest difference: M vs view {dm:.2e}, P vs projection {dp:.2e}"
    ));
}

/// The largest entry of M − view and of P − projection, P taken to wgpu's depth range.
fn differences(camera: &Camera) -> (f32, f32) {
    let m = matrices::modelview(camera);
    let p = matrices::projection(camera.hfov, camera.vfov, camera.near, camera.far);
    let (view, projection) = camera_matrices(camera);
    // z' = (z + w) / 2, column-major.
    let gl_to_wgpu = Mat4::from_cols_array_2d(&[
        [1.0, 0.0, 0.0, 0.0],
        [0.0, 1.0, 0.0, 0.0],
        [0.0, 0.0, 0.5, 0.0],
        [0.0, 0.0, 0.5, 1.0],
    ]);
    (
        largest_difference(m, view),
        largest_difference(gl_to_wgpu * p, projection),
    )
}

fn largest_difference(a: Mat4, b: Mat4) -> f32 {
    (a - b)
        .to_cols_array()
        .iter()
        .fold(0.0, |m, d| m.max(d.abs()))
}

#[cfg(test)]
mod tests {
    use close2gl_core::glam::Vec3;

    use super::*;

    #[test]
    fn the_reference_matrices_equal_close2gls_within_a_millionth_of_their_size() {
        for (position, hfov, vfov, near, far) in [
            (Vec3::new(3.0, 4.0, 5.0), 60.0, 60.0, 0.1, 100.0),
            (Vec3::new(-200.0, 10.0, 40.0), 90.0, 45.0, 1.0, 5000.0),
        ] {
            let camera = Camera {
                hfov,
                vfov,
                near,
                far,
                ..Camera::default()
            }
            .looking_at(position, Vec3::ZERO, Vec3::Y)
            .expect("a valid pose");
            let (dm, dp) = differences(&camera);
            let size = position.length();
            assert!(
                dm <= 1e-6 * size.max(1.0) * 4.0,
                "M vs view: {dm} at {position}"
            );
            assert!(dp <= 1e-5, "P vs projection: {dp}");
        }
    }
}

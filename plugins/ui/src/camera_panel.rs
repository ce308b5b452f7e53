use bevy_ecs::prelude::*;
use close2gl_camera::motion::{zoom, zoom_factor};
use close2gl_core::limits::{FOV_RANGE, MOVE_SPEED_RANGE, ROTATE_SPEED_RANGE};
use close2gl_core::{Camera, CameraAction, CameraActions, CameraMode, CameraRequest, CameraSpeeds};

use crate::state::PanelState;

/// Mode, hfov and vfov (locked together, they zoom as the scroll wheel does), near, far, speeds,
/// and reset. An edit is asked of the camera plugin, which sets it in this frame.
pub fn section(
    InMut(ui): InMut<egui::Ui>,
    (cameras, mut request): (Query<&Camera>, ResMut<CameraRequest>),
    mut speeds: ResMut<CameraSpeeds>,
    mut actions: ResMut<CameraActions>,
    mut state: ResMut<PanelState>,
) {
    let Ok(camera) = cameras.single() else {
        return;
    };
    // An edit already asked for this frame (a watched configuration's) is the one shown.
    let current = request.edited.unwrap_or(*camera);
    let mut edited = current;
    lens(ui, &mut edited, &mut state.lock_fov);
    if edited != current {
        request.edited = Some(edited);
    }

    let mut edited_speeds = *speeds;
    ui.horizontal(|ui| {
        ui.label("Move");
        ui.add(
            egui::DragValue::new(&mut edited_speeds.move_speed)
                .speed(0.01)
                .range(MOVE_SPEED_RANGE)
                .suffix(" radii/s"),
        );
        ui.label("Rotate");
        ui.add(
            egui::DragValue::new(&mut edited_speeds.rotate_speed)
                .speed(0.005)
                .range(ROTATE_SPEED_RANGE)
                .suffix(" °/px"),
        );
    });
    speeds.set_if_neq(edited_speeds);

    ui.horizontal(|ui| {
        if ui.button("Reset").clicked() {
            actions.0.push(CameraAction::Reset);
        }
        ui.weak(format!(
            "eye ({:.2}, {:.2}, {:.2})",
            edited.position.x, edited.position.y, edited.position.z
        ));
    });
}

fn lens(ui: &mut egui::Ui, camera: &mut Camera, lock: &mut bool) {
    ui.horizontal(|ui| {
        ui.label("Mode");
        for &mode in CameraMode::ALL {
            ui.selectable_value(&mut camera.mode, mode, mode.name());
        }
    });
    ui.checkbox(lock, "Lock hfov and vfov");
    let before = (camera.hfov, camera.vfov);
    for (fov, name) in [(&mut camera.hfov, "hfov"), (&mut camera.vfov, "vfov")] {
        ui.add(egui::Slider::new(fov, FOV_RANGE).text(name).suffix("°"));
    }
    let (from, to) = match camera.hfov != before.0 {
        true => (before.0, camera.hfov),
        false => (before.1, camera.vfov),
    };
    if *lock && from != to {
        // The one that moved zooms both, by the camera's one zoom rule (the scroll wheel's).
        (camera.hfov, camera.vfov) = before;
        zoom(camera, zoom_factor(from, to));
    }
    // Speeds proportional to the value: the planes range from 1e-4 to 1e6 between models.
    let (near, far) = (camera.near, camera.far);
    ui.horizontal(|ui| {
        ui.label("Near");
        ui.add(
            egui::DragValue::new(&mut camera.near)
                .speed(near * 0.01)
                .range(f32::MIN_POSITIVE..=far * 0.999),
        );
        ui.label("Far");
        ui.add(
            egui::DragValue::new(&mut camera.far)
                .speed(far * 0.01)
                .range(near * 1.001..=f32::MAX),
        );
    });
}

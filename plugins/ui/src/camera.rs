use bevy_ecs::prelude::*;
use close2gl_core::limits::{FOV_RANGE, MOVE_SPEED_RANGE, ROTATE_SPEED_RANGE};
use close2gl_core::{Camera, CameraAction, CameraActions, CameraMode, CameraSpeeds};

use crate::PanelState;

/// Mode, hfov and vfov (locked together or not), near, far, speeds, and reset.
pub fn section(ui: &mut egui::Ui, world: &mut World) {
    let mut cameras = world.query::<&mut Camera>();
    let Ok(camera) = cameras.single(world) else {
        return;
    };
    let original = *camera;
    let mut edited = original;
    lens(
        ui,
        &mut edited,
        &mut world.resource_mut::<PanelState>().lock_fov,
    );
    if edited != original
        && let Ok(mut camera) = cameras.single_mut(world)
    {
        *camera = edited;
    }

    if let Some(mut speeds) = world.get_resource::<CameraSpeeds>().copied() {
        ui.horizontal(|ui| {
            ui.label("Move");
            ui.add(
                egui::DragValue::new(&mut speeds.move_speed)
                    .speed(0.01)
                    .range(MOVE_SPEED_RANGE)
                    .suffix(" radii/s"),
            );
            ui.label("Rotate");
            ui.add(
                egui::DragValue::new(&mut speeds.rotate_speed)
                    .speed(0.005)
                    .range(ROTATE_SPEED_RANGE)
                    .suffix(" °/px"),
            );
        });
        crate::write_if_changed(world, &speeds);
    }

    ui.horizontal(|ui| {
        if ui.button("Reset").clicked()
            && let Some(mut actions) = world.get_resource_mut::<CameraActions>()
        {
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
    if *lock {
        // The one that moved drags the other by the same number of degrees.
        let delta = (camera.hfov - before.0) + (camera.vfov - before.1);
        camera.hfov = (before.0 + delta).clamp(*FOV_RANGE.start(), *FOV_RANGE.end());
        camera.vfov = (before.1 + delta).clamp(*FOV_RANGE.start(), *FOV_RANGE.end());
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

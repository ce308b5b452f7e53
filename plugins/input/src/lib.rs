//! The input plugin. It owns the mapping from raw input to intent: it reads `InputState` (keys
//! held and pressed, mouse drag, scroll, frame time), `InputBindings` and `CameraSpeeds`, and
//! writes `CameraActions` (moves scaled by the model's size, rotations, zoom, reset, mode toggle)
//! and, for the lecture's Shift+D / Shift+P / Shift+G keys, `Appearance::shading`, the inspector's
//! keys into `Overlay`, and the
//! tool keys (cheat sheet, screenshot, copy as command) into `ToolRequests`, and the outside
//! view's keys into `OutsideView::show` and `OutsideOrbit::whole_volume`. It knows no window
//! system: the viewer fills `InputState`, and so can a test. It owns `InputState` and
//! `InputBindings` and `ToolRequests`; the camera plugin provides the actions and speeds, the core's
//! `SettingsPlugin` the appearance and the overlay. Its system runs in `FrameSet::Input`.

mod outside_keys;

use bevy_ecs::prelude::*;
use close2gl_core::Owner;
use close2gl_core::{
    Action, App, Appearance, CameraAction, CameraActions, CameraSpeeds, FrameSet, InputBindings,
    InputState, Overlay, Plugin, Shading, ToolRequests, Update,
};

pub struct InputPlugin;

impl Plugin for InputPlugin {
    fn build(&self, app: &mut App) {
        app.init_resource::<InputState>()
            .init_resource::<InputBindings>()
            .init_resource::<ToolRequests>()
            .requires::<CameraActions>(Owner::Camera)
            .requires::<CameraSpeeds>(Owner::Camera)
            .requires::<Appearance>(Owner::Settings)
            .requires::<Overlay>(Owner::Settings)
            .add_systems(
                Update,
                (map_input, outside_keys::toggle_outside).in_set(FrameSet::Input),
            );
    }
}

/// A long stall (a window drag, a breakpoint) must not fling the camera away.
const MAX_DT: f32 = 0.1;
/// Held rotate keys turn this many times `rotate_speed` degrees per second.
const KEY_ROTATE_RATE: f32 = 360.0;
/// Each scroll line scales tan(fov/2) by this.
const ZOOM_PER_LINE: f32 = 0.9;

pub fn map_input(
    input: Res<InputState>,
    bindings: Res<InputBindings>,
    speeds: Res<CameraSpeeds>,
    mut actions: ResMut<CameraActions>,
    (mut look, mut overlay): (ResMut<Appearance>, ResMut<Overlay>),
    mut tools: ResMut<ToolRequests>,
) {
    let dt = input.dt.clamp(0.0, MAX_DT);
    // Held keys move the camera only without Shift, which belongs to the shading keys.
    let held = |action: Action| {
        !input.held.contains("shift") && bindings.keys(action).any(|key| input.held.contains(key))
    };
    let axis = |plus: Action, minus: Action| f32::from(held(plus)) - f32::from(held(minus));

    let step = speeds.move_speed * speeds.model_radius * dt;
    let (u, v, n) = (
        axis(Action::Right, Action::Left) * step,
        axis(Action::Up, Action::Down) * step,
        axis(Action::Back, Action::Forward) * step,
    );
    if (u, v, n) != (0.0, 0.0, 0.0) {
        actions.0.push(CameraAction::Translate { u, v, n });
    }

    let turn = (speeds.rotate_speed * KEY_ROTATE_RATE * dt).to_radians();
    let per_pixel = speeds.rotate_speed.to_radians();
    let pitch = axis(Action::PitchUp, Action::PitchDown) * turn - input.drag.y * per_pixel;
    let yaw = axis(Action::YawLeft, Action::YawRight) * turn - input.drag.x * per_pixel;
    let roll = axis(Action::RollLeft, Action::RollRight) * turn;
    if (pitch, yaw, roll) != (0.0, 0.0, 0.0) {
        actions.0.push(CameraAction::Rotate { pitch, yaw, roll });
    }

    if input.scroll != 0.0 {
        actions.0.push(CameraAction::Zoom {
            factor: ZOOM_PER_LINE.powf(input.scroll),
        });
    }

    for pressed in &input.pressed {
        apply_press(
            pressed,
            &bindings,
            &mut actions.0,
            (&mut look, &mut overlay),
            &mut tools,
        );
    }
}

/// One key press: a camera action, the lecture's shading keys, an overlay or a tool. `look`,
/// `overlay` and `tools`
/// are written only when one of their keys is pressed, so that they are not marked changed
/// every frame.
fn apply_press(
    pressed: &str,
    bindings: &InputBindings,
    actions: &mut Vec<CameraAction>,
    (look, overlay): (&mut ResMut<Appearance>, &mut ResMut<Overlay>),
    tools: &mut ResMut<ToolRequests>,
) {
    let is = |action: Action| bindings.matches(action, pressed);
    if is(Action::Reset) {
        actions.push(CameraAction::Reset);
    } else if is(Action::ToggleMode) {
        actions.push(CameraAction::ToggleMode);
    } else if is(Action::OriginalColor) {
        look.shading = Shading::None;
    } else if is(Action::Phong) {
        look.shading = Shading::Phong;
    } else if is(Action::Gouraud) {
        look.shading = Shading::GouraudAds;
    } else if is(Action::Help) {
        tools.toggle_help = true;
    } else if is(Action::Screenshot) {
        tools.screenshot = true;
    } else if is(Action::CopyCommand) {
        tools.copy_command = true;
    } else if is(Action::FateView) {
        **overlay = toggled(**overlay, Overlay::FateView);
    } else if is(Action::DifferenceView) {
        **overlay = toggled(**overlay, Overlay::Difference);
    }
}

/// `overlay` switched off if it is already shown, else shown in place of any other.
fn toggled(current: Overlay, overlay: Overlay) -> Overlay {
    if current == overlay {
        Overlay::Off
    } else {
        overlay
    }
}

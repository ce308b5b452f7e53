//! Whether an event is the panel's or the camera's, and the camera's events as `InputState`.

use bevy_ecs::world::World;
use close2gl_core::{InputState, ModelRequest, ModelSource, TextureRequest};
use close2gl_trace::view::TraceRequest;
use winit::event::{ElementState, MouseButton, WindowEvent};
use winit::window::{Window, WindowId};

use crate::gui::Gui;
use crate::input_tracker::InputTracker;

/// What the panel has taken: the keyboard (a text field has focus) and this pointer event (the
/// pointer is over the panel).
#[derive(Clone, Copy, Debug, Default)]
pub struct PanelTook {
    pub keys: bool,
    pub pointer: bool,
    /// The event came to the main window (the one with the panel).
    pub main: bool,
}

/// Hands `event` to the panel when it may be the panel's. Key presses reach egui only while a
/// text field has focus: otherwise egui would move its focus on Tab and click the focused button
/// on Space, and those keys are the camera's. Only the main window has the panel.
pub fn offer_to_panel(
    gui: &mut Gui,
    window: &Window,
    is_main: bool,
    event: &WindowEvent,
) -> PanelTook {
    let keys = is_main && gui.ctx.egui_wants_keyboard_input();
    let camera_key = matches!(event, WindowEvent::KeyboardInput { event, .. }
        if event.state == ElementState::Pressed && !keys);
    if !is_main || camera_key {
        return PanelTook {
            keys,
            pointer: false,
            main: is_main,
        };
    }
    let response = gui.on_event(window, event);
    if response.repaint {
        window.request_redraw();
    }
    PanelTook {
        keys,
        pointer: response.consumed,
        main: is_main,
    }
}

/// Turns what the panel did not take into input for the app: keys, drags and scrolls into
/// `InputState`, a dropped file into a `ModelRequest`. Returns whether a frame should follow.
pub fn apply_input(
    tracker: &mut InputTracker,
    world: &mut World,
    window: WindowId,
    event: WindowEvent,
    panel: PanelTook,
) -> bool {
    let mut input = world.resource_mut::<InputState>();
    match event {
        WindowEvent::KeyboardInput { event, .. } => {
            let pressed = event.state == ElementState::Pressed;
            if !(pressed && panel.keys) {
                let (key, logical) = (event.physical_key, &event.logical_key);
                tracker.key(&mut input, key, logical, pressed, event.repeat);
            }
        }
        WindowEvent::MouseInput {
            state,
            button: MouseButton::Left,
            ..
        } => {
            let pressed = state == ElementState::Pressed && !panel.pointer;
            if pressed && input.held.contains("ctrl") {
                // Ctrl+click probes the pixel instead of starting a drag.
                tracker.probe(&mut input, window, !panel.main);
            } else {
                tracker.button(pressed);
            }
        }
        WindowEvent::CursorMoved { position, .. } => {
            return tracker.cursor(&mut input, window, position);
        }
        WindowEvent::MouseWheel { delta, .. } if !panel.pointer => {
            tracker.scroll(&mut input, delta);
        }
        WindowEvent::DroppedFile(path) => drop_file(world, path),
        WindowEvent::Focused(false) => tracker.release_all(&mut input),
        _ => return false,
    }
    true
}

/// A dropped image becomes the texture, a `.trace` or `.raster` file the trace the views show
/// (the trace plugin tells a raster trace by its first line);
/// anything else is taken for a model (whose loader names what it expected when it is not one).
pub fn drop_file(world: &mut World, path: std::path::PathBuf) {
    let extension = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    if matches!(extension.as_deref(), Some("png" | "jpg" | "jpeg")) {
        world.insert_resource(TextureRequest(Some(path)));
    } else if matches!(extension.as_deref(), Some("trace" | "raster")) {
        world.insert_resource(TraceRequest(Some(path)));
    } else {
        world.insert_resource(ModelRequest(Some(ModelSource::File(path))));
    }
}

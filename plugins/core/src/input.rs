use std::collections::{BTreeMap, BTreeSet};

use bevy_ecs::prelude::*;
use glam::Vec2;

/// Raw input for this frame, in window-system-neutral names: keys are lower-case names such as
/// `"w"`, `"space"`, `"tab"`, `"shift"`. The viewer fills it from winit; tests fill it by hand.
#[derive(Resource, Clone, Debug, Default)]
pub struct InputState {
    /// Keys held down now.
    pub held: BTreeSet<String>,
    /// Keys that went down this frame (with the modifiers held at the time), e.g. `"shift+d"`.
    pub pressed: Vec<String>,
    /// Mouse movement while the button was held this frame, pixels (x right, y down).
    pub drag: Vec2,
    /// Scroll this frame, in lines (positive away from the user).
    pub scroll: f32,
    /// Seconds since the last frame.
    pub dt: f32,
    /// Where a Ctrl+click asked for the pixel probe this frame.
    pub probe: Option<ProbeClick>,
}

/// A Ctrl+click on a view: where, in the physical pixels of the window it was in.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProbeClick {
    pub at: Vec2,
    /// In the Close2GL window of the windows layout; else in the panel's window.
    pub close2gl_window: bool,
}

impl InputState {
    /// Clears the per-frame parts; held keys stay held.
    pub fn end_frame(&mut self) {
        self.pressed.clear();
        self.drag = Vec2::ZERO;
        self.scroll = 0.0;
        self.probe = None;
    }
}

/// Which key does what: action name → key name (e.g. `"forward" → "w"`, `"phong" → "shift+p"`).
#[derive(Resource, Clone, Debug, PartialEq, Eq)]
pub struct InputBindings(pub BTreeMap<String, String>);

impl InputBindings {
    /// Every bindable action with its default key.
    pub const DEFAULTS: [(&'static str, &'static str); 23] = [
        ("forward", "w"),
        ("back", "s"),
        ("left", "a"),
        ("right", "d"),
        ("up", "r"),
        ("down", "f"),
        ("roll_left", "z"),
        ("roll_right", "x"),
        ("pitch_up", "up"),
        ("pitch_down", "down"),
        ("yaw_left", "left"),
        ("yaw_right", "right"),
        ("reset", "space"),
        ("toggle_mode", "tab"),
        ("original_color", "shift+d"),
        ("phong", "shift+p"),
        ("gouraud", "shift+g"),
        ("help", "f1 ?"),
        ("screenshot", "f12"),
        ("copy_command", "c"),
        ("fate_view", "i"),
        ("difference_view", "v"),
        ("outside_view", "o"),
    ];

    /// The binding as written: one key, or several separated by spaces (`"f1 ?"`).
    pub fn key(&self, action: &str) -> Option<&str> {
        self.0.get(action).map(String::as_str)
    }

    /// Each key bound to `action`.
    pub fn keys<'a>(&'a self, action: &str) -> impl Iterator<Item = &'a str> {
        self.key(action).into_iter().flat_map(str::split_whitespace)
    }

    /// Whether `pressed` (a name from `InputState::pressed`) is one of `action`'s keys. A symbol
    /// typed with Shift ("?" on most layouts) also matches its binding without "shift+".
    pub fn matches(&self, action: &str, pressed: &str) -> bool {
        let symbol = |k: &str| k.chars().count() == 1 && !k.chars().all(char::is_alphanumeric);
        self.keys(action).any(|key| {
            key == pressed || (symbol(key) && pressed.strip_prefix("shift+") == Some(key))
        })
    }
}

impl Default for InputBindings {
    fn default() -> Self {
        Self(
            Self::DEFAULTS
                .iter()
                .map(|(a, k)| (a.to_string(), k.to_string()))
                .collect(),
        )
    }
}

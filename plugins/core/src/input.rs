//! The input that reaches systems: held and pressed actions, drags, the wheel and the probe's
//! click, and the bindings from keys to actions.

use std::collections::{BTreeSet, HashMap};

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

/// Declares [`Action`] and [`InputBindings::DEFAULTS`] from one list, so that an action and its
/// default key are written once, side by side.
macro_rules! actions {
    ($($variant:ident = $name:literal => $key:literal,)+) => {
        named_enum!(
            /// Everything a key can be bound to, by the name the config's `[input]` table uses: a
            /// typo is an unknown name there and a compile error in code.
            Action { $($variant = $name),+ }
        );

        impl InputBindings {
            /// Every bindable action with its default key, in the cheat sheet's order.
            pub const DEFAULTS: &'static [(Action, &'static str)] = &[$((Action::$variant, $key)),+];
        }
    };
}

// The cheat sheet's order: moves, turns, the camera's mode, shading, tools, the overlays.
actions! {
    Forward = "forward" => "w",
    Back = "back" => "s",
    Left = "left" => "a",
    Right = "right" => "d",
    Up = "up" => "r",
    Down = "down" => "f",

    RollLeft = "roll_left" => "z",
    RollRight = "roll_right" => "x",
    PitchUp = "pitch_up" => "up",
    PitchDown = "pitch_down" => "down",
    YawLeft = "yaw_left" => "left",
    YawRight = "yaw_right" => "right",

    Reset = "reset" => "space",
    ToggleMode = "toggle_mode" => "tab",

    OriginalColor = "original_color" => "shift+d",
    Phong = "phong" => "shift+p",
    Gouraud = "gouraud" => "shift+g",

    Help = "help" => "f1 ?",
    Screenshot = "screenshot" => "f12",
    CopyCommand = "copy_command" => "c",

    FateView = "fate_view" => "i",
    DifferenceView = "difference_view" => "v",
    OutsideView = "outside_view" => "o",
    OutsideWholeVolume = "outside_whole_volume" => "shift+o",
}

/// Which key does what: action → key name (e.g. `Forward → "w"`, `Phong → "shift+p"`).
#[derive(Resource, Clone, Debug, PartialEq, Eq)]
pub struct InputBindings(pub HashMap<Action, String>);

impl InputBindings {
    /// The binding as written: one key, or several separated by spaces (`"f1 ?"`).
    pub fn key(&self, action: Action) -> Option<&str> {
        self.0.get(&action).map(String::as_str)
    }

    /// Each key bound to `action`.
    pub fn keys(&self, action: Action) -> impl Iterator<Item = &str> {
        self.key(action).into_iter().flat_map(str::split_whitespace)
    }

    /// Whether `pressed` (a name from `InputState::pressed`) is one of `action`'s keys. A symbol
    /// typed with Shift ("?" on most layouts) also matches its binding without "shift+".
    pub fn matches(&self, action: Action, pressed: &str) -> bool {
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
                .map(|(a, k)| (*a, k.to_string()))
                .collect(),
        )
    }
}

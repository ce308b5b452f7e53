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

named_enum!(
    /// Everything a key can be bound to, by the name the config's `[input]` table uses: a typo
    /// is an unknown name there and a compile error in code.
    Action {
        Forward = "forward",
        Back = "back",
        Left = "left",
        Right = "right",
        Up = "up",
        Down = "down",
        RollLeft = "roll_left",
        RollRight = "roll_right",
        PitchUp = "pitch_up",
        PitchDown = "pitch_down",
        YawLeft = "yaw_left",
        YawRight = "yaw_right",
        Reset = "reset",
        ToggleMode = "toggle_mode",
        OriginalColor = "original_color",
        Phong = "phong",
        Gouraud = "gouraud",
        Help = "help",
        Screenshot = "screenshot",
        CopyCommand = "copy_command",
        FateView = "fate_view",
        DifferenceView = "difference_view",
        OutsideView = "outside_view",
        OutsideWholeVolume = "outside_whole_volume"
    }
);

/// Which key does what: action → key name (e.g. `Forward → "w"`, `Phong → "shift+p"`).
#[derive(Resource, Clone, Debug, PartialEq, Eq)]
pub struct InputBindings(pub HashMap<Action, String>);

impl InputBindings {
    /// Every bindable action with its default key, in the cheat sheet's order.
    pub const DEFAULTS: [(Action, &'static str); 24] = [
        (Action::Forward, "w"),
        (Action::Back, "s"),
        (Action::Left, "a"),
        (Action::Right, "d"),
        (Action::Up, "r"),
        (Action::Down, "f"),
        (Action::RollLeft, "z"),
        (Action::RollRight, "x"),
        (Action::PitchUp, "up"),
        (Action::PitchDown, "down"),
        (Action::YawLeft, "left"),
        (Action::YawRight, "right"),
        (Action::Reset, "space"),
        (Action::ToggleMode, "tab"),
        (Action::OriginalColor, "shift+d"),
        (Action::Phong, "shift+p"),
        (Action::Gouraud, "shift+g"),
        (Action::Help, "f1 ?"),
        (Action::Screenshot, "f12"),
        (Action::CopyCommand, "c"),
        (Action::FateView, "i"),
        (Action::DifferenceView, "v"),
        (Action::OutsideView, "o"),
        (Action::OutsideWholeVolume, "shift+o"),
    ];

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

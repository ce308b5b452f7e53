//! winit events → `InputState`, in the window-system-neutral names the input plugin binds.

use std::collections::HashMap;

use close2gl_core::glam::Vec2;
use close2gl_core::{InputState, ProbeClick};
use winit::dpi::PhysicalPosition;
use winit::event::MouseScrollDelta;
use winit::keyboard::{Key, NamedKey, PhysicalKey};
use winit::window::WindowId;

/// Pixels of a touchpad's smooth scroll that count as one wheel line.
const PIXELS_PER_LINE: f32 = 40.0;

/// The name a key is bound by: a character in lower case ("w", "d" also under Shift), or one of
/// the named keys below. `None` for keys nothing can bind.
pub fn key_name(key: &Key) -> Option<String> {
    let name = match key {
        Key::Character(text) => return Some(text.to_lowercase()),
        Key::Named(named) => match named {
            NamedKey::Space => "space",
            NamedKey::Tab => "tab",
            NamedKey::Enter => "enter",
            NamedKey::Escape => "escape",
            NamedKey::Backspace => "backspace",
            NamedKey::Delete => "delete",
            NamedKey::Insert => "insert",
            NamedKey::Home => "home",
            NamedKey::End => "end",
            NamedKey::PageUp => "pageup",
            NamedKey::PageDown => "pagedown",
            NamedKey::ArrowUp => "up",
            NamedKey::ArrowDown => "down",
            NamedKey::ArrowLeft => "left",
            NamedKey::ArrowRight => "right",
            NamedKey::Shift => "shift",
            NamedKey::Control => "ctrl",
            NamedKey::Alt => "alt",
            NamedKey::F1 => "f1",
            NamedKey::F2 => "f2",
            NamedKey::F3 => "f3",
            NamedKey::F4 => "f4",
            NamedKey::F5 => "f5",
            NamedKey::F6 => "f6",
            NamedKey::F7 => "f7",
            NamedKey::F8 => "f8",
            NamedKey::F9 => "f9",
            NamedKey::F10 => "f10",
            NamedKey::F11 => "f11",
            NamedKey::F12 => "f12",
            _ => return None,
        },
        _ => return None,
    };
    Some(name.to_string())
}

/// What `InputState` cannot hold between events: the name each physical key went down with
/// (so that a key released after Shift changed its character is still released), and the mouse
/// drag in progress.
#[derive(Debug, Default)]
pub struct InputTracker {
    down: HashMap<PhysicalKey, String>,
    dragging: bool,
    cursor: Option<(WindowId, PhysicalPosition<f64>)>,
}

impl InputTracker {
    /// A key went down or up. Repeats of a held key are not new presses.
    pub fn key(
        &mut self,
        input: &mut InputState,
        physical: PhysicalKey,
        logical: &Key,
        pressed: bool,
        repeat: bool,
    ) {
        if !pressed {
            if let Some(name) = self.down.remove(&physical) {
                input.held.remove(&name);
            }
            return;
        }
        let Some(name) = key_name(logical) else {
            return;
        };
        if repeat && self.down.contains_key(&physical) {
            return;
        }
        let pressed = if name != "shift" && input.held.contains("shift") {
            format!("shift+{name}")
        } else {
            name.clone()
        };
        input.pressed.push(pressed);
        input.held.insert(name.clone());
        self.down.insert(physical, name);
    }

    /// The left button: a press starts a drag (the caller passes `false` when the press belongs
    /// to the panel), a release ends it.
    pub fn button(&mut self, pressed: bool) {
        self.dragging = pressed;
    }

    /// A probe click: the pixel under the cursor in `window` (the panel's, or the Close2GL
    /// window of the windows layout), when the cursor was last seen there.
    pub fn probe(&self, input: &mut InputState, window: WindowId, close2gl_window: bool) {
        if let Some((w, position)) = self.cursor
            && w == window
        {
            input.probe = Some(ProbeClick {
                at: Vec2::new(position.x as f32, position.y as f32),
                close2gl_window,
            });
        }
    }

    /// The cursor moved in `window`; while dragging, the movement adds to `drag`. Returns whether
    /// it did.
    pub fn cursor(
        &mut self,
        input: &mut InputState,
        window: WindowId,
        position: PhysicalPosition<f64>,
    ) -> bool {
        let previous = self.cursor.replace((window, position));
        match previous {
            Some((w, last)) if self.dragging && w == window => {
                input.drag += Vec2::new((position.x - last.x) as f32, (position.y - last.y) as f32);
                true
            }
            _ => false,
        }
    }

    /// Wheel lines, positive away from the user.
    pub fn scroll(&mut self, input: &mut InputState, delta: MouseScrollDelta) {
        input.scroll += match delta {
            MouseScrollDelta::LineDelta(_, lines) => lines,
            MouseScrollDelta::PixelDelta(pixels) => pixels.y as f32 / PIXELS_PER_LINE,
        };
    }

    /// Focus went elsewhere: whatever was held will never be seen released.
    pub fn release_all(&mut self, input: &mut InputState) {
        self.down.clear();
        input.held.clear();
        self.dragging = false;
        self.cursor = None;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use winit::keyboard::KeyCode;

    fn press(t: &mut InputTracker, i: &mut InputState, code: KeyCode, key: Key) {
        t.key(i, PhysicalKey::Code(code), &key, true, false);
    }

    fn release(t: &mut InputTracker, i: &mut InputState, code: KeyCode, key: Key) {
        t.key(i, PhysicalKey::Code(code), &key, false, false);
    }

    fn held(i: &InputState) -> Vec<&str> {
        i.held.iter().map(String::as_str).collect()
    }

    #[test]
    fn keys_get_the_names_the_bindings_use() {
        let names = [
            (Key::Character("w".into()), Some("w")),
            (Key::Character("W".into()), Some("w")),
            (Key::Named(NamedKey::Space), Some("space")),
            (Key::Named(NamedKey::Tab), Some("tab")),
            (Key::Named(NamedKey::ArrowUp), Some("up")),
            (Key::Named(NamedKey::ArrowDown), Some("down")),
            (Key::Named(NamedKey::ArrowLeft), Some("left")),
            (Key::Named(NamedKey::ArrowRight), Some("right")),
            (Key::Named(NamedKey::Shift), Some("shift")),
            (Key::Named(NamedKey::F1), Some("f1")),
            (Key::Named(NamedKey::F13), None),
        ];
        for (key, name) in names {
            assert_eq!(key_name(&key).as_deref(), name, "{key:?}");
        }
        for (action, key) in close2gl_core::InputBindings::DEFAULTS {
            let bare = key.trim_start_matches("shift+");
            let winit_key = match bare {
                "space" => Key::Named(NamedKey::Space),
                "tab" => Key::Named(NamedKey::Tab),
                "up" => Key::Named(NamedKey::ArrowUp),
                "down" => Key::Named(NamedKey::ArrowDown),
                "left" => Key::Named(NamedKey::ArrowLeft),
                "right" => Key::Named(NamedKey::ArrowRight),
                "f1" => Key::Named(NamedKey::F1),
                "f12" => Key::Named(NamedKey::F12),
                letter => Key::Character(letter.into()),
            };
            assert_eq!(key_name(&winit_key).as_deref(), Some(bare), "{action:?}");
        }
    }

    #[test]
    fn held_keys_stay_until_released_and_presses_last_one_frame() {
        let (mut t, mut i) = (InputTracker::default(), InputState::default());
        press(&mut t, &mut i, KeyCode::KeyW, Key::Character("w".into()));
        t.key(
            &mut i,
            PhysicalKey::Code(KeyCode::KeyW),
            &Key::Character("w".into()),
            true,
            true,
        );
        press(
            &mut t,
            &mut i,
            KeyCode::ArrowLeft,
            Key::Named(NamedKey::ArrowLeft),
        );
        assert_eq!(held(&i), ["left", "w"]);
        assert_eq!(i.pressed, ["w", "left"], "a repeat is not a new press");
        i.end_frame();
        assert!(i.pressed.is_empty());
        assert_eq!(held(&i), ["left", "w"]);
        release(&mut t, &mut i, KeyCode::KeyW, Key::Character("w".into()));
        assert_eq!(held(&i), ["left"]);
    }

    #[test]
    fn shift_prefixes_presses_and_a_key_releases_under_another_character() {
        let (mut t, mut i) = (InputTracker::default(), InputState::default());
        press(
            &mut t,
            &mut i,
            KeyCode::ShiftLeft,
            Key::Named(NamedKey::Shift),
        );
        press(&mut t, &mut i, KeyCode::KeyP, Key::Character("P".into()));
        assert_eq!(i.pressed, ["shift", "shift+p"]);
        assert_eq!(held(&i), ["p", "shift"]);
        release(
            &mut t,
            &mut i,
            KeyCode::ShiftLeft,
            Key::Named(NamedKey::Shift),
        );
        // Shift is up, so the same key now reports "p": the release still finds what went down.
        press(&mut t, &mut i, KeyCode::Digit1, Key::Character("1".into()));
        release(&mut t, &mut i, KeyCode::KeyP, Key::Character("p".into()));
        assert_eq!(held(&i), ["1"]);
        t.release_all(&mut i);
        assert!(i.held.is_empty());
    }

    #[test]
    fn the_mouse_drags_only_while_the_button_is_down_and_scrolls_in_lines() {
        let (mut t, mut i) = (InputTracker::default(), InputState::default());
        let window = WindowId::dummy();
        assert!(!t.cursor(&mut i, window, PhysicalPosition::new(10.0, 10.0)));
        t.button(true);
        assert!(t.cursor(&mut i, window, PhysicalPosition::new(14.0, 7.0)));
        assert!(t.cursor(&mut i, window, PhysicalPosition::new(20.0, 7.0)));
        t.button(false);
        assert!(!t.cursor(&mut i, window, PhysicalPosition::new(50.0, 50.0)));
        assert_eq!(i.drag, Vec2::new(10.0, -3.0));
        t.scroll(&mut i, MouseScrollDelta::LineDelta(0.0, 2.0));
        t.scroll(
            &mut i,
            MouseScrollDelta::PixelDelta(PhysicalPosition::new(0.0, -PIXELS_PER_LINE as f64)),
        );
        assert_eq!(i.scroll, 1.0);
    }
}

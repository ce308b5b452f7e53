//! The outside view's orbit camera takes the drags that start over it and the scrolls over it;
//! everything else stays the main camera's. It writes `OutsideOrbit` directly: the orbit is the
//! illustration's own camera, not an action of the Close2GL camera's.

use bevy_ecs::world::World;
use close2gl_core::OutsideOrbit;
use winit::dpi::PhysicalPosition;
use winit::event::{ElementState, MouseButton, MouseScrollDelta, WindowEvent};

use crate::routing::PanelTook;
use crate::view_layout::PixelRect;

/// Pixels of a touchpad's smooth scroll that count as one wheel line (as for the main camera).
const PIXELS_PER_LINE: f32 = 40.0;

/// The drag in progress over the outside view, and where the pointer is in the main window.
#[derive(Debug, Default)]
pub struct OrbitInput {
    dragging: bool,
    cursor: Option<PhysicalPosition<f64>>,
}

impl OrbitInput {
    /// Offers a main-window `event` to the orbit, with the outside view's `area` when it shows.
    /// Returns `(taken, redraw)`: a taken event is not the main camera's.
    pub fn offer(
        &mut self,
        world: &mut World,
        area: Option<PixelRect>,
        event: &WindowEvent,
        panel: PanelTook,
    ) -> (bool, bool) {
        let over =
            |p: Option<PhysicalPosition<f64>>| area.zip(p).is_some_and(|(a, p)| contains(a, p));
        match event {
            WindowEvent::CursorMoved { position, .. } => {
                let last = self.cursor.replace(*position);
                let (Some(last), true) = (last, self.dragging) else {
                    return (false, false);
                };
                let (dx, dy) = (position.x - last.x, position.y - last.y);
                orbit(world).drag(dx as f32, dy as f32);
                // Not taken: the main camera's tracker follows the pointer too (it is not
                // dragging, so it adds nothing).
                (false, true)
            }
            WindowEvent::MouseInput {
                state,
                button: MouseButton::Left,
                ..
            } => {
                let press = *state == ElementState::Pressed;
                self.dragging = press && !panel.pointer && over(self.cursor);
                (self.dragging, false)
            }
            WindowEvent::MouseWheel { delta, .. } if !panel.pointer && over(self.cursor) => {
                let lines = match delta {
                    MouseScrollDelta::LineDelta(_, lines) => *lines,
                    MouseScrollDelta::PixelDelta(pixels) => pixels.y as f32 / PIXELS_PER_LINE,
                };
                orbit(world).scroll(lines);
                (true, true)
            }
            WindowEvent::Focused(false) => {
                self.dragging = false;
                (false, false)
            }
            _ => (false, false),
        }
    }
}

fn orbit(world: &mut World) -> bevy_ecs::world::Mut<'_, OutsideOrbit> {
    world.get_resource_or_insert_with(OutsideOrbit::default)
}

fn contains(area: PixelRect, p: PhysicalPosition<f64>) -> bool {
    let (x, y) = (p.x, p.y);
    x >= area.x as f64
        && y >= area.y as f64
        && x < (area.x + area.width) as f64
        && y < (area.y + area.height) as f64
}

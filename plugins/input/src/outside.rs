use bevy_ecs::prelude::*;
use close2gl_core::{InputBindings, InputState, OutsideView};

/// The `outside_view` key shows or hides the outside view. `OutsideView` is written only when
/// the key is pressed, so that it is not marked changed every frame.
pub fn toggle_outside(
    input: Res<InputState>,
    bindings: Res<InputBindings>,
    mut outside: ResMut<OutsideView>,
) {
    let presses = input
        .pressed
        .iter()
        .filter(|pressed| bindings.matches("outside_view", pressed))
        .count();
    if presses % 2 == 1 {
        outside.show = !outside.show;
    }
}

//! The outside view's keys: show it or hide it, and switch what its orbit camera frames.

use bevy_ecs::prelude::*;
use close2gl_core::{Action, InputBindings, InputState, OutsideOrbit, OutsideView};

/// The `outside_view` key shows or hides the outside view, and `outside_whole_volume` switches
/// its framing between the model with the near plane and the whole volume (the settings
/// plugin's `OutsideView` and `OutsideOrbit`; an app without them has no outside view). Each is
/// written only when its key is pressed, so that it is not marked changed every frame.
pub fn toggle_outside(
    input: Res<InputState>,
    bindings: Res<InputBindings>,
    outside: Option<ResMut<OutsideView>>,
    orbit: Option<ResMut<OutsideOrbit>>,
) {
    // Pressed twice in one frame is no change.
    let toggled = |action| {
        let presses = input.pressed.iter().filter(|p| bindings.matches(action, p));
        presses.count() % 2 == 1
    };
    if let Some(mut outside) = outside.filter(|_| toggled(Action::OutsideView)) {
        outside.show = !outside.show;
    }
    if let Some(mut orbit) = orbit.filter(|_| toggled(Action::OutsideWholeVolume)) {
        orbit.whole_volume = !orbit.whole_volume;
    }
}

#[cfg(test)]
mod tests {
    use bevy_ecs::system::RunSystemOnce;

    use super::*;

    /// Whether the view shows and frames the whole volume after `key`.
    fn press(world: &mut World, key: &str) -> (bool, bool) {
        world.resource_mut::<InputState>().pressed = vec![key.to_string()];
        world
            .run_system_once(toggle_outside)
            .expect("the system runs");
        (
            world.resource::<OutsideView>().show,
            world.resource::<OutsideOrbit>().whole_volume,
        )
    }

    #[test]
    fn the_bound_keys_show_the_outside_view_and_switch_its_framing() {
        let mut world = World::new();
        world.init_resource::<InputBindings>();
        world.init_resource::<InputState>();
        world.init_resource::<OutsideView>();
        world.init_resource::<OutsideOrbit>();
        assert_eq!(press(&mut world, "o"), (true, false));
        assert_eq!(press(&mut world, "shift+o"), (true, true));
        assert_eq!(press(&mut world, "shift+o"), (true, false));
        assert_eq!(press(&mut world, "o"), (false, false));
        world
            .resource_mut::<InputBindings>()
            .0
            .insert(Action::OutsideView, "f5".into());
        assert_eq!(press(&mut world, "o"), (false, false), "no longer bound");
        assert_eq!(press(&mut world, "f5"), (true, false));
    }
}

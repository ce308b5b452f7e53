use bevy_ecs::prelude::*;
use close2gl_core::{Action, InputBindings, InputState, OutsideView};

/// The `outside_view` key shows or hides the outside view (the settings plugin's `OutsideView`;
/// an app without it has no outside view to show). `OutsideView` is written only when the key
/// is pressed, so that it is not marked changed every frame.
pub fn toggle_outside(
    input: Res<InputState>,
    bindings: Res<InputBindings>,
    outside: Option<ResMut<OutsideView>>,
) {
    let presses = input
        .pressed
        .iter()
        .filter(|pressed| bindings.matches(Action::OutsideView, pressed))
        .count();
    if let Some(mut outside) = outside.filter(|_| presses % 2 == 1) {
        outside.show = !outside.show;
    }
}

#[cfg(test)]
mod tests {
    use bevy_ecs::system::RunSystemOnce;

    use super::*;

    fn press(world: &mut World, key: &str) -> bool {
        world.resource_mut::<InputState>().pressed = vec![key.to_string()];
        world
            .run_system_once(toggle_outside)
            .expect("the system runs");
        world.resource::<OutsideView>().show
    }

    #[test]
    fn the_bound_key_shows_and_hides_the_outside_view() {
        let mut world = World::new();
        world.init_resource::<InputBindings>();
        world.init_resource::<InputState>();
        world.init_resource::<OutsideView>();
        assert!(press(&mut world, "o"));
        assert!(!press(&mut world, "o"));
        world
            .resource_mut::<InputBindings>()
            .0
            .insert(Action::OutsideView, "f5".into());
        assert!(!press(&mut world, "o"), "no longer bound");
        assert!(press(&mut world, "f5"));
    }
}

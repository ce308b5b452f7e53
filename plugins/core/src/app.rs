use std::any::TypeId;
use std::collections::HashSet;

use bevy_ecs::prelude::*;
use bevy_ecs::schedule::{InternedScheduleLabel, IntoScheduleConfigs, ScheduleLabel};
use bevy_ecs::system::ScheduleSystem;

/// Runs once, before the first frame.
#[derive(ScheduleLabel, Clone, Debug, PartialEq, Eq, Hash)]
pub struct Startup;
/// Turns raw input into actions.
#[derive(ScheduleLabel, Clone, Debug, PartialEq, Eq, Hash)]
pub struct PreUpdate;
/// Applies actions: camera moves, model loads, settings change.
#[derive(ScheduleLabel, Clone, Debug, PartialEq, Eq, Hash)]
pub struct Update;
/// Derives per-frame data from the updated state (the Close2GL pipeline runs here).
#[derive(ScheduleLabel, Clone, Debug, PartialEq, Eq, Hash)]
pub struct PostUpdate;
/// Draws: GPU systems only, so a headless world may leave it empty.
#[derive(ScheduleLabel, Clone, Debug, PartialEq, Eq, Hash)]
pub struct Render;

/// The schedules `App::update` runs every frame, in order.
pub fn frame_schedules() -> [InternedScheduleLabel; 4] {
    [
        PreUpdate.intern(),
        Update.intern(),
        PostUpdate.intern(),
        Render.intern(),
    ]
}

/// A unit of behaviour, added the bevy way: `app.add_plugins(MyPlugin)`.
pub trait Plugin: 'static {
    fn build(&self, app: &mut App);
}

type Runner = Box<dyn FnOnce(App) -> Result<(), String>>;

/// A World, its named schedules and the plugins that filled them. Small on purpose: bevy_app's
/// job without its weight.
pub struct App {
    world: World,
    plugins: HashSet<TypeId>,
    started: bool,
    runner: Option<Runner>,
}

impl Default for App {
    fn default() -> Self {
        Self::new()
    }
}

impl App {
    pub fn new() -> Self {
        let mut world = World::new();
        world.add_schedule(Schedule::new(Startup));
        for label in frame_schedules() {
            world.add_schedule(Schedule::new(label));
        }
        Self {
            world,
            plugins: HashSet::new(),
            started: false,
            runner: None,
        }
    }

    /// Builds a plugin once; adding the same plugin type again is a no-op, so plugin groups may
    /// overlap.
    pub fn add_plugins<P: Plugin>(&mut self, plugin: P) -> &mut Self {
        if self.plugins.insert(TypeId::of::<P>()) {
            plugin.build(self);
        }
        self
    }

    pub fn add_systems<M>(
        &mut self,
        schedule: impl ScheduleLabel,
        systems: impl IntoScheduleConfigs<ScheduleSystem, M>,
    ) -> &mut Self {
        self.world
            .get_resource_or_init::<Schedules>()
            .add_systems(schedule, systems);
        self
    }

    pub fn insert_resource<R: Resource>(&mut self, resource: R) -> &mut Self {
        self.world.insert_resource(resource);
        self
    }

    pub fn init_resource<R: Resource + FromWorld>(&mut self) -> &mut Self {
        self.world.init_resource::<R>();
        self
    }

    pub fn world(&self) -> &World {
        &self.world
    }

    pub fn world_mut(&mut self) -> &mut World {
        &mut self.world
    }

    /// Runs one frame: `Startup` the first time, then every frame schedule in order.
    pub fn update(&mut self) {
        if !self.started {
            self.started = true;
            self.world.run_schedule(Startup);
        }
        for label in frame_schedules() {
            self.world.run_schedule(label);
        }
    }

    /// Replaces what `run` does (the viewer installs its event loop here).
    pub fn set_runner(&mut self, runner: impl FnOnce(App) -> Result<(), String> + 'static) {
        self.runner = Some(Box::new(runner));
    }

    /// Hands the app to its runner; with none, runs a single frame.
    pub fn run(mut self) -> Result<(), String> {
        match self.runner.take() {
            Some(runner) => runner(self),
            None => {
                self.update();
                Ok(())
            }
        }
    }
}

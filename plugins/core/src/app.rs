//! The app: a bevy_ecs world and its one frame schedule, the `Plugin` trait, and `requires`
//! with `Owner`, which say which plugin provides what another one needs.

use std::any::TypeId;
use std::collections::HashSet;

use bevy_ecs::prelude::*;
use bevy_ecs::schedule::{IntoScheduleConfigs, ScheduleLabel};
use bevy_ecs::system::ScheduleSystem;

use crate::schedule::{Update, frame_schedule};

/// A unit of behaviour, added the bevy way: `app.add_plugins(MyPlugin)`. A plain
/// `fn(&mut App)` (or closure) is a plugin too.
pub trait Plugin: 'static {
    fn build(&self, app: &mut App);

    /// What errors call the plugin.
    fn name(&self) -> &str {
        std::any::type_name::<Self>()
    }

    /// Whether adding the plugin a second time is a mistake: it would add its systems twice, and
    /// its data (if any differs) would silently lose to the first. A plugin meant to be added
    /// several times, each time with its own data, returns false.
    fn is_unique(&self) -> bool {
        true
    }
}

impl<F: Fn(&mut App) + 'static> Plugin for F {
    fn build(&self, app: &mut App) {
        self(app);
    }
}

type Runner = Box<dyn FnOnce(App) -> Result<(), String>>;

named_enum!(
    /// The plugins that own a resource another plugin requires: a requirement names its owner by
    /// this, and the error for a missing resource names the plugin to add.
    Owner {
        Settings = "SettingsPlugin",
        Model = "ModelPlugin",
        Camera = "CameraPlugin",
        Close2gl = "Close2glPlugin",
        Input = "InputPlugin"
    }
);

/// A resource a plugin reads but another plugin owns, checked before the first frame.
struct Requirement {
    present: fn(&World) -> bool,
    resource: &'static str,
    by: &'static str,
    owner: Owner,
}

/// A World, its frame schedule and the plugins that filled it. Small on purpose: bevy_app's
/// job without its weight.
pub struct App {
    world: World,
    plugins: HashSet<TypeId>,
    requirements: Vec<Requirement>,
    /// The plugins being built, innermost last: who declares a requirement.
    building: Vec<&'static str>,
    started: bool,
    runner: Option<Runner>,
}

impl Default for App {
    fn default() -> Self {
        Self::new()
    }
}

impl App {
    /// An empty world with the frame's schedule, its [`crate::FrameSet`]s in order.
    pub fn new() -> Self {
        let mut world = World::new();
        world.add_schedule(frame_schedule());
        Self {
            world,
            plugins: HashSet::new(),
            requirements: Vec::new(),
            building: Vec::new(),
            started: false,
            runner: None,
        }
    }

    /// Builds `plugin`. Adding a unique plugin (see [`Plugin::is_unique`]) again is a programming
    /// error, so it panics naming the plugin, as bevy does; a group that may overlap another
    /// uses [`App::add_plugin_once`].
    pub fn add_plugins<P: Plugin>(&mut self, plugin: P) -> &mut Self {
        let first = self.plugins.insert(TypeId::of::<P>());
        if !first && plugin.is_unique() {
            panic!(
                "the plugin {} was added twice: a plugin is built once per app (a plugin meant \
                 to be added more than once overrides Plugin::is_unique)",
                plugin.name()
            );
        }
        self.building.push(short_type_name::<P>());
        plugin.build(self);
        self.building.pop();
        self
    }

    /// Builds `plugin` unless one of its type is already in the app: for groups that may overlap
    /// (two groups both needing the GPU plugin), where the second copy would carry the same data.
    pub fn add_plugin_once<P: Plugin>(&mut self, plugin: P) -> &mut Self {
        if !self.is_plugin_added::<P>() {
            self.add_plugins(plugin);
        }
        self
    }

    /// Whether a plugin of this type has been added.
    pub fn is_plugin_added<P: Plugin>(&self) -> bool {
        self.plugins.contains(&TypeId::of::<P>())
    }

    /// Declares that the plugin being built reads resource `R`, which the plugin `owner` owns.
    /// Before the first frame the app checks that `R` exists (added by the owner, or inserted by
    /// hand) and otherwise names the missing plugin and the one that needs it (by its type).
    pub fn requires<R: Resource>(&mut self, owner: Owner) -> &mut Self {
        self.requirements.push(Requirement {
            present: |world| world.contains_resource::<R>(),
            resource: short_type_name::<R>(),
            by: self.building.last().copied().unwrap_or("the app"),
            owner,
        });
        self
    }

    /// Every declared requirement met, or a message naming the first resource missing, who
    /// needs it and which plugin provides it.
    pub fn check_requirements(&self) -> Result<(), String> {
        match self.requirements.iter().find(|r| !(r.present)(&self.world)) {
            None => Ok(()),
            Some(r) => Err(format!(
                "{} needs the {} resource: add {} (or insert {} yourself)",
                r.by,
                r.resource,
                r.owner.name(),
                r.resource
            )),
        }
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

    /// Runs one frame: the [`Update`] schedule. The first frame panics when a plugin's
    /// requirement is not met (see [`App::requires`]): a missing plugin is a programming error,
    /// and the message names it.
    pub fn update(&mut self) {
        if !self.started {
            if let Err(message) = self.check_requirements() {
                panic!("{message}");
            }
            self.started = true;
        }
        self.world.run_schedule(Update);
    }

    /// Replaces what `run` does (the viewer installs its event loop here).
    pub fn set_runner(&mut self, runner: impl FnOnce(App) -> Result<(), String> + 'static) {
        self.runner = Some(Box::new(runner));
    }

    /// Hands the app to its runner (after checking the plugins' requirements); with none, runs
    /// a single frame.
    pub fn run(mut self) -> Result<(), String> {
        self.check_requirements()?;
        match self.runner.take() {
            Some(runner) => runner(self),
            None => {
                self.update();
                Ok(())
            }
        }
    }
}

/// `close2gl_core::settings::PipelineSettings` → `PipelineSettings`.
fn short_type_name<T>() -> &'static str {
    let full = std::any::type_name::<T>();
    full.rsplit("::").next().unwrap_or(full)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{FrameSet, OutputStep, Update};

    #[derive(Resource, Default)]
    struct Log(Vec<&'static str>);

    struct Adds(&'static str);

    impl Plugin for Adds {
        fn build(&self, app: &mut App) {
            app.init_resource::<Log>();
            app.world_mut().resource_mut::<Log>().0.push(self.0);
        }
    }

    struct Repeatable(&'static str);

    impl Plugin for Repeatable {
        fn build(&self, app: &mut App) {
            Adds(self.0).build(app);
        }

        fn is_unique(&self) -> bool {
            false
        }
    }

    #[test]
    #[should_panic(expected = "the plugin close2gl_core::app::tests::Adds was added twice")]
    fn adding_a_plugin_twice_panics_naming_it() {
        App::new()
            .add_plugins(Adds("first"))
            .add_plugins(Adds("second"));
    }

    #[test]
    fn a_plugin_that_is_not_unique_is_built_every_time() {
        let mut app = App::new();
        app.add_plugins(Repeatable("a"))
            .add_plugins(Repeatable("b"));
        assert_eq!(app.world().resource::<Log>().0, ["a", "b"]);
        assert!(app.is_plugin_added::<Repeatable>());
        assert!(!app.is_plugin_added::<Adds>());
    }

    #[test]
    fn a_function_is_a_plugin() {
        fn hello(app: &mut App) {
            app.init_resource::<Log>();
        }
        let mut app = App::new();
        app.add_plugins(hello);
        assert!(app.world().contains_resource::<Log>());
    }

    #[test]
    fn a_missing_requirement_names_the_resource_and_its_plugin() {
        let mut app = App::new();
        struct ReaderPlugin;
        impl Plugin for ReaderPlugin {
            fn build(&self, app: &mut App) {
                app.requires::<Log>(Owner::Settings);
            }
        }
        app.add_plugins(ReaderPlugin);
        assert_eq!(
            app.check_requirements(),
            Err(
                "ReaderPlugin needs the Log resource: add SettingsPlugin (or insert Log yourself)"
                    .into()
            )
        );
        app.init_resource::<Log>();
        assert_eq!(app.check_requirements(), Ok(()));
    }

    #[test]
    fn the_sets_run_in_order_whatever_order_the_systems_were_added_in() {
        let mut app = App::new();
        app.init_resource::<Log>();
        for set in FrameSet::ALL.into_iter().rev() {
            let name = match set {
                FrameSet::Input => "input",
                FrameSet::Panel => "panel",
                FrameSet::Load => "load",
                FrameSet::Camera => "camera",
                FrameSet::Close2gl => "close2gl",
                FrameSet::Output => "output",
            };
            app.add_systems(
                Update,
                (move |mut log: ResMut<Log>| log.0.push(name)).in_set(set),
            );
        }
        app.update();
        assert_eq!(
            app.world().resource::<Log>().0,
            ["input", "panel", "load", "camera", "close2gl", "output"]
        );
    }

    #[test]
    fn a_report_sees_the_frame_as_uploaded() {
        let mut app = App::new();
        app.init_resource::<Log>();
        for (step, name) in [
            (OutputStep::Report, "report"),
            (OutputStep::Upload, "upload"),
        ] {
            app.add_systems(
                Update,
                (move |mut log: ResMut<Log>| log.0.push(name)).in_set(step),
            );
        }
        app.update();
        assert_eq!(app.world().resource::<Log>().0, ["upload", "report"]);
    }
}

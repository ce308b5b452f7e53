//! The world as the panel's layout sees it: a place to run the panel's parts. Each section, and
//! each thing painted over the views, is a system of its own (`Res`, `ResMut`, `Query`: its
//! parameters say what it reads and writes) taking the `egui::Ui` it draws in as its input;
//! [`Parts`] runs them one after another, so that two may write the same resource.

use bevy_ecs::prelude::*;
use close2gl_core::CommandLine;

/// The panel system's world, lent to the layout for one frame.
pub struct Parts<'w>(pub &'w mut World);

impl Parts<'_> {
    /// Runs `part` with `input` (the `Ui` it draws in, and what else it is handed) and returns
    /// its answer. A part whose resources the app lacks (no trace plugin, a test's bare app) is
    /// left out, as it has nothing to show: `None`.
    pub fn run<I, O, M>(
        &mut self,
        part: impl IntoSystem<I, O, M> + 'static,
        input: I::Inner<'_>,
    ) -> Option<O>
    where
        I: SystemInput + 'static,
        O: 'static,
    {
        self.0.run_system_cached_with(part, input).ok()
    }

    /// The `close2gl render` command for what the views show, writing its images to `out`: the
    /// app's writer ([`CommandLine`]), which reads the whole world; `None` without a writer or
    /// before anything shows.
    pub fn command(&mut self, out: &str) -> Option<String> {
        let write = self.0.get_resource::<CommandLine>()?.0;
        write(self.0, out)
    }
}

//! The user's tools asked for this frame, by a key or a panel button: the input plugin and the
//! panel set them, the viewer (screenshot) and the panel (copy as command, key cheat sheet)
//! carry them out and clear them.

use bevy_ecs::prelude::*;

#[derive(Resource, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ToolRequests {
    /// Save both views as PNGs, with the command that reproduces them beside.
    pub screenshot: bool,
    /// Put the command that reproduces the views on the clipboard and the terminal.
    pub copy_command: bool,
    /// Show or hide the key cheat sheet.
    pub toggle_help: bool,
    /// Compare the two views' pixels once more (their coverage agreement, as `close2gl render`
    /// computes it), without saving them.
    pub compare_views: bool,
    /// In a browser: open the page's file chooser (a model, an image, a trace).
    pub open_file: bool,
}

/// In a browser: the page's link to what the views show (model, camera and settings in its
/// fragment), kept current by the page, for the panel's Copy link.
#[derive(Resource, Clone, Debug, Default, PartialEq)]
pub struct PageLink(pub String);

/// How the views are written as a `close2gl render` command writing its images to the directory
/// given (copy as command, the screenshot key). Written in `plugins/config/src/command.rs`
/// (`close2gl_config::command`, whose `CommandPlugin` inserts it), from the same key table the
/// configuration is read with. `None` before anything shows.
#[derive(Resource, Clone, Copy)]
pub struct CommandLine(pub fn(&mut World, &str) -> Option<String>);

impl ToolRequests {
    pub fn any(&self) -> bool {
        self.screenshot
            || self.copy_command
            || self.toggle_help
            || self.compare_views
            || self.open_file
    }
}

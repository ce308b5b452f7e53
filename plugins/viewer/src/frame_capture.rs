//! What a frame keeps of itself besides showing it. Asked before the drawing (the window on
//! `--screenshot`'s frame; each view when the screenshot key or a comparison of the views asks,
//! `ToolRequests`), captured while drawing (`present.rs`), and kept once back from the GPU (in
//! a browser, frames later): the window's PNG, the views compared into `ViewStats`, and saved
//! beside the command that renders them again when the key asked. The capture follows the
//! drawing, which follows the frame's systems, so this is a step of the viewer's, not a system:
//! a replay's last frame must write its shot before the run ends.

use bevy_ecs::world::World;
use close2gl_core::ToolRequests;
use close2gl_core::parity::CoverageComparison;
use close2gl_gpu::Gpu;
use close2gl_ui::{Notice, ViewStats};

use crate::ViewerOptions;
use crate::present::{Capture, PendingShot, Shot};

/// The captures asked for and not yet kept.
#[derive(Default)]
pub struct FrameCapture {
    /// A frame's capture still on its way back from the GPU (in a browser, where it cannot be
    /// waited for).
    shot: Option<PendingShot>,
    /// The screenshot key asked for the views being captured: they are saved when they arrive.
    save_views: bool,
}

impl FrameCapture {
    /// What frame number `frame` keeps of itself: the window for `--screenshot` on its frame,
    /// each view when the screenshot key (or button) asked, or a comparison of the views.
    pub fn asked(&mut self, options: &ViewerOptions, frame: u32, world: &mut World) -> Capture {
        let (key, compare) = match world.get_resource_mut::<ToolRequests>() {
            Some(mut tools) => (
                std::mem::take(&mut tools.screenshot),
                std::mem::take(&mut tools.compare_views),
            ),
            None => (false, false),
        };
        let capture = if options.screenshot.is_some() && options.screenshot_frame == Some(frame + 1)
        {
            Capture::Window
        } else if key || compare {
            Capture::Views
        } else {
            Capture::Nothing
        };
        self.save_views |= key && capture == Capture::Views;
        capture
    }

    /// Keeps the shot `drawn` this frame, or in a browser one drawn before that has now arrived.
    pub fn keep(
        &mut self,
        options: &ViewerOptions,
        world: &mut World,
        gpu: &Gpu,
        drawn: Option<PendingShot>,
    ) -> Result<(), String> {
        let Some(shot) = arrived_shot(&mut self.shot, drawn, gpu)? else {
            return Ok(());
        };
        let save_views = matches!(shot, Shot::Views { .. }) && std::mem::take(&mut self.save_views);
        save(options, world, shot, save_views)
    }

    /// Whether a capture is still on its way back from the GPU (the viewer draws until it has
    /// arrived).
    pub fn waiting(&self) -> bool {
        self.shot.is_some()
    }
}

/// The frame's shot, or in a browser one captured before that has now arrived (`waiting` holds
/// it meanwhile; a newer capture replaces it).
#[cfg(not(target_arch = "wasm32"))]
fn arrived_shot(
    _waiting: &mut Option<PendingShot>,
    drawn: Option<PendingShot>,
    gpu: &Gpu,
) -> Result<Option<Shot>, String> {
    drawn.map_or(Ok(None), |pending| pending.wait(gpu))
}

#[cfg(target_arch = "wasm32")]
fn arrived_shot(
    waiting: &mut Option<PendingShot>,
    drawn: Option<PendingShot>,
    gpu: &Gpu,
) -> Result<Option<Shot>, String> {
    if drawn.is_some() {
        *waiting = drawn;
    }
    let Some(pending) = waiting else {
        return Ok(None);
    };
    match pending.finish(gpu) {
        None => Ok(None),
        Some(shot) => {
            *waiting = None;
            shot
        }
    }
}

/// Writes what the frame captured: the window where `--screenshot` says, or both views (the
/// screenshot key) beside the command that renders them again, with a notice naming the files.
fn save(
    options: &ViewerOptions,
    world: &mut World,
    shot: Shot,
    save_views: bool,
) -> Result<(), String> {
    match (shot, &options.screenshot) {
        (Shot::Window(image), Some(path)) => image.write_png(path),
        (
            Shot::Views {
                reference,
                close2gl,
            },
            _,
        ) => {
            // Captured with alpha 0 where a view drew nothing: its coverage.
            let compared = CoverageComparison::of_images(&reference, &close2gl);
            world.resource_mut::<ViewStats>().coverage_agreement =
                Some(compared.coverage_agreement);
            if !save_views {
                return Ok(());
            }
            let notice = match crate::screenshot::save_views(
                &options.screenshot_dir,
                &reference,
                &close2gl,
                world,
            ) {
                Ok(saved) => saved,
                Err(e) => format!("Screenshot not saved: {e}"),
            };
            eprintln!("close2gl: {notice}");
            world.insert_resource(Notice::new(notice));
            Ok(())
        }
        (Shot::Window(_), None) => Ok(()),
    }
}

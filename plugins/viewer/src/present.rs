//! Drawing every window for one frame, and the `--screenshot` capture of what they show.

use bevy_ecs::world::World;
use close2gl_gpu::{Gpu, Image, Views};
use close2gl_ui::ViewStats;

use crate::draw::draw_views;
use crate::gui::GuiFrame;
use crate::layout::Placement;
use crate::screenshot;
use crate::surface::WindowSurface;
use crate::windows::Windows;

impl Windows {
    /// Draws every window, and returns the screenshot when `capture` asks for one.
    pub fn draw(
        &mut self,
        world: &mut World,
        gui: &GuiFrame,
        placement: &Placement,
        capture: bool,
    ) -> Result<Option<Image>, String> {
        // A lost device draws nothing and reports nothing: stop with its reason instead.
        if let Some(lost) = self.gpu.lost() {
            return Err(lost);
        }
        // Taken out for the frame, so that the views can be borrowed from the world beside it
        // (`Views` must stay put: its upload systems watch when it was added).
        let mut stats = world.remove_resource::<ViewStats>().unwrap_or_default();
        let result = match world.get_resource::<Views>() {
            Some(views) => self.draw_with(views, &mut stats, gui, placement, capture),
            None => Err("the GPU views are gone".into()),
        };
        world.insert_resource(stats);
        result
    }

    fn draw_with(
        &mut self,
        views: &Views,
        stats: &mut ViewStats,
        gui_frame: &GuiFrame,
        placement: &Placement,
        capture: bool,
    ) -> Result<Option<Image>, String> {
        let Windows {
            gpu,
            main,
            close2gl,
            gui,
            ..
        } = self;
        let mut shots = Vec::new();
        let main_shot = draw_window(gpu, main, capture, |target, depth, timed| {
            let stats = timed.then_some(&mut *stats);
            draw_views(gpu, views, target, depth, &placement.main, stats);
            gui.paint(gpu, gui_frame, target);
        })?;
        shots.extend(main_shot);
        if let Some(window) = close2gl {
            let shot = draw_window(gpu, window, capture, |target, depth, timed| {
                let stats = timed.then_some(&mut *stats);
                draw_views(gpu, views, target, depth, &placement.close2gl, stats);
            })?;
            shots.extend(shot);
        }
        Ok(capture.then(|| screenshot::side_by_side(&shots)))
    }
}

/// Draws one window with `draw(target, depth, timed)` and presents it; when `capture` asks,
/// draws it once more into a texture that can be read back (untimed) and returns that image.
fn draw_window(
    gpu: &Gpu,
    window: &mut WindowSurface,
    capture: bool,
    mut draw: impl FnMut(&wgpu::TextureView, &wgpu::TextureView, bool),
) -> Result<Option<Image>, String> {
    if let Some(texture) = window.acquire(gpu)? {
        let target = texture.texture.create_view(&Default::default());
        if let Some(depth) = window.depth() {
            draw(&target, depth, true);
        }
        gpu.queue.present(texture);
    }
    let Some(depth) = window.depth().filter(|_| capture) else {
        return Ok(None);
    };
    let (width, height) = window.size();
    screenshot::capture(gpu, window.format(), width, height, |target| {
        draw(target, depth, false)
    })
    .map(Some)
}

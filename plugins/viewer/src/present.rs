//! Drawing every window for one frame (`draw`, over the `Windows`, whose own file opens and
//! places them), and the captures of what they show: the whole window (`--screenshot`) or each
//! view alone (the screenshot key, comparing the views), on their way back from the GPU.

use bevy_ecs::world::World;
use close2gl_core::View;
use close2gl_gpu::outside::OutsideRenderer;
use close2gl_gpu::{Gpu, Image, Views};
use close2gl_ui::ViewStats;

use crate::draw::{AllViews, ViewTimes, draw_views, record_times};
use crate::gui::GuiFrame;
use crate::screenshot::{self, PendingImage};
use crate::surface::WindowSurface;
use crate::view_layout::{Placed, Placement};
use crate::windows::Windows;

/// What a frame keeps of itself besides showing it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Capture {
    Nothing,
    /// Every window as shown, panel included, side by side.
    Window,
    /// Each view alone, without the panel or labels over it: the pixels `close2gl render`
    /// writes for the same view.
    Views,
}

pub enum Shot {
    Window(Image),
    Views { reference: Image, close2gl: Image },
}

/// What a frame captured, on its way back from the GPU: each window drawn, with the views
/// placed in it, read back ([`PendingShot::finish`]).
pub struct PendingShot {
    capture: Capture,
    windows: Vec<(PendingImage, Vec<Placed>)>,
    arrived: Vec<Option<Image>>,
}

impl PendingShot {
    /// The shot once every window is back from the GPU: `None` while one is not yet; the
    /// shot is `None` when the views it asked for were not drawn.
    pub fn finish(&mut self, gpu: &Gpu) -> Option<Result<Option<Shot>, String>> {
        for ((pending, _), arrived) in self.windows.iter().zip(&mut self.arrived) {
            if arrived.is_none() {
                match pending.finish(gpu)? {
                    Ok(image) => *arrived = Some(image),
                    Err(e) => return Some(Err(e)),
                }
            }
        }
        let images = self.arrived.iter().flatten();
        let placed = self.windows.iter().map(|(_, placed)| placed);
        Some(Ok(shot(self.capture, images.zip(placed).collect())))
    }

    /// [`Self::finish`], waiting for the GPU.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn wait(mut self, gpu: &Gpu) -> Result<Option<Shot>, String> {
        gpu.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| format!("cannot read the frame back from the GPU: {e}"))?;
        self.finish(gpu)
            .unwrap_or_else(|| Err("the GPU never finished copying the frame".into()))
    }
}

/// How one drawing of a window goes: `timed` when it is the frame shown (its times are the
/// stats'), `panel` when the panel is painted over the views, `coverage` when it is a capture
/// of the views, cleared with alpha 0 so that its alpha says which pixels each view covered (a
/// window shown is cleared opaque: its alpha is how it blends with the desktop or the page).
#[derive(Clone, Copy)]
struct Pass {
    timed: bool,
    panel: bool,
    coverage: bool,
}

impl Pass {
    fn clear(self, views: &Views) -> wgpu::Color {
        match self.coverage {
            true => views.clear_color(),
            false => views.opaque_clear_color(),
        }
    }
}

/// Draws every window, and returns what `capture` asks to keep.
pub fn draw(
    windows: &mut Windows,
    world: &mut World,
    gui: &GuiFrame,
    placement: &Placement,
    capture: Capture,
) -> Result<Option<PendingShot>, String> {
    // A lost device draws nothing and reports nothing: stop with its reason instead.
    if let Some(lost) = windows.gpu.lost() {
        return Err(lost);
    }
    let mut times = ViewTimes::default();
    let outside = world.get_resource::<OutsideRenderer>();
    let result = match world.get_resource::<Views>() {
        Some(views) => {
            let all = AllViews { views, outside };
            draw_with(windows, all, &mut times, gui, placement, capture)
        }
        None => Err("the GPU views are gone".into()),
    };
    if let Some(mut stats) = world.get_resource_mut::<ViewStats>() {
        record_times(&mut stats, &times);
    }
    result
}

fn draw_with(
    windows: &mut Windows,
    views: AllViews<'_>,
    times: &mut ViewTimes,
    gui_frame: &GuiFrame,
    placement: &Placement,
    capture: Capture,
) -> Result<Option<PendingShot>, String> {
    let Windows {
        gpu,
        main,
        close2gl,
        outside,
        gui,
        ..
    } = windows;
    let mut shots = Vec::new();
    let main_shot = draw_window(gpu, main, capture, |target, depth, pass| {
        let times = pass.timed.then_some(&mut *times);
        let clear = pass.clear(views.views);
        draw_views(gpu, views, (target, depth), clear, &placement.main, times);
        if pass.panel {
            gui.paint(gpu, gui_frame, target);
        }
    })?;
    shots.extend(main_shot.map(|shot| (shot, placement.main.clone())));
    for (window, placed) in [
        (close2gl, &placement.close2gl),
        (outside, &placement.outside),
    ] {
        let Some(window) = window else {
            continue;
        };
        let shot = draw_window(gpu, window, capture, |target, depth, pass| {
            let times = pass.timed.then_some(&mut *times);
            let clear = pass.clear(views.views);
            draw_views(gpu, views, (target, depth), clear, placed, times);
        })?;
        shots.extend(shot.map(|shot| (shot, placed.clone())));
    }
    Ok((capture != Capture::Nothing).then(|| PendingShot {
        capture,
        arrived: shots.iter().map(|_| None).collect(),
        windows: shots,
    }))
}

/// What `capture` keeps of the windows drawn (each with the views placed in it).
fn shot(capture: Capture, shots: Vec<(&Image, &Vec<Placed>)>) -> Option<Shot> {
    match capture {
        Capture::Nothing => None,
        Capture::Window => {
            let images: Vec<Image> = shots.into_iter().map(|(shot, _)| shot.clone()).collect();
            Some(Shot::Window(screenshot::side_by_side(&images)))
        }
        Capture::Views => {
            let view = |wanted: View| {
                shots.iter().find_map(|(shot, placed)| {
                    let p = placed.iter().find(|p| p.view == wanted)?;
                    Some(screenshot::crop(shot, p.rect))
                })
            };
            let (reference, close2gl) = (view(View::Reference)?, view(View::Close2gl)?);
            Some(Shot::Views {
                reference,
                close2gl,
            })
        }
    }
}

/// Draws one window with `draw(target, depth, pass)` and presents it; when `capture` asks,
/// returns the picture: the window's frame read back before it is presented, where the surface
/// allows; else, and for the views alone (without the panel's labels over them), drawn once
/// more (untimed) into a texture that can be read back.
fn draw_window(
    gpu: &Gpu,
    window: &mut WindowSurface,
    capture: Capture,
    mut draw: impl FnMut(&wgpu::TextureView, &wgpu::TextureView, Pass),
) -> Result<Option<PendingImage>, String> {
    let mut shot = None;
    if let Some(texture) = window.acquire()? {
        let target = texture.texture.create_view(&Default::default());
        if let Some(depth) = window.depth() {
            let shown = Pass {
                timed: true,
                panel: true,
                coverage: false,
            };
            draw(&target, depth, shown);
            if capture == Capture::Window && window.readable() {
                shot = Some(screenshot::read_back(gpu, &texture.texture, false)?);
            }
        }
        window.present(texture);
    }
    if shot.is_some() {
        return Ok(shot);
    }
    let Some(depth) = window.depth().filter(|_| capture != Capture::Nothing) else {
        return Ok(None);
    };
    let kept = Pass {
        timed: false,
        panel: capture == Capture::Window,
        coverage: capture == Capture::Views,
    };
    let (width, height) = window.size();
    let size = (window.format(), width, height);
    screenshot::capture(gpu, size, kept.coverage, |target| draw(target, depth, kept)).map(Some)
}

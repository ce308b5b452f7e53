//! Opening and placing the windows, and keeping them the same size in the windows layout.

use std::collections::HashMap;
use std::sync::Arc;

use bevy_ecs::world::World;
use close2gl_core::Layout;
use close2gl_gpu::outside::OutsideRenderer;
use close2gl_gpu::{Gpu, Views};
use close2gl_ui::ViewStats;
use winit::dpi::{PhysicalPosition, PhysicalSize};
use winit::event_loop::ActiveEventLoop;
use winit::window::{Window, WindowId};

use crate::ViewerOptions;
use crate::gui::{Gui, GuiFrame};
use crate::layout::{self, PixelRect, Placement};
use crate::surface::WindowSurface;

/// Everything that exists once the windows do.
pub struct Windows {
    pub gpu: Gpu,
    /// The panel's window: both views (split) or the reference view (windows).
    pub main: WindowSurface,
    /// The Close2GL window of the windows layout.
    pub close2gl: Option<WindowSurface>,
    pub gui: Gui,
    /// The size last asked of each window, so that the answer to our own request is not taken
    /// for the user resizing it.
    asked: HashMap<WindowId, PhysicalSize<u32>>,
    /// Pixels of the main window's width that are not the reference view (the panel).
    panel_width: u32,
    /// Where the outside view was last placed in the main window, for its orbit's input.
    pub outside_area: Option<PixelRect>,
}

impl Windows {
    /// Opens the windows `options` ask for, on one GPU device that can present to them, and
    /// gives the world the `Gpu` and `Views` resources and the adapter's name.
    pub fn open(
        event_loop: &ActiveEventLoop,
        instance: &wgpu::Instance,
        options: &ViewerOptions,
        world: &mut World,
    ) -> Result<Windows, String> {
        let (main_window, close2gl_window) = create_windows(event_loop, options)?;
        let surface = WindowSurface::create_surface(instance, &main_window)?;
        let gpu = Gpu::for_surface(instance.clone(), &surface)?;
        let main = WindowSurface::new(&gpu, main_window, surface, None)?;
        let close2gl = match close2gl_window {
            Some(window) => {
                let surface = WindowSurface::create_surface(instance, &window)?;
                Some(WindowSurface::new(
                    &gpu,
                    window,
                    surface,
                    Some(main.format()),
                )?)
            }
            None => None,
        };
        let gui = Gui::new(&gpu, &main.window, main.format());
        install(world, &gpu, main.format());
        Ok(Windows {
            gpu,
            main,
            close2gl,
            gui,
            asked: HashMap::new(),
            panel_width: 0,
            outside_area: None,
        })
    }

    pub fn missed_frame(&self) -> bool {
        self.main.missed() || self.close2gl.as_ref().is_some_and(WindowSurface::missed)
    }

    /// Where each view goes this frame, given what the panel left of the main window and
    /// whether the outside view shows (a third column of the split layout).
    pub fn placement(&mut self, gui: &GuiFrame, outside: bool) -> Placement {
        let (width, height) = self.main.size();
        let area = PixelRect::from_points(gui.views_area, gui.pixels_per_point, width, height);
        self.panel_width = width.saturating_sub(area.width);
        let placement = match &self.close2gl {
            None => layout::split(area, outside),
            Some(close2gl) => {
                let (w, h) = close2gl.size();
                layout::two_windows(area, w, h)
            }
        };
        self.outside_area = placement
            .main
            .iter()
            .find(|p| p.view == layout::View::Outside)
            .map(|p| p.rect);
        placement
    }

    pub fn window_mut(&mut self, id: WindowId) -> Option<&mut WindowSurface> {
        if self.main.window.id() == id {
            Some(&mut self.main)
        } else {
            self.close2gl.as_mut().filter(|w| w.window.id() == id)
        }
    }

    /// A window changed size: reconfigure it and, in the windows layout, ask the other window
    /// for the size that keeps the two views equal, unless this is the answer to our own ask.
    pub fn resized(&mut self, id: WindowId, size: PhysicalSize<u32>) {
        let gpu = self.gpu.clone();
        if let Some(window) = self.window_mut(id) {
            window.resize(&gpu, size.width, size.height);
        }
        if self.asked.get(&id) == Some(&size) {
            self.asked.remove(&id);
            return;
        }
        let Some(close2gl) = &self.close2gl else {
            return;
        };
        if size.width == 0 || size.height == 0 {
            return;
        }
        let main_resized = id == self.main.window.id();
        let other = if main_resized {
            &close2gl.window
        } else {
            &self.main.window
        };
        let (width, height) =
            layout::matching_size(main_resized, size.width, size.height, self.panel_width);
        let wanted = PhysicalSize::new(width, height);
        if other.inner_size() != wanted {
            self.asked.insert(other.id(), wanted);
            // `Some` means the window took the size at once; the Resized event still follows.
            let _ = other.request_inner_size(wanted);
        }
    }
}

/// The main window and, in the windows layout, the Close2GL window beside it.
fn create_windows(
    event_loop: &ActiveEventLoop,
    options: &ViewerOptions,
) -> Result<(Arc<Window>, Option<Arc<Window>>), String> {
    let (width, height) = (options.width, options.height);
    match options.layout {
        Layout::Split => {
            let title = "Close2GL viewer: Reference (wgpu) | Close2GL";
            Ok((open_window(event_loop, title, width, height, None)?, None))
        }
        // The panel's window gets the panel on top of its half, so both views start equal.
        Layout::Windows => {
            let scale = event_loop
                .primary_monitor()
                .map_or(1.0, |m| m.scale_factor());
            let panel = (close2gl_ui::PANEL_WIDTH as f64 * scale) as u32;
            let reference = open_window(
                event_loop,
                "Reference (wgpu)",
                width / 2 + panel,
                height,
                None,
            )?;
            // Beside the reference window, as the assignment shows its two windows (a window
            // manager may still place it elsewhere).
            let beside = reference
                .outer_position()
                .ok()
                .map(|at| PhysicalPosition::new(at.x + reference.outer_size().width as i32, at.y));
            let close2gl = open_window(event_loop, "Close2GL", width / 2, height, beside)?;
            Ok((reference, Some(close2gl)))
        }
    }
}

fn open_window(
    event_loop: &ActiveEventLoop,
    title: &str,
    width: u32,
    height: u32,
    position: Option<PhysicalPosition<i32>>,
) -> Result<Arc<Window>, String> {
    let mut attributes = Window::default_attributes()
        .with_title(title)
        .with_inner_size(PhysicalSize::new(width.max(1), height.max(1)));
    if let Some(position) = position {
        attributes = attributes.with_position(position);
    }
    event_loop
        .create_window(attributes)
        .map(Arc::new)
        .map_err(|e| format!("cannot open a window: {e}"))
}

/// The GPU resources the upload systems wait for, and what the panel says about the adapter.
fn install(world: &mut World, gpu: &Gpu, format: wgpu::TextureFormat) {
    let views = Views::new(gpu, format);
    let limitations = views.limitations();
    world.insert_resource(views);
    world.insert_resource(OutsideRenderer::new(gpu, format));
    let mut stats = world.resource_mut::<ViewStats>();
    stats.adapter = format!("{} ({})", gpu.adapter_name(), gpu.backend_name());
    stats.limitations = limitations;
    world.insert_resource(gpu.clone());
}

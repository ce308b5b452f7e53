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
use crate::gui::Gui;
use crate::surface::{NewWindow, WindowSurface};
use crate::surface_source::{Connections, SurfaceSource};
use crate::view_layout::{self, PixelRect, Placement};

/// Everything that exists once the windows do.
pub struct Windows {
    pub gpu: Gpu,
    /// The panel's window: both views (split) or the reference view (windows).
    pub main: WindowSurface,
    /// The Close2GL window of the windows layout.
    pub close2gl: Option<WindowSurface>,
    /// The outside view's own window in the windows layout, open while the view is shown.
    pub outside: Option<WindowSurface>,
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
    /// Draws into the windows `create_windows` opened, on one GPU device that can present to
    /// them, and gives the world the `Gpu` and `Views` resources and the adapter's name.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn open(
        created: Created,
        (instance, connections): &(wgpu::Instance, Connections),
        world: &mut World,
    ) -> Result<Windows, String> {
        let main_surface = surface_for(&created.0, instance, *connections)?;
        let gpu = Gpu::for_surface(instance.clone(), &main_surface.1)?;
        Self::with_gpu(created, main_surface, gpu, *connections, world)
    }

    /// [`Self::open`] once the GPU is chosen for the main window's `main_surface` (in a
    /// browser, where that is awaited: [`crate::browser`]).
    pub fn with_gpu(
        (main_window, close2gl_window): Created,
        main_surface: (SurfaceSource, wgpu::Surface<'static>),
        gpu: Gpu,
        connections: Connections,
        world: &mut World,
    ) -> Result<Windows, String> {
        let instance = &gpu.instance;
        let surface_for = |window: &NewWindow| surface_for(window, instance, connections);
        let main = WindowSurface::new(&gpu, main_window, main_surface, None)?;
        let close2gl = match close2gl_window {
            Some(window) => {
                let surface = surface_for(&window)?;
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
            outside: None,
            gui,
            asked: HashMap::new(),
            panel_width: 0,
            outside_area: None,
        })
    }

    pub fn missed_frame(&self) -> bool {
        let others = [&self.close2gl, &self.outside];
        self.main.missed()
            || others
                .iter()
                .any(|w| w.as_ref().is_some_and(WindowSurface::missed))
    }

    /// In the windows layout, opens the outside view's own window when the view is `shown` and
    /// closes it when it is not. An error (no window, no surface) is the caller's to report; the
    /// view then stays without a window.
    pub fn show_outside_window(
        &mut self,
        event_loop: &ActiveEventLoop,
        (instance, connections): &(wgpu::Instance, Connections),
        options: &ViewerOptions,
        shown: bool,
    ) -> Result<(), String> {
        if self.close2gl.is_none() || shown == self.outside.is_some() {
            return Ok(());
        }
        if !shown {
            self.outside = None;
            return Ok(());
        }
        let (width, height) = (options.width / 2, options.height);
        let position = columns(event_loop, options.width).2;
        let window = open_window(event_loop, "Outside view", width, height, Some(position))?;
        let surface = surface_for(&window, instance, *connections)?;
        let format = Some(self.main.format());
        self.outside = Some(WindowSurface::new(&self.gpu, window, surface, format)?);
        Ok(())
    }

    /// Whether `id` is the outside view's own window.
    pub fn is_outside_window(&self, id: WindowId) -> bool {
        self.outside.as_ref().is_some_and(|w| w.window.id() == id)
    }

    /// Where each view goes this frame, given what the panel left of the main window and
    /// whether the outside view shows (a third column of the split layout).
    pub fn placement(
        &mut self,
        (views, pixels_per_point): (egui::Rect, f32),
        outside: bool,
    ) -> Placement {
        let (width, height) = self.main.size();
        let area = PixelRect::from_points(views, pixels_per_point, width, height);
        self.panel_width = width.saturating_sub(area.width);
        let placement = match &self.close2gl {
            None => view_layout::split(area, outside),
            Some(close2gl) => {
                let (w, h) = close2gl.size();
                let outside = self.outside.as_ref().map(WindowSurface::size);
                view_layout::two_windows(area, w, h, outside)
            }
        };
        self.outside_area = placement
            .main
            .iter()
            .find(|p| p.view == close2gl_core::View::Outside)
            .map(|p| p.rect);
        placement
    }

    pub fn window_mut(&mut self, id: WindowId) -> Option<&mut WindowSurface> {
        if self.main.window.id() == id {
            Some(&mut self.main)
        } else if self.is_outside_window(id) {
            self.outside.as_mut()
        } else {
            self.close2gl.as_mut().filter(|w| w.window.id() == id)
        }
    }

    /// A window changed size: reconfigure it and, in the windows layout, ask the other window
    /// for the size that keeps the two views equal, unless this is the answer to our own ask.
    pub fn resized(&mut self, id: WindowId, size: PhysicalSize<u32>) {
        if let Some(window) = self.window_mut(id) {
            window.resize(size);
        }
        // The outside view's window is sized on its own.
        if self.asked.get(&id) == Some(&size) || self.is_outside_window(id) {
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
        let other = if main_resized { close2gl } else { &self.main };
        let (width, height) =
            view_layout::matching_size(main_resized, size.width, size.height, self.panel_width);
        let wanted = PhysicalSize::new(width, height);
        if other.window_size() != wanted {
            self.asked.insert(other.window.id(), wanted);
            // `Some` means the window took the size at once; the Resized event still follows.
            let _ = other.window.request_inner_size(wanted);
        }
    }
}

/// The main window and, in the windows layout, the Close2GL window beside it.
pub type Created = (NewWindow, Option<NewWindow>);

/// Opens the main window and, in the windows layout, the Close2GL window beside it.
pub fn create_windows(
    event_loop: &ActiveEventLoop,
    options: &ViewerOptions,
) -> Result<Created, String> {
    let (width, height) = window_size(event_loop, options);
    match options.layout {
        Layout::Split => {
            let title = "Close2GL viewer: Reference (wgpu) | Close2GL";
            Ok((open_window(event_loop, title, width, height, None)?, None))
        }
        // The panel's window gets the panel on top of its half, so both views start equal.
        // Placed side by side from the monitor's corner, as the assignment shows its two windows
        // (a window manager may still place them elsewhere): from what we asked, not from where
        // X says the first one is, which winit would panic on if it had gone.
        Layout::Windows => {
            let (corner, beside, _) = columns(event_loop, width);
            let reference_width = (beside.x - corner.x) as u32;
            let reference = open_window(
                event_loop,
                "Reference (wgpu)",
                reference_width,
                height,
                Some(corner),
            )?;
            let close2gl = open_window(event_loop, "Close2GL", width / 2, height, Some(beside))?;
            Ok((reference, Some(close2gl)))
        }
    }
}

/// The size asked for all windows together, shrunk when `options` says to fit the monitor: the
/// panel and the views (both windows of the windows layout, side by side) within the monitor,
/// less room for the window manager's title bars and a task bar.
fn window_size(event_loop: &ActiveEventLoop, options: &ViewerOptions) -> (u32, u32) {
    let (width, height) = (options.width, options.height);
    let monitor = event_loop.primary_monitor();
    let Some(room) = monitor.map(|m| m.size()).filter(|_| options.fit_to_monitor) else {
        return (width, height);
    };
    let panel_in_addition = match options.layout {
        Layout::Split => 0,
        Layout::Windows => close2gl_ui::PANEL_WIDTH as u32,
    };
    let fit = |asked: u32, room: u32, margin: u32| asked.min(room.saturating_sub(margin).max(1));
    (
        fit(width, room.width, 16 + panel_in_addition),
        fit(height, room.height, 96),
    )
}

/// Where the windows layout's windows go, left to right from the monitor's corner, for a
/// `width` of both views: the panel's window (half of it plus the panel), the Close2GL window,
/// then the outside view's.
fn columns(
    event_loop: &ActiveEventLoop,
    width: u32,
) -> (
    PhysicalPosition<i32>,
    PhysicalPosition<i32>,
    PhysicalPosition<i32>,
) {
    let monitor = event_loop.primary_monitor();
    let scale = monitor.as_ref().map_or(1.0, |m| m.scale_factor());
    let corner = monitor.map_or(PhysicalPosition::new(0, 0), |m| m.position());
    let panel = (close2gl_ui::PANEL_WIDTH as f64 * scale) as i32;
    let beside = |x: i32| PhysicalPosition::new(corner.x + x, corner.y);
    let half = (width / 2) as i32;
    (corner, beside(half + panel), beside(2 * half + panel))
}

/// What a window's surface is made from, and the surface.
pub fn surface_for(
    window: &NewWindow,
    instance: &wgpu::Instance,
    connections: Connections,
) -> Result<(SurfaceSource, wgpu::Surface<'static>), String> {
    let source = SurfaceSource::new(window.window.clone(), connections)?;
    let surface = source.create_surface(instance)?;
    Ok((source, surface))
}

#[cfg(not(target_arch = "wasm32"))]
fn open_window(
    event_loop: &ActiveEventLoop,
    title: &str,
    width: u32,
    height: u32,
    position: Option<PhysicalPosition<i32>>,
) -> Result<NewWindow, String> {
    let size = PhysicalSize::new(width.max(1), height.max(1));
    let mut attributes = Window::default_attributes()
        .with_title(title)
        .with_inner_size(size);
    if let Some(position) = position {
        attributes = attributes.with_position(position);
    }
    let window = event_loop
        .create_window(attributes)
        .map_err(|e| format!("cannot open a window: {e}"))?;
    Ok(NewWindow {
        window: Arc::new(window),
        size,
    })
}

/// In a browser the window is a canvas added to the page, sized by the page's style sheet
/// (winit reports its size as it changes; until then it has no pixels and is not drawn).
#[cfg(target_arch = "wasm32")]
fn open_window(
    event_loop: &ActiveEventLoop,
    title: &str,
    _width: u32,
    _height: u32,
    _position: Option<PhysicalPosition<i32>>,
) -> Result<NewWindow, String> {
    use winit::platform::web::WindowAttributesExtWebSys;
    let attributes = Window::default_attributes()
        .with_title(title)
        .with_append(true);
    let window = event_loop
        .create_window(attributes)
        .map_err(|e| format!("cannot add the canvas to the page: {e}"))?;
    let size = window.inner_size();
    Ok(NewWindow {
        window: Arc::new(window),
        size,
    })
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

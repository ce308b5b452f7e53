//! The winit application: windows appear on `resumed`, events become input, and each redraw of
//! the main window runs one app frame and draws every window.

use std::collections::HashMap;
use std::sync::Arc;
use std::time::{Duration, Instant};

use close2gl_core::{App, InputState, ModelRequest, ModelSource, Viewport};
use close2gl_gpu::{Gpu, Views};
use close2gl_ui::ViewStats;
use winit::application::ApplicationHandler;
use winit::dpi::{PhysicalPosition, PhysicalSize};
use winit::event::{ElementState, MouseButton, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::window::{Window, WindowId};

use crate::draw::{Placed, View, draw_views};
use crate::gui::{Gui, GuiFrame};
use crate::input::InputTracker;
use crate::layout::PixelRect;
use crate::screenshot;
use crate::surface::WindowSurface;
use crate::{Layout, ViewerOptions};

pub struct Viewer {
    app: App,
    options: ViewerOptions,
    instance: wgpu::Instance,
    windows: Option<Windows>,
    tracker: InputTracker,
    result: Result<(), String>,
    frames: u32,
    last_frame: Instant,
    /// Keys were held last frame: the camera is moving, so keep drawing.
    moving: bool,
    /// When the panel wants to be drawn again by itself.
    repaint_at: Option<Instant>,
}

/// Everything that exists once the windows do.
struct Windows {
    gpu: Gpu,
    /// The panel's window: both views (split) or the reference view (windows).
    main: WindowSurface,
    /// The Close2GL window of the windows layout.
    close2gl: Option<WindowSurface>,
    gui: Gui,
    /// The size last asked of each window, so that the answer to our own request is not taken
    /// for the user resizing it.
    asked: HashMap<WindowId, PhysicalSize<u32>>,
    /// Pixels of the main window's width that are not the reference view (the panel).
    panel_width: u32,
}

impl Viewer {
    pub fn new(app: App, options: ViewerOptions, event_loop: &EventLoop<()>) -> Self {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_with_display_handle_from_env(
                Box::new(event_loop.owned_display_handle()),
            ));
        Self {
            app,
            options,
            instance,
            windows: None,
            tracker: InputTracker::default(),
            result: Ok(()),
            frames: 0,
            last_frame: Instant::now(),
            moving: false,
            repaint_at: None,
        }
    }

    /// What the run came to, once the event loop has returned.
    pub fn finish(self) -> Result<(), String> {
        self.result
    }

    fn fail(&mut self, event_loop: &ActiveEventLoop, error: String) {
        self.result = Err(error);
        event_loop.exit();
    }

    fn open_windows(&mut self, event_loop: &ActiveEventLoop) -> Result<Windows, String> {
        let (width, height) = (self.options.width, self.options.height);
        let open =
            |title: &str, width: u32, height: u32, position: Option<PhysicalPosition<i32>>| {
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
            };
        let (main_window, close2gl_window) = match self.options.layout {
            Layout::Split => (
                open(
                    "Close2GL viewer: Reference (wgpu) | Close2GL",
                    width,
                    height,
                    None,
                )?,
                None,
            ),
            // The panel's window gets the panel on top of its half, so both views start equal.
            Layout::Windows => {
                let panel = (close2gl_ui::PANEL_WIDTH as f64
                    * event_loop
                        .primary_monitor()
                        .map_or(1.0, |m| m.scale_factor())) as u32;
                let reference = open("Reference (wgpu)", width / 2 + panel, height, None)?;
                // Beside the reference window, as the assignment shows its two windows (a window
                // manager may still place it elsewhere).
                let beside = reference.outer_position().ok().map(|at| {
                    PhysicalPosition::new(at.x + reference.outer_size().width as i32, at.y)
                });
                let close2gl = open("Close2GL", width / 2, height, beside)?;
                (reference, Some(close2gl))
            }
        };
        let surface = WindowSurface::create_surface(&self.instance, &main_window)?;
        let gpu = Gpu::for_surface(self.instance.clone(), &surface)?;
        let main = WindowSurface::new(&gpu, main_window, surface, None)?;
        let close2gl = match close2gl_window {
            Some(window) => {
                let surface = WindowSurface::create_surface(&self.instance, &window)?;
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

        let world = self.app.world_mut();
        world.insert_resource(Views::new(&gpu, main.format()));
        let limitations = world.resource::<Views>().limitations();
        let mut stats = world.resource_mut::<ViewStats>();
        stats.adapter = format!("{} ({})", gpu.adapter_name(), gpu.backend_name());
        stats.limitations = limitations;
        world.insert_resource(gpu.clone());
        Ok(Windows {
            gpu,
            main,
            close2gl,
            gui,
            asked: HashMap::new(),
            panel_width: 0,
        })
    }

    /// One app frame: the panel, the layout, the systems, then every window drawn.
    fn redraw(&mut self, event_loop: &ActiveEventLoop) {
        let Some(windows) = self.windows.as_mut() else {
            return;
        };
        let now = Instant::now();
        let world = self.app.world_mut();
        // The first frame of a hold has no previous moving frame to measure from: it counts as
        // one nominal frame, so that a quick tap still moves the camera a little.
        world.resource_mut::<InputState>().dt = if self.moving {
            now.duration_since(self.last_frame).as_secs_f32()
        } else {
            1.0 / 60.0
        };
        self.last_frame = now;

        let both_views = windows.close2gl.is_none();
        let mut gui_frame = windows.gui.run(&windows.main.window, world, both_views);
        windows.gui.upload_textures(&windows.gpu, &mut gui_frame);
        let (main_views, close2gl_views, viewport) = windows.layout(&gui_frame);
        if let Some(viewport) = viewport
            && *world.resource::<Viewport>() != viewport
        {
            world.insert_resource(viewport);
        }
        self.app.update();

        let capture = self.options.exit_after_frames == Some(self.frames + 1)
            && self.options.screenshot.is_some();
        let drawn = windows.draw(
            self.app.world_mut(),
            &gui_frame,
            [&main_views, &close2gl_views],
            capture,
        );
        windows.gui.free_textures(&mut gui_frame);
        let world = self.app.world_mut();
        let mut input = world.resource_mut::<InputState>();
        input.end_frame();
        let was_moving = self.moving;
        self.moving = !input.held.is_empty();

        match drawn {
            Err(e) => return self.fail(event_loop, e),
            Ok(None) => {}
            Ok(Some(shot)) => {
                if let Some(path) = &self.options.screenshot
                    && let Err(e) = shot.write_png(path)
                {
                    return self.fail(event_loop, e);
                }
            }
        }
        self.frames += 1;
        if self
            .options
            .exit_after_frames
            .is_some_and(|n| self.frames >= n)
        {
            event_loop.exit();
            return;
        }
        // A window that could not present this frame is drawn again shortly: otherwise the last
        // camera move before an idle stretch could stay unseen.
        if windows.missed_frame() {
            self.repaint_at = now.checked_add(RETRY_MISSED_FRAME);
            return;
        }
        // One more frame after the camera stops, so the panel shows where it stopped.
        let again = self.moving
            || was_moving
            || self.options.exit_after_frames.is_some()
            || gui_frame.repaint_delay.is_zero();
        if again {
            windows.main.window.request_redraw();
        }
        self.repaint_at = now.checked_add(gui_frame.repaint_delay).filter(|_| !again);
    }
}

/// How long to wait before drawing again a frame that a window could not present.
const RETRY_MISSED_FRAME: Duration = Duration::from_millis(50);

impl Windows {
    fn missed_frame(&self) -> bool {
        self.main.missed() || self.close2gl.as_ref().is_some_and(WindowSurface::missed)
    }

    /// Where each view goes, and the `Viewport` they share (`None` while there is no room).
    fn layout(&mut self, gui: &GuiFrame) -> (Vec<Placed>, Vec<Placed>, Option<Viewport>) {
        let (width, height) = self.main.size();
        let area = PixelRect::from_points(gui.views_area, gui.pixels_per_point, width, height);
        self.panel_width = width.saturating_sub(area.width);
        match &self.close2gl {
            None => {
                let [left, right] = area.halves();
                if left.is_empty() {
                    return (Vec::new(), Vec::new(), None);
                }
                let placed = vec![
                    Placed {
                        view: View::Reference,
                        rect: left,
                    },
                    Placed {
                        view: View::Close2gl,
                        rect: right,
                    },
                ];
                (placed, Vec::new(), Some(left.size()))
            }
            Some(close2gl) => {
                let (w, h) = close2gl.size();
                let own = PixelRect::whole(w, h);
                // The reference view never grows past the Close2GL window's size, so the two
                // views match even before (or without) the window manager honouring the resize.
                let reference = PixelRect {
                    width: area.width.min(w),
                    height: area.height.min(h),
                    ..area
                };
                let main = (!reference.is_empty()).then_some(Placed {
                    view: View::Reference,
                    rect: reference,
                });
                let other = (!own.is_empty()).then_some(Placed {
                    view: View::Close2gl,
                    rect: own,
                });
                // The Close2GL window sets the size; the windows are also resized together (see
                // `resized`).
                let viewport = (!own.is_empty())
                    .then(|| own.size())
                    .or(main.map(|p| p.rect.size()));
                (
                    main.into_iter().collect(),
                    other.into_iter().collect(),
                    viewport,
                )
            }
        }
    }

    /// Draws every window, and returns the screenshot when `capture` asks for one.
    fn draw(
        &mut self,
        world: &mut bevy_ecs::world::World,
        gui: &GuiFrame,
        placed: [&[Placed]; 2],
        capture: bool,
    ) -> Result<Option<close2gl_gpu::Image>, String> {
        // Taken out for the frame, so that the views can be borrowed from the world beside it
        // (`Views` must stay put: its upload systems watch when it was added).
        let mut stats = world.remove_resource::<ViewStats>().unwrap_or_default();
        let result = match world.get_resource::<Views>() {
            Some(views) => self.draw_with(views, &mut stats, gui, placed, capture),
            None => Err("the GPU views are gone".into()),
        };
        world.insert_resource(stats);
        result
    }

    fn draw_with(
        &mut self,
        views: &Views,
        stats: &mut ViewStats,
        gui: &GuiFrame,
        [main_views, close2gl_views]: [&[Placed]; 2],
        capture: bool,
    ) -> Result<Option<close2gl_gpu::Image>, String> {
        let gpu = &self.gpu;
        let mut shots = Vec::new();
        {
            let main = &mut self.main;
            let gui_renderer = &mut self.gui;
            let mut draw_main = |target: &wgpu::TextureView,
                                 depth: &wgpu::TextureView,
                                 stats: Option<&mut ViewStats>| {
                draw_views(gpu, views, target, depth, main_views, stats);
                gui_renderer.paint(gpu, gui, target);
            };
            if let Some(texture) = main.acquire(gpu)? {
                let target = texture.texture.create_view(&Default::default());
                if let Some(depth) = main.depth() {
                    draw_main(&target, depth, Some(&mut *stats));
                }
                gpu.queue.present(texture);
            }
            if capture && let Some(depth) = main.depth() {
                let (w, h) = main.size();
                shots.push(screenshot::capture(gpu, main.format(), w, h, |target| {
                    draw_main(target, depth, None)
                })?);
            }
        }
        if let Some(window) = self.close2gl.as_mut() {
            if let Some(texture) = window.acquire(gpu)? {
                let target = texture.texture.create_view(&Default::default());
                if let Some(depth) = window.depth() {
                    draw_views(gpu, views, &target, depth, close2gl_views, Some(stats));
                }
                gpu.queue.present(texture);
            }
            if capture && let Some(depth) = window.depth() {
                let (w, h) = window.size();
                shots.push(screenshot::capture(gpu, window.format(), w, h, |target| {
                    draw_views(gpu, views, target, depth, close2gl_views, None)
                })?);
            }
        }
        Ok(capture.then(|| screenshot::side_by_side(&shots)))
    }

    fn window_mut(&mut self, id: WindowId) -> Option<&mut WindowSurface> {
        if self.main.window.id() == id {
            Some(&mut self.main)
        } else {
            self.close2gl.as_mut().filter(|w| w.window.id() == id)
        }
    }

    /// A window changed size: reconfigure it and, in the windows layout, ask the other window
    /// for the size that keeps the two views equal, unless this is the answer to our own ask.
    fn resized(&mut self, id: WindowId, size: PhysicalSize<u32>) {
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
        let (other, wanted) = if id == self.main.window.id() {
            let width = size.width.saturating_sub(self.panel_width).max(1);
            (&close2gl.window, PhysicalSize::new(width, size.height))
        } else {
            let width = size.width + self.panel_width;
            (&self.main.window, PhysicalSize::new(width, size.height))
        };
        if other.inner_size() != wanted {
            self.asked.insert(other.id(), wanted);
            // `Some` means the window took the size at once; the Resized event still follows.
            let _ = other.request_inner_size(wanted);
        }
    }
}

impl ApplicationHandler for Viewer {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.windows.is_some() {
            return;
        }
        match self.open_windows(event_loop) {
            Ok(windows) => {
                windows.main.window.request_redraw();
                self.windows = Some(windows);
            }
            Err(e) => self.fail(event_loop, e),
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, id: WindowId, event: WindowEvent) {
        let Some(windows) = self.windows.as_mut() else {
            return;
        };
        let is_main = windows.main.window.id() == id;
        if !is_main && windows.window_mut(id).is_none() {
            return;
        }
        if let WindowEvent::RedrawRequested = event {
            // Not for egui: it would ask for another redraw, forever.
            if is_main {
                self.redraw(event_loop);
            } else {
                windows.main.window.request_redraw();
            }
            return;
        }
        // What the panel takes is not the camera's: the pointer over the panel, keys while a
        // text field has focus. Other key presses never reach egui, which would otherwise move
        // its focus on Tab and click the focused button on Space: those keys are the camera's.
        let panel_keys = is_main && windows.gui.ctx.egui_wants_keyboard_input();
        let camera_key = matches!(&event, WindowEvent::KeyboardInput { event, .. }
            if event.state == ElementState::Pressed && !panel_keys);
        let panel_pointer = if is_main && !camera_key {
            let response = windows.gui.on_event(&windows.main.window, &event);
            if response.repaint {
                windows.main.window.request_redraw();
            }
            response.consumed
        } else {
            false
        };
        let world = self.app.world_mut();
        let mut redraw = true;
        match event {
            WindowEvent::CloseRequested => {
                event_loop.exit();
                return;
            }
            WindowEvent::Resized(size) => windows.resized(id, size),
            WindowEvent::KeyboardInput { event, .. } => {
                let pressed = event.state == ElementState::Pressed;
                if !(pressed && panel_keys) {
                    let mut input = world.resource_mut::<InputState>();
                    self.tracker.key(
                        &mut input,
                        event.physical_key,
                        &event.logical_key,
                        pressed,
                        event.repeat,
                    );
                }
            }
            WindowEvent::MouseInput {
                state,
                button: MouseButton::Left,
                ..
            } => {
                self.tracker
                    .button(state == ElementState::Pressed && !panel_pointer);
            }
            WindowEvent::CursorMoved { position, .. } => {
                let mut input = world.resource_mut::<InputState>();
                redraw = self.tracker.cursor(&mut input, id, position);
            }
            WindowEvent::MouseWheel { delta, .. } if !panel_pointer => {
                self.tracker
                    .scroll(&mut world.resource_mut::<InputState>(), delta);
            }
            WindowEvent::DroppedFile(path) => {
                world.insert_resource(ModelRequest(Some(ModelSource::File(path))));
            }
            WindowEvent::Focused(false) => {
                self.tracker
                    .release_all(&mut world.resource_mut::<InputState>());
            }
            _ => redraw = false,
        }
        if redraw {
            windows.main.window.request_redraw();
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        match self.repaint_at {
            Some(at) if at <= Instant::now() => {
                self.repaint_at = None;
                if let Some(windows) = &self.windows {
                    windows.main.window.request_redraw();
                }
                event_loop.set_control_flow(ControlFlow::Wait);
            }
            Some(at) => event_loop.set_control_flow(ControlFlow::WaitUntil(at)),
            None => event_loop.set_control_flow(ControlFlow::Wait),
        }
    }
}

//! The winit application: windows appear on `resumed`, events become input, and each redraw of
//! the main window runs one app frame and draws every window.

use web_time::{Duration, Instant};

use bevy_ecs::world::World;
use close2gl_core::{App, InputState, OutsideView, Wake};
use close2gl_ui::{Notice, PanelState, ViewStats};
use winit::application::ApplicationHandler;
use winit::event::WindowEvent;
use winit::event_loop::{ActiveEventLoop, ControlFlow};
use winit::window::WindowId;

use crate::ViewerOptions;
use crate::frame_capture::FrameCapture;
use crate::input_tracker::InputTracker;
use crate::orbit_input::OrbitInput;
use crate::pacing::Pacing;
use crate::pixel_probe::on_its_way;
use crate::placed_views::ViewPlacement;
use crate::present;
use crate::routing::{apply_input, offer_to_panel};
use crate::session::Session;
use crate::surface_source::Connections;
use crate::view_layout::PixelRect;
use crate::windows::{Created, Windows, create_windows};

pub struct Viewer {
    app: App,
    options: ViewerOptions,
    /// What windows draw with, and on which X connections (see [`surface_source`]).
    instance: (wgpu::Instance, Connections),
    windows: Option<Windows>,
    tracker: InputTracker,
    orbit: OrbitInput,
    pacing: Pacing,
    result: Result<(), String>,
    frames: u32,
    session: Session,
    /// Windows whose drawing could not be set up, kept for a moment: see [`Opening`].
    opening: Option<Opening>,
    /// What frames asked to keep of themselves (screenshots, comparisons of the views).
    capture: FrameCapture,
    /// In a browser: the windows waiting for their GPU, which arrives later.
    #[cfg(target_arch = "wasm32")]
    arriving: Option<crate::browser::Arriving>,
}

/// A window destroyed by another client while the app sets up its surface makes the setup fail
/// (its surface offers no format, or no adapter can present to it), and that is a close, not a
/// fault. Its `Destroyed` event is already on its way when the failure shows: the error stands
/// only if none arrives within [`OPENING_GRACE`].
struct Opening {
    windows: Created,
    error: String,
    /// `None`: the clock cannot count that far on, so the error stands at once.
    deadline: Option<Instant>,
}

/// What sizing a frame found, for the steps after it.
struct FrameStart {
    now: Instant,
    /// The main window's surface, in pixels.
    surface: (u32, u32),
    placement: crate::view_layout::Placement,
    /// Whether the outside view was shown before the systems ran.
    outside: bool,
}

#[cfg(not(target_arch = "wasm32"))]
const OPENING_GRACE: Duration = Duration::from_millis(500);

impl Viewer {
    pub fn new(
        app: App,
        options: ViewerOptions,
        session: Session,
        instance: (wgpu::Instance, Connections),
    ) -> Self {
        Self {
            app,
            options,
            instance,
            windows: None,
            tracker: InputTracker::default(),
            orbit: OrbitInput::default(),
            pacing: Pacing::new(Instant::now()),
            result: Ok(()),
            frames: 0,
            session,
            opening: None,
            capture: FrameCapture::default(),
            #[cfg(target_arch = "wasm32")]
            arriving: None,
        }
    }

    /// What the run came to, once the event loop has returned (in a browser it never does).
    #[cfg(not(target_arch = "wasm32"))]
    pub fn finish(self) -> Result<(), String> {
        self.result
    }

    fn fail(&mut self, event_loop: &ActiveEventLoop, error: String) {
        #[cfg(target_arch = "wasm32")]
        crate::browser::report(&error);
        self.result = Err(error);
        event_loop.exit();
    }

    /// One app frame, in the wgpu examples' steps: size (the input and the layout), update (the
    /// app's systems, the viewport and the probe among them), draw and present (every window,
    /// then what the frame captured).
    fn redraw(&mut self, event_loop: &ActiveEventLoop) {
        let Some(start) = self.size_frame(event_loop) else {
            return;
        };
        self.app.update();
        let Some((held, delay)) = self.draw_frame(event_loop, &start) else {
            return;
        };
        self.frames += 1;
        self.next_frame(event_loop, start.now, held, delay);
    }

    /// The frame's input handed to the panel and the world, the outside view's window shown or
    /// hidden, the views laid out and their placement told to the world (a system sets the
    /// viewport from it). None when the frame is not drawn (the window is still being resized,
    /// or the session failed).
    fn size_frame(&mut self, event_loop: &ActiveEventLoop) -> Option<FrameStart> {
        let windows = self.windows.as_mut()?;
        if self.session.wait_for_resize(self.frames, &windows.main) {
            windows.main.window.request_redraw();
            return None;
        }
        let now = Instant::now();
        let world = self.app.world_mut();
        let surface = windows.main.size();
        let mut raw = windows.gui.take_input(&windows.main.window, surface);
        let dt = self.pacing.frame_dt(now);
        if let Err(e) = self.session.begin_frame(self.frames, dt, &mut raw, world) {
            self.fail(event_loop, e);
            return None;
        }
        world.resource_mut::<ViewStats>().replay = self.session.replay_progress(self.frames);
        let both_views = windows.close2gl.is_none();
        windows.gui.hand_input(world, raw, both_views);
        let outside = world.get_resource::<OutsideView>().is_some_and(|o| o.show);
        if let Err(e) =
            windows.show_outside_window(event_loop, &self.instance, &self.options, outside)
        {
            world.insert_resource(Notice::new(format!("the outside view's window: {e}")));
        }
        let hidden = world.get_resource::<PanelState>().is_some_and(|p| p.hidden);
        let views = windows
            .gui
            .views_area(&windows.main.window, surface, hidden);
        let placement = windows.placement(views, outside);
        world.insert_resource(ViewPlacement(placement.clone()));
        Some(FrameStart {
            now,
            surface,
            placement,
            outside,
        })
    }

    /// The panel finished, every window drawn and presented, and what the frame captured kept:
    /// whether input is still held and how long the panel may wait for its next frame. None
    /// when the session failed.
    fn draw_frame(
        &mut self,
        event_loop: &ActiveEventLoop,
        start: &FrameStart,
    ) -> Option<(bool, Duration)> {
        let windows = self.windows.as_mut()?;
        let world = self.app.world_mut();
        let mut gui_frame = windows
            .gui
            .finish(&windows.main.window, world, start.surface);
        windows.gui.upload_textures(&windows.gpu, &mut gui_frame);
        // The panel showed or hid the outside view this frame: lay the views out again at once.
        let relayout = world.get_resource::<OutsideView>().is_some_and(|o| o.show) != start.outside;
        let capture = self.capture.asked(&self.options, self.frames, world);
        let drawn = present::draw(windows, world, &gui_frame, &start.placement, capture);
        windows.gui.free_textures(&mut gui_frame);
        let held = end_input_frame(world);
        let kept =
            drawn.and_then(|shot| self.capture.keep(&self.options, world, &windows.gpu, shot));
        // In a browser a shot or a probe arrives frames later: draw until it has.
        let held = held || self.capture.waiting() || on_its_way(world);
        if let Err(e) = kept.and_then(|()| self.session.end_frame(self.frames, world)) {
            self.fail(event_loop, e);
            return None;
        }
        let delay = match relayout {
            true => Duration::ZERO,
            false => gui_frame.repaint_delay,
        };
        Some((held, delay))
    }

    /// After a frame: exit when the frame budget is spent, else ask for the next frame when
    /// keys are held, a frame was missed, the run draws continuously or the panel wants one.
    fn next_frame(
        &mut self,
        event_loop: &ActiveEventLoop,
        now: Instant,
        held: bool,
        delay: Duration,
    ) {
        let Some(windows) = self.windows.as_ref() else {
            return;
        };
        let budget = self.options.exit_after_frames;
        if budget.is_some_and(|n| self.frames >= n) {
            return event_loop.exit();
        }
        let continuous = budget.is_some() || self.session.is_replaying();
        let missed = windows.missed_frame();
        if self
            .pacing
            .after_frame(now, held, missed, continuous, delay)
        {
            windows.main.window.request_redraw();
        }
    }
}

impl Viewer {
    /// While the windows' drawing is being set up: the close of one of them ends the run as
    /// closed (see [`Opening`]).
    fn opening_event(&mut self, event_loop: &ActiveEventLoop, id: WindowId, event: &WindowEvent) {
        let Some(opening) = &self.opening else {
            return;
        };
        let (main, close2gl) = &opening.windows;
        let ours = main.window.id() == id || close2gl.as_ref().is_some_and(|w| w.window.id() == id);
        if ours && is_close(event) {
            self.opening = None;
            event_loop.exit();
        }
    }

    /// An event that is input: the panel's first, then the outside view's orbit (over its
    /// column of the main window, or its own window), then the camera's.
    fn input_event(&mut self, id: WindowId, is_main: bool, event: WindowEvent) {
        let Some(windows) = self.windows.as_mut() else {
            return;
        };
        let panel = offer_to_panel(&mut windows.gui, &windows.main.window, is_main, &event);
        let world = self.app.world_mut();
        let (taken, orbited) = match windows.outside.as_ref().filter(|w| w.window.id() == id) {
            Some(own) => {
                let area = PixelRect::whole(own.size().0, own.size().1);
                self.orbit.offer(world, Some(area), &event, panel)
            }
            None if is_main => self.orbit.offer(world, windows.outside_area, &event, panel),
            None => (false, false),
        };
        let redraw = orbited || (!taken && apply_input(&mut self.tracker, world, id, event, panel));
        if redraw {
            windows.main.window.request_redraw();
        }
    }
}

/// The user closed the window, or another client destroyed it.
fn is_close(event: &WindowEvent) -> bool {
    matches!(event, WindowEvent::CloseRequested | WindowEvent::Destroyed)
}

/// Clears this frame's presses, drags and scrolls; returns whether keys are still held.
fn end_input_frame(world: &mut World) -> bool {
    let mut input = world.resource_mut::<InputState>();
    input.end_frame();
    !input.held.is_empty()
}

impl Viewer {
    /// The windows are drawn into from now on: background work wakes the main one.
    fn opened(&mut self, windows: Windows) {
        // The window may have opened smaller than asked (fitted to the monitor): a recording
        // replays at the size it was made at, so that a recorded click lands on the same pixel.
        self.session.window_resized(windows.main.window_size());
        let window = windows.main.window.clone();
        if let Some(wake) = self.app.world().get_resource::<Wake>() {
            wake.install(move || window.request_redraw());
        }
        windows.main.window.request_redraw();
        self.windows = Some(windows);
    }

    /// In a browser: once the GPU has arrived, the windows waiting for it open.
    #[cfg(target_arch = "wasm32")]
    fn take_arrived(&mut self, event_loop: &ActiveEventLoop) {
        let Some((created, surface, gpu)) = self.arriving.as_ref().and_then(|a| a.take()) else {
            return;
        };
        self.arriving = None;
        let world = self.app.world_mut();
        let opened =
            gpu.and_then(|gpu| Windows::with_gpu(created, surface, gpu, self.instance.1, world));
        match opened {
            Ok(windows) => self.opened(windows),
            Err(e) => self.fail(event_loop, e),
        }
    }
}

impl ApplicationHandler for Viewer {
    #[cfg(target_arch = "wasm32")]
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.windows.is_some() || self.arriving.is_some() {
            return;
        }
        let created = create_windows(event_loop, &self.options).and_then(|created| {
            let surface =
                crate::windows::surface_for(&created.0, &self.instance.0, self.instance.1)?;
            Ok((created, surface))
        });
        match created {
            Ok((created, surface)) => {
                self.arriving = Some(crate::browser::choose_gpu(
                    &self.instance.0,
                    created,
                    surface,
                ));
            }
            Err(e) => self.fail(event_loop, e),
        }
    }

    #[cfg(not(target_arch = "wasm32"))]
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.windows.is_some() || self.opening.is_some() {
            return;
        }
        let created = match create_windows(event_loop, &self.options) {
            Ok(created) => created,
            Err(e) => return self.fail(event_loop, e),
        };
        let world = self.app.world_mut();
        match Windows::open(created.clone(), &self.instance, world) {
            Ok(windows) => self.opened(windows),
            Err(error) => {
                self.opening = Some(Opening {
                    windows: created,
                    error,
                    deadline: Instant::now().checked_add(OPENING_GRACE),
                });
            }
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, id: WindowId, event: WindowEvent) {
        #[cfg(target_arch = "wasm32")]
        self.take_arrived(event_loop);
        let Some(windows) = self.windows.as_mut() else {
            return self.opening_event(event_loop, id, &event);
        };
        let is_main = windows.main.window.id() == id;
        if !is_main && windows.window_mut(id).is_none() {
            return;
        }
        match event {
            WindowEvent::RedrawRequested if is_main => return self.redraw(event_loop),
            // Not for egui: it would ask for another redraw, forever.
            WindowEvent::RedrawRequested => return windows.main.window.request_redraw(),
            // Closing the outside view's own window turns the view off; the app goes on.
            _ if is_close(&event) && windows.is_outside_window(id) => {
                windows.outside = None;
                let world = self.app.world_mut();
                world.get_resource_or_insert_with(OutsideView::default).show = false;
                return windows.main.window.request_redraw();
            }
            // Destroyed: another client (or a window manager) took the window away. The windows
            // go at once: a redraw already queued must not ask X about a window that is gone
            // (winit unwraps the error).
            _ if is_close(&event) => {
                self.windows = None;
                return event_loop.exit();
            }
            WindowEvent::Resized(size) => {
                if is_main {
                    self.session.window_resized(size);
                }
                windows.resized(id, size);
                return windows.main.window.request_redraw();
            }
            // A replay's input is the recording's alone.
            _ if self.session.is_replaying() => return,
            WindowEvent::DroppedFile(ref path) => self.session.file_dropped(path),
            _ => {}
        }
        self.input_event(id, is_main, event);
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        if let Some(opening) = &self.opening {
            if let Some(deadline) = opening.deadline.filter(|d| Instant::now() < *d) {
                return event_loop.set_control_flow(ControlFlow::WaitUntil(deadline));
            }
            let error = opening.error.clone();
            self.opening = None;
            return self.fail(event_loop, error);
        }
        let (control_flow, due) = self.pacing.wait(Instant::now());
        if due && let Some(windows) = &self.windows {
            windows.main.window.request_redraw();
        }
        event_loop.set_control_flow(control_flow);
    }
}

//! The winit application: windows appear on `resumed`, events become input, and each redraw of
//! the main window runs one app frame and draws every window.

use std::time::Instant;

use bevy_ecs::world::World;
use close2gl_core::{App, InputState, Viewport};
use close2gl_gpu::Image;
use winit::application::ApplicationHandler;
use winit::event::WindowEvent;
use winit::event_loop::{ActiveEventLoop, EventLoop};
use winit::window::WindowId;

use crate::ViewerOptions;
use crate::input::InputTracker;
use crate::pacing::Pacing;
use crate::routing::{apply_input, offer_to_panel};
use crate::windows::Windows;

pub struct Viewer {
    app: App,
    options: ViewerOptions,
    instance: wgpu::Instance,
    windows: Option<Windows>,
    tracker: InputTracker,
    pacing: Pacing,
    result: Result<(), String>,
    frames: u32,
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
            pacing: Pacing::new(Instant::now()),
            result: Ok(()),
            frames: 0,
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

    /// One app frame: the panel, the layout, the systems, then every window drawn.
    fn redraw(&mut self, event_loop: &ActiveEventLoop) {
        let capture = self.options.screenshot.is_some()
            && self.options.exit_after_frames == Some(self.frames + 1);
        let Some(windows) = self.windows.as_mut() else {
            return;
        };
        let now = Instant::now();
        let world = self.app.world_mut();
        world.resource_mut::<InputState>().dt = self.pacing.frame_dt(now);
        let both_views = windows.close2gl.is_none();
        let mut gui_frame = windows.gui.run(&windows.main.window, world, both_views);
        windows.gui.upload_textures(&windows.gpu, &mut gui_frame);
        let placement = windows.placement(&gui_frame);
        update_viewport(world, placement.viewport);
        self.app.update();

        let drawn = windows.draw(self.app.world_mut(), &gui_frame, &placement, capture);
        windows.gui.free_textures(&mut gui_frame);
        let held = end_input_frame(self.app.world_mut());
        if let Err(e) = drawn.and_then(|shot| save(&self.options, shot)) {
            return self.fail(event_loop, e);
        }
        self.frames += 1;
        let continuous = self.options.exit_after_frames;
        if continuous.is_some_and(|n| self.frames >= n) {
            return event_loop.exit();
        }
        let missed = windows.missed_frame();
        let delay = gui_frame.repaint_delay;
        if self
            .pacing
            .after_frame(now, held, missed, continuous.is_some(), delay)
        {
            windows.main.window.request_redraw();
        }
    }
}

/// Keeps `Viewport` equal to the Close2GL view's size; written only when it changed, so that the
/// pipeline does not run again for nothing.
fn update_viewport(world: &mut World, viewport: Option<Viewport>) {
    if let Some(viewport) = viewport
        && *world.resource::<Viewport>() != viewport
    {
        world.insert_resource(viewport);
    }
}

/// Clears this frame's presses, drags and scrolls; returns whether keys are still held.
fn end_input_frame(world: &mut World) -> bool {
    let mut input = world.resource_mut::<InputState>();
    input.end_frame();
    !input.held.is_empty()
}

/// Writes the frame's screenshot, when one was taken, where `--screenshot` says.
fn save(options: &ViewerOptions, shot: Option<Image>) -> Result<(), String> {
    match (shot, &options.screenshot) {
        (Some(shot), Some(path)) => shot.write_png(path),
        _ => Ok(()),
    }
}

impl ApplicationHandler for Viewer {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.windows.is_some() {
            return;
        }
        let world = self.app.world_mut();
        match Windows::open(event_loop, &self.instance, &self.options, world) {
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
        match event {
            WindowEvent::RedrawRequested if is_main => return self.redraw(event_loop),
            // Not for egui: it would ask for another redraw, forever.
            WindowEvent::RedrawRequested => return windows.main.window.request_redraw(),
            // Destroyed: another client (or a window manager) took the window away.
            WindowEvent::CloseRequested | WindowEvent::Destroyed => return event_loop.exit(),
            _ => {}
        }
        let panel = offer_to_panel(&mut windows.gui, &windows.main.window, is_main, &event);
        let redraw = match event {
            WindowEvent::Resized(size) => {
                windows.resized(id, size);
                true
            }
            event => apply_input(&mut self.tracker, self.app.world_mut(), id, event, panel),
        };
        if redraw {
            windows.main.window.request_redraw();
        }
    }

    fn about_to_wait(&mut self, event_loop: &ActiveEventLoop) {
        let (control_flow, due) = self.pacing.wait(Instant::now());
        if due && let Some(windows) = &self.windows {
            windows.main.window.request_redraw();
        }
        event_loop.set_control_flow(control_flow);
    }
}

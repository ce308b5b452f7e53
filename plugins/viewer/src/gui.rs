//! egui in a winit window drawn by wgpu: events in, the frame's input handed to the panel system
//! (`close2gl_ui::panel_system`, which runs in the app's frame), its paint out.

use web_time::{Duration, Instant};

use bevy_ecs::world::World;
use close2gl_gpu::Gpu;
use close2gl_ui::{PanelInput, PanelOutput};
use winit::window::Window;

pub struct Gui {
    pub ctx: egui::Context,
    state: egui_winit::State,
    renderer: egui_wgpu::Renderer,
    /// egui's clock starts with the panel.
    started: Instant,
}

/// One panel frame, ready to paint.
pub struct GuiFrame {
    /// When egui wants to draw again by itself (a blinking cursor, an animation).
    pub repaint_delay: Duration,
    paint: Vec<egui::ClippedPrimitive>,
    textures: egui::TexturesDelta,
    screen: egui_wgpu::ScreenDescriptor,
}

impl GuiFrame {
    /// Nothing to paint.
    fn empty(size: (u32, u32)) -> Self {
        GuiFrame {
            repaint_delay: Duration::MAX,
            paint: Vec::new(),
            textures: Default::default(),
            screen: egui_wgpu::ScreenDescriptor {
                size_in_pixels: [size.0, size.1],
                pixels_per_point: 1.0,
            },
        }
    }
}

impl Gui {
    pub fn new(gpu: &Gpu, window: &Window, format: wgpu::TextureFormat) -> Self {
        let ctx = egui::Context::default();
        let max_texture_side = gpu.device.limits().max_texture_dimension_2d;
        let state = egui_winit::State::new(
            ctx.clone(),
            egui::ViewportId::ROOT,
            window,
            Some(window.scale_factor() as f32),
            None,
            Some(max_texture_side as usize),
        );
        let renderer =
            egui_wgpu::Renderer::new(&gpu.device, format, egui_wgpu::RendererOptions::default());
        Self {
            ctx,
            state,
            renderer,
            started: Instant::now(),
        }
    }

    pub fn on_event(
        &mut self,
        window: &Window,
        event: &winit::event::WindowEvent,
    ) -> egui_winit::EventResponse {
        self.state.on_window_event(window, event)
    }

    /// The panel's input since the last frame, laid out in `size`, the window's surface. Not
    /// egui-winit's `take_egui_input`: that asks X for the window's size, and winit unwraps X's
    /// answer, which is an error when the window was destroyed in that instant. The size comes
    /// from the last `Resized` event instead; the scale factor is winit's cached one.
    pub fn take_input(&mut self, window: &Window, size: (u32, u32)) -> egui::RawInput {
        let native = window.scale_factor() as f32;
        let (screen, _) = self.screen(window, size);
        let input = self.state.egui_input_mut();
        input.time = Some(self.started.elapsed().as_secs_f64());
        input.screen_rect = (size.0 > 0 && size.1 > 0).then_some(screen);
        input.viewport_id = egui::ViewportId::ROOT;
        input
            .viewports
            .entry(egui::ViewportId::ROOT)
            .or_default()
            .native_pixels_per_point = Some(native);
        input.take()
    }

    /// A `size` surface in points, and the points' size in pixels (egui's zoom times winit's
    /// cached scale factor).
    fn screen(&self, window: &Window, size: (u32, u32)) -> (egui::Rect, f32) {
        let pixels_per_point = self.ctx.zoom_factor() * window.scale_factor() as f32;
        let points = egui::vec2(size.0 as f32, size.1 as f32) / pixels_per_point;
        (
            egui::Rect::from_min_size(egui::Pos2::ZERO, points),
            pixels_per_point,
        )
    }

    /// Where the views go in a `size` window, in points, and the points' size in pixels: what
    /// the panel leaves (`close2gl_ui::views_area`; everything when it is `hidden`), known
    /// before the panel runs.
    pub fn views_area(&self, window: &Window, size: (u32, u32), hidden: bool) -> (egui::Rect, f32) {
        let (screen, pixels_per_point) = self.screen(window, size);
        (close2gl_ui::views_area(screen, hidden), pixels_per_point)
    }

    /// Hands the panel system (`close2gl_ui::panel_system`) this frame's `input` (from
    /// [`Self::take_input`]); `both_views` when this window shows both views.
    pub fn hand_input(&self, world: &mut World, input: egui::RawInput, both_views: bool) {
        world.insert_resource(PanelInput {
            ctx: self.ctx.clone(),
            raw: Some(input),
            both_views,
        });
    }

    /// What the panel system painted this frame, ready to paint into a `size` surface; nothing
    /// when it did not run.
    pub fn finish(&mut self, window: &Window, world: &mut World, size: (u32, u32)) -> GuiFrame {
        let Some(PanelOutput(output)) = world.remove_resource::<PanelOutput>() else {
            return GuiFrame::empty(size);
        };
        #[cfg(target_arch = "wasm32")]
        copy_to_clipboard(&output.platform_output);
        self.state
            .handle_platform_output(window, output.platform_output);
        let repaint_delay = output
            .viewport_output
            .get(&egui::ViewportId::ROOT)
            .map_or(Duration::MAX, |v| v.repaint_delay);
        GuiFrame {
            repaint_delay,
            paint: self.ctx.tessellate(output.shapes, output.pixels_per_point),
            textures: output.textures_delta,
            screen: egui_wgpu::ScreenDescriptor {
                size_in_pixels: [size.0, size.1],
                pixels_per_point: output.pixels_per_point,
            },
        }
    }

    /// Uploads the frame's new textures (the font atlas, first).
    pub fn upload_textures(&mut self, gpu: &Gpu, frame: &mut GuiFrame) {
        for (id, deltas) in frame.textures.set.drain() {
            for delta in &deltas {
                self.renderer
                    .update_texture(&gpu.device, &gpu.queue, id, delta);
            }
        }
    }

    /// Records the panel over what `target` already shows, and submits it.
    pub fn paint(&mut self, gpu: &Gpu, frame: &GuiFrame, target: &wgpu::TextureView) {
        let mut encoder = gpu.device.create_command_encoder(&Default::default());
        let buffers = self.renderer.update_buffers(
            &gpu.device,
            &gpu.queue,
            &mut encoder,
            &frame.paint,
            &frame.screen,
        );
        {
            let mut pass = encoder
                .begin_render_pass(&wgpu::RenderPassDescriptor {
                    label: Some("panel"),
                    color_attachments: &[Some(close2gl_gpu::attachments::color_attachment(
                        target,
                        wgpu::LoadOp::Load,
                    ))],
                    depth_stencil_attachment: None,
                    timestamp_writes: None,
                    occlusion_query_set: None,
                    multiview_mask: None,
                })
                .forget_lifetime();
            self.renderer.render(&mut pass, &frame.paint, &frame.screen);
        }
        gpu.queue
            .submit(buffers.into_iter().chain([encoder.finish()]));
    }

    /// Frees the textures egui is done with, once the frame has been painted.
    pub fn free_textures(&mut self, frame: &mut GuiFrame) {
        for id in frame.textures.free.drain() {
            self.renderer.free_texture(&id);
        }
    }
}

#[cfg(target_arch = "wasm32")]
/// What the panel copied (copy as command, copy link), put on the page's clipboard: egui's own
/// clipboard has no browser backend.
pub fn copy_to_clipboard(output: &egui::PlatformOutput) {
    let Some(clipboard) = web_sys::window().map(|w| w.navigator().clipboard()) else {
        return;
    };
    for command in &output.commands {
        if let egui::OutputCommand::CopyText(text) = command {
            // A promise the page does not wait for: a browser that refuses (no permission)
            // leaves the clipboard as it was.
            let _ = clipboard.write_text(text);
        }
    }
}

//! egui in a winit window drawn by wgpu: events in, the panel over the world, paint out.

use std::time::{Duration, Instant};

use bevy_ecs::world::World;
use close2gl_core::OutsideView;
use close2gl_gpu::Gpu;
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
    /// What the panel left for the views, in points.
    pub views_area: egui::Rect,
    pub pixels_per_point: f32,
    /// When egui wants to draw again by itself (a blinking cursor, an animation).
    pub repaint_delay: Duration,
    paint: Vec<egui::ClippedPrimitive>,
    textures: egui::TexturesDelta,
    screen: egui_wgpu::ScreenDescriptor,
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
        let pixels_per_point = self.ctx.zoom_factor() * native;
        let input = self.state.egui_input_mut();
        input.time = Some(self.started.elapsed().as_secs_f64());
        input.screen_rect = (size.0 > 0 && size.1 > 0).then(|| {
            let points = egui::vec2(size.0 as f32, size.1 as f32) / pixels_per_point;
            egui::Rect::from_min_size(egui::Pos2::ZERO, points)
        });
        input.viewport_id = egui::ViewportId::ROOT;
        input
            .viewports
            .entry(egui::ViewportId::ROOT)
            .or_default()
            .native_pixels_per_point = Some(native);
        input.take()
    }

    /// Runs the control panel over `world` with `input` (from [`Self::take_input`], laid out in
    /// the surface); `both_views` when this window shows both views. `size` is the window's
    /// surface, what the frame draws into.
    pub fn run(
        &mut self,
        window: &Window,
        world: &mut World,
        both_views: bool,
        input: egui::RawInput,
        size: (u32, u32),
    ) -> GuiFrame {
        let mut views_area = egui::Rect::NOTHING;
        let output = self.ctx.run_ui(input, |ui| {
            views_area = close2gl_ui::show(ui, world);
            let outside = world.get_resource::<OutsideView>().is_some_and(|o| o.show);
            close2gl_ui::label_views(ui, views_area, both_views, outside);
        });
        self.state
            .handle_platform_output(window, output.platform_output);
        let repaint_delay = output
            .viewport_output
            .get(&egui::ViewportId::ROOT)
            .map_or(Duration::MAX, |v| v.repaint_delay);
        GuiFrame {
            views_area,
            pixels_per_point: output.pixels_per_point,
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
                    color_attachments: &[Some(close2gl_gpu::texture::color_attachment(
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

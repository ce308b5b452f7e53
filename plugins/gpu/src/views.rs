//! Both views' GPU state, as one resource.

use bevy_ecs::prelude::*;
use close2gl_core::parity::ColorTolerance;
use close2gl_core::{Overlay, Rasterizer};
use glam::Vec3;

use crate::gpu::Gpu;
use crate::pass::submit_pass;

use crate::close2gl_view::Close2glView;
use crate::difference_view::DifferenceView;
use crate::fate_view::FateView;
use crate::highlight::Highlight;
use crate::image_view::ImageView;
use crate::reference::{Reference, clear_color};

/// GPU state for both views (a Resource): the reference renderer and the Close2GL 2D renderer.
/// The upload systems of [`crate::GpuPlugin`] keep it up to date; the owner of the target
/// records the draws.
#[derive(Resource)]
pub struct Views {
    pub(crate) reference: Reference,
    pub(crate) close2gl: Close2glView,
    pub(crate) software: ImageView,
    /// A raster trace's fixed frame (`ViewImages`), shown in place of each view's own drawing
    /// while `fixed` says so: the reference's image, then the Close2GL view's.
    pub(crate) fixed_images: [ImageView; 2],
    pub(crate) fixed: bool,
    pub(crate) fates: FateView,
    pub(crate) difference: DifferenceView,
    pub(crate) highlight: Highlight,
    /// The inspector's display over both views.
    pub(crate) overlay: Overlay,
    /// Which of the two Close2GL views is shown.
    pub(crate) rasterizer: Rasterizer,
    /// `Appearance::background`.
    pub(crate) background: Vec3,
    /// The background the reference clears to: `background`, unless a [`crate::ReferenceSkew`]
    /// moves it.
    pub(crate) reference_background: Vec3,
}

impl Views {
    /// `color_format` is the format of the target both views draw into (a surface's, or
    /// [`crate::OFFSCREEN_FORMAT`]).
    pub fn new(gpu: &Gpu, color_format: wgpu::TextureFormat) -> Views {
        Views {
            reference: Reference::new(&gpu.device, &gpu.queue, color_format),
            close2gl: Close2glView::new(&gpu.device, color_format),
            software: ImageView::new(&gpu.device, color_format, false),
            fixed_images: [
                ImageView::new(&gpu.device, color_format, true),
                ImageView::new(&gpu.device, color_format, false),
            ],
            fixed: false,
            fates: FateView::new(&gpu.device, color_format),
            difference: DifferenceView::new(&gpu.device, color_format),
            highlight: Highlight::new(&gpu.device, color_format),
            overlay: Overlay::Off,
            rasterizer: Rasterizer::Gpu,
            background: close2gl_core::Appearance::default().background,
            reference_background: close2gl_core::Appearance::default().background,
        }
    }

    /// Records the reference view into a pass that has a [`crate::DEPTH_FORMAT`] depth
    /// attachment (cleared to 1.0); the caller sets the pass viewport (the whole target, or the
    /// left half in the split layout). Draws nothing before the first frame's uploads. In the
    /// fate view, the GPU's own facing and depth-test answers are drawn over the model; the
    /// selected triangle, if any, over everything. A raster trace's fixed frame has no model in
    /// it: its image alone.
    pub fn draw_reference(&self, pass: &mut wgpu::RenderPass<'_>) {
        if self.fixed {
            return self.draw_compared_reference(pass);
        }
        self.reference.draw(pass, self.overlay == Overlay::FateView);
        self.highlight.draw_reference(pass);
    }

    /// The reference the Close2GL view is compared with: the GPU's drawing, or a fixed image.
    fn draw_compared_reference(&self, pass: &mut wgpu::RenderPass<'_>) {
        match self.fixed {
            true => self.fixed_images[0].draw(pass),
            false => self.reference.draw(pass, false),
        }
    }

    /// Records the Close2GL view (2D, no depth attachment needed): its 2D buffer drawn by the
    /// GPU, or the software rasterizer's image. The caller sets the viewport rectangle, which
    /// should have the size of `Viewport`. In the fate view, every triangle in its fate's colour
    /// instead; in the live difference, where the two views differ. The selected triangle, if
    /// any, over everything. A raster trace's fixed frame shows its image, or the difference.
    pub fn draw_close2gl(&self, pass: &mut wgpu::RenderPass<'_>) {
        match self.overlay {
            Overlay::Difference if self.fixed => return self.difference.draw(pass),
            _ if self.fixed => return self.draw_compared_close2gl(pass),
            Overlay::FateView => self.fates.draw(pass),
            Overlay::Difference => self.difference.draw(pass),
            Overlay::Off => self.draw_compared_close2gl(pass),
        }
        self.highlight.draw_close2gl(pass);
    }

    /// The Close2GL view the reference is compared with: drawn by the GPU, rasterized, or a
    /// fixed image.
    fn draw_compared_close2gl(&self, pass: &mut wgpu::RenderPass<'_>) {
        match (self.fixed, self.rasterizer) {
            (true, _) => self.fixed_images[1].draw(pass),
            (false, Rasterizer::Gpu) => self.close2gl.draw(pass),
            (false, Rasterizer::Software) => self.software.draw(pass),
        }
    }

    /// For the live difference: draws this frame's two views, as they are without an overlay,
    /// into the difference's own `size` textures, each cleared as [`Self::clear_color`] says
    /// (alpha 0), which `draw_close2gl` then compares by their alpha.
    pub(crate) fn render_difference(&mut self, gpu: &Gpu, size: (u32, u32)) {
        self.difference.prepare(&gpu.device, size);
        let Some(inputs) = self.difference.inputs() else {
            return;
        };
        let depth = Some(&inputs.depth);
        let clear = wgpu::LoadOp::Clear(self.reference_clear_color());
        submit_pass(gpu, &inputs.reference, depth, clear, |pass| {
            self.draw_compared_reference(pass)
        });
        let clear = wgpu::LoadOp::Clear(self.clear_color());
        submit_pass(gpu, &inputs.close2gl, None, clear, |pass| {
            self.draw_compared_close2gl(pass)
        });
    }

    /// `Appearance::background` as the Close2GL view's clear colour, with alpha 0: every view
    /// draws alpha 1 where it covers a pixel, so that a target cleared to this says in its
    /// alpha which pixels the view drew ([`close2gl_core::parity::coverage`]). Every GPU stores
    /// alpha 0 and 1 exactly, where it may round the colour to either byte.
    pub fn clear_color(&self) -> wgpu::Color {
        uncovered(self.background)
    }

    /// The reference view's clear colour: [`Self::clear_color`], moved by the
    /// [`crate::ReferenceSkew`] when one is set.
    pub fn reference_clear_color(&self) -> wgpu::Color {
        uncovered(self.reference_background)
    }

    /// The background, opaque: for a window, whose alpha the desktop or the web page may blend
    /// with (the software image's uncovered pixels keep a window's alpha; see
    /// `image_view.rs`).
    pub fn opaque_clear_color(&self) -> wgpu::Color {
        wgpu::Color {
            a: 1.0,
            ..self.clear_color()
        }
    }

    /// The tolerance the two views' colours are held to, by what the reference draws (the
    /// shading, the texture's filter) and who rasterizes Close2GL.
    pub fn color_tolerance(&self) -> ColorTolerance {
        let (shading, texture) = self.reference.drawn_look();
        ColorTolerance::for_views(self.rasterizer, shading, texture)
    }

    /// Shown in the UI when the device lacks POLYGON_MODE_LINE / POINT (how lines and points are
    /// drawn instead), else None.
    pub fn limitations(&self) -> Option<String> {
        self.reference.limitations()
    }
}

/// `color` as a clear colour that says "nothing drawn here": alpha 0.
fn uncovered(color: Vec3) -> wgpu::Color {
    wgpu::Color {
        a: 0.0,
        ..clear_color(color)
    }
}

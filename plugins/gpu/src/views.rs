//! Both views' GPU state, as one resource.

use bevy_ecs::prelude::*;

use crate::Gpu;
use close2gl_core::{Overlay, Rasterizer};

use crate::close2gl_view::Close2glView;
use crate::fate_view::FateView;
use crate::reference::{Reference, clear_color};
use crate::software_view::SoftwareView;

/// GPU state for both views (a Resource): the reference renderer and the Close2GL 2D renderer.
/// The `Render` systems of [`crate::GpuPlugin`] keep it up to date; the owner of the target
/// records the draws.
#[derive(Resource)]
pub struct Views {
    pub(crate) reference: Reference,
    pub(crate) close2gl: Close2glView,
    pub(crate) software: SoftwareView,
    pub(crate) fates: FateView,
    /// The inspector's display over both views.
    pub(crate) overlay: Overlay,
    /// Which of the two Close2GL views is shown.
    pub(crate) rasterizer: Rasterizer,
    pub(crate) background: wgpu::Color,
}

impl Views {
    /// `color_format` is the format of the target both views draw into (a surface's, or
    /// [`crate::OFFSCREEN_FORMAT`]).
    pub fn new(gpu: &Gpu, color_format: wgpu::TextureFormat) -> Views {
        Views {
            reference: Reference::new(&gpu.device, &gpu.queue, color_format),
            close2gl: Close2glView::new(&gpu.device, color_format),
            software: SoftwareView::new(&gpu.device, color_format),
            fates: FateView::new(&gpu.device, color_format),
            overlay: Overlay::Off,
            rasterizer: Rasterizer::Gpu,
            background: clear_color(close2gl_core::RenderSettings::default().background),
        }
    }

    /// Records the reference view into a pass that has a [`crate::DEPTH_FORMAT`] depth
    /// attachment (cleared to 1.0); the caller sets the pass viewport (the whole target, or the
    /// left half in the split layout). Draws nothing before the first `Render` update. In the
    /// fate view, the GPU's own facing and depth-test answers are drawn over the model.
    pub fn draw_reference(&self, pass: &mut wgpu::RenderPass<'_>) {
        self.reference.draw(pass, self.overlay == Overlay::Fates);
    }

    /// Records the Close2GL view (2D, no depth attachment needed): its 2D buffer drawn by the
    /// GPU, or the software rasterizer's image. The caller sets the viewport rectangle, which
    /// should have the size of `Viewport`. In the fate view, every triangle in its fate's colour
    /// instead.
    pub fn draw_close2gl(&self, pass: &mut wgpu::RenderPass<'_>) {
        match (self.overlay, self.rasterizer) {
            (Overlay::Fates, _) => self.fates.draw(pass),
            (_, Rasterizer::Gpu) => self.close2gl.draw(pass),
            (_, Rasterizer::Software) => self.software.draw(pass),
        }
    }

    /// RenderSettings.background as a clear colour: both views clear to it.
    pub fn clear_color(&self) -> wgpu::Color {
        self.background
    }

    /// Shown in the UI when the adapter lacks POLYGON_MODE_LINE / POINT (what is drawn instead),
    /// else None.
    pub fn limitations(&self) -> Option<String> {
        self.reference.limitations()
    }
}

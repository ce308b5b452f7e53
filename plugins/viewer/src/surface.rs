//! A window and the wgpu surface that presents it: configure, resize, acquire (reconfiguring
//! when the surface is outdated, recreating it when lost), and the depth buffer the reference
//! view needs. What happens to a window (minimised to 0x0, wider than the GPU can draw, a surface
//! that is outdated, lost, refused or gone) is decided by [`crate::acquire`] and the pure
//! functions at the end, tested alone.

use std::sync::Arc;

use close2gl_gpu::attachments::texture_2d;
use close2gl_gpu::{DEPTH_FORMAT, Gpu};
use winit::dpi::PhysicalSize;
use winit::window::Window;

use crate::acquire::{NoTexture, Presentable, SurfaceState};
use crate::surface_source::SurfaceSource;

/// A window just opened, and the size it was opened at: the size its surface starts with.
/// Asking X for it instead could panic inside winit if another client destroyed the window in
/// that instant; if the window manager gives another size, a `Resized` event says so.
#[derive(Clone)]
pub struct NewWindow {
    pub window: Arc<Window>,
    pub size: PhysicalSize<u32>,
}

pub struct WindowSurface {
    pub window: Arc<Window>,
    wgpu: WgpuSurface,
    /// The window's size from its last `Resized` event (or its creation): a frame never asks X,
    /// which may have destroyed the window in that very instant (winit unwraps the error).
    window_size: PhysicalSize<u32>,
    depth: Option<wgpu::TextureView>,
    state: SurfaceState,
}

/// The wgpu side of a window's surface: what [`SurfaceState`] asks of it.
struct WgpuSurface {
    gpu: Gpu,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    /// After `surface`: what it presents through must outlive it.
    source: SurfaceSource,
}

impl WindowSurface {
    /// Configures `surface` (made from `source`) for `window`. `format` is the colour format every view uses: `None`
    /// lets the first window choose (linear 8-bit when offered, as offscreen rendering uses, so
    /// that windows and `close2gl render` show the same colours); later windows must offer it.
    pub fn new(
        gpu: &Gpu,
        NewWindow { window, size }: NewWindow,
        (source, surface): (SurfaceSource, wgpu::Surface<'static>),
        format: Option<wgpu::TextureFormat>,
    ) -> Result<Self, String> {
        let caps = surface.get_capabilities(&gpu.adapter);
        let format = choose_format(&caps, format)?;
        let config = wgpu::SurfaceConfiguration {
            // Readable where the surface allows it, so that a screenshot is the frame shown,
            // read back, not the window drawn a second time.
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT
                | (caps.usages & wgpu::TextureUsages::COPY_SRC),
            format,
            width: 0,
            height: 0,
            present_mode: wgpu::PresentMode::AutoVsync,
            desired_maximum_frame_latency: 2,
            alpha_mode: caps.alpha_modes[0],
            view_formats: vec![],
            color_space: wgpu::SurfaceColorSpace::Auto,
        };
        let mut this = Self {
            window,
            wgpu: WgpuSurface {
                gpu: gpu.clone(),
                surface,
                config,
                source,
            },
            window_size: size,
            depth: None,
            state: SurfaceState::default(),
        };
        this.resize(size);
        Ok(this)
    }

    pub fn format(&self) -> wgpu::TextureFormat {
        self.wgpu.config.format
    }

    /// Whether the frames it presents can be read back (see [`crate::screenshot::read_back`]).
    pub fn readable(&self) -> bool {
        self.wgpu
            .config
            .usage
            .contains(wgpu::TextureUsages::COPY_SRC)
    }

    /// The size drawn: the window's, at most the GPU's largest texture (the rest of a wider
    /// window stays undrawn); 0x0 while minimised.
    pub fn size(&self) -> (u32, u32) {
        (self.wgpu.config.width, self.wgpu.config.height)
    }

    /// The window's size as its last `Resized` event gave it.
    pub fn window_size(&self) -> PhysicalSize<u32> {
        self.window_size
    }

    /// The window is now `size` (its `Resized` event).
    pub fn resize(&mut self, size: PhysicalSize<u32>) {
        self.window_size = size;
        let max = self.wgpu.gpu.device.limits().max_texture_dimension_2d;
        let drawn = drawable_size(size.width, size.height, max).unwrap_or((0, 0));
        if drawn != self.size() {
            (self.wgpu.config.width, self.wgpu.config.height) = drawn;
            self.configure();
        }
    }

    /// A minimised window has no pixels: it is left unconfigured and skipped. So is a surface
    /// that refuses the configuration (its window destroyed under the app, before the event
    /// that says so arrives), until the next frame tries again.
    fn configure(&mut self) {
        let has_pixels = self.has_pixels();
        self.state.configure(&mut self.wgpu, has_pixels);
        self.update_depth();
    }

    fn has_pixels(&self) -> bool {
        self.size() != (0, 0)
    }

    /// A depth buffer the surface's size while it is configured, none otherwise.
    fn update_depth(&mut self) {
        if !self.state.configured {
            self.depth = None;
            return;
        }
        let size = self.size();
        let fits = |view: &wgpu::TextureView| {
            let t = view.texture();
            (t.width(), t.height()) == size
        };
        if !self.depth.as_ref().is_some_and(fits) {
            let depth = texture_2d(
                &self.wgpu.gpu.device,
                "window depth",
                size,
                DEPTH_FORMAT,
                wgpu::TextureUsages::RENDER_ATTACHMENT,
            );
            self.depth = Some(depth.create_view(&Default::default()));
        }
    }

    /// The depth buffer, the window's size; `None` while minimised.
    pub fn depth(&self) -> Option<&wgpu::TextureView> {
        self.depth.as_ref()
    }

    /// Whether the last [`Self::acquire`] skipped a frame that a visible window still needs.
    pub fn missed(&self) -> bool {
        self.state.missed
    }

    /// The next texture to draw into, or `None` when there is nothing to draw this time
    /// (minimised, occluded, a timeout, a surface refused or gone): the caller skips the frame,
    /// and draws again later when [`Self::missed`] says so.
    pub fn acquire(&mut self) -> Result<Option<wgpu::SurfaceTexture>, String> {
        let has_pixels = self.has_pixels();
        let texture = self.state.acquire(&mut self.wgpu, has_pixels);
        self.update_depth();
        texture
    }

    /// Shows `texture`. A present that wgpu refuses (the window went between acquire and
    /// present) only means the surface is configured again before the next frame.
    pub fn present(&mut self, texture: wgpu::SurfaceTexture) {
        let gpu = &self.wgpu.gpu;
        if gpu.validated(|| gpu.queue.present(texture)).is_err() {
            self.state.stale = true;
            self.state.missed = true;
        }
    }
}

impl Presentable for WgpuSurface {
    type Texture = wgpu::SurfaceTexture;

    fn configure(&mut self) -> bool {
        let Self {
            gpu,
            surface,
            config,
            ..
        } = self;
        gpu.validated(|| surface.configure(&gpu.device, config))
            .is_ok()
    }

    fn recreate(&mut self) -> Result<(), String> {
        self.surface = self.source.create_surface(&self.gpu.instance)?;
        Ok(())
    }

    fn next_texture(&mut self) -> Result<(wgpu::SurfaceTexture, bool), NoTexture> {
        let acquired = self.gpu.validated(|| self.surface.get_current_texture());
        match acquired.unwrap_or(wgpu::CurrentSurfaceTexture::Validation) {
            wgpu::CurrentSurfaceTexture::Success(texture) => Ok((texture, false)),
            wgpu::CurrentSurfaceTexture::Suboptimal(texture) => Ok((texture, true)),
            wgpu::CurrentSurfaceTexture::Timeout => Err(NoTexture::Timeout),
            wgpu::CurrentSurfaceTexture::Occluded => Err(NoTexture::Occluded),
            wgpu::CurrentSurfaceTexture::Outdated => Err(NoTexture::Outdated),
            wgpu::CurrentSurfaceTexture::Lost => Err(NoTexture::Lost),
            wgpu::CurrentSurfaceTexture::Validation => Err(NoTexture::Validation),
        }
    }

    fn device_lost(&self) -> Option<String> {
        self.gpu.lost()
    }
}

/// The surface size for a `width` x `height` window: `None` when it has no pixels (minimised),
/// else each side at most `max` (the GPU's largest texture), so that a window wider than the GPU
/// can draw still shows what fits instead of failing.
pub fn drawable_size(width: u32, height: u32, max: u32) -> Option<(u32, u32)> {
    (width > 0 && height > 0).then(|| (width.min(max), height.min(max)))
}

/// The format asked for when the surface offers it; with none asked, the first linear one offered
/// (else the first of any kind).
fn choose_format(
    caps: &wgpu::SurfaceCapabilities,
    wanted: Option<wgpu::TextureFormat>,
) -> Result<wgpu::TextureFormat, String> {
    match wanted {
        Some(format) if caps.formats.contains(&format) => Ok(format),
        Some(format) => Err(format!(
            "the second window cannot show {format:?}, the first window's colour format"
        )),
        None => caps
            .formats
            .iter()
            .copied()
            .find(|f| !f.is_srgb())
            .or(caps.formats.first().copied())
            .ok_or_else(|| "the GPU adapter cannot present to this window".to_string()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_window_without_pixels_is_not_drawn_and_one_too_wide_is_clamped() {
        assert_eq!(drawable_size(0, 0, 16384), None);
        assert_eq!(drawable_size(0, 600, 16384), None);
        assert_eq!(drawable_size(800, 0, 16384), None);
        assert_eq!(drawable_size(1, 1, 16384), Some((1, 1)));
        assert_eq!(drawable_size(16384, 300, 16384), Some((16384, 300)));
        assert_eq!(drawable_size(20000, 40000, 16384), Some((16384, 16384)));
    }
}

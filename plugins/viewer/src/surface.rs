//! A window and the wgpu surface that presents it: configure, resize, acquire (reconfiguring
//! when the surface is outdated, recreating it when lost), and the depth buffer the reference
//! view needs. What happens to a window (minimised to 0x0, wider than the GPU can draw, a surface
//! that is outdated, lost or failing) is decided by the pure functions at the end, tested alone.

use std::sync::Arc;

use close2gl_gpu::texture::texture_2d;
use close2gl_gpu::{DEPTH_FORMAT, Gpu};
use winit::window::Window;

pub struct WindowSurface {
    pub window: Arc<Window>,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    depth: Option<wgpu::TextureView>,
    /// Configure again before the next texture: the last one was suboptimal, or the surface
    /// refused its configuration.
    stale: bool,
    /// The last acquire got no texture though the window has pixels (a timeout, occluded): what
    /// it should have shown is still to be drawn.
    missed: bool,
}

impl WindowSurface {
    pub fn create_surface(
        instance: &wgpu::Instance,
        window: &Arc<Window>,
    ) -> Result<wgpu::Surface<'static>, String> {
        instance.create_surface(window.clone()).map_err(|e| {
            format!(
                "cannot draw into the window ({e}): no GPU backend can present here; install \
                     a Vulkan driver, e.g. `apt-get install mesa-vulkan-drivers` (Mesa's lavapipe \
                     runs without a GPU)"
            )
        })
    }

    /// Configures `surface` for `window`. `format` is the colour format every view uses: `None`
    /// lets the first window choose (linear 8-bit when offered, as offscreen rendering uses, so
    /// that windows and `close2gl render` show the same colours); later windows must offer it.
    pub fn new(
        gpu: &Gpu,
        window: Arc<Window>,
        surface: wgpu::Surface<'static>,
        format: Option<wgpu::TextureFormat>,
    ) -> Result<Self, String> {
        let caps = surface.get_capabilities(&gpu.adapter);
        let format = choose_format(&caps, format)?;
        let config = wgpu::SurfaceConfiguration {
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            format,
            width: 0,
            height: 0,
            present_mode: wgpu::PresentMode::AutoVsync,
            desired_maximum_frame_latency: 2,
            alpha_mode: caps.alpha_modes[0],
            view_formats: vec![],
            color_space: wgpu::SurfaceColorSpace::Auto,
        };
        let size = window.inner_size();
        let mut this = Self {
            window,
            surface,
            config,
            depth: None,
            stale: false,
            missed: false,
        };
        this.resize(gpu, size.width, size.height);
        Ok(this)
    }

    pub fn format(&self) -> wgpu::TextureFormat {
        self.config.format
    }

    /// The size drawn: the window's, at most the GPU's largest texture (the rest of a wider
    /// window stays undrawn); 0x0 while minimised.
    pub fn size(&self) -> (u32, u32) {
        (self.config.width, self.config.height)
    }

    /// The window is now `width` x `height` pixels.
    pub fn resize(&mut self, gpu: &Gpu, width: u32, height: u32) {
        let max = gpu.device.limits().max_texture_dimension_2d;
        let size = drawable_size(width, height, max).unwrap_or((0, 0));
        if size != self.size() {
            (self.config.width, self.config.height) = size;
            self.configure(gpu);
        }
    }

    /// A minimised window has no pixels: it is left unconfigured and skipped. So is a surface
    /// that refuses the configuration (its window destroyed under the app, before the event
    /// that says so arrives), until the next frame tries again.
    fn configure(&mut self, gpu: &Gpu) {
        self.depth = None;
        if self.config.width == 0 || self.config.height == 0 {
            return;
        }
        if gpu
            .validated(|| self.surface.configure(&gpu.device, &self.config))
            .is_err()
        {
            self.stale = true;
            return;
        }
        let depth = texture_2d(
            &gpu.device,
            "window depth",
            self.size(),
            DEPTH_FORMAT,
            wgpu::TextureUsages::RENDER_ATTACHMENT,
        );
        self.depth = Some(depth.create_view(&Default::default()));
    }

    /// The depth buffer, the window's size; `None` while minimised.
    pub fn depth(&self) -> Option<&wgpu::TextureView> {
        self.depth.as_ref()
    }

    /// Whether the last [`Self::acquire`] skipped a frame that a visible window still needs.
    pub fn missed(&self) -> bool {
        self.missed
    }

    /// The next texture to draw into, or `None` when there is nothing to draw this time
    /// (minimised, occluded, a timeout): the caller skips the frame, and draws again later when
    /// [`Self::missed`] says so.
    pub fn acquire(&mut self, gpu: &Gpu) -> Result<Option<wgpu::SurfaceTexture>, String> {
        self.missed = false;
        if std::mem::take(&mut self.stale) {
            self.configure(gpu);
        }
        if self.depth.is_none() {
            // A surface that could not be configured is tried again shortly.
            self.missed = self.stale;
            return Ok(None);
        }
        for retried in [false, true] {
            let failure = match self.surface.get_current_texture() {
                wgpu::CurrentSurfaceTexture::Success(texture) => return Ok(Some(texture)),
                wgpu::CurrentSurfaceTexture::Suboptimal(texture) => {
                    // Show it; the next frame gets a surface that fits the window again.
                    self.stale = true;
                    return Ok(Some(texture));
                }
                wgpu::CurrentSurfaceTexture::Timeout => NoTexture::Timeout,
                wgpu::CurrentSurfaceTexture::Occluded => NoTexture::Occluded,
                wgpu::CurrentSurfaceTexture::Outdated => NoTexture::Outdated,
                wgpu::CurrentSurfaceTexture::Lost => NoTexture::Lost,
                wgpu::CurrentSurfaceTexture::Validation => NoTexture::Validation,
            };
            match recovery(failure, retried) {
                Recovery::Reconfigure => self.configure(gpu),
                Recovery::Recreate => {
                    self.surface = Self::create_surface(&gpu.instance, &self.window)?;
                    self.configure(gpu);
                }
                Recovery::SkipFrame => break,
                // A lost device fails every acquire this way: say so rather than blame the surface.
                Recovery::Fail => {
                    return Err(gpu.lost().unwrap_or_else(|| {
                        "the window's surface failed wgpu's validation".into()
                    }));
                }
            }
        }
        self.missed = true;
        Ok(None)
    }
}

/// The surface size for a `width` x `height` window: `None` when it has no pixels (minimised),
/// else each side at most `max` (the GPU's largest texture), so that a window wider than the GPU
/// can draw still shows what fits instead of failing.
pub fn drawable_size(width: u32, height: u32, max: u32) -> Option<(u32, u32)> {
    (width > 0 && height > 0).then(|| (width.min(max), height.min(max)))
}

/// Why the surface gave no texture: wgpu's `CurrentSurfaceTexture` without a texture.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum NoTexture {
    Timeout,
    Occluded,
    Outdated,
    Lost,
    Validation,
}

/// What to do about it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Recovery {
    /// Configure the surface again (it no longer matches the window) and try again.
    Reconfigure,
    /// Make a new surface for the window and try again.
    Recreate,
    /// Draw nothing now; the frame is drawn again shortly.
    SkipFrame,
    /// Stop with a one-line error.
    Fail,
}

/// One repair per frame: a surface still outdated or lost after it has been tried is left until
/// the next frame (a window being resized keeps outdating it), instead of spinning here.
fn recovery(failure: NoTexture, retried: bool) -> Recovery {
    match failure {
        NoTexture::Validation => Recovery::Fail,
        NoTexture::Timeout | NoTexture::Occluded => Recovery::SkipFrame,
        _ if retried => Recovery::SkipFrame,
        NoTexture::Outdated => Recovery::Reconfigure,
        NoTexture::Lost => Recovery::Recreate,
    }
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

    #[test]
    fn each_failed_acquire_is_repaired_once_skipped_or_fatal() {
        use NoTexture::*;
        assert_eq!(recovery(Outdated, false), Recovery::Reconfigure);
        assert_eq!(recovery(Lost, false), Recovery::Recreate);
        for failure in [Outdated, Lost, Timeout, Occluded] {
            assert_eq!(recovery(failure, true), Recovery::SkipFrame, "{failure:?}");
        }
        assert_eq!(recovery(Timeout, false), Recovery::SkipFrame);
        assert_eq!(recovery(Occluded, false), Recovery::SkipFrame);
        assert_eq!(recovery(Validation, false), Recovery::Fail);
        assert_eq!(recovery(Validation, true), Recovery::Fail);
    }
}

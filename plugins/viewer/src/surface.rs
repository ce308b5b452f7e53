//! A window and the wgpu surface that presents it: configure, resize, acquire (reconfiguring
//! when the surface is outdated, recreating it when lost), and the depth buffer the reference
//! view needs.

use std::sync::Arc;

use close2gl_gpu::texture::texture_2d;
use close2gl_gpu::{DEPTH_FORMAT, Gpu};
use winit::window::Window;

pub struct WindowSurface {
    pub window: Arc<Window>,
    surface: wgpu::Surface<'static>,
    config: wgpu::SurfaceConfiguration,
    depth: Option<wgpu::TextureView>,
    /// The last texture was suboptimal: configure again before the next one.
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
        let size = window.inner_size();
        let config = wgpu::SurfaceConfiguration {
            usage: wgpu::TextureUsages::RENDER_ATTACHMENT,
            format,
            width: size.width,
            height: size.height,
            present_mode: wgpu::PresentMode::AutoVsync,
            desired_maximum_frame_latency: 2,
            alpha_mode: caps.alpha_modes[0],
            view_formats: vec![],
            color_space: wgpu::SurfaceColorSpace::Auto,
        };
        let mut this = Self {
            window,
            surface,
            config,
            depth: None,
            stale: false,
            missed: false,
        };
        this.configure(gpu);
        Ok(this)
    }

    pub fn format(&self) -> wgpu::TextureFormat {
        self.config.format
    }

    /// The configured size; 0x0 while minimised.
    pub fn size(&self) -> (u32, u32) {
        (self.config.width, self.config.height)
    }

    pub fn resize(&mut self, gpu: &Gpu, width: u32, height: u32) {
        if (width, height) != self.size() {
            self.config.width = width;
            self.config.height = height;
            self.configure(gpu);
        }
    }

    /// A minimised window has no pixels: it is left unconfigured and skipped.
    fn configure(&mut self, gpu: &Gpu) {
        if self.config.width == 0 || self.config.height == 0 {
            self.depth = None;
            return;
        }
        self.surface.configure(&gpu.device, &self.config);
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
        if self.depth.is_none() {
            return Ok(None);
        }
        if std::mem::take(&mut self.stale) {
            self.configure(gpu);
        }
        for _attempt in 0..2 {
            match self.surface.get_current_texture() {
                wgpu::CurrentSurfaceTexture::Success(texture) => return Ok(Some(texture)),
                wgpu::CurrentSurfaceTexture::Suboptimal(texture) => {
                    // Show it; the next frame gets a surface that fits the window again.
                    self.stale = true;
                    return Ok(Some(texture));
                }
                wgpu::CurrentSurfaceTexture::Timeout | wgpu::CurrentSurfaceTexture::Occluded => {
                    break;
                }
                wgpu::CurrentSurfaceTexture::Outdated => self.configure(gpu),
                wgpu::CurrentSurfaceTexture::Lost => {
                    self.surface = Self::create_surface(&gpu.instance, &self.window)?;
                    self.configure(gpu);
                }
                wgpu::CurrentSurfaceTexture::Validation => {
                    return Err("the window's surface failed wgpu's validation".into());
                }
            }
        }
        self.missed = true;
        Ok(None)
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

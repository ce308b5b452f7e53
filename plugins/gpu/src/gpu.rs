//! The one wgpu device every view and every window shares.

use std::sync::{Arc, Mutex};

use bevy_ecs::prelude::*;

/// The wgpu instance, adapter, device and queue every view shares (a Resource). Cloning is cheap:
/// wgpu's handles are reference-counted, so tests create one and hand copies to many apps.
#[derive(Resource, Clone, Debug)]
pub struct Gpu {
    pub instance: wgpu::Instance,
    pub adapter: wgpu::Adapter,
    pub device: wgpu::Device,
    pub queue: wgpu::Queue,
    /// Why the device was lost, once wgpu says so: a lost device draws nothing and reports no
    /// errors, so whoever presents must ask ([`Gpu::lost`]) to stop with a message.
    lost: Arc<Mutex<Option<String>>>,
}

/// The optional features the reference renderer uses when the adapter has them: glPolygonMode's
/// lines and points drawn by the hardware (without them, face by face).
const POLYGON_MODES: wgpu::Features =
    wgpu::Features::POLYGON_MODE_LINE.union(wgpu::Features::POLYGON_MODE_POINT);

/// Set to 1, the device is opened without [`POLYGON_MODES`] even where the adapter has them: the
/// way WebGL2 draws lines and points, on the desktop.
pub const NO_POLYGON_MODE_VAR: &str = "CLOSE2GL_NO_POLYGON_MODE";

/// The optional features to ask the adapter for: [`POLYGON_MODES`] unless
/// [`NO_POLYGON_MODE_VAR`] is 1.
fn wanted_features() -> wgpu::Features {
    match std::env::var(NO_POLYGON_MODE_VAR).as_deref() {
        Ok("1") => wgpu::Features::empty(),
        _ => POLYGON_MODES,
    }
}

impl Gpu {
    /// No window: `backends` picks Vulkan, GL, ... (`WGPU_BACKEND` in the environment is ignored
    /// so that the caller's choice is the one used). Fails with a message saying what to install
    /// when no adapter exists.
    pub fn headless(backends: wgpu::Backends) -> Result<Gpu, String> {
        Self::headless_with(backends, wanted_features())
    }

    /// [`Gpu::headless`] asking for the optional features in `wanted` (those the adapter has),
    /// whatever the environment says.
    pub fn headless_with(backends: wgpu::Backends, wanted: wgpu::Features) -> Result<Gpu, String> {
        let mut descriptor = wgpu::InstanceDescriptor::new_without_display_handle_from_env();
        descriptor.backends = backends;
        let instance = wgpu::Instance::new(descriptor);
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            ..Default::default()
        }))
        .map_err(|_| no_adapter(backends))?;
        pollster::block_on(Self::open_device(instance, adapter, wanted))
    }

    /// For windows: the caller made the instance (with a display handle) and a surface; the
    /// adapter chosen can present to it. The primary backends (Vulkan, Metal, DX12) come first;
    /// GL only when none of them has an adapter at all. Not merely when none can present to
    /// this surface: a window destroyed by another client while the app starts makes every
    /// adapter refuse it, and falling back to GL then crashed Mesa's EGL (a segfault configuring
    /// the dead window) where Vulkan reports an error and the app ends as closed.
    pub fn for_surface(
        instance: wgpu::Instance,
        surface: &wgpu::Surface<'_>,
    ) -> Result<Gpu, String> {
        let primary = pollster::block_on(instance.enumerate_adapters(wgpu::Backends::PRIMARY));
        let candidates = if primary.is_empty() {
            pollster::block_on(instance.enumerate_adapters(wgpu::Backends::all()))
        } else {
            primary
        };
        let names: Vec<String> = candidates.iter().map(|a| a.get_info().name).collect();
        let mut presenting: Vec<wgpu::Adapter> = candidates
            .into_iter()
            .filter(|adapter| adapter.is_surface_supported(surface))
            .collect();
        // Real GPUs before software ones, as `PowerPreference::HighPerformance` would.
        presenting.sort_by_key(|adapter| adapter.get_info().device_type == wgpu::DeviceType::Cpu);
        match presenting.into_iter().next() {
            Some(adapter) => {
                pollster::block_on(Self::open_device(instance, adapter, wanted_features()))
            }
            None if names.is_empty() => Err(no_adapter(wgpu::Backends::all())),
            None => Err(format!(
                "no GPU adapter can present to this window ({} cannot)",
                names.join(", ")
            )),
        }
    }

    /// In a browser: the adapter that draws on the canvas of `surface` (WebGL2 ties the two
    /// together), awaited as a browser requires.
    #[cfg(target_arch = "wasm32")]
    pub async fn for_canvas(
        instance: wgpu::Instance,
        surface: &wgpu::Surface<'_>,
    ) -> Result<Gpu, String> {
        let adapter = instance
            .request_adapter(&wgpu::RequestAdapterOptions {
                power_preference: wgpu::PowerPreference::HighPerformance,
                compatible_surface: Some(surface),
                ..Default::default()
            })
            .await
            .map_err(|e| format!("this browser offers no WebGPU or WebGL2 adapter: {e}"))?;
        Self::open_device(instance, adapter, wanted_features()).await
    }

    async fn open_device(
        instance: wgpu::Instance,
        adapter: wgpu::Adapter,
        wanted: wgpu::Features,
    ) -> Result<Gpu, String> {
        let (device, queue) = adapter
            .request_device(&wgpu::DeviceDescriptor {
                label: Some("close2gl"),
                required_features: adapter.features() & wanted,
                // Everything the adapter offers: big viewports need its real texture size limit.
                required_limits: adapter.limits(),
                ..Default::default()
            })
            .await
            .map_err(|e| {
                format!(
                    "the GPU adapter {} refused to open a device: {e}",
                    adapter.get_info().name
                )
            })?;
        Ok(Self::from_device(instance, adapter, device, queue))
    }

    /// A device opened by hand (a test that wants other features or limits), watched for its
    /// loss like every other.
    pub fn from_device(
        instance: wgpu::Instance,
        adapter: wgpu::Adapter,
        device: wgpu::Device,
        queue: wgpu::Queue,
    ) -> Gpu {
        let lost = Arc::new(Mutex::new(None));
        let flag = Arc::clone(&lost);
        device.set_device_lost_callback(move |reason, message| {
            if let Ok(mut lost) = flag.lock() {
                *lost = Some(lost_message(reason, &message));
            }
        });
        Gpu {
            instance,
            adapter,
            device,
            queue,
            lost,
        }
    }

    /// A one-line error when the device has been lost (a driver reset, the adapter removed):
    /// nothing drawn on it shows any more. wgpu reports a loss when it next polls the device.
    pub fn lost(&self) -> Option<String> {
        let _ = self.device.poll(wgpu::PollType::Poll);
        self.lost.lock().ok().and_then(|lost| lost.clone())
    }

    /// Runs `f`, returning wgpu's error as a message instead of letting it reach the
    /// uncaptured-error handler (which panics): for calls that can fail on what the window
    /// system did, not on a bug of ours. Every kind of error is caught: a swapchain refused for
    /// a window that is going away is a validation error or an internal one depending on the
    /// driver.
    #[cfg(not(target_arch = "wasm32"))]
    pub fn validated<T>(&self, f: impl FnOnce() -> T) -> Result<T, String> {
        let filters = [
            wgpu::ErrorFilter::Validation,
            wgpu::ErrorFilter::Internal,
            wgpu::ErrorFilter::OutOfMemory,
        ];
        let scopes = filters.map(|filter| self.device.push_error_scope(filter));
        let value = f();
        // Scopes pop innermost first.
        let mut error = None;
        for scope in scopes.into_iter().rev() {
            if let Some(e) = pollster::block_on(scope.pop()) {
                error.get_or_insert(e.to_string());
            }
        }
        match error {
            Some(error) => Err(error),
            None => Ok(value),
        }
    }

    /// In a browser the error scopes' answers can only be awaited, and no other client takes a
    /// canvas away: `f` runs unwatched, its errors logged in the browser's console.
    #[cfg(target_arch = "wasm32")]
    pub fn validated<T>(&self, f: impl FnOnce() -> T) -> Result<T, String> {
        Ok(f())
    }

    /// Whether the device draws lines and points with the hardware's polygon modes (otherwise
    /// the reference draws them face by face).
    pub fn has_polygon_modes(&self) -> bool {
        self.device.features().contains(POLYGON_MODES)
    }

    /// The adapter's name, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    pub fn adapter_name(&self) -> String {
        self.adapter.get_info().name
    }

    /// The backend in use, e.g. "vulkan" or "gl".
    pub fn backend_name(&self) -> String {
        self.adapter.get_info().backend.to_str().to_string()
    }
}

fn lost_message(reason: wgpu::DeviceLostReason, message: &str) -> String {
    let why = match reason {
        wgpu::DeviceLostReason::Destroyed => "destroyed",
        wgpu::DeviceLostReason::Unknown => "a driver error or the adapter went away",
    };
    match message.lines().next().filter(|line| !line.is_empty()) {
        Some(detail) => format!("the GPU device was lost ({why}: {detail}); restart close2gl"),
        None => format!("the GPU device was lost ({why}); restart close2gl"),
    }
}

fn no_adapter(backends: wgpu::Backends) -> String {
    format!(
        "no GPU adapter found for {}: install a Vulkan driver, e.g. `apt-get install \
         mesa-vulkan-drivers` (Mesa's lavapipe runs without a GPU)",
        backend_names(backends)
    )
}

/// "vulkan|gl" for the native backends among the flags set.
fn backend_names(backends: wgpu::Backends) -> String {
    let names: Vec<&str> = [
        (wgpu::Backends::VULKAN, "vulkan"),
        (wgpu::Backends::GL, "gl"),
        (wgpu::Backends::METAL, "metal"),
        (wgpu::Backends::DX12, "dx12"),
    ]
    .into_iter()
    .filter(|(flag, _)| backends.contains(*flag))
    .map(|(_, name)| name)
    .collect();
    if names.is_empty() {
        "no backend".into()
    } else {
        names.join("|")
    }
}

/// Parses `--backend`: vulkan, gl, metal, dx12 or all.
pub fn parse_backends(name: &str) -> Result<wgpu::Backends, String> {
    match name {
        "vulkan" => Ok(wgpu::Backends::VULKAN),
        "gl" => Ok(wgpu::Backends::GL),
        "metal" => Ok(wgpu::Backends::METAL),
        "dx12" => Ok(wgpu::Backends::DX12),
        "all" => Ok(wgpu::Backends::all()),
        other => Err(format!(
            "unknown backend \"{other}\": expected vulkan, gl, metal, dx12 or all"
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_lost_device_is_reported_as_one_line() {
        // A device of its own: destroying it is how wgpu lets a test lose one.
        let gpu = Gpu::headless(wgpu::Backends::PRIMARY).expect("a GPU adapter");
        assert_eq!(gpu.lost(), None);
        gpu.device.destroy();
        let lost = gpu
            .lost()
            .expect("the loss is reported once the device is polled");
        assert!(
            lost.starts_with("the GPU device was lost (destroyed"),
            "{lost}"
        );
        assert!(!lost.contains('\n'), "{lost}");
        assert_eq!(gpu.clone().lost(), Some(lost), "clones share the device");
    }
}

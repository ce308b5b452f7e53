//! What the viewer needs of a browser page. A browser can only be awaited: whether it offers
//! WebGPU, and which adapter draws on the canvas. So the run (`crate::run`) starts once the
//! [`instance`] is known (WebGPU where the browser has an adapter, WebGL2 otherwise, chosen
//! once), and the canvas's GPU arrives after its window opens ([`choose_gpu`]). What goes wrong
//! is shown on the page ([`report`]).

use std::cell::RefCell;
use std::rc::Rc;

use close2gl_gpu::Gpu;

use crate::surface_source::SurfaceSource;
use crate::windows::Created;

/// WebGPU when the browser has an adapter for it, else WebGL2 (wgpu's GL backend).
pub async fn instance() -> wgpu::Instance {
    let mut descriptor = wgpu::InstanceDescriptor::new_without_display_handle();
    descriptor.backends = wgpu::Backends::BROWSER_WEBGPU | wgpu::Backends::GL;
    wgpu::util::new_instance_with_webgpu_detection(descriptor).await
}

/// The windows, their main surface and the GPU chosen for it, once the browser has answered.
pub type Arrived = (
    Created,
    (SurfaceSource, wgpu::Surface<'static>),
    Result<Gpu, String>,
);

/// Where the GPU arrives; the viewer looks each time an event wakes it.
pub struct Arriving(Rc<RefCell<Option<Arrived>>>);

impl Arriving {
    pub fn take(&self) -> Option<Arrived> {
        self.0.borrow_mut().take()
    }
}

/// Asks the browser for the adapter that draws on the main window's canvas and a device on it;
/// the answer arrives later, and the main window is asked to redraw then.
pub fn choose_gpu(
    instance: &wgpu::Instance,
    created: Created,
    surface: (SurfaceSource, wgpu::Surface<'static>),
) -> Arriving {
    let slot = Rc::new(RefCell::new(None));
    let arrived = Rc::clone(&slot);
    let instance = instance.clone();
    wasm_bindgen_futures::spawn_local(async move {
        let gpu = Gpu::for_canvas(instance, &surface.1).await;
        let window = created.0.window.clone();
        *arrived.borrow_mut() = Some((created, surface, gpu));
        window.request_redraw();
    });
    Arriving(slot)
}

/// Shows `error` on the page: in its `#error` element when it has one, and the console.
pub fn report(error: &str) {
    web_sys::console::error_1(&format!("close2gl: {error}").into());
    let element = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.get_element_by_id("error"));
    if let Some(element) = element {
        element.set_text_content(Some(error));
    }
}

//! The viewer in a browser page. A browser can only be awaited: whether it offers WebGPU, and
//! which adapter draws on the canvas. So the run starts once the instance is known (WebGPU where
//! the browser has an adapter, WebGL2 otherwise, chosen once), and the canvas's GPU arrives
//! after its window opens ([`choose_gpu`]); the event loop itself is the browser's, which winit
//! hands the viewer to and returns at once. What goes wrong is shown on the page ([`report`]).

use std::cell::RefCell;
use std::rc::Rc;

use close2gl_core::App;
use close2gl_gpu::Gpu;
use winit::event_loop::{ControlFlow, EventLoop};
use winit::platform::web::EventLoopExtWebSys;

use crate::ViewerOptions;
use crate::handler::Viewer;
use crate::session::Session;
use crate::surface_source::{Connections, SurfaceSource};
use crate::windows::Created;

/// Starts the viewer on the page; it runs after this returns, for as long as the page lives.
pub fn run(app: App, options: ViewerOptions) -> Result<(), String> {
    wasm_bindgen_futures::spawn_local(async move {
        let instance = instance().await;
        let event_loop = match EventLoop::new() {
            Ok(event_loop) => event_loop,
            Err(e) => return report(&format!("cannot start the page's event loop: {e}")),
        };
        event_loop.set_control_flow(ControlFlow::Wait);
        let session = match Session::for_options(&options) {
            Ok(session) => session,
            Err(e) => return report(&e),
        };
        let viewer = Viewer::new(app, options, session, (instance, Connections::Winit));
        event_loop.spawn_app(viewer);
    });
    Ok(())
}

/// WebGPU when the browser has an adapter for it, else WebGL2 (wgpu's GL backend).
async fn instance() -> wgpu::Instance {
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

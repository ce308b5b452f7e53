//! Where a window's wgpu surface comes from, and on which X connection it presents.
//!
//! On X11 the Vulkan swapchain gets an X connection of its own. Given winit's, Mesa's swapchain
//! sends its requests on the connection winit's event loop reads: when another client destroys
//! the window, the X server's error for a swapchain request (Present's SelectInput on a window
//! that is gone) reaches winit's error handler, and winit then blames it on its own next call and
//! panics (`destroy_notify`: "Failed to destroy input context: BadWindow", seen one run in about
//! fifty of the window-destroying test). On a connection of its own, the error is the
//! swapchain's alone, and wgpu reports it as a refused configuration, which skips the frame.
//!
//! GL (the fallback where no Vulkan, Metal or DX12 adapter exists) presents through the display
//! winit opened, as EGL requires, and so do other window systems.

use std::sync::Arc;

#[cfg(not(target_arch = "wasm32"))]
use wgpu::rwh::{HasWindowHandle, RawWindowHandle};
use winit::window::Window;

/// The wgpu instance windows draw with: the primary backends (Vulkan, Metal, DX12) when one has
/// an adapter, with no display of winit's in it, so that surfaces may bring their own; else GL,
/// which needs winit's display to present on X11.
#[cfg(not(target_arch = "wasm32"))]
pub fn instance(display: &winit::event_loop::OwnedDisplayHandle) -> (wgpu::Instance, Connections) {
    let mut descriptor = wgpu::InstanceDescriptor::new_without_display_handle_from_env();
    descriptor.backends &= wgpu::Backends::PRIMARY;
    let primary = wgpu::Instance::new(descriptor);
    if !pollster::block_on(primary.enumerate_adapters(wgpu::Backends::PRIMARY)).is_empty() {
        return (primary, Connections::OwnOnX11);
    }
    let descriptor =
        wgpu::InstanceDescriptor::new_with_display_handle_from_env(Box::new(display.clone()));
    (wgpu::Instance::new(descriptor), Connections::Winit)
}

/// Which X connection surfaces present on.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Connections {
    /// A connection of each surface's own on X11; winit's elsewhere.
    OwnOnX11,
    /// winit's (the GL fallback).
    Winit,
}

/// A window and what its surfaces are made from. Kept beside the surface, after it, so that the
/// connection outlives it.
pub struct SurfaceSource {
    window: Arc<Window>,
    x11: Option<x11::OwnConnection>,
}

impl SurfaceSource {
    pub fn new(window: Arc<Window>, connections: Connections) -> Result<Self, String> {
        let x11 = match (connections, x11_window(&window)) {
            (Connections::OwnOnX11, Some(id)) => Some(x11::OwnConnection::open(id)?),
            _ => None,
        };
        Ok(Self { window, x11 })
    }

    /// A new surface for the window.
    pub fn create_surface(
        &self,
        instance: &wgpu::Instance,
    ) -> Result<wgpu::Surface<'static>, String> {
        let surface = match &self.x11 {
            Some(own) => own.create_surface(instance),
            None => instance
                .create_surface(self.window.clone())
                .map_err(|e| e.to_string()),
        };
        surface.map_err(|e| {
            format!(
                "cannot draw into the window ({e}): no GPU backend can present here; install \
                 a Vulkan driver, e.g. `apt-get install mesa-vulkan-drivers` (Mesa's lavapipe \
                 runs without a GPU)"
            )
        })
    }
}

/// The X window's id, when `window` is one.
#[cfg(not(target_arch = "wasm32"))]
fn x11_window(window: &Window) -> Option<u32> {
    match window.window_handle().map(|h| h.as_raw()) {
        Ok(RawWindowHandle::Xlib(handle)) => u32::try_from(handle.window).ok(),
        Ok(RawWindowHandle::Xcb(handle)) => Some(handle.window.get()),
        _ => None,
    }
}

#[cfg(target_arch = "wasm32")]
fn x11_window(_window: &Window) -> Option<u32> {
    None
}

#[cfg(all(
    unix,
    not(any(target_os = "macos", target_os = "ios", target_os = "android"))
))]
mod x11 {
    use std::sync::Arc;

    use wgpu::rwh::{RawDisplayHandle, RawWindowHandle, XcbDisplayHandle, XcbWindowHandle};
    use x11rb::xcb_ffi::XCBConnection;

    pub struct OwnConnection {
        connection: Arc<XCBConnection>,
        screen: i32,
        window: u32,
    }

    impl OwnConnection {
        pub fn open(window: u32) -> Result<Self, String> {
            let (connection, screen) = XCBConnection::connect(None)
                .map_err(|e| format!("cannot connect to the X server for drawing: {e}"))?;
            Ok(Self {
                connection: Arc::new(connection),
                screen: screen as i32,
                window,
            })
        }

        pub fn create_surface(
            &self,
            instance: &wgpu::Instance,
        ) -> Result<wgpu::Surface<'static>, String> {
            let connection = std::ptr::NonNull::new(self.connection.get_raw_xcb_connection());
            let window =
                std::num::NonZeroU32::new(self.window).ok_or("an X window without an id")?;
            let target = wgpu::SurfaceTargetUnsafe::RawHandle {
                raw_display_handle: Some(RawDisplayHandle::Xcb(XcbDisplayHandle::new(
                    connection,
                    self.screen,
                ))),
                raw_window_handle: RawWindowHandle::Xcb(XcbWindowHandle::new(window)),
            };
            // SAFETY: the connection is kept beside the surface and dropped after it
            // (`WgpuSurface`'s field order), and the window is destroyed only after the surface is
            // dropped (winit's `Window` is held there too), or by another client, which the X
            // server answers with errors, not undefined behaviour.
            unsafe { instance.create_surface_unsafe(target) }.map_err(|e| e.to_string())
        }
    }
}

/// No X11 here: surfaces always use the window system's own connection.
#[cfg(not(all(
    unix,
    not(any(target_os = "macos", target_os = "ios", target_os = "android"))
)))]
mod x11 {
    pub enum OwnConnection {}

    impl OwnConnection {
        pub fn open(_window: u32) -> Result<Self, String> {
            Err("X11 is not available on this platform".into())
        }

        pub fn create_surface(
            &self,
            _instance: &wgpu::Instance,
        ) -> Result<wgpu::Surface<'static>, String> {
            match *self {}
        }
    }
}

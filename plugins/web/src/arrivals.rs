//! Files the page is handed, dropped on it or picked with the panel's Open button: the browser
//! reads them later (a promise), into a queue; the frame after, each is kept in the app's file
//! table under its name and requested as the desktop's drop requests a file (a model, an image
//! for the texture, a trace).

use std::path::PathBuf;
use std::sync::{Arc, Mutex};

use bevy_ecs::prelude::*;
use close2gl_core::{ToolRequests, Wake};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use wasm_bindgen_futures::JsFuture;

/// A file the browser has read: its name and bytes.
type Arrived = (String, Vec<u8>);

/// Files read by the browser and not yet handed to the app.
#[derive(Resource, Clone, Default)]
pub struct Arrivals(Arc<Mutex<Vec<Arrived>>>);

/// The page's hidden file input, which the Open button clicks.
const PICKER: &str = "close2gl-file";

/// Listens for files dropped anywhere on the page and picked with the page's file input.
pub fn listen(arrivals: &Arrivals, wake: &Wake) -> Result<(), String> {
    let document = web_sys::window()
        .and_then(|w| w.document())
        .ok_or("no document")?;
    let over = Closure::<dyn Fn(web_sys::DragEvent)>::new(|event: web_sys::DragEvent| {
        // Without this the browser opens the file itself instead of letting the page have it.
        event.prevent_default();
    });
    let (queue, waker) = (arrivals.clone(), wake.clone());
    let drop = Closure::<dyn Fn(web_sys::DragEvent)>::new(move |event: web_sys::DragEvent| {
        event.prevent_default();
        if let Some(files) = event.data_transfer().and_then(|d| d.files()) {
            read_all(files, &queue, &waker);
        }
    });
    let picker: web_sys::HtmlInputElement = document
        .create_element("input")
        .map_err(|e| format!("{e:?}"))?
        .dyn_into()
        .map_err(|e| format!("{e:?}"))?;
    picker.set_type("file");
    picker.set_id(PICKER);
    picker.set_accept(".in,.obj,.png,.jpg,.jpeg,.trace");
    picker.set_hidden(true);
    let (queue, waker, input) = (arrivals.clone(), wake.clone(), picker.clone());
    let picked = Closure::<dyn Fn()>::new(move || {
        if let Some(files) = input.files() {
            read_all(files, &queue, &waker);
        }
        // The same file picked again is a change too.
        input.set_value("");
    });
    let target: &web_sys::EventTarget = document.as_ref();
    let listen =
        |name: &str, f: &js_sys::Function| target.add_event_listener_with_callback(name, f);
    listen("dragover", over.as_ref().unchecked_ref()).map_err(|e| format!("{e:?}"))?;
    listen("drop", drop.as_ref().unchecked_ref()).map_err(|e| format!("{e:?}"))?;
    picker
        .add_event_listener_with_callback("change", picked.as_ref().unchecked_ref())
        .map_err(|e| format!("{e:?}"))?;
    document
        .body()
        .ok_or("no body")?
        .append_child(&picker)
        .map_err(|e| format!("{e:?}"))?;
    // They live as long as the page.
    over.forget();
    drop.forget();
    picked.forget();
    Ok(())
}

fn read_all(files: web_sys::FileList, queue: &Arrivals, wake: &Wake) {
    for file in (0..files.length()).filter_map(|i| files.get(i)) {
        let (queue, wake) = (queue.clone(), wake.clone());
        wasm_bindgen_futures::spawn_local(async move {
            let Ok(buffer) = JsFuture::from(file.array_buffer()).await else {
                return;
            };
            let bytes = js_sys::Uint8Array::new(&buffer).to_vec();
            if let Ok(mut queue) = queue.0.lock() {
                queue.push((file.name(), bytes));
            }
            wake.wake();
        });
    }
}

/// Each file arrived becomes a request, as a file dropped on the desktop's window does.
pub fn hand_over(world: &mut World) {
    let arrived: Vec<Arrived> = match world.resource::<Arrivals>().0.lock() {
        Ok(mut queue) => std::mem::take(&mut *queue),
        Err(_) => return,
    };
    for (name, bytes) in arrived {
        close2gl_core::files::keep(name.clone(), bytes);
        close2gl_viewer::drop_file(world, PathBuf::from(name));
    }
}

/// The panel's Open button clicks the page's file input (within the click's grace, so the
/// browser lets the page open its file chooser).
pub fn open_picker(mut tools: ResMut<ToolRequests>) {
    if !std::mem::take(&mut tools.open_file) {
        return;
    }
    let picker = web_sys::window()
        .and_then(|w| w.document())
        .and_then(|d| d.get_element_by_id(PICKER))
        .and_then(|e| e.dyn_into::<web_sys::HtmlElement>().ok());
    if let Some(picker) = picker {
        picker.click();
    }
}

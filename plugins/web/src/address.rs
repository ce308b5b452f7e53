//! The view in the page's link: the model and every setting that decides the views' pixels,
//! written as copy as command writes them (`close2gl_config::keys::pixel_keys_from`).

use bevy_ecs::prelude::*;
use close2gl_core::{ModelSource, PageLink, Wake};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use web_time::Instant;

use crate::link;
use crate::link_throttle::LinkThrottle;

/// The fragment last written, and when; whether a later one waits for the throttle.
#[derive(Resource, Default)]
pub struct Address {
    written: String,
    throttle: LinkThrottle,
    waiting: bool,
}

/// What the world shows, as a link's fragment; `None` before a model and a camera exist.
pub fn fragment(world: &mut World) -> Option<String> {
    let config = close2gl_config::command::of_world(world)?;
    let model = match &config.model {
        ModelSource::File(path) => path.file_name()?.to_string_lossy().into_owned(),
        ModelSource::Primitive(kind) => kind.name().to_string(),
    };
    let settings = close2gl_config::keys::pixel_keys_from(&config, crate::base_config());
    Some(link::write(&model, &settings))
}

/// Replaces the page's fragment with the view's when it changed, at most every
/// [`LinkThrottle::PERIOD`]
/// (a change within it is written when it ends), without adding an entry to the history for
/// each camera move; and keeps [`PageLink`] for the panel's Copy link.
pub fn write_link(world: &mut World) {
    let Some(fragment) = fragment(world) else {
        return;
    };
    let wake = world.resource::<Wake>().clone();
    let mut address = world.resource_mut::<Address>();
    if address.written == fragment {
        return;
    }
    let Some(window) = web_sys::window() else {
        return;
    };
    let wait = address.throttle.wait(Instant::now());
    if !wait.is_zero() {
        if !std::mem::replace(&mut address.waiting, true) {
            let later = Closure::once_into_js(move || wake.wake());
            let _ = window.set_timeout_with_callback_and_timeout_and_arguments_0(
                later.unchecked_ref(),
                wait.as_millis() as i32,
            );
        }
        return;
    }
    let url = format!("#{fragment}");
    let replaced = window.history().is_ok_and(|history| {
        history
            .replace_state_with_url(&JsValue::NULL, "", Some(&url))
            .is_ok()
    });
    address.throttle.wrote(Instant::now());
    address.waiting = false;
    if replaced {
        let location = window.location();
        let page = location.origin().unwrap_or_default() + &location.pathname().unwrap_or_default();
        address.written = fragment;
        world.insert_resource(PageLink(format!("{page}{url}")));
    }
}

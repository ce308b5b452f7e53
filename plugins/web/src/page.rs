//! The page's start: the bundled models fetched beside the page, the link read, the app built
//! on them as `close2gl MODEL --set ...` builds it, then the viewer on the page's canvas.

use close2gl_config::Config;
use close2gl_core::{App, Layout, ModelSource, Viewport};
use close2gl_ui::Notice;
use close2gl_viewer::{ViewerOptions, ViewerPlugin, browser::report};
use wasm_bindgen::JsCast;
use wasm_bindgen::prelude::*;
use wasm_bindgen_futures::JsFuture;

use crate::link::{self, query_flag};
use crate::{BUNDLED, DEFAULT_MODEL, WebPlugin};

/// Called by the page's JavaScript glue once the module is loaded.
#[wasm_bindgen(start)]
pub fn start() {
    std::panic::set_hook(Box::new(|info| {
        report(&format!("close2gl stopped: {info}"))
    }));
    wasm_bindgen_futures::spawn_local(async {
        if let Err(error) = open().await {
            report(&error);
        }
    });
}

async fn open() -> Result<(), String> {
    let window = web_sys::window().ok_or("not in a browser window")?;
    let location = window.location();
    let query = location.search().unwrap_or_default();
    for name in BUNDLED {
        let bytes = fetch(&window, &format!("models/{name}")).await?;
        close2gl_core::files::keep(name, bytes);
    }
    let (config, mut problems) = config_of_link(&location.hash().unwrap_or_default());
    let size = Viewport {
        width: inner(window.inner_width()),
        height: inner(window.inner_height()),
    };
    let mut app = match close2gl_app::build_app(&config, size) {
        Ok(app) => app,
        // The link's model does not load: the default one does, and the panel says why.
        Err(error) => {
            problems.push(error);
            let fallback = Config {
                model: ModelSource::File(DEFAULT_MODEL.into()),
                ..config
            };
            close2gl_app::build_app(&fallback, size)?
        }
    };
    if !problems.is_empty() {
        app.insert_resource(Notice::new(problems.join("; ")));
    }
    start_viewer(
        app,
        WebPlugin {
            embed: query_flag(&query, "embed"),
            test: query_flag(&query, "test"),
        },
        size,
    )
}

/// The configuration a link asks for, and what was wrong with it (a broken link shows the
/// default view with the reason).
fn config_of_link(fragment: &str) -> (Config, Vec<String>) {
    let mut problems = Vec::new();
    let parsed = link::parse(fragment).unwrap_or_else(|e| {
        problems.push(e);
        link::Link::default()
    });
    let mut config = crate::config_with(&parsed.settings).unwrap_or_else(|e| {
        problems.push(format!("the link: {e}"));
        crate::base_config().clone()
    });
    let model = parsed.model.as_deref().unwrap_or(DEFAULT_MODEL);
    config.model = ModelSource::parse(model);
    (config, problems)
}

fn start_viewer(mut app: App, web: WebPlugin, size: Viewport) -> Result<(), String> {
    app.add_plugins(web)
        .add_plugins(ViewerPlugin(ViewerOptions {
            layout: Layout::Split,
            width: size.width,
            height: size.height,
            fit_to_monitor: false,
            screenshot: None,
            screenshot_frame: None,
            exit_after_frames: None,
            screenshot_dir: ".".into(),
            record: None,
            scene: Vec::new(),
            replay: None,
        }));
    app.run()
}

fn inner(size: Result<JsValue, JsValue>) -> u32 {
    size.ok().and_then(|v| v.as_f64()).unwrap_or(1.0).max(1.0) as u32
}

/// The bytes at `url`, relative to the page.
async fn fetch(window: &web_sys::Window, url: &str) -> Result<Vec<u8>, String> {
    let failed = |e: JsValue| format!("{url}: cannot fetch: {e:?}");
    let response: web_sys::Response = JsFuture::from(window.fetch_with_str(url))
        .await
        .map_err(failed)?
        .dyn_into()
        .map_err(failed)?;
    if !response.ok() {
        return Err(format!("{url}: cannot fetch: HTTP {}", response.status()));
    }
    let buffer = JsFuture::from(response.array_buffer().map_err(failed)?)
        .await
        .map_err(failed)?;
    Ok(js_sys::Uint8Array::new(&buffer).to_vec())
}

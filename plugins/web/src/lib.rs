//! close2gl in a browser page: the same app, compiled to WebAssembly (`scripts/build-web`
//! writes the static site). The page (`page.rs`) fetches the bundled models into the app's file
//! table (`close2gl_core::files`), reads the view from its link ([`link`]) and builds the app as
//! `close2gl MODEL --set ...` does, on the page's canvas. Its plugin, [`WebPlugin`], owns the
//! page's side of the world: it reads the camera, the model and the settings and writes them
//! into the link (throttled, replacing the history's entry rather than adding one); it turns a
//! file dropped on the page or picked (`ToolRequests::open_file`) into the request the desktop's
//! drop makes; with `?embed=1` it hides the panel (`PanelState::hidden`); with `?test=1` it keeps
//! a JSON status in the page's `#status` element for a test to read (frames, the first frame's
//! time, the backend and adapter, the model, the views' coverage agreement, the settings shown).

#[cfg(target_arch = "wasm32")]
mod address;
#[cfg(target_arch = "wasm32")]
mod arrivals;
pub mod link;
pub mod link_throttle;
#[cfg(target_arch = "wasm32")]
mod page;
#[cfg(target_arch = "wasm32")]
mod status;

/// The models the page serves beside itself (`models/NAME`), as `scripts/build-web` copies them
/// from `assets/`; a link's `model` names one of them or a primitive.
pub const BUNDLED: [&str; 4] = ["knot.obj", "cube.in", "textured_cube.in", "far_away.in"];

/// What the page shows when its link names no model: the desktop app's default.
pub const DEFAULT_MODEL: &str = "knot.obj";

/// The page's configuration before its link: the desktop app's `config.toml`, so that both
/// start alike.
pub const CONFIG_TOML: &str = include_str!("../../../config.toml");

/// The page's configuration before its link ([`CONFIG_TOML`]; the defaults if it does not read).
pub fn base_config() -> &'static close2gl_config::Config {
    static BASE: std::sync::OnceLock<close2gl_config::Config> = std::sync::OnceLock::new();
    BASE.get_or_init(|| config_with(&[]).unwrap_or_default())
}

/// The page's base configuration ([`CONFIG_TOML`]) with a link's `settings` applied.
pub fn config_with(settings: &[String]) -> Result<close2gl_config::Config, String> {
    close2gl_config::load_text(
        CONFIG_TOML,
        "config.toml",
        std::path::Path::new(""),
        settings,
    )
}

/// The page's side of the world (see the crate's doc).
pub struct WebPlugin {
    /// `?embed=1`: no panel, the views only.
    pub embed: bool,
    /// `?test=1`: the JSON status in `#status`.
    pub test: bool,
}

#[cfg(target_arch = "wasm32")]
mod plugin {
    use bevy_ecs::prelude::*;
    use close2gl_core::{App, FrameSet, Plugin, Update, Wake};
    use close2gl_ui::PanelState;

    use crate::{WebPlugin, address, arrivals, status};

    impl Plugin for WebPlugin {
        fn build(&self, app: &mut App) {
            let arrivals = arrivals::Arrivals::default();
            let wake = app
                .world_mut()
                .get_resource_or_insert_with(Wake::default)
                .clone();
            if let Err(e) = arrivals::listen(&arrivals, &wake) {
                close2gl_viewer::browser::report(&format!("files cannot be dropped here: {e}"));
            }
            app.world_mut()
                .get_resource_or_insert_with(PanelState::default)
                .hidden = self.embed;
            app.insert_resource(arrivals)
                .init_resource::<address::Address>()
                .add_systems(
                    Update,
                    (arrivals::hand_over, arrivals::open_picker).in_set(FrameSet::Input),
                )
                .add_systems(Update, address::write_link.in_set(FrameSet::Output));
            if self.test {
                app.init_resource::<status::Status>()
                    .add_systems(Update, status::write_status.in_set(FrameSet::Output));
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bundled_models_are_the_assets_models() {
        let assets = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../assets");
        let mut models: Vec<String> = std::fs::read_dir(assets)
            .unwrap()
            .filter_map(|e| e.ok()?.file_name().into_string().ok())
            .filter(|name| name.ends_with(".in") || name.ends_with(".obj"))
            .collect();
        models.sort();
        let mut bundled = BUNDLED.map(String::from).to_vec();
        bundled.sort();
        assert_eq!(
            bundled, models,
            "scripts/build-web copies assets/*.in and *.obj"
        );
        assert!(BUNDLED.contains(&DEFAULT_MODEL));
    }

    #[test]
    fn a_link_written_against_the_page_config_reads_back_to_the_same_view() {
        let mut config = config_with(&["render.clipping=\"simple\"".into()]).unwrap();
        // Back to a built-in default that the page's config.toml changes: still in the link.
        config.render.appearance.shading = close2gl_core::Shading::None;
        config.camera.hfov = 45.0;
        let settings = close2gl_config::keys::pixel_keys_from(&config, base_config());
        let fragment = link::write("cube.in", &settings);
        let read = link::parse(&fragment).unwrap();
        let again = config_with(&read.settings).unwrap();
        assert_eq!(again.render, config.render);
        assert_eq!(again.camera.hfov, 45.0);
        assert!(fragment.contains("render.shading=none"), "{fragment}");
        assert!(
            !fragment.contains("close2gl_raster"),
            "unchanged from config.toml: {fragment}"
        );
    }
}

//! `--watch`: the model, its texture image, the config file and a shown trace (with a raster
//! trace's buffers) are reloaded when they change on disk, and the camera stays where it is. A
//! thread polls the files' modification times (no event loop wakes for a file, and polling a
//! handful of files four times a second costs nothing) and wakes the viewer when one has changed and then stayed unchanged for one poll, so
//! that an editor's save half-written is not read. A save that does not load shows its error
//! in the panel and the last good model and settings stay.

use std::collections::{BTreeMap, BTreeSet};
use std::path::PathBuf;
use std::sync::{Arc, Mutex, Weak};
use std::time::{Duration, SystemTime};

use close2gl_core::Owner;
use close2gl_core::bevy_ecs::prelude::*;
use close2gl_core::{
    App, Camera, CameraRequest, CameraSpeeds, FrameSet, KeepPose, ModelRequest, ModelSource,
    ModelStatus, Plugin, Texture, TextureRequest, Update, Wake,
};

use close2gl_trace::view::{TraceRequest, TraceView};

use close2gl_config::Config;

/// How often the files are looked at.
const POLL: Duration = Duration::from_millis(250);

/// Reads the configuration again, as the command line did at start-up (file, overrides, model).
pub type Reload = Arc<dyn Fn() -> Result<Config, String> + Send + Sync>;

/// Adds the watch; `config_file` is the file the configuration was read from, if any, and
/// `reload` reads the whole configuration again.
pub struct WatchPlugin {
    pub config_file: Option<PathBuf>,
    pub reload: Reload,
}

impl Plugin for WatchPlugin {
    fn build(&self, app: &mut App) {
        let wake = app.world().resource::<Wake>().clone();
        let files = Arc::new(Mutex::new(Files::default()));
        spawn_poller(Arc::downgrade(&files), wake);
        app.insert_resource(Watch {
            files,
            config_file: self.config_file.clone(),
            reload: self.reload.clone(),
            model_reload: None,
        })
        .requires::<ModelStatus>(Owner::Model)
        .requires::<KeepPose>(Owner::Camera)
        .requires::<CameraRequest>(Owner::Camera)
        .add_systems(Update, reload_changed_files.in_set(FrameSet::Input));
    }
}

/// The watched files, shared with the polling thread.
#[derive(Resource)]
pub struct Watch {
    files: Arc<Mutex<Files>>,
    config_file: Option<PathBuf>,
    reload: Reload,
    /// The model generation a reload of the watched model waits to replace.
    model_reload: Option<u64>,
}

/// What the poller looks at and what it found.
#[derive(Default)]
struct Files {
    /// Each watched path with its last stamp and whether it has changed since it was reported.
    watched: BTreeMap<PathBuf, Watched>,
    /// Changed and then settled: for the frame to reload.
    settled: BTreeSet<PathBuf>,
}

#[derive(Clone, Copy, Default)]
struct Watched {
    stamp: Option<Stamp>,
    changing: bool,
}

/// What tells a file's versions apart without reading it.
#[derive(Clone, Copy, PartialEq, Eq)]
struct Stamp {
    modified: Option<SystemTime>,
    len: u64,
}

fn stamp(path: &PathBuf) -> Option<Stamp> {
    let meta = std::fs::metadata(path).ok()?;
    Some(Stamp {
        modified: meta.modified().ok(),
        len: meta.len(),
    })
}

impl Files {
    /// Watches exactly `paths` from now on, keeping what is known of the ones already watched.
    fn set(&mut self, paths: BTreeSet<PathBuf>) {
        self.watched.retain(|path, _| paths.contains(path));
        for path in paths {
            self.watched.entry(path.clone()).or_insert_with(|| Watched {
                stamp: stamp(&path),
                changing: false,
            });
        }
        self.settled.retain(|path| self.watched.contains_key(path));
    }

    /// One look at every file; whether one has settled after a change.
    fn poll(&mut self) -> bool {
        let mut settled = false;
        for (path, watched) in &mut self.watched {
            let now = stamp(path);
            if now != watched.stamp {
                *watched = Watched {
                    stamp: now,
                    changing: true,
                };
            } else if watched.changing && now.is_some() {
                watched.changing = false;
                settled |= self.settled.insert(path.clone());
            }
        }
        settled
    }
}

/// Polls until the app (and its `Watch`) is gone.
fn spawn_poller(files: Weak<Mutex<Files>>, wake: Wake) {
    let spawned = std::thread::Builder::new()
        .name("close2gl-watch".into())
        .spawn(move || {
            while let Some(files) = files.upgrade() {
                let settled = files.lock().is_ok_and(|mut f| f.poll());
                drop(files);
                if settled {
                    wake.wake();
                }
                std::thread::sleep(POLL);
            }
        });
    if let Err(e) = spawned {
        eprintln!("close2gl: warning: --watch: cannot start the file watch: {e}");
    }
}

/// Keeps the watched set equal to the shown model, its texture and the config file, and reloads
/// what has changed: the model with the camera kept, the config's settings as a whole or not at
/// all.
pub fn reload_changed_files(world: &mut World) {
    let model = match &world.resource::<ModelStatus>().source {
        Some(ModelSource::File(path)) => Some(path.clone()),
        _ => None,
    };
    let texture = world
        .get_resource::<Texture>()
        .and_then(|t| t.source.clone());
    let view = world.get_resource::<TraceView>();
    let trace = view.and_then(|view| view.path.clone());
    let trace_files = view.map(TraceView::files).unwrap_or_default();
    finish_model_reload(world);
    let watch = world.resource::<Watch>();
    let paths: BTreeSet<PathBuf> = [model.clone(), texture.clone(), watch.config_file.clone()]
        .into_iter()
        .flatten()
        .chain(trace_files.iter().cloned())
        .collect();
    let settled = match watch.files.lock() {
        Ok(mut files) => {
            files.set(paths);
            std::mem::take(&mut files.settled)
        }
        Err(_) => return,
    };
    let config_file = watch.config_file.clone();
    if config_file.as_ref().is_some_and(|c| settled.contains(c)) {
        reload_config(world);
    }
    if let Some(model) = model.filter(|m| settled.contains(m)) {
        let generation = world.resource::<ModelStatus>().generation;
        world.resource_mut::<Watch>().model_reload = Some(generation);
        world.resource_mut::<KeepPose>().0 = true;
        world.resource_mut::<ModelRequest>().0 = Some(ModelSource::File(model));
    }
    if let Some(texture) = texture.filter(|t| settled.contains(t)) {
        world.resource_mut::<TextureRequest>().0 = Some(texture);
    }
    if let Some(trace) = trace.filter(|_| trace_files.iter().any(|f| settled.contains(f))) {
        world.resource_mut::<TraceRequest>().0 = Some(trace);
    }
}

/// A watched model's reload that failed leaves the camera free to be framed by the next load.
fn finish_model_reload(world: &mut World) {
    let Some(generation) = world.resource::<Watch>().model_reload else {
        return;
    };
    let status = world.resource::<ModelStatus>();
    let in_flight = world.resource::<ModelRequest>().0.is_some() || status.loading.is_some();
    if in_flight {
        return;
    }
    if status.generation == generation {
        world.resource_mut::<KeepPose>().0 = false;
    }
    world.resource_mut::<Watch>().model_reload = None;
}

/// The configuration read again: applied whole when it loads, else its error shown and nothing
/// changed. The camera's pose stays; its lens (fields of view, pinned near and far) follows the
/// file. A different model or texture in it is loaded (and framed, being a different model).
fn reload_config(world: &mut World) {
    let loaded = (world.resource::<Watch>().reload)();
    let config = match loaded {
        Ok(config) => config,
        Err(error) => {
            world.resource_mut::<ModelStatus>().error = Some(error);
            return;
        }
    };
    let model_changed = world.resource::<ModelStatus>().source.as_ref() != Some(&config.model);
    let primitive_changed = matches!(config.model, ModelSource::Primitive(_))
        && *world.resource::<close2gl_core::PrimitiveParams>() != config.primitives;
    close2gl_app::apply_settings(world, &config);
    let radius = world.resource::<CameraSpeeds>().model_radius;
    world.insert_resource(CameraSpeeds {
        model_radius: radius,
        ..config.camera.speeds
    });
    // The camera plugin sets the lens in this frame, before it frames a new model.
    let current = world.query::<&Camera>().iter(world).next().copied();
    if let Some(current) = current {
        let mut request = world.resource_mut::<CameraRequest>();
        config.camera.set_lens(request.edit(&current));
    }
    if model_changed || primitive_changed {
        world.resource_mut::<KeepPose>().0 = !model_changed;
        world.resource_mut::<ModelRequest>().0 = Some(config.model.clone());
    }
    let texture = world
        .get_resource::<Texture>()
        .and_then(|t| t.source.clone());
    if config.texture.is_some() && config.texture != texture {
        world.resource_mut::<TextureRequest>().0 = config.texture.clone();
    }
    world.resource_mut::<ModelStatus>().error = None;
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_change_is_reported_once_it_has_settled() {
        let dir = std::env::temp_dir().join(format!("close2gl-watch-unit-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join("m.in");
        std::fs::write(&path, "one").unwrap();
        let mut files = Files::default();
        files.set(BTreeSet::from([path.clone()]));
        assert!(!files.poll(), "nothing changed yet");
        std::fs::write(&path, "two, longer").unwrap();
        assert!(!files.poll(), "changing: not settled");
        assert!(files.poll(), "unchanged for one poll: settled");
        assert!(files.settled.contains(&path));
        assert!(!files.poll(), "reported once");
        std::fs::remove_file(&path).unwrap();
        assert!(
            !files.poll() && !files.poll(),
            "a deleted file is not a settled save"
        );
        let _ = std::fs::remove_dir_all(&dir);
    }
}

//! Big model files load on a worker thread, so that the window keeps drawing the last model
//! (and a progress bar) while they do; the frame that finds the worker done swaps the mesh in
//! (during a replay, the frame the recording says, see [`LoadPace`]).

use std::path::PathBuf;
use std::sync::Arc;
use std::thread::JoinHandle;

use bevy_ecs::prelude::*;
use close2gl_core::limits::BACKGROUND_LOAD_BYTES;
use close2gl_core::{LoadPace, Loading, ModelSource};

use crate::progress::LoadProgress;
use crate::{LoadedModel, load_file};

/// The model file loading on a worker thread, if any. At most one: a new request cancels it.
#[derive(Resource, Default)]
pub struct BackgroundLoad(Option<InFlight>);

struct InFlight {
    source: ModelSource,
    /// The file, as errors name it.
    label: String,
    progress: Arc<LoadProgress>,
    worker: JoinHandle<Result<LoadedModel, String>>,
}

/// What a load in flight has come to this frame.
pub(crate) enum Poll {
    Running(f32),
    Done(ModelSource, Result<LoadedModel, String>),
}

/// The file `source` names, when it is too big to load within a frame (see
/// [`BACKGROUND_LOAD_BYTES`]). A file that cannot be examined loads in the frame, which
/// reports why it cannot be read.
pub(crate) fn big_file(source: &ModelSource) -> Option<PathBuf> {
    match source {
        ModelSource::File(path) => std::fs::metadata(path)
            .is_ok_and(|m| m.is_file() && m.len() > BACKGROUND_LOAD_BYTES)
            .then(|| path.clone()),
        ModelSource::Primitive(_) => None,
    }
}

impl BackgroundLoad {
    /// Starts loading `path` on a worker thread, cancelling any load in flight. `None` when no
    /// thread could be started (the caller then loads in the frame).
    pub(crate) fn start(&mut self, source: ModelSource, path: PathBuf) -> Option<Loading> {
        self.cancel();
        let progress = Arc::new(LoadProgress::default());
        let counted = Arc::clone(&progress);
        let label = path.display().to_string();
        let worker = std::thread::Builder::new()
            .name("close2gl model load".into())
            .spawn(move || load_file(&path, &counted))
            .ok()?;
        self.0 = Some(InFlight {
            source: source.clone(),
            label,
            progress,
            worker,
        });
        Some(Loading {
            source,
            fraction: 0.0,
        })
    }

    /// Drops the load in flight: its worker stops at its next read and its result is never
    /// shown.
    pub(crate) fn cancel(&mut self) {
        if let Some(in_flight) = self.0.take() {
            in_flight.progress.cancel();
        }
    }

    /// The finished load, taken, or how far the running one is, as `pace` says it is (see
    /// [`LoadPace`]); `None` when nothing loads.
    pub(crate) fn poll(&mut self, pace: LoadPace) -> Option<Poll> {
        let in_flight = self.0.as_ref()?;
        let done = match pace {
            LoadPace::Live => in_flight.worker.is_finished(),
            LoadPace::Replay(Some(_)) => false,
            LoadPace::Replay(None) => true,
        };
        if !done {
            let fraction = match pace {
                LoadPace::Replay(Some(fraction)) => fraction,
                _ => in_flight.progress.fraction(),
            };
            return Some(Poll::Running(fraction));
        }
        let InFlight {
            source,
            label,
            worker,
            ..
        } = self.0.take()?;
        // Waits, when a replay says the load ended this frame.
        let result = worker.join().unwrap_or_else(|_| {
            Err(format!(
                "{label}: the loader stopped unexpectedly (a bug: please report it with the file)"
            ))
        });
        Some(Poll::Done(source, result))
    }
}

//! A way for work outside the frame (a thread watching files, a model loading in the background)
//! to ask for a frame: the viewer sleeps until something happens, and a file changing on disk
//! is not an event it would otherwise hear of.

use std::sync::{Arc, RwLock};

use bevy_ecs::prelude::*;

type WakeFn = Arc<dyn Fn() + Send + Sync>;

/// Cloned into the threads that may need a frame; the viewer installs what waking means (a
/// redraw request) once its window exists, and every clone sees it. Headless, waking does
/// nothing: the caller's loop runs frames anyway.
#[derive(Resource, Clone, Default)]
pub struct Wake(Arc<RwLock<Option<WakeFn>>>);

impl Wake {
    /// What waking does from now on, for every clone.
    pub fn install(&self, wake: impl Fn() + Send + Sync + 'static) {
        if let Ok(mut slot) = self.0.write() {
            *slot = Some(Arc::new(wake));
        }
    }

    /// Asks for a frame.
    pub fn wake(&self) {
        let installed = self.0.read().ok().and_then(|slot| slot.clone());
        if let Some(wake) = installed {
            wake();
        }
    }
}

impl std::fmt::Debug for Wake {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str("Wake")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicU32, Ordering};

    #[test]
    fn every_clone_wakes_what_was_installed_later() {
        let wake = Wake::default();
        let clone = wake.clone();
        clone.wake(); // nothing installed yet: no effect, no panic
        let count = Arc::new(AtomicU32::new(0));
        let counted = count.clone();
        wake.install(move || {
            counted.fetch_add(1, Ordering::SeqCst);
        });
        clone.wake();
        std::thread::spawn(move || clone.wake()).join().unwrap();
        assert_eq!(count.load(Ordering::SeqCst), 2);
    }
}

//! When a window's surface may be asked for a texture, and what to do when it gives none. Kept
//! apart from wgpu behind [`Presentable`] so that every path (refused, outdated, lost, gone) is
//! driven in a unit test: X cannot make a surface fail on demand.
//!
//! The one rule wgpu does not forgive: `get_current_texture` on a surface that has never been
//! configured reports its error to no error scope and panics (wgpu-30 `handle_error_fatal`). A
//! surface is asked for a texture only while its last configuration was accepted.

/// What a window's surface can be asked to do.
pub trait Presentable {
    type Texture;

    /// Configures the surface for the window's current size; false when it was refused (the
    /// window is going away, or has no pixels).
    fn configure(&mut self) -> bool;

    /// Replaces a lost surface with a new one for the same window.
    fn recreate(&mut self) -> Result<(), String>;

    /// The next texture, and whether it is suboptimal. Only called while configured.
    fn next_texture(&mut self) -> Result<(Self::Texture, bool), NoTexture>;

    /// Why the device is gone, when it is.
    fn device_lost(&self) -> Option<String>;
}

/// Why the surface gave no texture: wgpu's `CurrentSurfaceTexture` without a texture.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NoTexture {
    Timeout,
    Occluded,
    Outdated,
    Lost,
    /// wgpu's validation refused the acquire (caught in an error scope).
    Validation,
}

/// What to do about it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Recovery {
    /// Configure the surface again (it no longer matches the window) and try again.
    Reconfigure,
    /// Make a new surface for the window and try again.
    Recreate,
    /// Draw nothing now; the frame is drawn again shortly.
    SkipFrame,
    /// Stop with a one-line error.
    Fail,
}

/// One repair per frame: a surface still outdated or lost after it has been tried is left until
/// the next frame (a window being resized keeps outdating it), instead of spinning here.
fn recovery(failure: NoTexture, retried: bool) -> Recovery {
    match failure {
        NoTexture::Validation => Recovery::Fail,
        NoTexture::Timeout | NoTexture::Occluded => Recovery::SkipFrame,
        _ if retried => Recovery::SkipFrame,
        NoTexture::Outdated => Recovery::Reconfigure,
        NoTexture::Lost => Recovery::Recreate,
    }
}

/// Frames in a row whose surface refuses its configuration or its acquire before the refusal
/// is taken for a fault of ours, not a window going away: with a missed frame drawn again every
/// 50 ms, about two seconds, far longer than a destroyed window takes to say so.
pub const REFUSALS_BEFORE_FAILING: u32 = 40;

/// Where a surface stands between frames.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SurfaceState {
    /// The last configuration was accepted: only then may a texture be asked for.
    pub configured: bool,
    /// Configure again before the next texture: the last one was suboptimal, or the surface
    /// refused its configuration.
    pub stale: bool,
    /// The last acquire got no texture though the window has pixels: what it should have
    /// shown is still to be drawn.
    pub missed: bool,
    /// Frames in a row that were refused (see [`REFUSALS_BEFORE_FAILING`]).
    pub refusals: u32,
}

impl SurfaceState {
    /// Configures `surface` and remembers whether it was accepted (a refused one is tried
    /// again on the next acquire). `has_pixels` false (minimised) leaves it unconfigured.
    pub fn configure<S: Presentable>(&mut self, surface: &mut S, has_pixels: bool) {
        self.configured = has_pixels && surface.configure();
        self.stale = has_pixels && !self.configured;
    }

    /// The next texture to draw into, or `None` when this frame draws nothing (minimised,
    /// occluded, a timeout, a surface that is refused or gone): the caller skips the frame, and
    /// draws again later when [`Self::missed`] says so.
    pub fn acquire<S: Presentable>(
        &mut self,
        surface: &mut S,
        has_pixels: bool,
    ) -> Result<Option<S::Texture>, String> {
        self.missed = false;
        if std::mem::take(&mut self.stale) {
            self.configure(surface, has_pixels);
        }
        for retried in [false, true] {
            if !self.configured {
                break;
            }
            let failure = match surface.next_texture() {
                Ok((texture, suboptimal)) => {
                    // Show it; a suboptimal one gets a surface that fits the window next time.
                    self.stale = suboptimal;
                    self.refusals = 0;
                    return Ok(Some(texture));
                }
                Err(failure) => failure,
            };
            match recovery(failure, retried) {
                Recovery::Reconfigure => self.configure(surface, has_pixels),
                Recovery::Recreate => {
                    self.configured = false;
                    surface.recreate()?;
                    self.configure(surface, has_pixels);
                }
                Recovery::SkipFrame => break,
                // A lost device fails every acquire this way: say so rather than blame the
                // surface. Otherwise the window is most likely being destroyed under us: skip,
                // and let its close end the run.
                Recovery::Fail => match surface.device_lost() {
                    Some(lost) => return Err(lost),
                    None => {
                        self.configured = false;
                        self.stale = has_pixels;
                        break;
                    }
                },
            }
        }
        self.missed = has_pixels;
        self.count_refusal()?;
        Ok(None)
    }

    /// Counts a frame the surface refused to configure; too many in a row is an error.
    fn count_refusal(&mut self) -> Result<(), String> {
        if self.stale {
            self.refusals += 1;
            if self.refusals >= REFUSALS_BEFORE_FAILING {
                return Err(format!(
                    "the window's surface refused wgpu {} frames in a row",
                    self.refusals
                ));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A surface that answers from a script, and panics where wgpu would: a texture asked of a
    /// surface whose configuration was not accepted.
    #[derive(Default)]
    struct Scripted {
        configures: Vec<bool>,
        textures: Vec<Result<bool, NoTexture>>,
        configured: bool,
        recreated: usize,
        lost_device: Option<String>,
    }

    impl Presentable for Scripted {
        type Texture = ();

        fn configure(&mut self) -> bool {
            self.configured = self.configures.remove(0);
            self.configured
        }

        fn recreate(&mut self) -> Result<(), String> {
            self.configured = false;
            self.recreated += 1;
            Ok(())
        }

        fn next_texture(&mut self) -> Result<((), bool), NoTexture> {
            assert!(
                self.configured,
                "a texture asked of an unconfigured surface"
            );
            self.textures.remove(0).map(|suboptimal| ((), suboptimal))
        }

        fn device_lost(&self) -> Option<String> {
            self.lost_device.clone()
        }
    }

    fn configured(surface: &mut Scripted) -> SurfaceState {
        let mut state = SurfaceState::default();
        state.configure(surface, true);
        state
    }

    #[test]
    fn a_refused_configuration_skips_the_frame_and_is_tried_again() {
        let mut surface = Scripted {
            configures: vec![false, false, true],
            textures: vec![Ok(false)],
            ..Default::default()
        };
        let mut state = configured(&mut surface);
        assert!(!state.configured && state.stale);
        // Refused again on the next frame: skipped, still to be drawn.
        assert_eq!(state.acquire(&mut surface, true), Ok(None));
        assert!(state.missed);
        // Accepted on the one after: drawn.
        assert_eq!(state.acquire(&mut surface, true), Ok(Some(())));
        assert!(!state.missed);
    }

    #[test]
    fn outdated_then_refused_skips_the_frame() {
        let mut surface = Scripted {
            configures: vec![true, false],
            textures: vec![Err(NoTexture::Outdated)],
            ..Default::default()
        };
        let mut state = configured(&mut surface);
        assert_eq!(state.acquire(&mut surface, true), Ok(None));
        assert!(state.missed && state.stale && !state.configured);
    }

    #[test]
    fn lost_recreated_then_refused_skips_the_frame() {
        let mut surface = Scripted {
            configures: vec![true, false],
            textures: vec![Err(NoTexture::Lost)],
            ..Default::default()
        };
        let mut state = configured(&mut surface);
        assert_eq!(state.acquire(&mut surface, true), Ok(None));
        assert_eq!(surface.recreated, 1);
        assert!(state.missed && state.stale);
    }

    #[test]
    fn each_failed_acquire_is_repaired_once_then_skipped() {
        for failure in [NoTexture::Outdated, NoTexture::Lost] {
            let mut surface = Scripted {
                configures: vec![true, true],
                textures: vec![Err(failure), Err(failure)],
                ..Default::default()
            };
            let mut state = configured(&mut surface);
            assert_eq!(state.acquire(&mut surface, true), Ok(None), "{failure:?}");
            assert!(surface.textures.is_empty() && state.missed, "{failure:?}");
        }
        for failure in [NoTexture::Timeout, NoTexture::Occluded] {
            let mut surface = Scripted {
                configures: vec![true],
                textures: vec![Err(failure)],
                ..Default::default()
            };
            let mut state = configured(&mut surface);
            assert_eq!(state.acquire(&mut surface, true), Ok(None), "{failure:?}");
            assert!(state.missed && state.configured, "{failure:?}");
        }
    }

    #[test]
    fn a_refused_acquire_is_fatal_only_when_the_device_is_lost() {
        let mut surface = Scripted {
            configures: vec![true, false],
            textures: vec![Err(NoTexture::Validation)],
            ..Default::default()
        };
        let mut state = configured(&mut surface);
        assert_eq!(state.acquire(&mut surface, true), Ok(None));
        assert!(state.stale && !state.configured);
        // Tried again next frame, refused: still no texture asked of it.
        assert_eq!(state.acquire(&mut surface, true), Ok(None));

        let mut surface = Scripted {
            configures: vec![true],
            textures: vec![Err(NoTexture::Validation)],
            lost_device: Some("the GPU device was lost".into()),
            ..Default::default()
        };
        let mut state = configured(&mut surface);
        assert_eq!(
            state.acquire(&mut surface, true),
            Err("the GPU device was lost".into())
        );
    }

    #[test]
    fn a_surface_refused_frame_after_frame_ends_the_run_with_an_error() {
        let mut surface = Scripted {
            configures: vec![false; REFUSALS_BEFORE_FAILING as usize + 1],
            ..Default::default()
        };
        let mut state = configured(&mut surface);
        for _ in 1..REFUSALS_BEFORE_FAILING {
            assert_eq!(state.acquire(&mut surface, true), Ok(None));
        }
        let error = state.acquire(&mut surface, true).unwrap_err();
        assert!(error.contains("40 frames in a row"), "{error}");
    }

    #[test]
    fn a_window_without_pixels_is_neither_configured_nor_missed() {
        let mut surface = Scripted::default();
        let mut state = SurfaceState::default();
        state.configure(&mut surface, false);
        assert_eq!(state.acquire(&mut surface, false), Ok(None));
        assert!(!state.missed && !state.stale && !state.configured);
    }

    #[test]
    fn a_suboptimal_texture_is_shown_and_the_surface_configured_again_next_frame() {
        let mut surface = Scripted {
            configures: vec![true, true],
            textures: vec![Ok(true), Ok(false)],
            ..Default::default()
        };
        let mut state = configured(&mut surface);
        assert_eq!(state.acquire(&mut surface, true), Ok(Some(())));
        assert!(state.stale);
        assert_eq!(state.acquire(&mut surface, true), Ok(Some(())));
        assert!(
            surface.configures.is_empty(),
            "configured again before the second"
        );
    }
}

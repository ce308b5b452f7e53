//! Whose input a frame gets: the window system's (live, and written down with `--record`), or
//! a recording's (`--replay`), which then owns the frames until it ends.

use web_time::{Duration, Instant};

use crate::surface::WindowSurface;
use bevy_ecs::world::World;
use close2gl_core::{InputState, LoadPace, ModelStatus};
use winit::dpi::PhysicalSize;

use crate::recording::{FrameInput, Recorder, Recording};
use crate::routing::drop_file;

/// How long a replayed resize may take to reach the window before the frame goes on anyway (a
/// window manager may refuse the size).
const RESIZE_WAIT: Duration = Duration::from_secs(1);

pub enum Session {
    Live,
    Recording(Recorder),
    Replaying(Player),
}

pub struct Player {
    recording: Recording,
    /// The panel's clock: the recorded time steps added up, never the wall clock.
    time: f64,
    /// A resize asked of the window for the next frame, and since when.
    resizing: Option<(PhysicalSize<u32>, Instant)>,
}

impl Player {
    pub fn new(recording: Recording) -> Self {
        Self {
            recording,
            time: 0.0,
            resizing: None,
        }
    }
}

impl Session {
    /// Live, or recording or replaying as `--record` and `--replay` say.
    pub fn for_options(options: &crate::ViewerOptions) -> Result<Session, String> {
        Ok(match (&options.record, &options.replay) {
            (_, Some(recording)) => Session::Replaying(Player::new(recording.clone())),
            (Some(path), None) => Session::Recording(Recorder::create(
                path,
                [options.width, options.height],
                options.scene.clone(),
            )?),
            (None, None) => Session::Live,
        })
    }

    pub fn is_replaying(&self) -> bool {
        matches!(self, Session::Replaying(_))
    }

    /// During a replay, `(frame, frames)` for the panel.
    pub fn replay_progress(&self, frame: u32) -> Option<(u32, u32)> {
        match self {
            Session::Replaying(player) => Some((frame, player.recording.frames.len() as u32)),
            _ => None,
        }
    }

    /// A replay whose next frame resizes the window: asks for the size, and says to wait
    /// (draw nothing yet) until the window has it.
    pub fn wait_for_resize(&mut self, frame: u32, window: &WindowSurface) -> bool {
        let Session::Replaying(player) = self else {
            return false;
        };
        let wanted = match player.recording.frames.get(frame as usize) {
            Some(FrameInput {
                resize: Some([w, h]),
                ..
            }) => PhysicalSize::new(*w, *h),
            _ => return false,
        };
        if window.window_size() == wanted {
            player.resizing = None;
            return false;
        }
        let (_, since) = *player.resizing.get_or_insert_with(|| {
            let _ = window.window.request_inner_size(wanted);
            (wanted, Instant::now())
        });
        since.elapsed() < RESIZE_WAIT
    }

    /// The start of frame `frame`: the panel's input in `raw` and the app's `InputState` (whose
    /// time step is `dt` when live) come from the window system, or from the recording; what the
    /// frame gets is recorded.
    pub fn begin_frame(
        &mut self,
        frame: u32,
        dt: f32,
        raw: &mut egui::RawInput,
        world: &mut World,
    ) -> Result<(), String> {
        match self {
            Session::Live => world.resource_mut::<InputState>().dt = dt,
            Session::Recording(recorder) => {
                let mut input = world.resource_mut::<InputState>();
                input.dt = dt;
                recorder.pending.panel = raw.events.clone();
                recorder.begin_frame(FrameInput::from_state(frame, &input));
            }
            Session::Replaying(player) => {
                let Some(recorded) = player.recording.frames.get(frame as usize) else {
                    return Ok(());
                };
                raw.events = recorded.panel.clone();
                raw.time = Some(player.time);
                raw.predicted_dt = recorded.dt;
                player.time += recorded.dt as f64;
                recorded.apply(&mut world.resource_mut::<InputState>());
                world.insert_resource(LoadPace::Replay(recorded.loading));
                for path in &recorded.dropped {
                    drop_file(world, path.clone());
                }
            }
        }
        Ok(())
    }

    /// After frame `frame`: a recording writes the frame down, with where a background load
    /// stood; a replay that has played its last frame hands over to the window system (when
    /// the viewer stays open), and loads go at their own pace again.
    pub fn end_frame(&mut self, frame: u32, world: &mut World) -> Result<(), String> {
        match self {
            Session::Live => {}
            Session::Recording(recorder) => {
                let status = world.resource::<ModelStatus>();
                recorder.end_frame(status.loading.as_ref().map(|l| l.fraction))?;
            }
            Session::Replaying(player) => {
                if frame as usize + 1 >= player.recording.frames.len() {
                    *self = Session::Live;
                    world.insert_resource(LoadPace::Live);
                }
            }
        }
        Ok(())
    }

    /// A window event the recording must know of: the main window resized, a file dropped.
    pub fn window_resized(&mut self, size: PhysicalSize<u32>) {
        if let Session::Recording(recorder) = self {
            recorder.pending.resize = Some([size.width, size.height]);
        }
    }

    pub fn file_dropped(&mut self, path: &std::path::Path) {
        if let Session::Recording(recorder) = self {
            recorder.pending.dropped.push(path.to_path_buf());
        }
    }
}

#[cfg(test)]
mod tests {
    use close2gl_core::{Loading, ModelSource, PrimitiveKind};

    use super::*;

    #[test]
    fn a_recorded_loads_progress_paces_the_replay_frame_by_frame() {
        let path = std::env::temp_dir().join(format!("close2gl-pace-{}.rec", std::process::id()));
        let mut world = World::new();
        world.init_resource::<InputState>();
        world.init_resource::<ModelStatus>();
        world.init_resource::<LoadPace>();
        // Nothing loading, a load half way, then in.
        let shown = [None, Some(0.0), Some(0.5), None];
        let recorder = Recorder::create(&path, [64, 64], Vec::new()).expect("record");
        let mut session = Session::Recording(recorder);
        for (frame, fraction) in (0..).zip(shown) {
            let mut raw = egui::RawInput::default();
            session
                .begin_frame(frame, 0.01, &mut raw, &mut world)
                .unwrap();
            world.resource_mut::<ModelStatus>().loading = fraction.map(|fraction| Loading {
                source: ModelSource::Primitive(PrimitiveKind::Box),
                fraction,
            });
            session.end_frame(frame, &mut world).unwrap();
        }

        let recording = Recording::read(&path).expect("read back");
        let _ = std::fs::remove_file(&path);
        let mut session = Session::Replaying(Player::new(recording));
        for (frame, fraction) in (0..).zip(shown) {
            let mut raw = egui::RawInput::default();
            session
                .begin_frame(frame, 0.5, &mut raw, &mut world)
                .unwrap();
            assert_eq!(*world.resource::<LoadPace>(), LoadPace::Replay(fraction));
            session.end_frame(frame, &mut world).unwrap();
        }
        assert!(!session.is_replaying());
        assert_eq!(*world.resource::<LoadPace>(), LoadPace::Live);
    }
}

//! `--record FILE` and `--replay FILE`: every frame's input, written as one JSON line, and read
//! back. What is recorded is what the app and the panel were handed each frame, after the
//! window system's events were sorted out: the keys held and pressed, the drag and the scroll
//! and a probe click (`InputState`), the panel's own egui events, a file dropped on the window, the main window
//! resized, the frame's time step, and how far a model loading in the background had come by
//! the frame's end. A replay hands the same to the same frames, with the recorded time steps
//! instead of the clock's and the recorded load's progress instead of the worker's, so it moves
//! the camera exactly as the recording did, and draws the same pixels on every run.

use std::collections::BTreeSet;
use std::fs::File;
use std::io::{BufRead, BufReader, BufWriter, Write};
use std::path::{Path, PathBuf};

use close2gl_core::glam::Vec2;
use close2gl_core::{InputState, ProbeClick};
use serde::{Deserialize, Serialize};

/// The first line of a recording.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Header {
    /// The format's version; a file of another version is refused, not misread.
    pub close2gl_recording: u32,
    /// The window's size the recording was made at, in pixels (as `--size` gives it).
    pub size: [u32; 2],
    /// The command line's words that chose the scene (model, config file, overrides), so that
    /// a replay given none shows the scene the recording was made on.
    #[serde(default)]
    pub scene: Vec<String>,
}

const VERSION: u32 = 1;

/// One frame's input.
#[derive(Clone, Debug, Default, PartialEq, Serialize, Deserialize)]
#[serde(default)]
pub struct FrameInput {
    pub frame: u32,
    /// Seconds the frame covered.
    pub dt: f32,
    #[serde(skip_serializing_if = "BTreeSet::is_empty")]
    pub held: BTreeSet<String>,
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub pressed: Vec<String>,
    #[serde(skip_serializing_if = "is_zero")]
    pub drag: [f32; 2],
    #[serde(skip_serializing_if = "is_zero_f32")]
    pub scroll: f32,
    /// A probe click's window pixel (Ctrl+click).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub probe: Option<[f32; 2]>,
    /// The probe click was in the Close2GL window of the windows layout.
    #[serde(skip_serializing_if = "std::ops::Not::not")]
    pub probe_close2gl_window: bool,
    /// What the panel received (pointer, clicks, typed text, its keys).
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub panel: Vec<egui::Event>,
    /// The main window's new inner size, when it was resized before this frame.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub resize: Option<[u32; 2]>,
    /// Files dropped on a window before this frame.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub dropped: Vec<PathBuf>,
    /// How far a model loading in the background was at the end of this frame, as the panel
    /// showed it; none when nothing was loading (so a load in flight before it ended here).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub loading: Option<f32>,
}

fn is_zero(v: &[f32; 2]) -> bool {
    *v == [0.0, 0.0]
}

fn is_zero_f32(v: &f32) -> bool {
    *v == 0.0
}

impl FrameInput {
    /// What `input` holds for frame `frame` (its time step included).
    pub fn from_state(frame: u32, input: &InputState) -> Self {
        FrameInput {
            frame,
            dt: input.dt,
            held: input.held.clone(),
            pressed: input.pressed.clone(),
            drag: input.drag.to_array(),
            scroll: input.scroll,
            probe: input.probe.map(|p| p.at.to_array()),
            probe_close2gl_window: input.probe.is_some_and(|p| p.close2gl_window),
            ..FrameInput::default()
        }
    }

    /// Hands the frame's app input to `input`, replacing what the window system gave.
    pub fn apply(&self, input: &mut InputState) {
        input.dt = self.dt;
        input.held = self.held.clone();
        input.pressed = self.pressed.clone();
        input.drag = Vec2::from_array(self.drag);
        input.scroll = self.scroll;
        input.probe = self.probe.map(|at| ProbeClick {
            at: Vec2::from_array(at),
            close2gl_window: self.probe_close2gl_window,
        });
    }
}

/// Writes a recording as the frames happen, so that a crash keeps what came before it.
pub struct Recorder {
    path: PathBuf,
    out: BufWriter<File>,
    /// What arrived between frames, for the next frame's line.
    pub pending: FrameInput,
    /// The frame under way, written when it ends.
    current: Option<Box<FrameInput>>,
}

impl Recorder {
    pub fn create(path: &Path, size: [u32; 2], scene: Vec<String>) -> Result<Recorder, String> {
        let name = path.display();
        let file = File::create(path).map_err(|e| format!("{name}: cannot record: {e}"))?;
        let mut recorder = Recorder {
            path: path.to_path_buf(),
            out: BufWriter::new(file),
            pending: FrameInput::default(),
            current: None,
        };
        let header = Header {
            close2gl_recording: VERSION,
            size,
            scene,
        };
        recorder.line(&header)?;
        Ok(recorder)
    }

    /// Starts frame `input`, with what arrived since the last frame.
    pub fn begin_frame(&mut self, input: FrameInput) {
        let pending = std::mem::take(&mut self.pending);
        self.current = Some(Box::new(FrameInput {
            panel: pending.panel,
            resize: pending.resize,
            dropped: pending.dropped,
            ..input
        }));
    }

    /// Writes the frame begun last, with where a background load stood at its end.
    pub fn end_frame(&mut self, loading: Option<f32>) -> Result<(), String> {
        match self.current.take() {
            Some(frame) => self.line(&FrameInput { loading, ..*frame }),
            None => Ok(()),
        }
    }

    fn line(&mut self, value: &impl Serialize) -> Result<(), String> {
        let name = self.path.display();
        serde_json::to_writer(&mut self.out, value)
            .map_err(|e| e.to_string())
            .and_then(|()| writeln!(self.out).map_err(|e| e.to_string()))
            .and_then(|()| self.out.flush().map_err(|e| e.to_string()))
            .map_err(|e| format!("{name}: cannot record: {e}"))
    }
}

/// A recording read whole, played frame by frame.
#[derive(Clone, Debug, PartialEq)]
pub struct Recording {
    pub header: Header,
    /// One entry per frame, in order, frame numbers from 0 without gaps.
    pub frames: Vec<FrameInput>,
}

impl Recording {
    /// Reads `path`; an error names the file, the line and what was expected there.
    pub fn read(path: &Path) -> Result<Recording, String> {
        let name = path.display();
        let file = File::open(path).map_err(|e| format!("{name}: cannot read: {e}"))?;
        let mut lines = BufReader::new(file).lines().enumerate();
        let header: Header = match lines.next() {
            Some((_, Ok(text))) => serde_json::from_str(&text).map_err(|e| {
                format!("{name}:1: expected a close2gl recording's header line: {e}")
            })?,
            Some((_, Err(e))) => return Err(format!("{name}:1: cannot read: {e}")),
            None => return Err(format!("{name}: empty file: expected a close2gl recording")),
        };
        if header.close2gl_recording != VERSION {
            return Err(format!(
                "{name}:1: a recording of format version {}, expected version {VERSION}",
                header.close2gl_recording
            ));
        }
        let mut frames = Vec::new();
        for (index, line) in lines {
            let number = index + 1;
            let text = line.map_err(|e| format!("{name}:{number}: cannot read: {e}"))?;
            if text.trim().is_empty() {
                continue;
            }
            let frame: FrameInput = serde_json::from_str(&text)
                .map_err(|e| format!("{name}:{number}: expected one frame's input: {e}"))?;
            if frame.frame as usize != frames.len() {
                return Err(format!(
                    "{name}:{number}: expected frame {}, found frame {}",
                    frames.len(),
                    frame.frame
                ));
            }
            if !(frame.dt.is_finite() && frame.dt >= 0.0) {
                return Err(format!(
                    "{name}:{number}: expected a time step of 0 seconds or more, found {}",
                    frame.dt
                ));
            }
            if let Some(fraction) = frame.loading
                && !(0.0..=1.0).contains(&fraction)
            {
                return Err(format!(
                    "{name}:{number}: expected a load's progress from 0 to 1, found {fraction}"
                ));
            }
            frames.push(frame);
        }
        if frames.is_empty() {
            return Err(format!("{name}: the recording has no frames"));
        }
        Ok(Recording { header, frames })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("close2gl-rec-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("a temporary directory");
        dir.join(name)
    }

    #[test]
    fn what_is_recorded_reads_back_the_same() {
        let path = temp("round.rec");
        let scene = vec![
            "torus".to_string(),
            "--set".into(),
            "render.mode=wireframe".into(),
        ];
        let mut recorder = Recorder::create(&path, [800, 600], scene.clone()).unwrap();
        let mut input = InputState {
            dt: 0.02,
            drag: Vec2::new(3.0, -1.5),
            scroll: 1.0,
            ..InputState::default()
        };
        input.held.insert("w".into());
        input.pressed.push("shift+p".into());
        recorder
            .pending
            .panel
            .push(egui::Event::PointerMoved(egui::pos2(10.0, 20.5)));
        recorder.pending.resize = Some([640, 480]);
        recorder.pending.dropped.push("a model.in".into());
        recorder.begin_frame(FrameInput::from_state(0, &input));
        recorder.end_frame(Some(0.25)).unwrap();
        recorder.begin_frame(FrameInput::from_state(1, &InputState::default()));
        recorder.end_frame(None).unwrap();

        let recording = Recording::read(&path).unwrap();
        assert_eq!(recording.header.size, [800, 600]);
        assert_eq!(recording.header.scene, scene);
        assert_eq!(recording.frames.len(), 2);
        let mut replayed = InputState::default();
        recording.frames[0].apply(&mut replayed);
        assert_eq!(replayed.held, input.held);
        assert_eq!(replayed.pressed, input.pressed);
        assert_eq!(
            (replayed.drag, replayed.scroll, replayed.dt),
            (input.drag, 1.0, 0.02)
        );
        assert_eq!(recording.frames[0].resize, Some([640, 480]));
        assert_eq!(
            recording.frames[0].dropped,
            vec![PathBuf::from("a model.in")]
        );
        assert_eq!(
            recording.frames[0].panel,
            vec![egui::Event::PointerMoved(egui::pos2(10.0, 20.5))]
        );
        assert_eq!(recording.frames[0].loading, Some(0.25));
        assert_eq!(
            recording.frames[1],
            FrameInput {
                frame: 1,
                ..FrameInput::default()
            }
        );
    }

    #[test]
    fn a_bad_recording_is_refused_naming_the_line() {
        let cases = [
            ("", "empty file"),
            (
                "{\"size\":[1,1]}\n",
                ":1: expected a close2gl recording's header",
            ),
            (
                "{\"close2gl_recording\":9,\"size\":[1,1]}\n",
                ":1: a recording of format version 9",
            ),
            (
                "{\"close2gl_recording\":1,\"size\":[1,1]}\n",
                "has no frames",
            ),
            (
                "{\"close2gl_recording\":1,\"size\":[1,1]}\n{\"frame\":0}\n{\"frame\":2}\n",
                ":3: expected frame 1, found frame 2",
            ),
            (
                "{\"close2gl_recording\":1,\"size\":[1,1]}\n{\"frame\":0,\"dt\":-1}\n",
                ":2: expected a time step",
            ),
            (
                "{\"close2gl_recording\":1,\"size\":[1,1]}\n{\"frame\":0,\"loading\":2}\n",
                ":2: expected a load's progress from 0 to 1, found 2",
            ),
            (
                "{\"close2gl_recording\":1,\"size\":[1,1]}\nnot json\n",
                ":2: expected one frame's input",
            ),
        ];
        for (i, (text, expected)) in cases.into_iter().enumerate() {
            let path = temp(&format!("bad{i}.rec"));
            std::fs::write(&path, text).unwrap();
            let error = Recording::read(&path).expect_err(text);
            assert!(
                error.contains(expected),
                "{error:?} should say {expected:?}"
            );
            assert!(!error.contains('\n'), "one line: {error:?}");
        }
    }
}

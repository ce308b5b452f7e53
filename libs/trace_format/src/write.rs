//! Traces and scenes written back as files. Every number is in Rust's shortest round-trip
//! spelling (`{:?}`: `0.1`, `-0.0`, `1e-7`, `1e300`), which C's `strtod` and this crate's reader
//! both take, so reading the text back gives the same bits.
//!
//! Only values the readers can produce write a file that reads back: a `Trace` or `SceneFile` made
//! by hand with a NaN, a `Piece` of 2 corners or a model name holding a blank or `#` does not. The `line`
//! fields read back as the lines of the written text.

use std::fmt::Write;

use close2gl_core::declaration::{ClipPlanes, ClipRule, WindingSpace};
use close2gl_core::{FrontFace, NamedEnum, RenderMode};

use super::camera_lines::LINES;
use super::magic::Format;
use super::names::{clipping_name, culling_name};
use super::output::MATRIX_NAMES;
use super::{CameraLines, Motion, Piece, SceneCamera, SceneFile, SceneLook, Trace};

impl Trace {
    /// This trace as a `close2gl-trace 1` file, every line it holds written out (the defaults
    /// too), in the order of the format's table.
    pub fn to_text(&self) -> String {
        let mut text = Text::new(Format::Trace);
        if let Some(model) = &self.model {
            text.line(&format!("model {model}"), []);
        }
        if let Some((n, _)) = self.triangles {
            text.line(&format!("triangles {n}"), []);
        }
        text.line(&format!("window {} {}", self.window.0, self.window.1), []);
        let o = self.ortho2d;
        text.line("ortho2d", [o.left, o.right, o.bottom, o.top]);
        text.camera(&self.camera);
        text.trace_switches(self);
        let matrices = [self.m, self.p, self.v, self.model_matrix];
        for (name, m) in MATRIX_NAMES.iter().zip(matrices) {
            if let Some(m) = m {
                // glam is column-major: the columns of the transpose are the rows.
                text.line(&format!("matrix {name}"), m.transpose().to_cols_array());
            }
        }
        for clip in &self.clip {
            let corners = clip.corners.iter().flat_map(|c| c.to_array());
            text.line(&format!("clip {}", clip.triangle), corners);
        }
        for piece in &self.pieces {
            text.piece(piece);
        }
        if let Some((n, _)) = self.drawn {
            text.line(&format!("drawn {n}"), []);
        }
        if self.ended {
            text.line("end", []);
        }
        text.0
    }
}

impl SceneFile {
    /// This scene as a `close2gl-scene 1` file, ending with `end`.
    pub fn to_text(&self) -> String {
        let mut text = Text::new(Format::Scene);
        text.line(&format!("model {}", self.model), []);
        text.line(&format!("window {} {}", self.window.0, self.window.1), []);
        match &self.camera {
            SceneCamera::Framed {
                hfov,
                vfov,
                near,
                far,
            } => {
                text.line("camera framed", []);
                for ((key, _), x) in LINES[4..].iter().zip([hfov, vfov, near, far]) {
                    if let Some(x) = x {
                        text.line(key, [*x]);
                    }
                }
            }
            SceneCamera::Given(camera) => text.camera(camera),
        }
        text.switches(self.culling, self.clipping, self.mode);
        if let Some(at) = self.lookat {
            text.line("lookat", at.to_array());
        }
        for motion in &self.motions {
            let (verb, axis, x) = match *motion {
                Motion::Move(axis, x) => ("move", axis, x),
                Motion::Rotate(axis, x) => ("rotate", axis, x),
                Motion::Orbit(axis, x) => ("orbit", axis, x),
            };
            text.line(&format!("{verb} {}", axis.name()), [x]);
        }
        text.look(&self.look);
        text.line("end", []);
        text.0
    }
}

/// A file being written, a line at a time.
struct Text(String);

impl Text {
    fn new(format: Format) -> Self {
        Self(format.magic() + "\n")
    }

    /// `head` and then the numbers, each in its shortest round-trip spelling.
    fn line(&mut self, head: &str, numbers: impl IntoIterator<Item = f64>) {
        self.0.push_str(head);
        for x in numbers {
            // Writing to a String cannot fail.
            let _ = write!(self.0, " {x:?}");
        }
        self.0.push('\n');
    }

    /// The rasterizer assignment's lines, those that are not their defaults.
    fn look(&mut self, look: &SceneLook) {
        let default = SceneLook::default();
        if look.shading != default.shading {
            self.line(&format!("shading {}", look.shading.name()), []);
        }
        for (key, value, default) in [
            ("color", look.color, default.color),
            ("background", look.background, default.background),
            ("light", look.light, default.light),
        ] {
            if value != default {
                self.line(key, value.to_array());
            }
        }
        if let Some(texture) = &look.texture {
            self.line(&format!("texture {texture}"), []);
            self.line(&format!("filter {}", look.filter.name()), []);
        }
    }

    fn camera(&mut self, c: &CameraLines) {
        for ((key, _), v) in LINES.iter().zip([c.position, c.u, c.v, c.n]) {
            self.line(key, v.to_array());
        }
        for ((key, _), x) in LINES[4..].iter().zip([c.hfov, c.vfov, c.near, c.far]) {
            self.line(key, [x]);
        }
    }

    fn switches(&mut self, culling: Option<FrontFace>, clip: ClipRule, mode: Option<RenderMode>) {
        self.line(&format!("culling {}", culling_name(culling)), []);
        self.line(&format!("clipping {}", clipping_name(clip)), []);
        if let Some(mode) = mode {
            self.line(&format!("mode {}", mode.name()), []);
        }
    }

    /// A trace's switches, with the culling space and the planes where it gives them.
    fn trace_switches(&mut self, trace: &Trace) {
        let space = match trace.winding {
            None | Some(WindingSpace::Screen) => "",
            Some(WindingSpace::Ndc) => " ndc",
            Some(WindingSpace::Window) => " window",
        };
        let planes = match trace.planes {
            ClipPlanes::All => "",
            ClipPlanes::NearFar => " near_far",
        };
        self.line(
            &format!("culling {}{space}", culling_name(trace.culling)),
            [],
        );
        self.line(
            &format!("clipping {}{planes}", clipping_name(trace.clipping)),
            [],
        );
        if let Some(mode) = trace.mode {
            self.line(&format!("mode {}", mode.name()), []);
        }
    }

    /// A 3-corner piece as `tri`, any other as `poly`; the depths after each corner's x y.
    fn piece(&mut self, piece: &Piece) {
        let k = piece.corners.len();
        let head = match k {
            3 => format!("tri {}", piece.triangle),
            _ => format!("poly {} {k}", piece.triangle),
        };
        let depths = piece.depths.as_deref();
        let corners = piece.corners.iter().enumerate().flat_map(|(i, c)| {
            let z = depths.and_then(|d| d.get(i).copied());
            [c.x, c.y].into_iter().chain(z)
        });
        self.line(&head, corners);
    }
}

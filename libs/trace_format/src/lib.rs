//! close2gl's scene and trace files (`trace-format.md`, version 1), which let any program, in
//! any language, be checked against close2gl's pipeline: a scene is what a grader hands a
//! program to say which frame to draw, a trace is what the program wrote about that frame of its
//! own Close2GL (its camera, its matrices, the 2D triangles it drew). This library owns reading
//! both from text or a file into plain values, checked line by line with every fault a one-line
//! [`FormatError`] naming the file and line, and writing them back as text that reads back the
//! same. It reads files and strings and writes strings, nothing else; a file's switches are read
//! straight into the words core shares with the pipeline (culling an `Option<FrontFace>`,
//! clipping a [`ClipRule`](close2gl_core::declaration::ClipRule), the 2D system a [`System2d`],
//! the camera a [`CameraLines`]): it depends on core alone. Whether a trace's triangle indices
//! fit its model is for whoever has the model (`close2gl_check`).

mod camera_lines;
mod common;
mod magic;
mod names;
mod output;
pub mod raster;
mod read;
mod scene;
mod syntax;
mod trace;
mod write;

/// `ortho2d L R B T`: the arguments the program gave `gluOrtho2D`, the 2D system of its output,
/// read straight into the shared word.
pub use close2gl_core::declaration::System2d;
pub use names::{CLIPPINGS, CULLINGS, clipping_name, culling_name};
pub use output::{ClipLine, Piece};
pub use raster::{
    Attribute, RasterCorner, RasterFrame, RasterTrace, RasterTriangle, is_raster_trace,
    parse_raster_trace, read_raster_frame, read_raster_trace,
};
pub use scene::{Motion, SceneCamera, SceneFile, SceneLook, parse_scene, read_scene};
pub use syntax::FormatError;
pub use trace::{Trace, parse_trace, parse_trace_bytes, read_trace};

/// The most `clip`, `tri` and `poly` lines one trace may hold, together: a mesh of millions of
/// triangles fits, and a hostile file cannot make the values outgrow memory.
pub const MAX_RECORDS: usize = 50_000_000;

/// The most corners a `poly` may have. A triangle clipped against the six planes has at most
/// nine; the rest is room for clippers that leave duplicate corners.
pub const MAX_POLY_CORNERS: usize = 64;

/// The largest file `read_trace` and `read_scene` read, bytes.
pub const MAX_FILE_BYTES: u64 = 1 << 30;

/// The eight `camera` lines, in the assignment's names: the centre of projection, the camera's
/// axes (right-handed, looking along -n) and its view volume (angles in degrees). The camera a
/// program holds, as the pipeline runs programs with it.
pub type CameraLines = close2gl_core::declaration::ProgramCamera;

/// One of the camera's own axes, which a scene's motions move along or turn about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Axis {
    U,
    V,
    N,
}

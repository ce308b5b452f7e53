//! The scene and trace files of `trace-format.md` (version 1), read into values and written
//! back. Reading checks what one line can tell (shapes, numbers, ranges, keys given twice, the
//! required lines); whether a trace's triangle indices fit its model is for whoever has the
//! model.

mod camera_lines;
mod common;
mod magic;
mod names;
mod output;
mod read;
mod scene;
mod syntax;
mod trace;
mod write;

/// `ortho2d L R B T`: the arguments the program gave `gluOrtho2D`, the 2D system of its output,
/// read straight into the pipeline's own type.
pub use close2gl_pipeline::program::System2d;
pub use output::{ClipLine, Piece};
pub use scene::{Motion, SceneCamera, SceneFile, parse_scene, read_scene};
pub use syntax::FormatError;
pub use trace::{Trace, parse_trace, read_trace};

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
/// program holds, as the pipeline's mistakes module runs programs with it.
pub type CameraLines = close2gl_pipeline::program::ProgramCamera;

/// `culling`: backface culling off, or which on-screen winding is front (`glFrontFace`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum Culling {
    #[default]
    Off,
    Ccw,
    Cw,
}

/// `clipping`: what the program did with triangles reaching outside the view volume.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum TraceClipping {
    /// The assignment's rule: a triangle with any corner outside is dropped.
    #[default]
    Simple,
    /// Polygons clipped against the six planes (`poly` lines).
    Full,
    /// Nothing: every triangle drawn whole.
    None,
}

/// One of the camera's own axes, which a scene's motions move along or turn about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Axis {
    U,
    V,
    N,
}

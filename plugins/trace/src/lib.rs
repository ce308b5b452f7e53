//! close2gl's scene and trace files (`trace-format.md`, version 1), which let any program, in
//! any language, be checked against close2gl's pipeline: a scene is what a grader hands a
//! program to say which frame to draw, a trace is what the program wrote about that frame of its
//! own Close2GL (its camera, its matrices, the 2D triangles it drew). This crate owns reading
//! both into plain values, with every fault a one-line [`FormatError`] naming the file and line,
//! and writing them back as text that reads back the same; [`check`] compares a trace with the
//! pipeline, and [`rubric`] makes the assignment's rubric into scenes and judges a program's
//! traces of them, for `close2gl grade`. It owns no ECS resource.

pub mod check;
pub mod format;
pub mod rubric;
pub mod view;

pub use format::{
    Axis, CameraLines, ClipLine, Culling, FormatError, Motion, Ortho2d, Piece, Scene, SceneCamera,
    Trace, TraceClipping, parse_scene, parse_trace, read_scene, read_trace,
};

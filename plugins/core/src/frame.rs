use bevy_ecs::prelude::*;
use serde::Serialize;

/// The pixel size of the Close2GL view (and of the reference view beside it).
#[derive(Resource, Clone, Copy, Debug, PartialEq, Eq)]
pub struct Viewport {
    pub width: u32,
    pub height: u32,
}

impl Default for Viewport {
    fn default() -> Self {
        Self {
            width: 640,
            height: 480,
        }
    }
}

/// What the 2D buffer's vertices form.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Topology {
    Points,
    Lines,
    #[default]
    Triangles,
}

/// How many triangles each stage of the Close2GL pipeline saw.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct StageCounts {
    /// Triangles in the mesh.
    pub triangles_in: usize,
    /// Removed whole by clipping (outside the view volume, or touching its border in simple mode).
    pub clipped: usize,
    /// Removed by backface culling.
    pub culled: usize,
    /// Survivors: `triangles_in - clipped - culled`.
    pub drawn: usize,
    /// Points, lines or triangles in the 2D buffer (clipping may cut one triangle into several).
    pub output_primitives: usize,
}

/// The Close2GL pipeline's output: 2D positions in window pixels (origin top-left, y down), ready
/// for a pass-through GPU pipeline, and the stage counts.
#[derive(Resource, Clone, Debug, Default, PartialEq)]
pub struct Close2glFrame {
    pub topology: Topology,
    pub vertices: Vec<[f32; 2]>,
    pub counts: StageCounts,
    /// Viewport the vertices were mapped to.
    pub viewport: Viewport,
    /// Wall time of the geometry stage, milliseconds.
    pub stage_ms: f64,
}

impl Close2glFrame {
    /// `[xmin, ymin, xmax, ymax]` of the emitted vertices, or `None` when nothing was emitted.
    pub fn bounds_px(&self) -> Option<[f32; 4]> {
        let mut it = self.vertices.iter();
        let first = it.next()?;
        Some(it.fold([first[0], first[1], first[0], first[1]], |b, p| {
            [
                b[0].min(p[0]),
                b[1].min(p[1]),
                b[2].max(p[0]),
                b[3].max(p[1]),
            ]
        }))
    }
}

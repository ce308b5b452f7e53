//! close2gl's view drawn by a [`Program`]: what a student's program with some mistakes (or none)
//! draws in this window, each triangle sent down the program's stages
//! ([`Program::triangle`]) and emitted as the mode draws it ([`Program::drawn_corners`], through
//! [`crate::emit`], as the pipeline's own triangles are). The view runs it for a frame with a
//! mistake, the pixel probe for the same frame; the fast path never sees a mistake.

use close2gl_core::{
    Camera, Close2glFrame, CutVertex, Fates, Mesh, PipelineSettings, RasterGeometry, Rasterizer,
    Viewport,
};

use super::{DrawnCorner, Program};
use crate::Tally;
use crate::emit;
use crate::mistakes::Mistakes;
use crate::stage::{Fate, FrameConstants};

/// The frame and every triangle's fate, recorded, that a program with `mistakes` draws of
/// `mesh` from `camera` with `settings` in `viewport`. With the software rasterizer, every
/// vertex it draws is a cut vertex: where it lies in its triangle says what its corners carry.
pub fn run(
    mesh: &Mesh,
    camera: &Camera,
    settings: &PipelineSettings,
    viewport: Viewport,
    mistakes: Mistakes,
) -> (Close2glFrame, Fates) {
    let program = Program::for_view(camera, settings, viewport, mistakes);
    let constants = FrameConstants::new(settings, viewport);
    let topology = constants.topology();
    let raster = settings.close2gl_raster == Rasterizer::Software;
    let mut frame = Close2glFrame {
        topology,
        viewport,
        ..Close2glFrame::default()
    };
    if raster {
        frame.raster.vertices = crate::fast::raster_vertices_of(mesh, camera, &constants);
        frame.raster.textured = !mesh.uvs.is_empty();
    }
    let mut fates = Fates {
        record: true,
        ..Fates::default()
    };
    let mut counts = Tally::default();
    for (index, outcome) in program.frame(mesh).iter().enumerate() {
        let corners = mesh.triangles[index];
        let drawn = program.drawn_corners(outcome, topology);
        let before = frame.vertices.len();
        for i in emit::corners(topology, drawn.len(), |i| drawn[i].own) {
            frame
                .vertices
                .push([drawn[i].at.x as f32, drawn[i].at.y as f32]);
            if raster {
                push_cut_vertex(&mut frame.raster, &drawn[i], corners);
            }
        }
        let primitives = (frame.vertices.len() - before) / constants.topology_vertices();
        if raster {
            // One triangle index per primitive, not per vertex.
            let owner = std::iter::repeat_n(index as u32, primitives);
            frame.raster.triangles.extend(owner);
        }
        counts.add(&Fate {
            fate: outcome.fate,
            primitives,
        });
        fates.triangles.push(outcome.fate);
    }
    frame.counts = counts.stage_counts();
    fates.counts = counts.fate_counts();
    (frame, fates)
}

/// A drawn corner of mesh triangle `corners` as a vertex of the software rasterizer: a cut
/// vertex, which carries where it lies in its triangle.
fn push_cut_vertex(raster: &mut RasterGeometry, corner: &DrawnCorner, corners: [u32; 3]) {
    let cut = raster.cuts.len() as u32;
    raster.primitives.push(raster.vertices.len() as u32 + cut);
    raster.cuts.push(CutVertex {
        window: [
            corner.at.x as f32,
            corner.at.y as f32,
            (corner.depth * 0.5 + 0.5) as f32,
            corner.inv_w as f32,
        ],
        corners,
        weights: corner.weights,
    });
}

//! The straightforward Close2GL frame: for each triangle, transform its three vertices by P·M and
//! send it down the stages. Slow (shared vertices are transformed once per triangle) and easy to
//! check; the fast path must produce exactly its output.

use close2gl_core::{
    Camera, Close2glFrame, CutVertex, Fates, Mesh, PipelineSettings, RasterGeometry, Rasterizer,
    RenderMode, Viewport,
};

use crate::Tally;
use crate::emit;
use crate::matrices::ClipTransform;
use crate::mistakes::Mistakes;
use crate::program::{Outcome, Program};
use crate::stage::{Fate, FrameConstants, corner, process};

/// The 2D buffer and counts for this camera, mesh, settings and viewport, in a new frame (the
/// fast path reuses one instead).
pub fn run(
    mesh: &Mesh,
    camera: &Camera,
    settings: &PipelineSettings,
    viewport: Viewport,
) -> Close2glFrame {
    run_recording(mesh, camera, settings, viewport).0
}

/// [`run`], and every triangle's fate, recorded.
pub fn run_recording(
    mesh: &Mesh,
    camera: &Camera,
    settings: &PipelineSettings,
    viewport: Viewport,
) -> (Close2glFrame, Fates) {
    let transform = ClipTransform::new(camera);
    let constants = FrameConstants::new(settings, viewport);
    let mut frame = Close2glFrame {
        topology: constants.topology(),
        viewport,
        ..Close2glFrame::default()
    };
    let mut fates = Fates {
        record: true,
        ..Fates::default()
    };
    let mut counts = Tally::default();
    for triangle in &mesh.triangles {
        let clip = triangle.map(|i| transform.apply(mesh.positions[i as usize]));
        let corners = clip.map(|c| corner(c, &constants));
        let codes = corners.map(|(code, _)| code);
        let window = corners.map(|(_, window)| window);
        let fate = process::<true>(
            *triangle,
            codes,
            window,
            || clip,
            &constants,
            &mut frame.vertices,
        );
        counts.add(&fate);
        fates.triangles.push(fate.fate);
    }
    frame.counts = counts.stage_counts();
    fates.counts = counts.fate_counts();
    (frame, fates)
}

/// [`run_recording`] for a Close2GL that makes `mistakes` (see [`crate::mistakes`]): the
/// frame a student's program with them would draw in this window, each triangle sent down the
/// textbook's stages with the mistaken choices. With the software rasterizer, every vertex it
/// draws is a cut vertex: where it lies in its triangle says what its corners carry.
pub fn run_mistaken(
    mesh: &Mesh,
    camera: &Camera,
    settings: &PipelineSettings,
    viewport: Viewport,
    mistakes: Mistakes,
) -> (Close2glFrame, Fates) {
    let program = Program::for_view(camera, settings, viewport, mistakes);
    let constants = FrameConstants::new(settings, viewport);
    let raster = settings.close2gl_raster == Rasterizer::Software;
    let mut frame = Close2glFrame {
        topology: constants.topology(),
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
        let before = frame.vertices.len();
        for i in emitted(outcome, settings.mode) {
            let p = outcome.polygon[i];
            frame.vertices.push([p.x as f32, p.y as f32]);
            if raster {
                push_cut_vertex(&mut frame.raster, outcome, i, corners, index);
            }
        }
        let primitives = (frame.vertices.len() - before) / constants.topology_vertices();
        counts.add(&Fate {
            fate: outcome.fate,
            primitives,
        });
        fates.triangles.push(outcome.fate);
    }
    if raster {
        // One triangle index per primitive, not per vertex.
        let step = constants.topology_vertices();
        let triangles = frame.raster.triangles.iter().step_by(step).copied();
        frame.raster.triangles = triangles.collect();
    }
    frame.counts = counts.stage_counts();
    fates.counts = counts.fate_counts();
    (frame, fates)
}

/// Corner `i` of `outcome`'s polygon (mesh triangle `index`, of `corners`) as a vertex of the
/// software rasterizer: a cut vertex, which carries where it lies in its triangle.
fn push_cut_vertex(
    raster: &mut RasterGeometry,
    outcome: &Outcome,
    i: usize,
    corners: [u32; 3],
    index: usize,
) {
    let cut = raster.cuts.len() as u32;
    raster.primitives.push(raster.vertices.len() as u32 + cut);
    let p = outcome.polygon[i];
    raster.cuts.push(CutVertex {
        window: [
            p.x as f32,
            p.y as f32,
            (outcome.depths[i] * 0.5 + 0.5) as f32,
            outcome.inv_w[i] as f32,
        ],
        corners,
        weights: outcome.weights[i],
    });
    raster.triangles.push(index as u32);
}

/// Which vertices of a drawn polygon the mode emits, in order ([`crate::emit`]).
fn emitted(outcome: &Outcome, mode: RenderMode) -> Vec<usize> {
    let n = outcome.polygon.len();
    match mode {
        RenderMode::Solid => emit::fan(n).collect(),
        RenderMode::Wireframe => emit::edges(n, |i| outcome.edges[i]).collect(),
        RenderMode::Points => (0..n).collect(),
    }
}

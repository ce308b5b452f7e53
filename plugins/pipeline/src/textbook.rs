//! The straightforward Close2GL frame: for each triangle, transform its three vertices by P·M and
//! send it down the stages. Slow (shared vertices are transformed once per triangle) and easy to
//! check; the fast path must produce exactly its output.

use close2gl_core::{Camera, Close2glFrame, Fates, Mesh, PipelineSettings, Viewport};

use crate::Tally;
use crate::matrices::ClipTransform;
use crate::stage::{FrameConstants, corner, process};

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

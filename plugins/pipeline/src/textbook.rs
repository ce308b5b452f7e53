//! The straightforward Close2GL frame: for each triangle, transform its three vertices by P·M and
//! send it down the stage. Slow (shared vertices are transformed once per triangle) and easy to
//! check; the fast path must produce exactly its output.

use close2gl_core::{Camera, Close2glFrame, Mesh, RenderSettings, StageCounts, Viewport};

use crate::matrices::ClipTransform;
use crate::stage::{Output, Stage, corner, process};
use crate::tally;

/// Fills `frame` with the 2D buffer and counts for this camera, mesh, settings and viewport.
pub fn run(
    mesh: &Mesh,
    camera: &Camera,
    settings: &RenderSettings,
    viewport: Viewport,
    frame: &mut Close2glFrame,
) {
    let transform = ClipTransform::new(camera);
    let stage = Stage::new(settings, viewport);
    let mut counts = StageCounts::default();
    frame.vertices.clear();
    for triangle in &mesh.triangles {
        let clip = triangle.map(|i| transform.apply(mesh.positions[i as usize]));
        let corners = clip.map(|c| corner(c, &stage));
        let codes = corners.map(|(code, _)| code);
        let window = corners.map(|(_, window)| window);
        let mut out = Output {
            window: &mut frame.vertices,
            raster: None,
        };
        let fate = process(*triangle, codes, window, || clip, &stage, &mut out);
        tally(&mut counts, fate);
    }
    frame.topology = stage.topology();
    frame.viewport = viewport;
    frame.counts = counts;
}

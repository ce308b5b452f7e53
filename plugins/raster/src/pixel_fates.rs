//! The two fates only the rasterizer can tell: a drawn triangle whose coverage reaches no pixel
//! centre (`no_pixels`), and one that covers centres but wins none of them in the depth test
//! (`hidden`). Run after the tiles, only while `Fates::record` is set, from the set-up
//! triangles and the id buffer the tiles wrote.

use close2gl_core::{FateCounts, FateKind, Fates};

use crate::bin::Bins;
use crate::target::NO_TRIANGLE;

const COVERS: u8 = 1;
const OWNS: u8 = 2;

/// What one frame's rasterization knows about each mesh triangle.
pub(crate) struct Rasterized<'a> {
    /// The set-up triangles kept for drawing (`per_primitive` were made of each primitive).
    pub bins: &'a Bins,
    pub per_primitive: usize,
    /// Each primitive's mesh triangle (the pipeline's `RasterGeometry::triangles`).
    pub mesh_triangles: &'a [u32],
}

impl Rasterized<'_> {
    fn mesh_triangle(&self, set_up: usize) -> Option<u32> {
        self.mesh_triangles
            .get(set_up / self.per_primitive)
            .copied()
    }

    /// Moves drawn and cut triangles that cover no centre, or win none, to `no_pixels` and
    /// `hidden`, recounts, and turns the id buffer's set-up indices into mesh triangles.
    /// `flags` is scratch space, kept by the caller so that recording allocates once.
    pub(crate) fn record(&self, ids: &mut [u32], flags: &mut Vec<u8>, fates: &mut Fates) {
        flags.clear();
        flags.resize(fates.triangles.len(), 0);
        for (k, t) in self.bins.footprints() {
            if let Some(mesh) = self.mesh_triangle(k as usize)
                && t.covers_any_centre()
            {
                flags[mesh as usize] |= COVERS;
            }
        }
        for id in ids.iter_mut().filter(|id| **id != NO_TRIANGLE) {
            *id = self.mesh_triangle(*id as usize).unwrap_or(NO_TRIANGLE);
            if let Some(flag) = flags.get_mut(*id as usize) {
                *flag |= OWNS;
            }
        }
        let mut counts = FateCounts::default();
        for (fate, flag) in fates.triangles.iter_mut().zip(flags.iter()) {
            if matches!(fate.kind, FateKind::Drawn | FateKind::Cut) {
                if flag & COVERS == 0 {
                    fate.kind = FateKind::NoPixels;
                } else if flag & OWNS == 0 {
                    fate.kind = FateKind::Hidden;
                }
            }
            counts.add(fate.kind);
        }
        fates.counts = counts;
    }
}

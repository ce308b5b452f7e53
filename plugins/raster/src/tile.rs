//! One tile (64×64 pixels, the top of the hierarchy tile → rows → blocks of eight lanes):
//! cleared, then each triangle binned there drawn in order: the edges that cross the tile (the
//! others are left out of every row), then each row's span of covered pixels, solved exactly
//! from those edges (no per-pixel edge test), handed to `row`. A small triangle's fragments
//! (see `bin`) are each depth-tested and written alone when the colour is the same at every
//! pixel or the fragment carries its values (Phong); otherwise the triangle is drawn by rows
//! at its first fragment.

use crate::bin::{Batch, Binned, Bins, ROWS};
use crate::edge::{Cover, Edge, row_inside, row_inside_narrow};
use crate::lanes::LANES;
use crate::queue::{Queue, Unqueued};
use crate::row::{RowBuffers, Span, draw_span};
use crate::setup::Footprint;
use crate::shading::PixelShader;
use crate::target::{NO_TRIANGLE, ROW, TileRect};
use crate::varyings::Planes;

/// One tile's buffers: colour, depth, the id buffer (empty when not recorded) and the
/// visibility buffer (used only when the tile is shaded after its depth test).
pub(crate) struct TileBuffers<'a> {
    pub color: &'a mut [u32],
    pub depth: &'a mut [f32],
    pub ids: &'a mut [u32],
    pub visible: &'a mut [u32],
}

impl TileBuffers<'_> {
    /// Clears the tile to `background`, the far plane and no triangle.
    pub(crate) fn clear(&mut self, background: u32) {
        self.color.fill(background);
        self.depth.fill(1.0);
        self.ids.fill(NO_TRIANGLE);
    }
}

/// One tile to draw: its number, where it lies, its buffers, what it is cleared to and what is
/// binned there.
pub(crate) struct TileJob<'a> {
    pub tile: usize,
    pub rect: TileRect,
    pub buffers: TileBuffers<'a>,
    pub background: u32,
    pub bins: &'a Bins,
}

/// Clears the tile to its background, the far plane and no triangle, then draws the triangles
/// binned there, batch after batch, partial blocks shaded through `queue`.
pub(crate) fn draw_tile<S: PixelShader, Q: Queue<S>>(job: TileJob<'_>, shader: &S, queue: &mut Q) {
    let (tile, rect, bins) = (job.tile, job.rect, job.bins);
    let mut buffers = job.buffers;
    buffers.clear(job.background);
    let mut rows = Rows::new(buffers.color, buffers.depth, buffers.ids);
    let uniform = shader.uniform();
    // The small triangle whose fragments in this tile its rows have drawn.
    let mut drawn = None;
    for_each_binned(bins, tile, |number, batch, binned, at| {
        let index = binned.index as usize;
        let set_up = || batch.set_up[index];
        let fragment = binned.pixel != ROWS;
        if let (true, Some(colour)) = (fragment, uniform) {
            rows.write_fragment(set_up, binned, || colour);
            return;
        }
        // A fragment that carries its values (then its triangle has no planes stored).
        let values = batch.values[tile].get(at).filter(|_| fragment);
        if let Some(colour) = values.and_then(|values| shader.at_pixel(values)) {
            rows.write_fragment(set_up, binned, || colour);
            return;
        }
        // A shading that varies is paid per block of eight lanes, and a small triangle's
        // fragments in one row share a block: it is drawn by rows at its first fragment.
        if fragment && drawn == Some(number) {
            return;
        }
        drawn = fragment.then_some(number);
        let planes = || batch.planes(index, bins.used);
        let footprint = &batch.footprints[index];
        draw_rows(rect, &mut rows, set_up(), footprint, planes, shader, queue);
    });
}

/// [`draw_tile`] with no queue, not inlined. Inlined into the tile runs' loop, the row loop it
/// calls ran the flat fill slower with the same instructions to the one (callgrind): where the
/// stack or the code fell, not anything done. The queued Phong tiles are the other way round,
/// faster inlined. Measured:
/// docs/performance.md#the-lightings-attenuation-and-sharing-the-tiles-between-the-threads
#[inline(never)]
pub(crate) fn draw_tile_unqueued<S: PixelShader>(job: TileJob<'_>, shader: &S) {
    draw_tile(job, shader, &mut Unqueued);
}

/// Each triangle or fragment binned in tile number `tile`, in submission order:
/// `f(number, batch, at)`, `number` counting the frame's kept triangles across the batches and
/// `at` its place in its batch's list for the tile.
#[inline(always)]
pub(crate) fn for_each_binned(
    bins: &Bins,
    tile: usize,
    mut f: impl FnMut(u32, &Batch, &Binned, usize),
) {
    for (batch, start) in bins.batches.iter().zip(&bins.starts) {
        for (at, binned) in batch.tiles[tile].iter().enumerate() {
            f(start + binned.index, batch, binned, at);
        }
    }
}

/// A tile's buffers as rows (`ids` has none when not recorded).
pub(crate) struct Rows<'a> {
    color: &'a mut [[u32; ROW]],
    depth: &'a mut [[f32; ROW]],
    ids: &'a mut [[u32; ROW]],
}

impl<'a> Rows<'a> {
    pub(crate) fn new(color: &'a mut [u32], depth: &'a mut [f32], ids: &'a mut [u32]) -> Self {
        Rows {
            color: color.as_chunks_mut::<ROW>().0,
            depth: depth.as_chunks_mut::<ROW>().0,
            ids: ids.as_chunks_mut::<ROW>().0,
        }
    }

    /// `fragment` of set-up triangle `index()` depth-tested, and where it passes, its depth
    /// written and `value` as its colour: what the rows write for a pixel of a shading that
    /// is the same at every pixel (the deferred first pass's mark). The index is read only
    /// while the id buffer is recorded. Whether it passed.
    #[inline(always)]
    pub(crate) fn write_fragment(
        &mut self,
        index: impl FnOnce() -> u32,
        fragment: &Binned,
        value: impl FnOnce() -> u32,
    ) -> bool {
        let (row, column) = (fragment.pixel as usize / ROW, fragment.pixel as usize % ROW);
        let passed = fragment.z < self.depth[row][column];
        if passed {
            self.depth[row][column] = fragment.z;
            self.color[row][column] = value();
            if let Some(ids) = self.ids.get_mut(row) {
                ids[column] = index();
            }
        }
        passed
    }
}

/// Set-up triangle `index`, drawing where `footprint` says, in the tile `rect`: each of its
/// rows there, its pixels all shaded (those `queue` takes too) before it returns. Its `planes`
/// are unpacked only when it has a row to draw.
#[inline(always)]
pub(crate) fn draw_rows<S: PixelShader, Q: Queue<S>>(
    rect: TileRect,
    rows: &mut Rows<'_>,
    index: u32,
    footprint: &Footprint,
    planes: impl FnOnce() -> Planes,
    shader: &S,
    queue: &mut Q,
) {
    let [x0, y0, x1, y1] = footprint.bbox;
    let area = TileRect {
        x0: x0.max(rect.x0),
        y0: y0.max(rect.y0),
        x1: x1.min(rect.x1),
        y1: y1.min(rect.y1),
    };
    if area.x0 > area.x1 || area.y0 > area.y1 {
        return;
    }
    let Some((crossing, count)) = crossing_edges(&footprint.edges, area) else {
        return;
    };
    let crossing = &crossing[..count];
    let narrow = area.x1 - area.x0 < LANES as i32;
    let mut planes = Some(planes);
    let mut unpacked = Planes::ZERO;
    for y in area.y0..=area.y1 {
        let (lo, hi) = match narrow {
            true => row_inside_narrow(crossing, y, (area.x0, area.x1)),
            false => row_inside(crossing, y, (area.x0, area.x1)),
        };
        if lo <= hi {
            let row = (y - rect.y0) as usize;
            let span = Span {
                y,
                lo: lo - rect.x0,
                hi: hi - rect.x0,
                x0: rect.x0,
            };
            let buffers = RowBuffers {
                color: &mut rows.color[row],
                depth: &mut rows.depth[row],
                ids: rows.ids.get_mut(row).map(|ids| (index, ids)),
            };
            if let Some(planes) = planes.take() {
                unpacked = planes();
            }
            draw_span(shader, &unpacked, span, buffers, queue);
        }
    }
    queue.shade(shader, &unpacked, rows.color);
}

/// The edges that cross `area` (the first `count` of them), or None when one leaves all of it
/// out; an edge that keeps all of it in needs no test in its rows.
#[inline(always)]
fn crossing_edges(edges: &[Edge; 3], area: TileRect) -> Option<([Edge; 3], usize)> {
    let mut crossing = [Edge::ZERO; 3];
    let mut count = 0;
    for edge in edges {
        match edge.over(area) {
            Cover::None => return None,
            Cover::All => {}
            Cover::Some => {
                crossing[count] = *edge;
                count += 1;
            }
        }
    }
    Some((crossing, count))
}

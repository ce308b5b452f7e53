//! Setup and binning in one parallel pass, in submission order. The primitives are cut into
//! runs (batches), a few per core; each batch is set up by one task, which keeps the triangles
//! that may cover a pixel centre and lists each, once, in every tile its bounding box touches,
//! in lists of its own. A tile then reads the batches' lists one after the other, so it meets
//! its triangles in submission order (which the depth test's ties depend on), and no triangle
//! is read by more tasks than the tiles it touches. A kept triangle is stored in two parts: its
//! footprint (edges and bounds, one cache line) and only the planes the frame's shading uses.
//! A small one (a bounding box of a few pixels, which setup has tested centre by centre) is
//! listed as its fragments instead: each covered pixel with its depth, which the tile tests
//! without reading the triangle (most of a big mesh's triangles cover a pixel or two), and,
//! for a shading done after the depth test, its values at the pixel, which the shading then
//! reads in order from the tile's own list, not from the triangle, anywhere in memory; such a
//! triangle's planes are then not stored at all.

use close2gl_core::Topology;
use rayon::prelude::*;

use crate::primitives::{SetupParams, indices_per_primitive, set_up};
use crate::setup::{Centres, Footprint, Triangle};
use crate::target::{Grid, ROW, TILE};
use crate::varyings::{AT_PIXEL, Planes, Used};
use crate::vertex::Vertex;

/// Batches per core: enough for a core done early to take another.
const BATCHES_PER_CORE: usize = 4;

/// One run of primitives, set up: its triangles, kept between frames.
#[derive(Debug, Default)]
pub(crate) struct Batch {
    /// The triangles that may cover a pixel centre, in order: where each draws...
    pub footprints: Vec<Footprint>,
    /// ...its place among the planes ([`NO_PLANES`] for a small one whose fragments carry
    /// their values, see `values`)...
    pub slots: Vec<u32>,
    /// ...which are packed ([`Planes::pack`]), `Bins::used.packed_floats()` each...
    pub planes: Vec<f32>,
    /// ...and its set-up index (what the id buffer records).
    pub set_up: Vec<u32>,
    /// For each tile, in order, the triangles whose bounding box touches it and the fragments
    /// of small ones that land in it...
    pub tiles: Vec<Vec<Binned>>,
    /// ...and, when the shading is one shaded after the depth test (`Used::at_pixel`), beside
    /// each, a fragment's values at its pixel (zeros for a triangle drawn by rows).
    pub values: Vec<Vec<[f32; AT_PIXEL]>>,
}

/// One entry of a tile's list: triangle `index` (in its batch) drawn by rows, or one pixel of
/// it, a fragment.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Binned {
    pub index: u32,
    /// The fragment's pixel in the tile (row · 64 + column), or [`ROWS`].
    pub pixel: u32,
    /// The fragment's depth, as the tile would compute it (`Planes::depth_in_tile`).
    pub z: f32,
}

/// `Binned::pixel` of a triangle drawn by rows.
pub(crate) const ROWS: u32 = u32::MAX;

/// `Batch::slots` of a triangle with no planes stored: a small one whose fragments carry their
/// values, which is all that the tiles then read of it (its planes were the most the frame
/// wrote, and read back from anywhere in memory).
pub(crate) const NO_PLANES: u32 = u32::MAX;

/// Every batch of a frame, in submission order.
#[derive(Debug, Default)]
pub(crate) struct Bins {
    pub batches: Vec<Batch>,
    /// The planes stored with each triangle.
    pub used: Used,
    /// Where each batch's triangles start in the frame's numbering of them all (what a tile's
    /// visibility buffer records).
    pub starts: Vec<u32>,
}

/// What setup reads: the primitives (their vertices' `indices`) and the vertices.
pub(crate) struct Primitives<'a> {
    pub topology: Topology,
    pub indices: &'a [u32],
    pub vertices: &'a [Vertex],
}

impl Bins {
    /// Sets up `primitives` and bins them into the tiles of `grid`.
    pub(crate) fn fill(&mut self, grid: Grid, primitives: Primitives<'_>, params: SetupParams) {
        self.used = params.used;
        let batches = (rayon::current_num_threads() * BATCHES_PER_CORE).max(1);
        self.batches.resize_with(batches, Batch::default);
        let per_primitive = indices_per_primitive(primitives.topology);
        let count = primitives.indices.len() / per_primitive;
        let per_batch = count.div_ceil(batches);
        self.batches
            .par_iter_mut()
            .enumerate()
            .for_each(|(k, batch)| {
                let first = (k * per_batch).min(count);
                let last = (first + per_batch).min(count);
                let indices = &primitives.indices[first * per_primitive..last * per_primitive];
                batch.clear(grid.tiles());
                // Compiled twice: the binning of the shading whose fragments carry their values,
                // and of the others, which pay nothing for them.
                match params.used.at_pixel() {
                    true => batch.fill::<true>(grid, &primitives, indices, first, params),
                    false => batch.fill::<false>(grid, &primitives, indices, first, params),
                }
            });
        self.starts.clear();
        let mut start = 0;
        for batch in &self.batches {
            self.starts.push(start);
            start += batch.footprints.len() as u32;
        }
    }

    /// How many triangles are binned in tile number `tile`.
    pub(crate) fn binned(&self, tile: usize) -> usize {
        self.batches.iter().map(|b| b.tiles[tile].len()).sum()
    }

    /// The packed planes of triangle `number` in the frame's numbering (see `starts`).
    #[inline(always)]
    pub(crate) fn packed(&self, number: u32) -> &[f32] {
        // Counted, not searched: a few batches' starts compared at once, with no dependent
        // loads (the shading pass asks this for most pixels of a big mesh).
        let batch = self.starts.iter().filter(|&&s| s <= number).count() - 1;
        let index = (number - self.starts[batch]) as usize;
        self.batches[batch].packed(index, self.used)
    }

    /// Where every kept triangle draws, with its set-up index, in order.
    pub(crate) fn footprints(&self) -> impl Iterator<Item = (u32, &Footprint)> {
        self.batches
            .iter()
            .flat_map(|b| b.set_up.iter().copied().zip(&b.footprints))
    }
}

impl Batch {
    /// Triangle `index`'s planes, unpacked.
    #[inline(always)]
    pub(crate) fn planes(&self, index: usize, used: Used) -> Planes {
        Planes::unpack(self.packed(index, used), used)
    }

    /// Triangle `index`'s packed planes (none when [`NO_PLANES`]: nothing asks for them).
    #[inline(always)]
    fn packed(&self, index: usize, used: Used) -> &[f32] {
        let floats = used.packed_floats();
        &self.planes[self.slots[index] as usize * floats..][..floats]
    }

    fn clear(&mut self, tiles: usize) {
        self.footprints.clear();
        self.slots.clear();
        self.planes.clear();
        self.set_up.clear();
        self.tiles.resize_with(tiles, Vec::new);
        self.tiles.iter_mut().for_each(Vec::clear);
        self.values.resize_with(tiles, Vec::new);
        self.values.iter_mut().for_each(Vec::clear);
    }

    /// Sets up and bins `indices`, the primitives from number `first`.
    #[inline(always)]
    fn fill<const VALUES: bool>(
        &mut self,
        grid: Grid,
        primitives: &Primitives<'_>,
        indices: &[u32],
        first: usize,
        params: SetupParams,
    ) {
        set_up(
            primitives.topology,
            indices,
            first,
            primitives.vertices,
            params,
            // Inlined, so that the triangle is not read back through memory.
            #[inline(always)]
            |set_up, t| self.push::<VALUES>(grid, params.used, set_up, t),
        );
    }

    /// Stores triangle `t` and lists it in its tiles, with its fragments' values when
    /// `VALUES` (`Used::at_pixel`).
    #[inline(always)]
    fn push<const VALUES: bool>(&mut self, grid: Grid, used: Used, set_up: u32, t: &Triangle) {
        let index = self.footprints.len() as u32;
        self.footprints.push(t.footprint);
        let values_only = VALUES && matches!(t.centres, Centres::Few(_));
        match values_only {
            true => self.slots.push(NO_PLANES),
            false => {
                let floats = used.packed_floats();
                self.slots.push((self.planes.len() / floats) as u32);
                t.planes.pack(used, &mut self.planes);
            }
        }
        self.set_up.push(set_up);
        let [x0, y0, x1, y1] = t.footprint.bbox;
        let tiles_x = grid.tiles_x as usize;
        let tile = |x: i32, y: i32| (y / TILE) as usize * tiles_x + (x / TILE) as usize;
        match t.centres {
            Centres::Rows => {
                let whole = Binned {
                    index,
                    pixel: ROWS,
                    z: 0.0,
                };
                for ty in y0 / TILE..=y1 / TILE {
                    for tx in x0 / TILE..=x1 / TILE {
                        let tile = tile(tx * TILE, ty * TILE);
                        self.tiles[tile].push(whole);
                        if VALUES {
                            self.values[tile].push([0.0; AT_PIXEL]);
                        }
                    }
                }
            }
            Centres::Few(mask) => {
                let mut bits = mask;
                while bits != 0 {
                    let (x, y) = t.footprint.centre(bits.trailing_zeros());
                    bits &= bits - 1;
                    let (tx0, ty0) = (x - x % TILE, y - y % TILE);
                    let tile = tile(x, y);
                    self.tiles[tile].push(Binned {
                        index,
                        pixel: ((y - ty0) * ROW as i32 + (x - tx0)) as u32,
                        z: t.planes.depth_in_tile(tx0, x, y),
                    });
                    if VALUES {
                        self.values[tile].push(t.planes.at_pixel(x, y));
                    }
                }
            }
        }
    }
}

//! Binning: each triangle is listed, once, in every tile its bounding box touches, in
//! submission order (which the depth test's ties depend on). The bins of a band of tile rows
//! are filled by one thread, so binning runs in parallel without locks.

use rayon::prelude::*;

use crate::setup::Triangle;
use crate::target::{Grid, TILE};

/// One list of triangle indices per tile, kept between frames.
#[derive(Debug, Default)]
pub(crate) struct Bins {
    pub tiles: Vec<Vec<u32>>,
}

impl Bins {
    pub(crate) fn fill(&mut self, grid: Grid, triangles: &[Triangle]) {
        self.tiles.resize_with(grid.tiles(), Vec::new);
        let tiles_x = grid.tiles_x as usize;
        // One band of tile rows per thread (and a few more, to balance uneven bands).
        let bands = (rayon::current_num_threads() * 2).max(1);
        let rows_per_band = (grid.tiles_y as usize).div_ceil(bands).max(1);
        self.tiles
            .par_chunks_mut(rows_per_band * tiles_x)
            .enumerate()
            .for_each(|(band, bins)| {
                bins.iter_mut().for_each(Vec::clear);
                let first_row = (band * rows_per_band) as i32;
                let last_row = first_row + (bins.len() / tiles_x) as i32 - 1;
                for (index, t) in triangles.iter().enumerate() {
                    if t.is_empty() {
                        continue;
                    }
                    let [x0, y0, x1, y1] = t.bbox;
                    let (ty0, ty1) = ((y0 / TILE).max(first_row), (y1 / TILE).min(last_row));
                    for ty in ty0..=ty1 {
                        let row = (ty - first_row) as usize * tiles_x;
                        for tx in x0 / TILE..=x1 / TILE {
                            bins[row + tx as usize].push(index as u32);
                        }
                    }
                }
            });
    }
}

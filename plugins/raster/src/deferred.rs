//! Shading once per pixel, after the depth test, for Phong without a texture, in tiles of small
//! triangles (the rasterizer chooses). The tile is drawn in two passes: first every triangle
//! binned there is depth-tested, writing into the tile's visibility buffer which triangle each
//! pixel shows (by the frame's numbering), or, where a small triangle's fragment won (one
//! compare each), a mark, and the fragment's values at its pixel (`Planes::at_pixel`, carried in
//! the tile's list) into the thread's own buffer. Then each block of eight pixels is coloured
//! once: from one triangle's planes when all its lanes show the same one, else from each lane's
//! values (`AtPixels`), read from that buffer or worked out from the lane's triangle's planes.
//! A one-pixel triangle then costs a lane, not a block of eight, a pixel covered many times is
//! shaded once, and the shading reads no triangle from memory for a small triangle's pixel (on
//! a million of them, that reading was most of this pass, measured:
//! docs/performance.md#fragments-that-carry-their-values). The colours are those of shading
//! each fragment as it passes, bit for bit: the depth test's winner is the fragment written
//! last, and each lane's arithmetic is the same.

use std::cell::RefCell;

use crate::bin::{Bins, ROWS};
use crate::lanes::{F8, LANES, with_avx2};
use crate::queue::Unqueued;
use crate::shading::{LaneShader, PixelShader};
use crate::target::{NO_TRIANGLE, ROW, TILE_PIXELS, TileRect};
use crate::tile::{Rows, TileJob, draw_rows, for_each_binned};
use crate::varyings::{AT_PIXEL, AtPixels, Planes};

/// The visibility buffer's mark where a small triangle's fragment won: its values at the pixel
/// are in the thread's [`WON`] (triangles are numbered from 0, far below).
const FRAGMENT: u32 = NO_TRIANGLE - 1;

thread_local! {
    /// The values of the fragments that won the depth test in the tile the thread is drawing,
    /// value k of pixel p at k · 4096 + p: kept from tile to tile and frame to frame, so that a
    /// steady frame allocates nothing. Read only where the tile's visibility buffer is marked,
    /// so never cleared.
    static WON: RefCell<Vec<f32>> = const { RefCell::new(Vec::new()) };
}

/// Draws the tile as [`crate::tile::draw_tile`] does, shading after the depth test.
pub(crate) fn draw_tile_deferred<S: PixelShader + LaneShader>(mut job: TileJob<'_>, shader: &S) {
    WON.with_borrow_mut(|won| {
        won.resize(AT_PIXEL * TILE_PIXELS, 0.0);
        let won = won.as_chunks_mut::<TILE_PIXELS>().0;
        job.buffers.clear(job.background);
        job.buffers.visible.fill(NO_TRIANGLE);
        depth_pass(&mut job, won);
        let (color, _) = job.buffers.color.as_chunks_mut::<ROW>();
        let (visible, _) = job.buffers.visible.as_chunks::<ROW>();
        shade_visible(job.rect, color, visible, won, job.bins, shader);
    });
}

/// The first pass: the visibility buffer takes the colour buffer's place, each triangle
/// "shading" its number, each fragment its mark, with its values put in `won`.
#[inline(always)]
fn depth_pass(job: &mut TileJob<'_>, won: &mut [[f32; TILE_PIXELS]]) {
    let (rect, bins, tile) = (job.rect, job.bins, job.tile);
    let mut rows = Rows::new(job.buffers.visible, job.buffers.depth, job.buffers.ids);
    for_each_binned(bins, tile, |number, batch, binned, at| {
        let index = binned.index as usize;
        let set_up = || batch.set_up[index];
        match binned.pixel {
            ROWS => {
                let planes = || batch.planes(index, bins.used);
                let footprint = &batch.footprints[index];
                let shader = &Number(number);
                draw_rows(
                    rect,
                    &mut rows,
                    set_up(),
                    footprint,
                    planes,
                    shader,
                    &mut Unqueued,
                );
            }
            pixel => {
                if rows.write_fragment(set_up, binned, || FRAGMENT) {
                    let values = &batch.values[tile][at];
                    for (won, &value) in won.iter_mut().zip(values) {
                        won[pixel as usize] = value;
                    }
                }
            }
        }
    });
}

/// A triangle's number, in every lane: what the first pass writes where it wins.
struct Number(u32);

impl PixelShader for Number {
    #[inline(always)]
    fn shade(&self, _: &Planes, _: F8, _: f32) -> [u32; LANES] {
        [self.0; LANES]
    }
}

with_avx2! {
    /// The second pass, compiled for the baseline x86-64 and for AVX2 and FMA.
    ///
    /// Each block of eight pixels that shows a triangle, coloured once.
    #[inline(always)]
    fn shade_visible[S: LaneShader + PixelShader](
        rect: TileRect,
        color: &mut [[u32; ROW]],
        visible: &[[u32; ROW]],
        won: &[[f32; TILE_PIXELS]],
        bins: &Bins,
        shader: &S,
    ) {
        let rows = (rect.y1 - rect.y0 + 1) as usize;
        let blocks = ((rect.x1 - rect.x0 + 1) as usize).div_ceil(LANES);
        // The planes of the triangle shown last: a large triangle's blocks follow one another.
        let mut last = (NO_TRIANGLE, Planes::ZERO);
        for (row, (color, visible)) in color.iter_mut().zip(visible).take(rows).enumerate() {
            let y = rect.y0 + row as i32;
            let fy = y as f32 + 0.5;
            let (color, _) = color.as_chunks_mut::<LANES>();
            let (visible, _) = visible.as_chunks::<LANES>();
            let blocks = color.iter_mut().zip(visible).take(blocks).enumerate();
            for (block, (color, shown)) in blocks {
                let Some(&first) = shown.iter().find(|&&n| n != NO_TRIANGLE) else {
                    continue;
                };
                let x0 = rect.x0 + (block * LANES) as i32;
                let x = F8::ramp(x0 as f32 + 0.5);
                let one = shown.iter().all(|&n| n == first || n == NO_TRIANGLE);
                let shaded = match one && first != FRAGMENT {
                    true => {
                        if last.0 != first {
                            last = (first, Planes::unpack(bins.packed(first), bins.used));
                        }
                        shader.shade(&last.1, x, fy)
                    }
                    false => {
                        let at = row * ROW + block * LANES;
                        let mut values = AtPixels::new(std::array::from_fn(|k| {
                            won[k][at..at + LANES].as_array().expect("a block of eight")
                        }));
                        for (lane, &n) in shown.iter().enumerate() {
                            if n != FRAGMENT && n != NO_TRIANGLE {
                                let planes = Planes::unpack(bins.packed(n), bins.used);
                                values.set_lane(lane, &planes.at_pixel(x0 + lane as i32, y));
                            }
                        }
                        shader.shade_lanes(&values, x, fy)
                    }
                };
                for (c, (s, &n)) in color.iter_mut().zip(shaded.into_iter().zip(shown)) {
                    if n != NO_TRIANGLE {
                        *c = s;
                    }
                }
            }
        }
    }
}

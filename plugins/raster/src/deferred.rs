//! Shading once per pixel, after the depth test, for Phong without a texture, in tiles of small
//! triangles (the rasterizer chooses). The tile is drawn in two passes: first every triangle
//! binned there is depth-tested (a small one's fragments one compare each), writing into the
//! tile's visibility buffer which triangle each pixel shows (by the frame's numbering);
//! then each block of eight pixels is coloured once, from one triangle's planes when all its
//! lanes show the same one, else each lane from its own triangle's (`LanePlanes`). A one-pixel
//! triangle then costs a lane, not a block of eight, and a pixel covered many times is shaded
//! once. The colours are those of shading each fragment as it passes, bit for bit: the depth
//! test's winner is the fragment written last, and each lane's arithmetic is the same.

use crate::bin::{Bins, ROWS};
use crate::lanes::{F8, LANES};
use crate::queue::Unqueued;
use crate::shading::{LaneShader, PixelShader};
use crate::target::{NO_TRIANGLE, ROW, TileRect};
use crate::tile::{Rows, TileBuffers, draw_rows, for_each_binned};
use crate::varyings::{LanePlanes, Planes};

/// Draws tile number `tile` as [`crate::tile::draw_tile`] does, shading after the depth test.
pub(crate) fn draw_tile_deferred<S: PixelShader + LaneShader>(
    rect: TileRect,
    mut buffers: TileBuffers<'_>,
    background: u32,
    bins: &Bins,
    tile: usize,
    shader: &S,
) {
    buffers.clear(background);
    buffers.visible.fill(NO_TRIANGLE);
    // The visibility buffer takes the colour buffer's place: each triangle "shades" its number.
    let mut rows = Rows::new(buffers.visible, buffers.depth, buffers.ids);
    for_each_binned(bins, tile, |number, batch, binned| {
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
            _ => rows.write_fragment(set_up, binned, number),
        }
    });
    let (color, _) = buffers.color.as_chunks_mut::<ROW>();
    let (visible, _) = buffers.visible.as_chunks::<ROW>();
    shade_visible(rect, color, visible, bins, shader);
}

/// A triangle's number, in every lane: what the first pass writes where it wins.
struct Number(u32);

impl PixelShader for Number {
    #[inline(always)]
    fn shade(&self, _: &Planes, _: F8, _: f32) -> [u32; LANES] {
        [self.0; LANES]
    }
}

/// The second pass, compiled twice as `row::draw_span` is: for the baseline x86-64 and, chosen
/// at run time, for AVX2 and FMA.
#[inline(always)]
fn shade_visible<S: LaneShader + PixelShader>(
    rect: TileRect,
    color: &mut [[u32; ROW]],
    visible: &[[u32; ROW]],
    bins: &Bins,
    shader: &S,
) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma") {
        // SAFETY: the CPU has the features the function is compiled for, checked just above.
        unsafe { shade_visible_avx2(rect, color, visible, bins, shader) };
        return;
    }
    shade_visible_portable(rect, color, visible, bins, shader);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline(never)]
fn shade_visible_avx2<S: LaneShader + PixelShader>(
    rect: TileRect,
    color: &mut [[u32; ROW]],
    visible: &[[u32; ROW]],
    bins: &Bins,
    shader: &S,
) {
    shade_visible_portable(rect, color, visible, bins, shader);
}

/// Each block of eight pixels that shows a triangle, coloured once.
#[inline(always)]
fn shade_visible_portable<S: LaneShader + PixelShader>(
    rect: TileRect,
    color: &mut [[u32; ROW]],
    visible: &[[u32; ROW]],
    bins: &Bins,
    shader: &S,
) {
    let rows = (rect.y1 - rect.y0 + 1) as usize;
    let blocks = ((rect.x1 - rect.x0 + 1) as usize).div_ceil(LANES);
    // The planes of the triangle shown last: a large triangle's blocks follow one another.
    let mut last = (NO_TRIANGLE, Planes::ZERO);
    for (row, (color, visible)) in color.iter_mut().zip(visible).take(rows).enumerate() {
        let fy = (rect.y0 + row as i32) as f32 + 0.5;
        let (color, _) = color.as_chunks_mut::<LANES>();
        let (visible, _) = visible.as_chunks::<LANES>();
        let blocks = color.iter_mut().zip(visible).take(blocks).enumerate();
        for (block, (color, shown)) in blocks {
            let Some(&first) = shown.iter().find(|&&n| n != NO_TRIANGLE) else {
                continue;
            };
            let x = F8::ramp((rect.x0 + (block * LANES) as i32) as f32 + 0.5);
            let shaded = match shown.iter().all(|&n| n == first || n == NO_TRIANGLE) {
                true => {
                    if last.0 != first {
                        last = (first, Planes::unpack(bins.packed(first), bins.used));
                    }
                    shader.shade(&last.1, x, fy)
                }
                false => shader.shade_lanes(&lane_planes(shown, bins), x, fy),
            };
            for (c, (s, &n)) in color.iter_mut().zip(shaded.into_iter().zip(shown)) {
                if n != NO_TRIANGLE {
                    *c = s;
                }
            }
        }
    }
}

/// The planes of the triangle each lane shows (the lanes that show none keep zeros: their
/// colours are computed and not written).
#[inline(always)]
fn lane_planes(shown: &[u32; LANES], bins: &Bins) -> LanePlanes {
    let mut planes = LanePlanes::ZERO;
    for (lane, &number) in shown.iter().enumerate() {
        if number != NO_TRIANGLE {
            planes.set_lane(lane, bins.packed(number), bins.used);
        }
    }
    planes
}

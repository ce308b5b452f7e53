//! One row of a tile: a triangle's span of covered pixels, depth-tested and shaded a block of
//! eight lanes at a time (the hierarchy is tile → rows → blocks of eight lanes), with the lanes
//! outside the span masked off; while fates are recorded, the winner's index in the id buffer.

use crate::lanes::{F8, LANES, Mask, with_avx2};
use crate::queue::Queue;
use crate::shading::PixelShader;
use crate::target::ROW;
use crate::varyings::Planes;

/// Pixels lo..=hi (columns within the tile) of row y; the tile starts at column x0.
#[derive(Clone, Copy)]
pub(crate) struct Span {
    pub y: i32,
    pub lo: i32,
    pub hi: i32,
    pub x0: i32,
}

/// One row of a tile's buffers; `ids` while fates are recorded: the triangle's index, and the
/// row of the id buffer it is written to where it passes the depth test.
pub(crate) struct RowBuffers<'a> {
    pub color: &'a mut [u32; ROW],
    pub depth: &'a mut [f32; ROW],
    pub ids: Option<(u32, &'a mut [u32; ROW])>,
}

/// The depth test and the shader over a span, or the `queue` for blocks it takes.
#[inline(always)]
pub(crate) fn draw_span<S: PixelShader, Q: Queue<S>>(
    shader: &S,
    planes: &Planes,
    span: Span,
    row: RowBuffers<'_>,
    queue: &mut Q,
) {
    // The row's buffers go apart, as separate arguments in registers, to the function that is
    // not inlined.
    let RowBuffers { color, depth, ids } = row;
    draw_span_parts(shader, planes, span, color, depth, ids, queue);
}

with_avx2! {
    /// [`draw_span`]'s work, compiled for the baseline x86-64 and for AVX2 and FMA.
    ///
    /// Works on whole blocks of eight pixels of the tile's row (the row is 64 wide, so they always
    /// exist), with lanes outside the span masked off: fixed-size, branch-free code is what the
    /// compiler vectorises.
    #[inline(always)]
    fn draw_span_parts[S: PixelShader, Q: Queue<S>](
        shader: &S,
        planes: &Planes,
        span: Span,
        color: &mut [u32; ROW],
        depth: &mut [f32; ROW],
        ids: Option<(u32, &mut [u32; ROW])>,
        queue: &mut Q,
    ) {
        let mut ids = ids;
        let fy = span.y as f32 + 0.5;
        let z_row = planes.depth_at(span.x0 as f32 + 0.5, fy);
        let (color, _) = color.as_chunks_mut::<LANES>();
        let (depth, _) = depth.as_chunks_mut::<LANES>();
        let first = span.lo as usize / LANES;
        let last = span.hi as usize / LANES;
        for block in first..=last {
            let base = block * LANES;
            let lanes = F8::ramp(base as f32);
            let z = lanes.mul_add(F8::splat(planes.depth.dadx), F8::splat(z_row));
            let pass = depth_test(span, base, z, &mut depth[block]);
            if pass == [0; LANES] {
                continue;
            }
            if let Some((index, ids)) = ids.as_mut() {
                let ids = &mut ids[base..base + LANES];
                for (id, p) in ids.iter_mut().zip(pass) {
                    *id = (*index & p) | (*id & !p);
                }
            }
            if queue.take(span.y, base, &pass) {
                continue;
            }
            let x = F8::ramp((span.x0 + base as i32) as f32 + 0.5);
            let shaded = shader.shade(planes, x, fy);
            let color = &mut color[block];
            for (c, (s, p)) in color.iter_mut().zip(shaded.into_iter().zip(pass)) {
                *c = (s & p) | (*c & !p);
            }
        }
    }
}

/// The block of eight pixels from column `base`: which lanes lie in the span and are nearer
/// than the depth buffer, whose depth then becomes `z`.
#[inline(always)]
fn depth_test(span: Span, base: usize, z: F8, depth: &mut [f32; LANES]) -> Mask {
    let mut pass = [0u32; LANES];
    for (i, (p, (z, d))) in pass
        .iter_mut()
        .zip(z.0.iter().zip(depth.iter()))
        .enumerate()
    {
        let x = (base + i) as i32;
        // `&`, not `&&`: no branch per lane.
        let passed = (x >= span.lo) & (x <= span.hi) & (z < d);
        *p = 0u32.wrapping_sub(passed as u32);
    }
    // Seen as a plain bit mask, the blends below stay blends: recognised as a selection,
    // they become masked stores, which some CPUs (AMD's) execute very slowly.
    let pass = std::hint::black_box(pass);
    for i in 0..LANES {
        depth[i] = f32::from_bits((z.0[i].to_bits() & pass[i]) | (depth[i].to_bits() & !pass[i]));
    }
    pass
}

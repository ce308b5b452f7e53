//! The pixels of a small triangle's partial blocks, queued to be shaded eight at a time. A
//! span a few pixels wide passes the depth test in two or three lanes of its block: shaded
//! there, the other lanes' work is thrown away, and Phong's lighting is most of a frame. So a
//! block whose lanes do not all pass leaves its pixels here, and when the triangle is done in
//! the tile they are shaded eight together, each lane at its own pixel of the triangle
//! (`AtPoints`). The colours are those of shading each block where it passed, bit for bit,
//! and a triangle's pixels are all written before the next triangle's.

use crate::lanes::{F8, LANES, Mask, with_avx2};
use crate::shading::{LaneShader, PixelShader};
use crate::target::{ROW, TILE_PIXELS, TileRect};
use crate::varyings::{AtPoints, Planes};

/// What a triangle's blocks that pass the depth test become: shaded where they pass
/// ([`Unqueued`]) or, when not every lane passes, queued ([`Pending`]).
pub(crate) trait Queue<S: PixelShader> {
    /// Takes the lanes of `pass` of the block at column `base` of row `y`, unless the block
    /// is to be shaded at once (false).
    fn take(&mut self, y: i32, base: usize, pass: &Mask) -> bool;

    /// Shades the queued pixels of the triangle whose `planes` these are into the tile's rows
    /// of `color`, and empties the queue.
    fn shade(&mut self, shader: &S, planes: &Planes, color: &mut [[u32; ROW]]);
}

/// Every block shaded where it passes: for shadings whose pixels cost little (flat, Gouraud),
/// or that need their block to be a row of pixels (texturing's level of detail).
pub(crate) struct Unqueued;

impl<S: PixelShader> Queue<S> for Unqueued {
    #[inline(always)]
    fn take(&mut self, _: i32, _: usize, _: &Mask) -> bool {
        false
    }

    #[inline(always)]
    fn shade(&mut self, _: &S, _: &Planes, _: &mut [[u32; ROW]]) {}
}

/// A triangle can cover the whole tile, and `take` writes a whole block past the last pixel.
const CAPACITY: usize = TILE_PIXELS + LANES;

/// The pixels of one tile waiting to be shaded, as their index in the tile (row · 64 + column).
pub(crate) struct Pending {
    rect: TileRect,
    pixels: [u16; CAPACITY],
    len: usize,
}

impl Pending {
    pub(crate) fn new(rect: TileRect) -> Pending {
        Pending {
            rect,
            pixels: [0; CAPACITY],
            len: 0,
        }
    }
}

impl<S: PixelShader + LaneShader> Queue<S> for Pending {
    #[inline(always)]
    fn take(&mut self, y: i32, base: usize, pass: &Mask) -> bool {
        if *pass == [u32::MAX; LANES] {
            return false;
        }
        let first = (y - self.rect.y0) as usize * ROW + base;
        // Every lane is written, and only the passing ones kept: no branch per lane.
        for (lane, &p) in pass.iter().enumerate() {
            self.pixels[self.len] = (first + lane) as u16;
            self.len += (p & 1) as usize;
        }
        true
    }

    #[inline(always)]
    fn shade(&mut self, shader: &S, planes: &Planes, color: &mut [[u32; ROW]]) {
        if self.len > 0 {
            shade_pending(shader, planes, color, self);
        }
    }
}

with_avx2! {
    /// [`Pending::shade`]'s work, compiled for the baseline x86-64 and for AVX2 and FMA. Once
    /// per triangle and tile, not per row, so that the triangle's planes are set out once for
    /// all its groups.
    fn shade_pending[S: LaneShader](
        shader: &S,
        planes: &Planes,
        color: &mut [[u32; ROW]],
        pending: &mut Pending,
    ) {
        let queued = &pending.pixels[..pending.len];
        let (groups, rest) = queued.as_chunks::<LANES>();
        for group in groups {
            shade_group(shader, planes, color, pending.rect, group, LANES);
        }
        if let Some(&first) = rest.first() {
            // The last few, with their first pixel again in the spare lanes.
            let mut group = [first; LANES];
            group[..rest.len()].copy_from_slice(rest);
            shade_group(shader, planes, color, pending.rect, &group, rest.len());
        }
        pending.len = 0;
    }
}

/// The first `count` pixels of `group`, shaded, into the tile `rect`'s rows of `color`.
#[inline(always)]
fn shade_group<S: LaneShader>(
    shader: &S,
    planes: &Planes,
    color: &mut [[u32; ROW]],
    rect: TileRect,
    group: &[u16; LANES],
    count: usize,
) {
    let column = F8(group.map(|p| (p % ROW as u16) as f32));
    let row = F8(group.map(|p| (p / ROW as u16) as f32));
    let x = column + F8::splat(rect.x0 as f32 + 0.5);
    let dy = row + F8::splat(rect.y0 as f32 + 0.5);
    // Stored whole before it is scattered: the compiler vectorises a shader whose eight
    // results go to eight adjacent places, and would not see one whose lanes go apart.
    let shaded = std::hint::black_box(shader.shade_lanes(&AtPoints { planes, dy }, x, 0.0));
    for (&p, &c) in group.iter().zip(&shaded).take(count) {
        color[p as usize / ROW][p as usize % ROW] = c;
    }
}

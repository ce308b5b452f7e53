//! Drawing one tile: for each triangle binned there, in order, the edges that cross the tile
//! (the others are left out of every row), then each row's run of covered pixels (solved exactly
//! from those edges, no per-pixel edge test), the depth test and the pixel shader over the run,
//! eight pixels at a time; while fates are recorded, the winner's index in the id buffer.

use crate::lanes::{F8, LANES};
use crate::setup::{Edge, FIXED_ONE, Triangle};
use crate::shading::PixelShader;
use crate::target::{NO_TRIANGLE, TILE, TileRect};

const ROW: usize = TILE as usize;

/// One tile's buffers: colour, depth, and the id buffer (empty when not recorded).
pub(crate) struct TileBuffers<'a> {
    pub color: &'a mut [u32],
    pub depth: &'a mut [f32],
    pub ids: &'a mut [u32],
}

/// Clears the tile to `background`, the far plane and no triangle, then draws `bin`'s
/// triangles into it.
pub(crate) fn draw_tile<S: PixelShader>(
    rect: TileRect,
    tile: TileBuffers<'_>,
    background: u32,
    bin: &[u32],
    triangles: &[Triangle],
    shader: &S,
) {
    tile.color.fill(background);
    tile.depth.fill(1.0);
    tile.ids.fill(NO_TRIANGLE);
    let (color_rows, _) = tile.color.as_chunks_mut::<ROW>();
    let (depth_rows, _) = tile.depth.as_chunks_mut::<ROW>();
    let (id_rows, _) = tile.ids.as_chunks_mut::<ROW>();
    let mut rows = Rows {
        color: color_rows,
        depth: depth_rows,
        ids: id_rows,
    };
    for &index in bin {
        let t = &triangles[index as usize];
        draw_triangle(rect, &mut rows, index, t, shader);
    }
}

/// A tile's buffers as rows (`ids` has none when not recorded).
struct Rows<'a> {
    color: &'a mut [[u32; ROW]],
    depth: &'a mut [[f32; ROW]],
    ids: &'a mut [[u32; ROW]],
}

fn draw_triangle<S: PixelShader>(
    rect: TileRect,
    rows: &mut Rows<'_>,
    index: u32,
    t: &Triangle,
    shader: &S,
) {
    let area = TileRect {
        x0: t.bbox[0].max(rect.x0),
        y0: t.bbox[1].max(rect.y0),
        x1: t.bbox[2].min(rect.x1),
        y1: t.bbox[3].min(rect.y1),
    };
    if area.x0 > area.x1 || area.y0 > area.y1 {
        return;
    }
    let mut crossing = [Edge::default(); 3];
    let mut count = 0;
    for edge in &t.edges {
        match edge.over(area) {
            Cover::None => return,
            Cover::All => {}
            Cover::Some => {
                crossing[count] = *edge;
                count += 1;
            }
        }
    }
    for y in area.y0..=area.y1 {
        let (mut lo, mut hi) = (area.x0, area.x1);
        for edge in &crossing[..count] {
            let (a, b) = edge.span(y);
            lo = lo.max(a);
            hi = hi.min(b);
        }
        if lo <= hi {
            let row = (y - rect.y0) as usize;
            let run = Run {
                y,
                lo: lo - rect.x0,
                hi: hi - rect.x0,
                x0: rect.x0,
            };
            let ids = rows.ids.get_mut(row).map(|ids| (index, ids));
            draw_run(
                shader,
                t,
                run,
                &mut rows.color[row],
                &mut rows.depth[row],
                ids,
            );
        }
    }
}

/// How much of a rectangle of pixels lies inside an edge.
enum Cover {
    None,
    Some,
    All,
}

impl Edge {
    /// Whether the pixels of `area` are all, some or none inside this edge: the edge function
    /// is linear, so its extremes over the rectangle are at corners.
    fn over(&self, area: TileRect) -> Cover {
        let (x0, x1) = (area.x0 as i64 * FIXED_ONE, area.x1 as i64 * FIXED_ONE);
        let (y0, y1) = (area.y0 as i64 * FIXED_ONE, area.y1 as i64 * FIXED_ONE);
        let dy = (self.dcdy * y0).min(self.dcdy * y1)..=(self.dcdy * y0).max(self.dcdy * y1);
        let dx = (self.dcdx * x0).min(self.dcdx * x1)..=(self.dcdx * x0).max(self.dcdx * x1);
        // F = c + dcdy·Y − dcdx·X; inside when F > 0.
        if self.c + dy.start() - dx.end() > 0 {
            Cover::All
        } else if self.c + dy.end() - dx.start() <= 0 {
            Cover::None
        } else {
            Cover::Some
        }
    }
}

/// Pixels lo..=hi (columns within the tile) of row y; the tile starts at column x0.
#[derive(Clone, Copy)]
struct Run {
    y: i32,
    lo: i32,
    hi: i32,
    x0: i32,
}

/// The depth test and the shader over a run, eight pixels at a time. Compiled twice: for the
/// baseline x86-64 and, chosen at run time, for AVX2 and FMA.
#[inline(always)]
fn draw_run<S: PixelShader>(
    shader: &S,
    t: &Triangle,
    run: Run,
    color: &mut [u32; ROW],
    depth: &mut [f32; ROW],
    ids: Option<(u32, &mut [u32; ROW])>,
) {
    #[cfg(target_arch = "x86_64")]
    if std::arch::is_x86_feature_detected!("avx2") && std::arch::is_x86_feature_detected!("fma") {
        // SAFETY: the CPU has the features the function is compiled for, checked just above.
        unsafe { draw_run_avx2(shader, t, run, color, depth, ids) };
        return;
    }
    draw_run_portable(shader, t, run, color, depth, ids);
}

#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline(never)]
fn draw_run_avx2<S: PixelShader>(
    shader: &S,
    t: &Triangle,
    run: Run,
    color: &mut [u32; ROW],
    depth: &mut [f32; ROW],
    ids: Option<(u32, &mut [u32; ROW])>,
) {
    draw_run_portable(shader, t, run, color, depth, ids);
}

/// Works on whole groups of eight pixels of the tile's row (the row is 64 wide, so they always
/// exist), with lanes outside the run masked off: fixed-size, branch-free code is what the
/// compiler vectorises. `ids`, while fates are recorded: this triangle's index, written where
/// it passes the depth test.
#[inline(always)]
fn draw_run_portable<S: PixelShader>(
    shader: &S,
    t: &Triangle,
    run: Run,
    color: &mut [u32; ROW],
    depth: &mut [f32; ROW],
    mut ids: Option<(u32, &mut [u32; ROW])>,
) {
    let fy = run.y as f32 + 0.5;
    let z_row = t.at(&t.depth, run.x0 as f32 + 0.5, fy);
    let (color, _) = color.as_chunks_mut::<LANES>();
    let (depth, _) = depth.as_chunks_mut::<LANES>();
    let first = run.lo as usize / LANES;
    let last = run.hi as usize / LANES;
    for group in first..=last {
        let base = group * LANES;
        let lanes = F8::ramp(base as f32);
        let z = lanes.mul_add(F8::splat(t.depth.dadx), F8::splat(z_row));
        let depth = &mut depth[group];
        let mut pass = [0u32; LANES];
        for (i, (p, (z, d))) in pass
            .iter_mut()
            .zip(z.0.iter().zip(depth.iter()))
            .enumerate()
        {
            let x = (base + i) as i32;
            // `&`, not `&&`: no branch per lane.
            let passed = (x >= run.lo) & (x <= run.hi) & (z < d);
            *p = 0u32.wrapping_sub(passed as u32);
        }
        // Seen as a plain bit mask, the blends below stay blends: recognised as a selection,
        // they become masked stores, which some CPUs (AMD's) execute very slowly.
        let pass = std::hint::black_box(pass);
        for i in 0..LANES {
            depth[i] =
                f32::from_bits((z.0[i].to_bits() & pass[i]) | (depth[i].to_bits() & !pass[i]));
        }
        if pass == [0; LANES] {
            continue;
        }
        if let Some((index, ids)) = ids.as_mut() {
            let ids = &mut ids[base..base + LANES];
            for (id, p) in ids.iter_mut().zip(pass) {
                *id = (*index & p) | (*id & !p);
            }
        }
        let x = F8::ramp((run.x0 + base as i32) as f32 + 0.5);
        let shaded = shader.shade(t, x, fy);
        let color = &mut color[group];
        for (c, (s, p)) in color.iter_mut().zip(shaded.into_iter().zip(pass)) {
            *c = (s & p) | (*c & !p);
        }
    }
}

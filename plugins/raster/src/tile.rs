//! Drawing one tile: for each triangle binned there, in order, each row's run of covered pixels
//! (solved exactly from the edge functions, no per-pixel edge test), the depth test, and the
//! pixel shader for the pixels that pass.

use crate::setup::Triangle;
use crate::shading::PixelShader;
use crate::target::{TILE, TileRect};

/// Clears the tile to `background` and the far plane, then draws `bin`'s triangles into it.
pub(crate) fn draw_tile<S: PixelShader>(
    rect: TileRect,
    color: &mut [u32],
    depth: &mut [f32],
    background: u32,
    bin: &[u32],
    triangles: &[Triangle],
    shader: &S,
) {
    color.fill(background);
    depth.fill(1.0);
    for &index in bin {
        draw_triangle(rect, color, depth, &triangles[index as usize], shader);
    }
}

#[inline(always)]
fn draw_triangle<S: PixelShader>(
    rect: TileRect,
    color: &mut [u32],
    depth: &mut [f32],
    t: &Triangle,
    shader: &S,
) {
    let (x_lo, x_hi) = (t.bbox[0].max(rect.x0), t.bbox[2].min(rect.x1));
    let (y_lo, y_hi) = (t.bbox[1].max(rect.y0), t.bbox[3].min(rect.y1));
    for y in y_lo..=y_hi {
        let mut lo = x_lo;
        let mut hi = x_hi;
        for edge in &t.edges {
            let (a, b) = edge.span(y);
            lo = lo.max(a);
            hi = hi.min(b);
        }
        if lo > hi {
            continue;
        }
        let fy = y as f32 + 0.5;
        let row = ((y - rect.y0) * TILE - rect.x0) as usize;
        let z_row = t.at(&t.depth, 0.5, fy);
        for x in lo..=hi {
            let i = row + x as usize;
            let z = z_row + t.depth.dadx * x as f32;
            // The reference's test: Less, against a buffer cleared to 1.0.
            if z < depth[i] {
                depth[i] = z;
                color[i] = shader.shade(t, x as f32 + 0.5, fy);
            }
        }
    }
}

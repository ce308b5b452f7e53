// Lines and points as the triangles Close2GL's software rasterizer draws them as
// (plugins/raster/src/primitives.rs, which are lavapipe's shapes): a line as the rectangle one
// pixel wide around it (long sides half a pixel either side, short sides through its ends), a
// point as the one-pixel square centred on it, each the triangles (0, 1, 2) and (0, 2, 3) of its
// four corners. Drawn as triangles, their pixels are the triangle fill rule's on every backend,
// not each backend's own rules for line and point primitives (SwiftShader's differ). The corners
// are placed on the software rasterizer's sub-pixel grid as it places them (its end snapped, then
// the offset rounded), so that a rasterizer with as many sub-pixel bits keeps them exactly.

// The vertices of one line's or point's two triangles.
const SHAPE_VERTICES: u32 = 6u;

// Steps a pixel has on the grid: the software rasterizer's 8 sub-pixel bits.
const SUBPIXEL: f32 = 256.0;

// Which of its shape's four corners vertex `k` (0..6) of the two triangles is.
fn shape_corner(k: u32) -> u32 {
    var corners = array<u32, 6>(0u, 1u, 2u, 0u, 2u, 3u);
    return corners[k % SHAPE_VERTICES];
}

// A window position (pixels) on the grid, rounded to nearest even from the pixel's centre.
fn snapped(window: vec2<f32>) -> vec2<f32> {
    return round((window - 0.5) * SUBPIXEL) / SUBPIXEL + 0.5;
}

// Vertex `k` of the line from `a` to `b` (window pixels): whether it belongs to b's end rather
// than a's, and its position. The corners are a - t, b - t, b + t, a + t, with t half a pixel
// across the line.
struct LineCorner {
    at_b: bool,
    window: vec2<f32>,
}

fn line_corner(k: u32, a: vec2<f32>, b: vec2<f32>) -> LineCorner {
    let d = a - b;
    // A line of no length has no across: its corners coincide and cover no pixel.
    let across = round(vec2<f32>(-d.y, d.x) * (0.5 / max(length(d), 1e-30)) * SUBPIXEL) / SUBPIXEL;
    let corner = shape_corner(k);
    let at_b = corner == 1u || corner == 2u;
    return LineCorner(at_b, snapped(select(a, b, at_b)) + select(-across, across, corner >= 2u));
}

// Vertex `k`'s position in the square of the point at `window`. The software rasterizer's
// square, centred on the snapped point s, covers the one pixel whose centre c has
// s - 0.5 <= c < s + 0.5 each way (the top-left rule); the square drawn here is that pixel's
// own cell, whose edges lie half a pixel from every centre, so that a rasterizer with fewer
// sub-pixel bits (SwiftShader snaps to 1/16) covers the same pixel.
fn point_corner(k: u32, window: vec2<f32>) -> vec2<f32> {
    let corner = shape_corner(k);
    let right = corner == 1u || corner == 2u;
    let cell = ceil(snapped(window) - 1.0);
    return cell + vec2<f32>(select(0.0, 1.0, right), select(0.0, 1.0, corner >= 2u));
}

// Lines and points as the triangles Close2GL's software rasterizer draws them as
// (plugins/raster/src/primitives.rs, which are lavapipe's shapes): a line as the rectangle one
// pixel wide around it (long sides half a pixel either side, short sides through its ends), a
// point as the one-pixel square centred on it, each the triangles (0, 1, 2) and (0, 2, 3) of its
// four corners. Drawn as triangles, their pixels are the triangle fill rule's on every backend,
// not each backend's own rules for line and point primitives (SwiftShader's differ).
//
// A rasterizer with fewer sub-pixel bits than the software's 8 (SwiftShader snaps to 1/16 pixel)
// would move a line's corners and change the pixels whose centres lie that close to its sides.
// So a line's rectangle is drawn MARGIN wider and longer on every side, and its fragment shader
// keeps only the fragments the software rasterizer draws (`line_covers`): the exact rectangle
// (`ExactLine`, its corners on the software's grid as it places them) tested at the pixel's
// centre with the software's own edge functions, in exact integer arithmetic.

// The vertices of one line's or point's two triangles.
const SHAPE_VERTICES: u32 = 6u;

// Steps a pixel has on the grid: the software rasterizer's 8 sub-pixel bits.
const SUBPIXEL: f32 = 256.0;

// How far (pixels) a line's drawn rectangle reaches beyond its exact one: more than the 1/32
// pixel a rasterizer with 4 sub-pixel bits may move a corner by each way, so that it loses no
// centre of the exact rectangle.
const MARGIN: f32 = 0.125;

// The software rasterizer's guard band (edge.rs's GUARD_PX, 2^21 pixels) on the grid: fixed-point
// positions within it keep every difference below 2^30.
const GUARD: f32 = 536870912.0;

// Which of its shape's four corners vertex `k` (0..6) of the two triangles is.
fn shape_corner(k: u32) -> u32 {
    var corners = array<u32, 6>(0u, 1u, 2u, 0u, 2u, 3u);
    return corners[k % SHAPE_VERTICES];
}

// A window position (pixels) on the grid, rounded to nearest even from the pixel's centre.
fn snapped(window: vec2<f32>) -> vec2<f32> {
    return round((window - 0.5) * SUBPIXEL) / SUBPIXEL + 0.5;
}

// The same position in the software's fixed point, where pixel (x, y)'s centre is (256x, 256y).
fn fixed(window: vec2<f32>) -> vec2<i32> {
    return vec2<i32>(clamp(round((window - 0.5) * SUBPIXEL), vec2<f32>(-GUARD), vec2<f32>(GUARD)));
}

// A line's rectangle as the software rasterizer sets it up, in fixed point: the corners
// ends.xy - across, ends.zw - across, ends.zw + across, ends.xy + across.
struct ExactLine {
    ends: vec4<i32>,
    across: vec2<i32>,
}

// Vertex `k` of the line from `a` to `b` (window pixels): whether it belongs to b's end rather
// than a's, its exact corner (a - t, b - t, b + t, a + t, with t half a pixel across the line,
// the end snapped, then t rounded, as the software does), the drawn corner's offsets from it
// across the line (along t) and along it (away from the other end), and the exact rectangle.
struct LineCorner {
    at_b: bool,
    window: vec2<f32>,
    wider: vec2<f32>,
    longer: vec2<f32>,
    line: ExactLine,
}

fn line_corner(k: u32, a: vec2<f32>, b: vec2<f32>) -> LineCorner {
    let d = a - b;
    let scale = 1.0 / max(length(d), 1e-30);
    // A line of no length has no across: its corners coincide and cover no pixel.
    let across = round(vec2<f32>(-d.y, d.x) * (0.5 * scale) * SUBPIXEL);
    let corner = shape_corner(k);
    let at_b = corner == 1u || corner == 2u;
    let side = select(-1.0, 1.0, corner >= 2u);
    return LineCorner(
        at_b,
        snapped(select(a, b, at_b)) + side * across / SUBPIXEL,
        side * across * (MARGIN / max(length(across), 1.0)),
        select(d, -d, at_b) * (MARGIN * scale),
        ExactLine(vec4<i32>(fixed(a), fixed(b)), vec2<i32>(across)),
    );
}

// A vertex's window position (y down, as the software's window) as a varying whose value at a
// fragment gives the fragment's own (`line_covers`), whatever viewport origin the pass draws at
// (@builtin(position) counts from the framebuffer's): the position times the vertex's clip w,
// and w, interpolated perspective-correct (WebGL2 has no noperspective); their quotient is
// linear in the window.
fn window_varying(clip: vec4<f32>, size: vec2<f32>) -> vec3<f32> {
    return vec3<f32>(vec2<f32>(clip.w + clip.x, clip.w - clip.y) * 0.5 * size, clip.w);
}

// Whether the software rasterizer draws, for `line`, the pixel whose centre's `window_varying`
// is `window`: inside either of its two triangles.
fn line_covers(line: ExactLine, window: vec3<f32>) -> bool {
    let s = vec2<i32>(floor(window.xy / window.z)) * 256;
    let a = line.ends.xy;
    let b = line.ends.zw;
    let t = line.across;
    return triangle_covers(a - t, b - t, b + t, s) || triangle_covers(a - t, b + t, a + t, s);
}

// Whether the triangle (p, q, r) covers the sample s, as the software's setup and edge functions
// decide (setup.rs, edge.rs): none when it has no area; otherwise wound so that its area is
// positive, and s inside all three edges, the top-left rule deciding a sample exactly on one.
fn triangle_covers(p: vec2<i32>, q: vec2<i32>, r: vec2<i32>, s: vec2<i32>) -> bool {
    let area = wide_sign(edge(p, q, r));
    let swap = area < 0;
    let q2 = select(q, r, swap);
    let r2 = select(r, q, swap);
    return area != 0 && inside(p, q2, s) && inside(q2, r2, s) && inside(r2, p, s);
}

// Whether the sample s is inside the edge from p to q (its edge function with the fill rule's
// bias, 1 for a left or a horizontal top edge, is positive).
fn inside(p: vec2<i32>, q: vec2<i32>, s: vec2<i32>) -> bool {
    let dcdx = p.y - q.y;
    let dcdy = p.x - q.x;
    let f = wide_sign(edge(p, q, s));
    return f > 0 || (f == 0 && (dcdx < 0 || (dcdx == 0 && dcdy > 0)));
}

// The edge function from p to q at s without the bias, dcdx·(p.x − s.x) − dcdy·(p.y − s.y): as
// a 64-bit integer, since products of differences up to 2^30 overflow i32 and f32 is not exact.
fn edge(p: vec2<i32>, q: vec2<i32>, s: vec2<i32>) -> vec2<u32> {
    let m = wide_product(p.y - q.y, p.x - s.x);
    let n = wide_product(p.x - q.x, p.y - s.y);
    return vec2<u32>(m.x - n.x, m.y - n.y - select(0u, 1u, m.x < n.x));
}

// a·b exactly, for |a|, |b| < 2^31: a 64-bit two's complement integer, x its low word and y its
// high word, from the four products of 16-bit halves.
fn wide_product(a: i32, b: i32) -> vec2<u32> {
    let x = u32(abs(a));
    let y = u32(abs(b));
    let low = (x & 0xffffu) * (y & 0xffffu);
    let mid = vec2<u32>((x >> 16u) * (y & 0xffffu), (x & 0xffffu) * (y >> 16u));
    let carry = (low >> 16u) + (mid.x & 0xffffu) + (mid.y & 0xffffu);
    let high = (x >> 16u) * (y >> 16u) + (mid.x >> 16u) + (mid.y >> 16u) + (carry >> 16u);
    let m = vec2<u32>((low & 0xffffu) | (carry << 16u), high);
    if (a < 0) == (b < 0) {
        return m;
    }
    let negated = ~m.x + 1u;
    return vec2<u32>(negated, ~m.y + select(0u, 1u, negated == 0u));
}

// The sign of a 64-bit integer (x: low word, y: high word).
fn wide_sign(v: vec2<u32>) -> i32 {
    if bitcast<i32>(v.y) < 0 {
        return -1;
    }
    return select(0, 1, any(v != vec2<u32>(0u)));
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

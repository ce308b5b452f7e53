// One triangle that covers the viewport, for the views that show an image one texel per pixel
// (the software rasterizer's, the live difference). Each such shader is this file followed by
// its own fragment stage.

struct Varyings {
    @builtin(position) position: vec4<f32>,
    // 0..1 across the viewport, y down.
    @location(0) uv: vec2<f32>,
}

@vertex
fn vs_main(@builtin(vertex_index) i: u32) -> Varyings {
    // (-1, 1), (3, 1), (-1, -3): one triangle whose middle is the whole viewport.
    let corner = vec2<f32>(f32(i == 1u) * 4.0 - 1.0, 1.0 - f32(i == 2u) * 4.0);
    var out: Varyings;
    out.position = vec4<f32>(corner, 0.0, 1.0);
    out.uv = vec2<f32>(corner.x + 1.0, 1.0 - corner.y) * 0.5;
    return out;
}

// The texel of a `size` image under this fragment.
fn texel_at(uv: vec2<f32>, size: vec2<u32>) -> vec2<u32> {
    return min(vec2<u32>(uv * vec2<f32>(size)), size - 1u);
}

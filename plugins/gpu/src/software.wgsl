// The Close2GL view with the software rasterizer: its image, one texel per pixel, drawn as one
// triangle that covers the viewport. textureLoad, not a sampler: no filtering, no rounding, the
// bytes Close2GL wrote are the bytes on screen.

@group(0) @binding(0) var image: texture_2d<f32>;

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

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    let size = vec2<f32>(textureDimensions(image));
    let texel = min(vec2<u32>(in.uv * size), textureDimensions(image) - 1u);
    return textureLoad(image, texel, 0);
}

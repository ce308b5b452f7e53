// The Close2GL view: the 2D buffer is already in window pixels (origin top-left, y down), so the
// GPU only maps pixels to normalised device coordinates and fills with one colour. No 3D
// transform, no depth, no culling: Close2GL did all of that.

struct Frame {
    // The viewport the pixels were computed for.
    size: vec2<f32>,
    color: vec4<f32>,
}

@group(0) @binding(0) var<uniform> frame: Frame;

@vertex
fn vs_main(@location(0) pixel: vec2<f32>) -> @builtin(position) vec4<f32> {
    let ndc = vec2<f32>(pixel.x / frame.size.x * 2.0 - 1.0, 1.0 - pixel.y / frame.size.y * 2.0);
    return vec4<f32>(ndc, 0.0, 1.0);
}

@fragment
fn fs_main() -> @location(0) vec4<f32> {
    return vec4<f32>(frame.color.rgb, 1.0);
}

// The Close2GL view: the 2D buffer is already in window pixels (origin top-left, y down), so the
// GPU only maps pixels to normalised device coordinates and fills with one colour. No 3D
// transform, no depth, no culling: Close2GL did all of that. Where the device lacks the
// polygon-mode features, lines and points are drawn as the software rasterizer's one-pixel
// rectangles and squares (`pixel_shapes.wgsl`), one instance each, as the reference draws them
// there, so that both views' pixels follow the same triangle rules; a line's rectangle drawn a
// little larger, its fragments kept where the software's exact rectangle covers their centres.

struct Frame {
    // The viewport the pixels were computed for.
    size: vec2<f32>,
    color: vec4<f32>,
}

@group(0) @binding(0) var<uniform> frame: Frame;

fn to_clip(pixel: vec2<f32>) -> vec4<f32> {
    let ndc = vec2<f32>(pixel.x / frame.size.x * 2.0 - 1.0, 1.0 - pixel.y / frame.size.y * 2.0);
    return vec4<f32>(ndc, 0.0, 1.0);
}

@vertex
fn vs_main(@location(0) pixel: vec2<f32>) -> @builtin(position) vec4<f32> {
    return to_clip(pixel);
}

// A fragment of a line's rectangle, and the exact rectangle (`ExactLine`), the same at every
// corner.
struct LineFragment {
    @builtin(position) position: vec4<f32>,
    @location(0) @interpolate(flat) ends: vec4<i32>,
    @location(1) @interpolate(flat) across: vec2<i32>,
    @location(2) window: vec3<f32>,
}

// Vertex `k` of the rectangle of the line from `a` to `b` (an instance), drawn larger.
@vertex
fn vs_line(
    @builtin(vertex_index) k: u32,
    @location(0) a: vec2<f32>,
    @location(1) b: vec2<f32>,
) -> LineFragment {
    let corner = line_corner(k, a, b);
    let clip = to_clip(corner.window + corner.wider + corner.longer);
    let window = window_varying(clip, frame.size);
    return LineFragment(clip, corner.line.ends, corner.line.across, window);
}

@fragment
fn fs_line(in: LineFragment) -> @location(0) vec4<f32> {
    if !line_covers(ExactLine(in.ends, in.across), in.window) {
        discard;
    }
    return vec4<f32>(frame.color.rgb, 1.0);
}

// Vertex `k` of the square of the point at `pixel` (an instance).
@vertex
fn vs_point(@builtin(vertex_index) k: u32, @location(0) pixel: vec2<f32>) -> @builtin(position) vec4<f32> {
    return to_clip(point_corner(k, pixel));
}

@fragment
fn fs_main() -> @location(0) vec4<f32> {
    return vec4<f32>(frame.color.rgb, 1.0);
}

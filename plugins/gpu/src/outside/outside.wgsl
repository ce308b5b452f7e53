// The outside view: the model, the Close2GL camera's view volume and its gizmo, already placed
// at the stage by the CPU (close2gl_pipeline::morph), seen by the outside view's own camera.
// Each vertex carries its clip coordinates P·M·p, multiplied by a weight k (1 in world and eye
// space; towards 1/w in NDC, where the drawn space is the divided one and clip coordinates are
// interpolated as clip/w and 1/w), so that each fragment can test |x|, |y|, |z| <= w exactly.

struct Frame {
    view_projection: mat4x4<f32>,
    // The outside camera's position, in drawn coordinates.
    eye: vec4<f32>,
}

@group(0) @binding(0) var<uniform> frame: Frame;

struct VertexIn {
    @location(0) position: vec3<f32>,
    // clip * k
    @location(1) clip: vec4<f32>,
    // x: k; y: 1 when the vertex is at or behind the eye and divided (the warning)
    @location(2) weight_warn: vec2<f32>,
    @location(3) color: vec4<f32>,
}

struct VertexOut {
    @builtin(position) position: vec4<f32>,
    @location(0) drawn: vec3<f32>,
    @location(1) clip: vec4<f32>,
    @location(2) weight_warn: vec2<f32>,
    @location(3) color: vec4<f32>,
}

// What the division does to a point behind the eye: one colour no fate uses.
const WARNING: vec3<f32> = vec3<f32>(1.0, 0.0, 1.0);
// How much of its colour a fragment outside the view volume keeps.
const DIMMED: f32 = 0.3;

@vertex
fn vs_main(v: VertexIn) -> VertexOut {
    var out: VertexOut;
    out.position = frame.view_projection * vec4<f32>(v.position, 1.0);
    out.drawn = v.position;
    out.clip = v.clip;
    out.weight_warn = v.weight_warn;
    out.color = v.color;
    return out;
}

// The model: flat-shaded from the drawn surface's own slope (so it shades right at every stage,
// where no normal survives the division), lit from the outside camera on both faces, dimmed
// outside the view volume, tinted where the division threw it from behind the eye.
@fragment
fn fs_mesh(v: VertexOut) -> @location(0) vec4<f32> {
    let normal = normalize(cross(dpdx(v.drawn), dpdy(v.drawn)));
    let to_eye = normalize(frame.eye.xyz - v.drawn);
    let light = 0.35 + 0.65 * abs(dot(normal, to_eye));
    let clip = v.clip / v.weight_warn.x;
    let inside = all(abs(clip.xyz) <= vec3<f32>(clip.w));
    var color = v.color.rgb * light;
    if !inside {
        color = color * DIMMED;
    }
    color = mix(color, WARNING * light, clamp(v.weight_warn.y, 0.0, 1.0));
    return vec4<f32>(color, 1.0);
}

// Lines and the translucent planes: their own colour, the warning where divided from behind.
@fragment
fn fs_flat(v: VertexOut) -> @location(0) vec4<f32> {
    let color = mix(v.color.rgb, WARNING, clamp(v.weight_warn.y, 0.0, 1.0));
    return vec4<f32>(color, v.color.a);
}

// The reference probe's ID pass: the reference's geometry (same clip coordinates, culling and
// depth test), but each fragment writes its mesh triangle's index + 1 (0 is the background) and
// its depth instead of a colour.

struct Uniforms {
    // clip <- world, relative to the mesh's origin as the reference draws it.
    view_projection: mat4x4<f32>,
    // xy: the target's size in pixels, which lines and points drawn face by face are measured in.
    viewport: vec4<f32>,
}

@group(0) @binding(0) var<uniform> u: Uniforms;

struct Varyings {
    @builtin(position) clip: vec4<f32>,
    // The same on all three corners, so which corner provokes it does not matter.
    @location(0) @interpolate(flat) triangle: u32,
    // A line drawn without polygon modes: its exact rectangle (`fragment_kept`).
    @location(1) @interpolate(flat) line_ends: vec4<i32>,
    @location(2) @interpolate(flat) line_across: vec2<i32>,
    @location(3) window: vec3<f32>,
}

struct Probe {
    @location(0) id: u32,
    @location(1) depth: f32,
}

// One face an instance: drawn as a triangle (3 vertices, culled by the hardware), or without
// polygon modes as its edges' rectangles or its points' squares, culled here (kept_faces.wgsl).
struct Face {
    @location(0) p0: vec3<f32>,
    @location(1) p1: vec3<f32>,
    @location(2) p2: vec3<f32>,
    @location(3) triangle: u32,
}

@vertex
fn vs_main(@builtin(vertex_index) index: u32, face: Face) -> Varyings {
    let clips = array<vec4<f32>, 3>(
        u.view_projection * vec4<f32>(face.p0, 1.0),
        u.view_projection * vec4<f32>(face.p1, 1.0),
        u.view_projection * vec4<f32>(face.p2, 1.0),
    );
    let v = face_vertex(index, clips, u.viewport.xy);
    var out: Varyings;
    out.clip = face_clip(v, clips);
    out.triangle = face.triangle;
    out.line_ends = v.line.ends;
    out.line_across = v.line.across;
    out.window = window_varying(out.clip, u.viewport.xy);
    return out;
}

// Lines drawn without polygon modes keep the fragments the reference keeps.
@fragment
fn fs_main(in: Varyings) -> Probe {
    if !fragment_kept(in.line_ends, in.line_across, in.window) {
        discard;
    }
    return Probe(in.triangle + 1u, in.clip.z);
}

// The reference probe's ID pass: the reference's geometry (same clip coordinates, culling and
// depth test), but each fragment writes its mesh triangle's index + 1 (0 is the background) and
// its depth instead of a colour.

struct Uniforms {
    // clip <- world, relative to the mesh's origin as the reference draws it.
    view_projection: mat4x4<f32>,
}

@group(0) @binding(0) var<uniform> u: Uniforms;

struct Varyings {
    @builtin(position) clip: vec4<f32>,
    // The same on all three corners, so which corner provokes it does not matter.
    @location(0) @interpolate(flat) triangle: u32,
}

struct Probe {
    @location(0) id: u32,
    @location(1) depth: f32,
}

@vertex
fn vs_main(@location(0) position: vec3<f32>, @location(1) triangle: u32) -> Varyings {
    var out: Varyings;
    out.clip = u.view_projection * vec4<f32>(position, 1.0);
    out.triangle = triangle;
    return out;
}

@fragment
fn fs_main(in: Varyings) -> Probe {
    return Probe(in.triangle + 1u, in.clip.z);
}

// The reference renderer: one source for every shading mode. The mode is chosen by the
// pipeline-overridable constants below, not by a branch: each mode gets its own pipeline built
// from this source, the compiler folds the unused terms away, and no fragment pays for a mode it
// is not in (nor for a uniform-controlled branch).

// 1: light at the vertices and interpolate the intensity (Gouraud).
override GOURAUD: f32 = 0.0;
// 1: interpolate the normal and light every fragment (Phong).
override PHONG: f32 = 0.0;
// 0: ambient + diffuse only (Gouraud AD); 1: with the specular term.
override SPECULAR: f32 = 1.0;

struct Uniforms {
    // clip <- world (the model matrix is the identity: world coordinates are the file's).
    view_projection: mat4x4<f32>,
    // eye <- world, and its inverse transpose for the normals.
    modelview: mat4x4<f32>,
    normal_matrix: mat4x4<f32>,
    // The light's position in eye space.
    light: vec4<f32>,
    // Ia * ka.
    ambient: vec4<f32>,
    // Il.
    intensity: vec4<f32>,
    // The user's colour.
    color: vec4<f32>,
    // kd, ks, shininess.
    material: vec4<f32>,
    // c0, c1, c2 of f_att = min(1 / (c0 + c1 d + c2 d^2), 1).
    attenuation: vec4<f32>,
    // x: 1 when the texture modulates the colour (texturing on, the mesh has coordinates), else 0.
    texturing: vec4<f32>,
    // xy: the target's size in pixels, which lines and points drawn face by face are measured in.
    viewport: vec4<f32>,
}

@group(0) @binding(0) var<uniform> u: Uniforms;
@group(0) @binding(1) var tex: texture_2d<f32>;
// Nearest, bilinear or trilinear: the filter is the bind group's, chosen by the host.
@group(0) @binding(2) var samp: sampler;

struct Varyings {
    @builtin(position) clip: vec4<f32>,
    @location(0) eye: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) gouraud: vec3<f32>,
    // Perspective-correct, as every @location varying is by default.
    @location(3) uv: vec2<f32>,
    // 1 on a front face drawn as lines or points without polygon modes (where the builtin
    // front_facing is their shapes' own), 0 on a back one; 1 elsewhere.
    @location(4) @interpolate(flat) front: f32,
    // A line drawn without polygon modes: its exact rectangle (`ExactLine`), outside which its
    // fragments are discarded (`fragment_kept`); zero elsewhere.
    @location(5) @interpolate(flat) line_ends: vec4<i32>,
    @location(6) @interpolate(flat) line_across: vec2<i32>,
    // Its fragment's window position (`window_varying`).
    @location(7) window: vec3<f32>,
}

fn drawn(in: Varyings) -> bool {
    return fragment_kept(in.line_ends, in.line_across, in.window);
}

// Normalises without producing NaN for a zero vector (a degenerate normal, a light on a vertex).
fn safe_normalize(x: vec3<f32>) -> vec3<f32> {
    return x * inverseSqrt(max(dot(x, x), 1e-30));
}

// I = Ia ka + f_att Il (kd max(N.L, 0) + ks max(V.R, 0)^n), in eye space.
fn illumination(eye: vec3<f32>, normal: vec3<f32>) -> vec3<f32> {
    let n = safe_normalize(normal);
    let to_light = u.light.xyz - eye;
    let d = length(to_light);
    let l = safe_normalize(to_light);
    let v = safe_normalize(-eye);
    let r = reflect(-l, n);
    let c = u.attenuation;
    let f_att = min(1.0 / (c.x + c.y * d + c.z * d * d), 1.0);
    let diffuse = u.material.x * max(dot(n, l), 0.0);
    let specular = SPECULAR * u.material.y * pow(max(dot(v, r), 1e-20), u.material.z);
    return u.ambient.rgb + f_att * u.intensity.rgb * (diffuse + specular);
}

@vertex
fn vs_main(
    @location(0) position: vec3<f32>,
    @location(1) normal: vec3<f32>,
    @location(2) uv: vec2<f32>,
) -> Varyings {
    return shade_vertex(position, normal, uv);
}

// One face (an instance) drawn as lines or points, without polygon modes (kept_faces.wgsl): its
// edges' rectangles or its points' squares, as triangles.
struct Face {
    @location(0) p0: vec3<f32>,
    @location(1) n0: vec3<f32>,
    @location(2) uv0: vec2<f32>,
    @location(3) p1: vec3<f32>,
    @location(4) n1: vec3<f32>,
    @location(5) uv1: vec2<f32>,
    @location(6) p2: vec3<f32>,
    @location(7) n2: vec3<f32>,
    @location(8) uv2: vec2<f32>,
}

@vertex
fn vs_face(@builtin(vertex_index) index: u32, face: Face) -> Varyings {
    var positions = array<vec3<f32>, 3>(face.p0, face.p1, face.p2);
    var normals = array<vec3<f32>, 3>(face.n0, face.n1, face.n2);
    var uvs = array<vec2<f32>, 3>(face.uv0, face.uv1, face.uv2);
    let clips = array<vec4<f32>, 3>(
        u.view_projection * vec4<f32>(face.p0, 1.0),
        u.view_projection * vec4<f32>(face.p1, 1.0),
        u.view_projection * vec4<f32>(face.p2, 1.0),
    );
    let v = face_vertex(index, clips, u.viewport.xy);
    let p = v.point;
    let first = shade_vertex(positions[p.i], normals[p.i], uvs[p.i]);
    var out = mix_varyings(first, shade_vertex(positions[p.j], normals[p.j], uvs[p.j]), p.t);
    out.front = select(0.0, 1.0, faces_front(clips[0], clips[1], clips[2]));
    out.clip = face_clip(v, clips);
    out.line_ends = v.line.ends;
    out.line_across = v.line.across;
    out.window = window_varying(out.clip, u.viewport.xy);
    return out;
}

// x and y mixed at t, as clipping interpolates a new vertex's varyings (linearly in clip space).
fn mix_varyings(x: Varyings, y: Varyings, t: f32) -> Varyings {
    var out = x;
    out.clip = mix(x.clip, y.clip, t);
    out.eye = mix(x.eye, y.eye, t);
    out.normal = mix(x.normal, y.normal, t);
    out.gouraud = mix(x.gouraud, y.gouraud, t);
    out.uv = mix(x.uv, y.uv, t);
    return out;
}

fn shade_vertex(position: vec3<f32>, normal: vec3<f32>, uv: vec2<f32>) -> Varyings {
    let world = vec4<f32>(position, 1.0);
    let eye = (u.modelview * world).xyz;
    let n = (u.normal_matrix * vec4<f32>(normal, 0.0)).xyz;
    var out: Varyings;
    out.clip = u.view_projection * world;
    out.eye = eye;
    out.normal = n;
    out.gouraud = GOURAUD * illumination(eye, n);
    out.uv = uv;
    out.front = 1.0;
    return out;
}

@fragment
fn fs_main(in: Varyings) -> @location(0) vec4<f32> {
    // lit is 0 for flat colour, 1 for any lighting: the colour is the user's times the light.
    let lit = GOURAUD + PHONG;
    let light = in.gouraud + PHONG * illumination(in.eye, in.normal);
    // Sampled whatever the flag says: textureSample needs uniform control flow (its implicit
    // derivatives pick the mip level). t grows upwards as in OpenGL, the texture's rows downwards.
    let texel = textureSample(tex, samp, vec2<f32>(in.uv.x, 1.0 - in.uv.y)).rgb;
    let modulation = mix(vec3<f32>(1.0), texel, u.texturing.x);
    // Discarded after the sampling, which needs uniform control flow.
    if !drawn(in) {
        discard;
    }
    return vec4<f32>(u.color.rgb * mix(vec3<f32>(1.0), light, lit) * modulation, 1.0);
}

// The inspector's overlays: what the GPU itself answers, drawn over the shaded reference with the
// same vertex stage (so the same fragments). Colours are FateKind's legend, packed 0x00BBGGRR.
override FRONT_COLOR: u32 = 0u;
override BACK_COLOR: u32 = 0u;
override FAILED_COLOR: u32 = 0u;

// Facing as the rasterizer decided it, on the fragments that won the depth test; for lines and
// points drawn face by face, as the vertex shader found it (their shapes' triangles face
// whichever way their corners' order makes them, not the face's way).
@fragment
fn fs_facing(in: Varyings, @builtin(front_facing) front: bool) -> @location(0) vec4<f32> {
    if !drawn(in) {
        discard;
    }
    let facing = select(front, in.front > 0.5, SHAPES);
    let color = select(BACK_COLOR, FRONT_COLOR, facing);
    return vec4<f32>(unpack4x8unorm(color).rgb, 0.6);
}

// Fragments the depth test rejected (drawn with the test reversed): more layers, more colour.
@fragment
fn fs_depth_failed(in: Varyings) -> @location(0) vec4<f32> {
    if !drawn(in) {
        discard;
    }
    return vec4<f32>(unpack4x8unorm(FAILED_COLOR).rgb, 0.35);
}

// glPolygonMode's lines and points where the adapter has no polygon modes: each face is one
// instance carrying its three corners. Its lines (3 edges) or points (6, see `face_point`) are
// drawn as one-pixel rectangles and squares of two triangles each (`pixel_shapes.wgsl`, so
// SHAPE_VERTICES vertices a line or point), and culling is decided here from the three clip
// positions, as the hardware decides it for a filled face (the shapes themselves are not culled).

// 1: lines or points drawn as shapes; 0: the face as a triangle (the ID pass with polygon modes).
override SHAPES: bool = false;
// 1: lines; 0: points.
override EDGES: bool = false;
// 1: glCullFace(GL_BACK) is on.
override CULL_BACK: bool = false;
// 1: glFrontFace(GL_CW).
override CLOCKWISE: bool = false;

// A point of a face that a line ends at or a point is drawn at: corner i mixed with corner j at
// t (t = 0: corner i). `near`: it lies on the near plane; `kept`: false where there is no such
// point (nor its line).
struct FacePoint {
    i: u32,
    j: u32,
    t: f32,
    near: bool,
    kept: bool,
}

// Vertex `index` of a face's instance: the face's point it belongs to, and its offset from that
// point in normalised device coordinates (to its corner of the rectangle or square).
struct FaceVertex {
    point: FacePoint,
    offset: vec2<f32>,
}

// Vertex `index` of the face with clip positions `clips`, drawn into a target of `size` pixels.
// Lines: the rectangles of edges 0-1, 1-2, 2-0; points: the squares of `face_point`'s points;
// a triangle: its corners.
fn face_vertex(index: u32, clips: array<vec4<f32>, 3>, size: vec2<f32>) -> FaceVertex {
    if !SHAPES {
        return FaceVertex(FacePoint(index, index, 0.0, false, true), vec2<f32>(0.0));
    }
    let shape = index / SHAPE_VERTICES;
    let k = index % SHAPE_VERTICES;
    let to_ndc = vec2<f32>(2.0, -2.0) / size;
    if !EDGES {
        let point = face_point(shape, clips);
        let at = window(point_clip(point, clips), size);
        return FaceVertex(point, (point_corner(k, at) - at) * to_ndc);
    }
    let a = edge_end(shape, (shape + 1u) % 3u, clips);
    let b = edge_end((shape + 1u) % 3u, shape, clips);
    let ends = array<vec2<f32>, 2>(window(point_clip(a, clips), size), window(point_clip(b, clips), size));
    let corner = line_corner(k, ends[0], ends[1]);
    if corner.at_b {
        return FaceVertex(b, (corner.window - ends[1]) * to_ndc);
    }
    return FaceVertex(a, (corner.window - ends[0]) * to_ndc);
}

// Points 0, 1, 2: the corners (those in front of the near plane); 3, 4, 5: where edges 0-1,
// 1-2, 2-0 cross the near plane (clip z = 0): the corners clipping gives the face there, which
// glPolygonMode(GL_POINT) draws too, as the hardware's polygon mode and Close2GL do.
fn face_point(index: u32, clips: array<vec4<f32>, 3>) -> FacePoint {
    var z = array<f32, 3>(clips[0].z, clips[1].z, clips[2].z);
    if index < 3u {
        return FacePoint(index, index, 0.0, false, z[index] >= 0.0);
    }
    let i = index - 3u;
    let j = (i + 1u) % 3u;
    let crosses = (z[i] < 0.0) != (z[j] < 0.0);
    let t = select(0.0, z[i] / (z[i] - z[j]), crosses);
    return FacePoint(i, j, t, true, crosses);
}

// The end at corner i of the edge from corner i to corner j, cut at the near plane (clip z = 0;
// wgpu's depth range is 0..w) when i is behind it; not kept when both are.
fn edge_end(i: u32, j: u32, clips: array<vec4<f32>, 3>) -> FacePoint {
    var z = array<f32, 3>(clips[0].z, clips[1].z, clips[2].z);
    if z[i] >= 0.0 {
        return FacePoint(i, i, 0.0, false, true);
    }
    return FacePoint(i, j, z[i] / (z[i] - z[j]), true, z[j] >= 0.0);
}

// The clip position of `p`.
fn point_clip(p: FacePoint, clips: array<vec4<f32>, 3>) -> vec4<f32> {
    var c = clips;
    var clip = mix(c[p.i], c[p.j], p.t);
    if p.near {
        // Exactly on the plane, as clipping puts it, not a rounding error behind it.
        clip.z = 0.0;
    }
    return clip;
}

// Window pixels (origin top-left, y down) of a clip position in front of the eye.
fn window(clip: vec4<f32>, size: vec2<f32>) -> vec2<f32> {
    let ndc = clip.xy / clip.w;
    return vec2<f32>(ndc.x + 1.0, 1.0 - ndc.y) * 0.5 * size;
}

// The clip position of `v`: its point moved by its offset times w (so that depth and varyings
// stay those of the point, perspective-correct), or outside the view volume (`CLIPPED`) where
// there is no such point or culling removes the face, so that it is clipped away.
fn face_clip(v: FaceVertex, clips: array<vec4<f32>, 3>) -> vec4<f32> {
    if !v.point.kept || culled(clips[0], clips[1], clips[2]) {
        return CLIPPED;
    }
    let clip = point_clip(v.point, clips);
    return vec4<f32>(clip.xy + v.offset * clip.w, clip.zw);
}

// Whether the face with clip positions a, b, c is front-facing. det[a.xyw; b.xyw; c.xyw] is
// w_a w_b w_c times twice the face's signed area in normalized device coordinates, and its sign
// is that of the part of the face in front of the eye (w > 0) even when the near plane cuts the
// face: the facing the hardware finds after clipping.
fn faces_front(a: vec4<f32>, b: vec4<f32>, c: vec4<f32>) -> bool {
    let det = dot(cross(a.xyw, b.xyw), c.xyw);
    return select(det > 0.0, det < 0.0, CLOCKWISE);
}

// Whether culling removes the face.
fn culled(a: vec4<f32>, b: vec4<f32>, c: vec4<f32>) -> bool {
    return CULL_BACK && !faces_front(a, b, c);
}

const CLIPPED: vec4<f32> = vec4<f32>(2.0, 2.0, 2.0, 1.0);

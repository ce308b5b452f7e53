// glPolygonMode's lines and points where the adapter has no polygon modes: each face is one
// instance carrying its three corners. Its lines (3 edges) or points (6, see `face_point`) are
// drawn as one-pixel rectangles and squares of two triangles each (`pixel_shapes.wgsl`, so
// SHAPE_VERTICES vertices a line or point; a line's rectangle drawn larger, its fragments kept
// by `line_covers`), and culling is decided here from the three clip positions, as the hardware
// decides it for a filled face (the shapes themselves are not culled).

// 1: lines or points drawn as shapes; 0: the face as a triangle (the ID pass with polygon modes).
override SHAPES: bool = false;
// 1: lines; 0: points.
override EDGES: bool = false;
// 1: glCullFace(GL_BACK) is on.
override CULL_BACK: bool = false;
// 1: glFrontFace(GL_CW).
override CLOCKWISE: bool = false;

// A point of a face that a line ends at or a point is drawn at: corner i mixed with corner j at
// t (t = 0: corner i). `near`, `far`: it lies on that plane (a line's end clipping cut there);
// `kept`: false where there is no such point (nor its line).
struct FacePoint {
    i: u32,
    j: u32,
    t: f32,
    near: bool,
    far: bool,
    kept: bool,
}

// Vertex `index` of a face's instance: the face's point it belongs to, its offset from that
// point in normalised device coordinates (to its corner of the rectangle or square), and for a
// line the exact rectangle its fragments are kept in (`line_covers`; zero otherwise).
struct FaceVertex {
    point: FacePoint,
    offset: vec2<f32>,
    line: ExactLine,
}

// Vertex `index` of the face with clip positions `clips`, drawn into a target of `size` pixels.
// Lines: the rectangles of edges 0-1, 1-2, 2-0; points: the squares of `face_point`'s points;
// a triangle: its corners.
fn face_vertex(index: u32, clips: array<vec4<f32>, 3>, size: vec2<f32>) -> FaceVertex {
    let none = ExactLine(vec4<i32>(0), vec2<i32>(0));
    if !SHAPES {
        return FaceVertex(FacePoint(index, index, 0.0, false, false, true), vec2<f32>(0.0), none);
    }
    let shape = index / SHAPE_VERTICES;
    let k = index % SHAPE_VERTICES;
    if !EDGES {
        let point = face_point(shape, clips);
        let at = window(point_clip(point, clips), size);
        return FaceVertex(point, (point_corner(k, at) - at) * to_ndc(size), none);
    }
    return edge_vertex(k, shape, (shape + 1u) % 3u, clips, size);
}

fn to_ndc(size: vec2<f32>) -> vec2<f32> {
    return vec2<f32>(2.0, -2.0) / size;
}

// Vertex `k` of the rectangle of the edge from corner i to corner j, drawn MARGIN wider and
// longer than the exact one (`line_corner`). Its corners at one end lie on the line through the
// other end and past this one, so they take the point MARGIN pixels beyond the end on the line
// (mixed from i and j as clipping mixes, perspective-correct) and move from it across the line
// only, along t: the drawn rectangle's depth and varyings are then those of the exact one,
// extended. An end cut at the near plane is not extended (behind it nothing is drawn).
fn edge_vertex(k: u32, i: u32, j: u32, clips: array<vec4<f32>, 3>, size: vec2<f32>) -> FaceVertex {
    let a = edge_end(i, j, clips);
    let b = edge_end(j, i, clips);
    let clip_a = point_clip(a, clips);
    let clip_b = point_clip(b, clips);
    let window_a = window(clip_a, size);
    let window_b = window(clip_b, size);
    let corner = line_corner(k, window_a, window_b);
    let f = MARGIN / max(distance(window_a, window_b), 1e-30);
    // This end, its window position, where it and the other end lie on the edge from i to j,
    // and their w.
    var end = a;
    var at = window_a;
    var t = vec2<f32>(a.t, 1.0 - b.t);
    var w = vec2<f32>(clip_a.w, clip_b.w);
    if corner.at_b {
        end = b;
        at = window_b;
        t = t.yx;
        w = w.yx;
    }
    let from_end = corner.window + corner.wider - at;
    // f, the screen fraction past the end, is the clip-space fraction s below (and w stays > 0
    // there while the denominator does).
    let denominator = w.y * (1.0 + f) - f * w.x;
    if !end.near && !end.far && denominator > 0.0 {
        let s = f * w.x / denominator;
        end = FacePoint(i, j, t.x - s * (t.y - t.x), false, false, end.kept);
    }
    return FaceVertex(end, from_end * to_ndc(size), corner.line);
}

// Whether the fragment is drawn: for a line drawn as its larger rectangle, where the software
// rasterizer's exact rectangle (`ends`, `across`: an `ExactLine`) covers its centre (`window`:
// the `window_varying` of its vertices' clip positions); any other fragment.
fn fragment_kept(ends: vec4<i32>, across: vec2<i32>, window: vec3<f32>) -> bool {
    return !(SHAPES && EDGES) || line_covers(ExactLine(ends, across), window);
}

// Points 0, 1, 2: the corners (those in front of the near plane); 3, 4, 5: where edges 0-1,
// 1-2, 2-0 cross the near plane (clip z = 0): the corners clipping gives the face there, which
// glPolygonMode(GL_POINT) draws too, as the hardware's polygon mode and Close2GL do.
fn face_point(index: u32, clips: array<vec4<f32>, 3>) -> FacePoint {
    var z = array<f32, 3>(clips[0].z, clips[1].z, clips[2].z);
    if index < 3u {
        return FacePoint(index, index, 0.0, false, false, z[index] >= 0.0);
    }
    let i = index - 3u;
    let j = (i + 1u) % 3u;
    let crosses = (z[i] < 0.0) != (z[j] < 0.0);
    let t = select(0.0, z[i] / (z[i] - z[j]), crosses);
    return FacePoint(i, j, t, true, false, crosses);
}

// The end at corner i of the edge from corner i to corner j, cut at the near plane (clip z = 0;
// wgpu's depth range is 0..w) when i is behind it, or at the far plane (z = w) when it is
// beyond, as Close2GL's clipping cuts it (the software rasterizer's rectangle runs from the cut
// end, and its sides' rounding follows that end); not kept when both are past the same plane.
fn edge_end(i: u32, j: u32, clips: array<vec4<f32>, 3>) -> FacePoint {
    var c = clips;
    let zi = c[i].z;
    let zj = c[j].z;
    if zi < 0.0 {
        return FacePoint(i, j, zi / (zi - zj), true, false, zj >= 0.0);
    }
    let fi = c[i].w - zi;
    let fj = c[j].w - zj;
    if fi < 0.0 {
        return FacePoint(i, j, fi / (fi - fj), false, true, fj >= 0.0);
    }
    return FacePoint(i, i, 0.0, false, false, true);
}

// The clip position of `p`.
fn point_clip(p: FacePoint, clips: array<vec4<f32>, 3>) -> vec4<f32> {
    var c = clips;
    var clip = mix(c[p.i], c[p.j], p.t);
    // Exactly on the plane, as clipping puts it, not a rounding error past it.
    if p.near {
        clip.z = 0.0;
    }
    if p.far {
        clip.z = clip.w;
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

// glPolygonMode's lines and points where the adapter has no polygon modes: each face is one
// instance carrying its three corners, drawn as 6 vertices of a line list or a point list
// (`face_vertex`), and culling is decided here from the three clip positions, as the hardware
// decides it for a filled face (lines and points themselves are never culled).

// 1: lines; 0: points.
override EDGES: bool = false;
// 1: glCullFace(GL_BACK) is on.
override CULL_BACK: bool = false;
// 1: glFrontFace(GL_CW).
override CLOCKWISE: bool = false;

// Vertex `index` of a face's instance: corner i mixed with corner j at t (t = 0: corner i).
// `near`: it lies on the near plane; `kept`: false where there is no such vertex.
struct FaceVertex {
    i: u32,
    j: u32,
    t: f32,
    near: bool,
    kept: bool,
}

// Lines: the corners of edges 0-1, 1-2, 2-0. Points: corners 0, 1, 2, then where edges 0-1,
// 1-2, 2-0 cross the near plane (clip z = 0): the corners clipping gives the face there, which
// glPolygonMode(GL_POINT) draws too, as the hardware's polygon mode and Close2GL do.
fn face_vertex(index: u32, a: vec4<f32>, b: vec4<f32>, c: vec4<f32>) -> FaceVertex {
    if EDGES || index < 3u {
        let corner = select(index, (index + 1u) / 2u, EDGES) % 3u;
        return FaceVertex(corner, corner, 0.0, false, true);
    }
    let i = index - 3u;
    let j = (i + 1u) % 3u;
    var z = array<f32, 3>(a.z, b.z, c.z);
    let crosses = (z[i] < 0.0) != (z[j] < 0.0);
    let t = select(0.0, z[i] / (z[i] - z[j]), crosses);
    return FaceVertex(i, j, t, true, crosses);
}

// Whether the face with clip positions a, b, c is front-facing. det[a.xyw; b.xyw; c.xyw] is
// w_a w_b w_c times twice the face's signed area in normalized device coordinates, and its sign
// is that of the part of the face in front of the eye (w > 0) even when the near plane cuts the
// face: the facing the hardware finds after clipping.
fn faces_front(a: vec4<f32>, b: vec4<f32>, c: vec4<f32>) -> bool {
    let det = dot(cross(a.xyw, b.xyw), c.xyw);
    return select(det > 0.0, det < 0.0, CLOCKWISE);
}

// Whether culling removes the face: its vertices then go outside the view volume (`CLIPPED`),
// so that its lines or points are clipped away, as are vertices that are not kept.
fn culled(a: vec4<f32>, b: vec4<f32>, c: vec4<f32>) -> bool {
    return CULL_BACK && !faces_front(a, b, c);
}

const CLIPPED: vec4<f32> = vec4<f32>(2.0, 2.0, 2.0, 1.0);

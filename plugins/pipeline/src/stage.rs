//! One triangle's journey after the transform by P·M, read top to bottom as in the textbook:
//! clip, divide by w, map to the viewport, cull, emit. Both the textbook path and the fast path
//! send every triangle through [`process`], so they cannot disagree on what a triangle becomes.

use close2gl_core::limits::has_no_area;
use close2gl_core::{Clipping, FrontFace, RenderMode, RenderSettings, Topology, Viewport};
use glam::{Mat4, Vec4};

use crate::clip::{NEAR, Outcode, Polygon, clip_polygon, outcode};
use crate::matrices;

/// What stays the same for every triangle of a frame.
#[derive(Clone, Copy, Debug)]
pub struct Stage {
    pub mode: RenderMode,
    pub clipping: Clipping,
    /// The front face when backface culling is on.
    pub culling: Option<FrontFace>,
    pub viewport: Mat4,
}

impl Stage {
    pub fn new(settings: &RenderSettings, viewport: Viewport) -> Self {
        Self {
            mode: settings.mode,
            clipping: settings.clipping,
            culling: settings.backface_culling.then_some(settings.front_face),
            viewport: matrices::viewport(viewport.width as f32, viewport.height as f32),
        }
    }

    pub fn topology(&self) -> Topology {
        match self.mode {
            RenderMode::Points => Topology::Points,
            RenderMode::Wireframe => Topology::Lines,
            RenderMode::Solid => Topology::Triangles,
        }
    }
}

/// A vertex after P·M: the planes it is outside of, and (only when it is inside, so the division
/// is safe) its window position.
pub fn corner(clip: Vec4, stage: &Stage) -> (Outcode, [f32; 2]) {
    let code = outcode(clip);
    if code == 0 {
        (code, to_window(clip, &stage.viewport))
    } else {
        (code, [f32::NAN; 2])
    }
}

/// The perspective division, then V.
pub fn to_window(clip: Vec4, viewport: &Mat4) -> [f32; 2] {
    let ndc = Vec4::new(clip.x / clip.w, clip.y / clip.w, clip.z / clip.w, 1.0);
    let window = *viewport * ndc;
    [window.x, window.y]
}

/// What happened to a triangle.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Fate {
    Clipped,
    Culled,
    /// Drawn as this many points, lines or triangles.
    Drawn(usize),
}

/// Clip, divide, map, cull and emit one triangle into `out`, given its corners' outcodes and
/// window positions (from [`corner`]). The clip coordinates are asked for only when the triangle
/// straddles the view volume's border: most triangles of a big mesh never need them. Inlined
/// into the callers' loops; the cutting is not (see [`cut`]).
#[inline(always)]
pub fn process(
    codes: [Outcode; 3],
    window: [[f32; 2]; 3],
    clip: impl FnOnce() -> [Vec4; 3],
    stage: &Stage,
    out: &mut Vec<[f32; 2]>,
) -> Fate {
    let outside_any = codes[0] | codes[1] | codes[2];
    if outside_any == 0 {
        // Trivially inside: the corners' window positions are already known.
        if is_culled(&window, stage.culling) {
            return Fate::Culled;
        }
        return Fate::Drawn(emit_inside(&window, stage.mode, out));
    }
    let outside_all = codes[0] & codes[1] & codes[2];
    if stage.clipping == Clipping::Simple || outside_all != 0 {
        return Fate::Clipped;
    }
    cut(clip(), outside_any, stage, out)
}

/// Clip, divide, map, cull and emit a triangle that straddles the planes in `outside_any`. Kept
/// out of line: its polygons need a large stack frame that the common, trivially inside
/// triangle should not pay for.
#[inline(never)]
fn cut(clip: [Vec4; 3], outside_any: Outcode, stage: &Stage, out: &mut Vec<[f32; 2]>) -> Fate {
    let triangle = Polygon::triangle(clip[0], clip[1], clip[2]);
    let piece = clip_polygon(&triangle, outside_any);
    let mut piece_window = [[0.0; 2]; crate::clip::MAX_POLYGON];
    for (w, p) in piece_window.iter_mut().zip(piece.vertices()) {
        *w = to_window(*p, &stage.viewport);
    }
    let piece_window = &piece_window[..piece.len];
    if piece_window.is_empty() || piece_window.iter().flatten().any(|x| !x.is_finite()) {
        return Fate::Clipped;
    }
    if is_culled(piece_window, stage.culling) {
        return Fate::Culled;
    }
    Fate::Drawn(match stage.mode {
        RenderMode::Solid => emit_fan(piece_window, out),
        RenderMode::Wireframe => emit_original_edges(piece_window, &piece.original, out),
        RenderMode::Points => emit_points(&triangle, outside_any, stage, out),
    })
}

/// Twice the signed area (the red book's formula). Window y grows downwards, so a polygon that
/// looks counter-clockwise on screen has a negative area here. (Triangles, the common case, use
/// the cross product of two edges: the same sign, fewer operations.)
fn signed_area(window: &[[f32; 2]]) -> f32 {
    let mut area = 0.0;
    for (i, a) in window.iter().enumerate() {
        let b = window[(i + 1) % window.len()];
        area += a[0] * b[1] - b[0] * a[1];
    }
    area
}

fn longest_edge_squared(window: &[[f32; 2]]) -> f32 {
    let mut longest = 0.0f32;
    for (i, a) in window.iter().enumerate() {
        let b = window[(i + 1) % window.len()];
        longest = longest.max((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2));
    }
    longest
}

#[inline(always)]
fn is_culled(window: &[[f32; 2]], culling: Option<FrontFace>) -> bool {
    let Some(front) = culling else { return false };
    let area = match window {
        [a, b, c] => (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]),
        polygon => signed_area(polygon),
    };
    let front_facing = match front {
        FrontFace::Ccw => area < 0.0,
        FrontFace::Cw => area > 0.0,
    };
    // Only front faces need the size check: most back faces are culled without it. A polygon
    // with no area is a back face, as in OpenGL (see `ZERO_AREA`, which the reference view uses).
    !front_facing || has_no_area(area, longest_edge_squared(window))
}

fn emit_inside(window: &[[f32; 2]; 3], mode: RenderMode, out: &mut Vec<[f32; 2]>) -> usize {
    match mode {
        RenderMode::Solid => {
            out.extend_from_slice(window);
            1
        }
        RenderMode::Wireframe => {
            out.extend_from_slice(&[
                window[0], window[1], window[1], window[2], window[2], window[0],
            ]);
            3
        }
        RenderMode::Points => {
            out.extend_from_slice(window);
            3
        }
    }
}

fn emit_fan(window: &[[f32; 2]], out: &mut Vec<[f32; 2]>) -> usize {
    for i in 1..window.len() - 1 {
        out.extend_from_slice(&[window[0], window[i], window[i + 1]]);
    }
    window.len() - 2
}

/// A GPU draws a clipped polygon in line mode as what is left of the triangle's own edges; the
/// edges clipping added along the planes are not drawn.
fn emit_original_edges(window: &[[f32; 2]], original: &[bool], out: &mut Vec<[f32; 2]>) -> usize {
    let before = out.len();
    for (i, a) in window.iter().enumerate() {
        if original[i] {
            out.extend_from_slice(&[*a, window[(i + 1) % window.len()]]);
        }
    }
    (out.len() - before) / 2
}

/// In point mode, a GPU draws the vertices that start one of the triangle's own edges once the
/// near plane has cut it: its corners, and the points where an edge comes back in front of the
/// near plane. Every other plane applies to each point alone (a point outside the viewport or
/// the depth range is dropped), so no vertex is made on them.
fn emit_points(
    triangle: &Polygon,
    outside: Outcode,
    stage: &Stage,
    out: &mut Vec<[f32; 2]>,
) -> usize {
    let near_cut = clip_polygon(triangle, outside & NEAR);
    let before = out.len();
    for (p, original) in near_cut.vertices().iter().zip(near_cut.original) {
        // Points made on the near plane are inside it by construction, whatever the rounding.
        if original && outcode(*p) & !NEAR == 0 {
            out.push(to_window(*p, &stage.viewport));
        }
    }
    out.len() - before
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sliver_is_a_back_face_whichever_face_is_front() {
        // A pole's copies 1e-7 apart: its area's sign is rounding, not geometry.
        let sliver = [[10.0, 10.0], [60.0, 40.0], [60.0, 40.0 + 1e-5]];
        let reversed = [sliver[0], sliver[2], sliver[1]];
        for front in [FrontFace::Ccw, FrontFace::Cw] {
            assert!(is_culled(&sliver, Some(front)));
            assert!(is_culled(&reversed, Some(front)));
        }
        assert!(
            !is_culled(&sliver, None),
            "without culling every triangle is drawn"
        );
    }

    #[test]
    fn a_thin_real_triangle_keeps_its_facing() {
        // 1 pixel tall over 100 pixels long: thin, but a triangle any rasteriser can fill.
        let thin = [[0.0, 0.0], [100.0, 0.0], [50.0, 1.0]];
        let reversed = [thin[0], thin[2], thin[1]];
        assert_ne!(
            is_culled(&thin, Some(FrontFace::Ccw)),
            is_culled(&reversed, Some(FrontFace::Ccw))
        );
    }
}

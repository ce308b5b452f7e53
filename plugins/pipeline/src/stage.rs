//! One triangle's journey after the transform by P·M, read top to bottom as in the textbook:
//! clip, divide by w, map to the viewport, cull, emit. Both the textbook path and the fast path
//! send every triangle through [`process`], so they cannot disagree on what a triangle becomes.

use close2gl_core::limits::has_no_area;
use close2gl_core::{
    Clipping, CutVertex, FateKind, FrontFace, PipelineSettings, RenderMode, Topology, TriangleFate,
    Viewport,
};
use glam::{Mat4, Vec4};

use crate::clip::{MAX_POLYGON, NEAR, Outcode, Polygon, clip_polygon, outcode};
use crate::{emit, matrices};

/// What stays the same for every triangle of a frame.
#[derive(Clone, Copy, Debug)]
pub struct FrameConstants {
    pub mode: RenderMode,
    pub clipping: Clipping,
    /// The front face when backface culling is on.
    pub culling: Option<FrontFace>,
    pub viewport: Mat4,
}

impl FrameConstants {
    pub fn new(settings: &PipelineSettings, viewport: Viewport) -> Self {
        Self {
            mode: settings.mode,
            clipping: settings.clipping,
            culling: settings.backface_culling.then_some(settings.front_face),
            viewport: matrices::viewport(viewport.width as f32, viewport.height as f32),
        }
    }

    /// How many vertices each primitive of [`FrameConstants::topology`] has.
    pub fn topology_vertices(&self) -> usize {
        match self.mode {
            RenderMode::Points => 1,
            RenderMode::Wireframe => 2,
            RenderMode::Solid => 3,
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
pub fn corner(clip: Vec4, constants: &FrameConstants) -> (Outcode, [f32; 2]) {
    let code = outcode(clip);
    if code == 0 {
        (code, to_window(clip, &constants.viewport))
    } else {
        (code, [f32::NAN; 2])
    }
}

/// The perspective division, then V.
pub fn to_window(clip: Vec4, viewport: &Mat4) -> [f32; 2] {
    let [x, y, _, _] = to_window_depth(clip, viewport);
    [x, y]
}

/// The perspective division, then V, keeping what the rasterizer needs: window x, y, the depth
/// in 0..1, and 1/w for perspective-correct interpolation.
pub fn to_window_depth(clip: Vec4, viewport: &Mat4) -> [f32; 4] {
    let inv_w = 1.0 / clip.w;
    let ndc = Vec4::new(clip.x * inv_w, clip.y * inv_w, clip.z * inv_w, 1.0);
    let window = *viewport * ndc;
    [window.x, window.y, window.z, inv_w]
}

/// What happened to a triangle, and how many points, lines or triangles it was drawn as (none
/// unless its fate is drawn or cut).
#[derive(Clone, Copy, Debug)]
pub struct Fate {
    pub fate: TriangleFate,
    pub primitives: usize,
}

impl Fate {
    /// Drawn, whole (`planes` = 0) or cut by `planes`, as `primitives` primitives.
    fn drawn(planes: Outcode, signed_area: f32, primitives: usize) -> Self {
        let kind = if planes == 0 {
            FateKind::Drawn
        } else {
            FateKind::Cut
        };
        let fate = TriangleFate {
            kind,
            planes,
            behind_eye: false,
            signed_area,
        };
        Fate { fate, primitives }
    }

    /// Culled as a back face or as having no area.
    fn culled(kind: FateKind, planes: Outcode, signed_area: f32) -> Self {
        let fate = TriangleFate {
            kind,
            planes,
            behind_eye: false,
            signed_area,
        };
        Fate {
            fate,
            primitives: 0,
        }
    }

    /// Removed whole by clipping (the planes it lay outside of).
    fn clipped(planes: Outcode, behind_eye: bool) -> Self {
        let fate = TriangleFate {
            kind: FateKind::Clipped,
            planes,
            behind_eye,
            signed_area: f32::NAN,
        };
        Fate {
            fate,
            primitives: 0,
        }
    }
}

/// Whether every corner is at or behind the eye (w <= 0), where no division means anything.
/// Only asked when every corner is outside the near plane (`outside_all`'s near bit), which
/// w <= 0 implies, so the clip coordinates are rarely needed.
#[inline(always)]
fn behind_eye(outside_all: Outcode, clip: impl FnOnce() -> [Vec4; 3]) -> bool {
    outside_all & NEAR != 0 && clip().iter().all(|p| p.w <= 0.0)
}

/// An index in [`RasterOut::primitives`] with this bit set names a vertex of `cuts` (the bit
/// cleared), not a mesh vertex. The fast path rebases these when it joins its chunks.
pub const CUT: u32 = 1 << 31;

/// The software rasterizer's share of the output: the primitives as vertex indices, the
/// vertices that clipping made, and (only while fates are recorded) each primitive's mesh
/// triangle.
#[derive(Debug, Default)]
pub struct RasterOut {
    pub primitives: Vec<u32>,
    pub cuts: Vec<CutVertex>,
    pub triangles: Vec<u32>,
}

/// Where a triangle's primitives go: the 2D buffer alone (a `Vec` of window positions), or with
/// the software rasterizer also [`RasterOut`] ([`RasterEmit`]). A trait, so that the 2D path is
/// compiled on its own and pays nothing for the rasterizer's output.
pub trait Emit {
    /// The 2D buffer.
    fn window(&mut self) -> &mut Vec<[f32; 2]>;
    /// The rasterizer's share, when it draws.
    fn raster(&mut self) -> Option<&mut RasterOut>;
}

impl Emit for Vec<[f32; 2]> {
    #[inline(always)]
    fn window(&mut self) -> &mut Vec<[f32; 2]> {
        self
    }

    #[inline(always)]
    fn raster(&mut self) -> Option<&mut RasterOut> {
        None
    }
}

/// The 2D buffer and the rasterizer's share of the output.
pub struct RasterEmit<'a> {
    pub window: &'a mut Vec<[f32; 2]>,
    pub raster: &'a mut RasterOut,
}

impl Emit for RasterEmit<'_> {
    #[inline(always)]
    fn window(&mut self) -> &mut Vec<[f32; 2]> {
        self.window
    }

    #[inline(always)]
    fn raster(&mut self) -> Option<&mut RasterOut> {
        Some(self.raster)
    }
}

/// Clip, divide, map, cull and emit one triangle (mesh vertices `corners`) into `out`, given its
/// corners' outcodes and window positions (from [`corner`]). The clip coordinates are asked for
/// only when the triangle straddles the view volume's border: most triangles of a big mesh never
/// need them. Inlined into the callers' loops; the cutting is not (see `cut`).
///
/// `RECORD` says whether someone will read the fate's details (the inspector). Without it, a
/// back face is culled without asking whether it also has no area, and a clipped triangle
/// without asking whether it lies behind the eye: the same output and the same stage counts, at
/// the cost of the pipeline before the inspector existed. A constant, so that each frame is
/// compiled without the questions it does not ask.
#[inline(always)]
pub fn process<const RECORD: bool>(
    corners: [u32; 3],
    codes: [Outcode; 3],
    window: [[f32; 2]; 3],
    clip: impl FnOnce() -> [Vec4; 3],
    constants: &FrameConstants,
    out: &mut impl Emit,
) -> Fate {
    let outside_any = codes[0] | codes[1] | codes[2];
    if outside_any == 0 {
        // Trivially inside: the corners' window positions are already known.
        let (area, culled) = face::<RECORD>(&window, constants.culling);
        if let Some(kind) = culled {
            return Fate::culled(kind, 0, area);
        }
        let primitives = emit_inside(&window, corners, constants.topology(), out);
        return Fate::drawn(0, area, primitives);
    }
    let outside_all = codes[0] & codes[1] & codes[2];
    if constants.clipping == Clipping::Simple || outside_all != 0 {
        let planes = match constants.clipping {
            Clipping::Simple => outside_any,
            _ => outside_all,
        };
        return Fate::clipped(planes, RECORD && behind_eye(outside_all, clip));
    }
    cut::<RECORD>(corners, clip(), outside_any, constants, out)
}

/// Clip, divide, map, cull and emit a triangle that straddles the planes in `outside_any`. Kept
/// out of line: its polygons need a large stack frame that the common, trivially inside
/// triangle should not pay for.
#[inline(never)]
fn cut<const RECORD: bool>(
    corners: [u32; 3],
    clip: [Vec4; 3],
    outside_any: Outcode,
    constants: &FrameConstants,
    out: &mut impl Emit,
) -> Fate {
    let triangle = Polygon::triangle(clip[0], clip[1], clip[2]);
    let piece = clip_polygon(&triangle, outside_any);
    let piece_window = windows(&piece, constants);
    let in_window = &piece_window[..piece.len];
    if in_window.is_empty() || in_window.iter().flatten().any(|x| !x.is_finite()) {
        return Fate::clipped(outside_any, false);
    }
    let (area, culled) = face::<RECORD>(in_window, constants.culling);
    if let Some(kind) = culled {
        return Fate::culled(kind, outside_any, area);
    }
    let topology = constants.topology();
    let (drawn, drawn_window) = match topology {
        Topology::Points => {
            let points = emit::points(&triangle, outside_any, ALL_PLANES);
            (points, windows(&points, constants))
        }
        _ => (piece, piece_window),
    };
    let ids = push_cuts(&drawn, corners, constants, out);
    let before = out.window().len();
    for i in emit::corners(topology, drawn.len, |i| drawn.original[i]) {
        out.window().push(drawn_window[i]);
        if let Some(raster) = out.raster() {
            raster.primitives.push(ids[i]);
        }
    }
    let primitives = (out.window().len() - before) / constants.topology_vertices();
    Fate::drawn(outside_any, area, primitives)
}

/// Every plane of the view volume: the pipeline clips against all six.
const ALL_PLANES: Outcode = 0x3f;

/// The window positions of a polygon's corners.
fn windows(polygon: &Polygon, constants: &FrameConstants) -> [[f32; 2]; MAX_POLYGON] {
    let mut window = [[0.0; 2]; MAX_POLYGON];
    for (w, p) in window.iter_mut().zip(polygon.vertices()) {
        *w = to_window(*p, &constants.viewport);
    }
    window
}

/// With the rasterizer, every vertex of a cut piece becomes a [`CutVertex`]; returns their
/// indices (with [`CUT`] set), or nothing without the rasterizer.
fn push_cuts(
    piece: &Polygon,
    corners: [u32; 3],
    constants: &FrameConstants,
    out: &mut impl Emit,
) -> [u32; MAX_POLYGON] {
    let mut ids = [0; MAX_POLYGON];
    if let Some(raster) = out.raster() {
        for (i, (p, weights)) in piece.vertices().iter().zip(piece.weights).enumerate() {
            ids[i] = CUT | raster.cuts.len() as u32;
            raster.cuts.push(CutVertex {
                window: to_window_depth(*p, &constants.viewport),
                corners,
                weights: weights.to_array(),
            });
        }
    }
    ids
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

pub(crate) fn longest_edge_squared(window: &[[f32; 2]]) -> f32 {
    let mut longest = 0.0f32;
    for (i, a) in window.iter().enumerate() {
        let b = window[(i + 1) % window.len()];
        longest = longest.max((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2));
    }
    longest
}

/// Backface culling: twice the polygon's signed window area, and, when culling is on and
/// removes it, why: a back face, or no area to speak of (a back face too, as in OpenGL; see
/// `ZERO_AREA`, which the reference view uses). A sliver's sign is rounding, so it is told
/// apart by its size whichever way it faces; only `RECORD` asks that of a back face, which is
/// culled either way.
#[inline(always)]
pub fn face<const RECORD: bool>(
    window: &[[f32; 2]],
    culling: Option<FrontFace>,
) -> (f32, Option<FateKind>) {
    let area = match window {
        [a, b, c] => (b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]),
        polygon => signed_area(polygon),
    };
    let Some(front) = culling else {
        return (area, None);
    };
    let front_facing = match front {
        FrontFace::Ccw => area < 0.0,
        FrontFace::Cw => area > 0.0,
    };
    let culled = if !RECORD && !front_facing {
        Some(FateKind::Culled)
    } else if has_no_area(area, longest_edge_squared(window)) {
        Some(FateKind::ZeroArea)
    } else if !front_facing {
        Some(FateKind::Culled)
    } else {
        None
    };
    (area, culled)
}

/// The triangle itself, its three edges as lines, or its three corners as points
/// ([`emit::whole`]). It runs once per triangle of every frame: a table, not the iterator.
#[inline(always)]
fn emit_inside(
    window: &[[f32; 2]; 3],
    corners: [u32; 3],
    topology: Topology,
    out: &mut impl Emit,
) -> usize {
    let order = emit::whole(topology);
    out.window().extend(order.iter().map(|&i| window[i]));
    if let Some(raster) = out.raster() {
        raster.primitives.extend(order.iter().map(|&i| corners[i]));
    }
    match topology {
        Topology::Triangles => 1,
        Topology::Lines | Topology::Points => 3,
    }
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
            assert_eq!(
                face::<true>(&sliver, Some(front)).1,
                Some(FateKind::ZeroArea)
            );
            assert_eq!(
                face::<true>(&reversed, Some(front)).1,
                Some(FateKind::ZeroArea)
            );
            let unrecorded = [
                face::<false>(&sliver, Some(front)),
                face::<false>(&reversed, Some(front)),
            ];
            assert!(
                unrecorded.iter().all(|(_, culled)| culled.is_some()),
                "culled, recorded or not"
            );
        }
        assert_eq!(
            face::<true>(&sliver, None).1,
            None,
            "without culling every triangle is drawn"
        );
    }

    #[test]
    fn a_thin_real_triangle_keeps_its_facing() {
        // 1 pixel tall over 100 pixels long: thin, but a triangle any rasteriser can fill.
        let thin = [[0.0, 0.0], [100.0, 0.0], [50.0, 1.0]];
        let reversed = [thin[0], thin[2], thin[1]];
        for culled in [
            face::<true>(&thin, Some(FrontFace::Ccw)),
            face::<false>(&thin, Some(FrontFace::Ccw)),
        ] {
            assert_eq!(culled.1, Some(FateKind::Culled));
        }
        assert_eq!(face::<true>(&reversed, Some(FrontFace::Ccw)).1, None);
        assert_eq!(face::<false>(&reversed, Some(FrontFace::Ccw)).1, None);
    }
}

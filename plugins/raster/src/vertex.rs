//! The vertex stage: each vertex as setup takes it, its window position and its varyings (in
//! the layout `varyings` gives): the mesh's vertices lit (Gouraud) or passed on (Phong) in
//! parallel, then the vertices clipping made, blended from their triangle's corners as a GPU's
//! clipper blends them.

use close2gl_core::{CutVertex, RasterGeometry, RasterVertex, Shading};
use glam::Vec3;
use rayon::prelude::*;

use crate::edge::{FIXED_ONE, GUARD_PX, snap};
use crate::lanes::V8;
use crate::lighting::Light;
use crate::setup::Corner;
use crate::varyings::{EYE, INTENSITY, NORMAL, UV, VARYINGS};

/// Mesh vertices per parallel task: few enough that a cow-sized model's (4,096 in the knot)
/// are shared by two cores. At 16 Ki, one core took them all while the other waited, and the
/// knot's whole frame was slower (measured:
/// docs/performance.md#the-lightings-attenuation-and-sharing-the-tiles-between-the-threads).
const CHUNK: usize = 2048;

/// A vertex as the pipeline and the vertex stage left it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Vertex {
    /// x, y in window pixels, depth, 1/w.
    pub window: [f32; 4],
    /// x, y snapped to fixed point once here, not once for each triangle the vertex is a corner
    /// of (six in a closed mesh): [`UNDRAWABLE`] when setup cannot take the vertex.
    fixed: [i32; 2],
    pub varyings: [f32; VARYINGS],
}

/// The fixed-point x of a vertex outside the guard band, or with a position, depth or 1/w that
/// is NaN or infinite: no vertex inside snaps to it (they are within ±2^29).
const UNDRAWABLE: i32 = i32::MIN;

impl Vertex {
    const ZERO: Vertex = Vertex {
        window: [0.0; 4],
        fixed: [UNDRAWABLE; 2],
        varyings: [0.0; VARYINGS],
    };

    pub(crate) fn new(window: [f32; 4], varyings: [f32; VARYINGS]) -> Vertex {
        let in_guard_band = window[..2].iter().all(|x| x.abs() <= GUARD_PX);
        let fixed = match in_guard_band && window.iter().all(|x| x.is_finite()) {
            true => [snap(window[0]) as i32, snap(window[1]) as i32],
            false => [UNDRAWABLE; 2],
        };
        Vertex {
            window,
            fixed,
            varyings,
        }
    }

    /// The vertex as a corner at its own position.
    pub(crate) fn corner(&self) -> Corner<'_> {
        Corner {
            fixed: self.fixed(),
            window: self.window,
            varyings: &self.varyings,
        }
    }

    /// The same vertex moved to a fixed-point position (where a line's or a point's rectangle
    /// has its corners), keeping depth, 1/w and the varyings.
    pub(crate) fn moved(&self, fixed: [i64; 2]) -> Corner<'_> {
        let to_window = |f: i64| f as f32 / FIXED_ONE as f32 + 0.5;
        let mut window = self.window;
        window[0] = to_window(fixed[0]);
        window[1] = to_window(fixed[1]);
        Corner {
            fixed,
            window,
            varyings: &self.varyings,
        }
    }

    pub(crate) fn fixed(&self) -> [i64; 2] {
        self.fixed.map(i64::from)
    }

    /// Whether the fixed-point arithmetic can hold this vertex (see [`GUARD_PX`]) and its
    /// window position, depth and 1/w are all finite. A primitive with a corner that is not
    /// is not drawn.
    pub(crate) fn drawable(&self) -> bool {
        self.fixed[0] != UNDRAWABLE
    }
}

/// Fills `vertices` with every vertex of `raster`: the mesh's, then the cuts'. Returns the
/// distance from the light to the farthest mesh vertex (eye positions), found in the same pass
/// (see `Light::reaching`): with the cuts blended from them, no point of the frame is farther.
/// A NaN position is passed over: its window position is NaN too, and its triangles are not
/// drawn.
pub(crate) fn vertex_stage(
    raster: &RasterGeometry,
    shading: Shading,
    light: &Light,
    vertices: &mut Vec<Vertex>,
) -> f32 {
    let mesh_vertices = raster.vertices.len();
    vertices.resize(mesh_vertices + raster.cuts.len(), Vertex::ZERO);
    let (mesh, cuts) = vertices.split_at_mut(mesh_vertices);
    let farthest_squared = mesh
        .par_chunks_mut(CHUNK)
        .zip(raster.vertices.par_chunks(CHUNK))
        .map(|(out, vertices)| {
            let mut farthest_squared = 0.0f32;
            for (o, v) in out.iter_mut().zip(vertices) {
                *o = Vertex::lit(v, shading, light);
                let eye = Vec3::from(v.eye);
                farthest_squared = farthest_squared.max(light.position.distance_squared(eye));
            }
            farthest_squared
        })
        .reduce(|| 0.0, f32::max);
    for (o, cut) in cuts.iter_mut().zip(&raster.cuts) {
        *o = Vertex::cut(cut, mesh);
    }
    farthest_squared.sqrt()
}

impl Vertex {
    /// A mesh vertex with its varyings: lit (Gouraud) or passed on (Phong).
    #[inline(always)]
    pub(crate) fn lit(v: &RasterVertex, shading: Shading, light: &Light) -> Vertex {
        let (eye, normal) = (Vec3::from(v.eye), Vec3::from(v.normal));
        Vertex::new(v.window, vertex_varyings(shading, light, eye, normal, v.uv))
    }

    /// A vertex clipping made, its varyings blended from its triangle's corners among the
    /// `mesh` vertices, as a GPU's clipper blends them.
    #[inline(always)]
    pub(crate) fn cut(cut: &CutVertex, mesh: &[Vertex]) -> Vertex {
        let mut varyings = [0.0; VARYINGS];
        for (corner, weight) in cut.corners.iter().zip(cut.weights) {
            let from = &mesh[*corner as usize].varyings;
            for (v, f) in varyings.iter_mut().zip(from) {
                *v += weight * f;
            }
        }
        Vertex::new(cut.window, varyings)
    }
}

/// A vertex's varyings from its eye position, normal and texture coordinates.
#[inline(always)]
fn vertex_varyings(
    shading: Shading,
    light: &Light,
    eye: Vec3,
    normal: Vec3,
    uv: [f32; 2],
) -> [f32; VARYINGS] {
    let mut v = [0.0; VARYINGS];
    match shading {
        Shading::None => {}
        Shading::GouraudAd | Shading::GouraudAds => {
            let i = light
                .illumination(V8::splat(eye), V8::splat(normal))
                .first();
            v[INTENSITY..INTENSITY + 3].copy_from_slice(&i.to_array());
        }
        Shading::Phong => {
            v[EYE..EYE + 3].copy_from_slice(&eye.to_array());
            v[NORMAL..NORMAL + 3].copy_from_slice(&normal.to_array());
        }
    }
    v[UV..UV + 2].copy_from_slice(&uv);
    v
}

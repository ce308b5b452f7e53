//! The vertex stage: what each corner carries to the pixels. A mesh vertex gets Gouraud's lit
//! intensity, Phong's eye position and normal and the texture coordinates; a vertex clipping
//! made blends its triangle's corners' by its weights, as a GPU's clipper blends them.

use close2gl_core::RasterGeometry;
use glam::Vec3;

use super::Shader;

/// Where each varying is in [`Vertex::varyings`]: Gouraud's intensity (or a traced corner's
/// colour), Phong's eye position and normal, the texture coordinates.
pub(super) const INTENSITY: usize = 0;
pub(super) const EYE: usize = 3;
pub(super) const NORMAL: usize = 6;
pub(super) const UV: usize = 9;
pub(super) const VARYINGS: usize = 11;

/// A vertex: x, y in window pixels (y down), depth and 1/w; its varyings; where it is snapped
/// to when primitive assembly put it on the 1/256 grid itself (a line's or a point's rectangle:
/// far off screen, x and y in f32 no longer hold that grid exactly); and x, y as a program gave
/// them in f64 (its y, up or down), which decide its snapping and rounding as they decided the
/// program's.
#[derive(Clone, Copy, Debug)]
pub(super) struct Vertex {
    pub(super) window: [f32; 4],
    pub(super) varyings: [f32; VARYINGS],
    pub(super) snapped: Option<[i64; 2]>,
    pub(super) exact: Option<[f64; 2]>,
}

/// A corner as a student's rasterizer receives it: window x, y (y as its origin says), depth
/// in 0..1 and q = 1/w, as the program wrote them; Gouraud's lit colour, the eye-space position
/// and normal, and the texture coordinates (zero where the program has none).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Corner {
    pub window: [f64; 4],
    pub rgb: [f32; 3],
    pub eye: [f32; 3],
    pub normal: [f32; 3],
    pub uv: [f32; 2],
}

impl Corner {
    /// The vertex it is, y turned down when `flip_from` gives the window's height.
    pub(super) fn vertex(&self, flip_from: Option<f64>) -> Vertex {
        let [x, y, z, q] = self.window;
        let down = flip_from.map_or(y, |height| height - y);
        let window = [x, down, z, q].map(|x| x as f32);
        let exact = [x, y];
        let mut varyings = [0.0; VARYINGS];
        varyings[INTENSITY..EYE].copy_from_slice(&self.rgb);
        varyings[EYE..NORMAL].copy_from_slice(&self.eye);
        varyings[NORMAL..UV].copy_from_slice(&self.normal);
        varyings[UV..].copy_from_slice(&self.uv);
        Vertex {
            window,
            varyings,
            snapped: None,
            exact: Some(exact),
        }
    }
}

/// Every vertex of `raster` with its varyings: the mesh's (lit, for Gouraud), then those clipping
/// made, whose varyings are their triangle's corners' blended by their weights (a Gouraud
/// intensity is not lit again).
pub(super) fn stage(raster: &RasterGeometry, shader: &Shader) -> Vec<Vertex> {
    let gouraud = shader.shading.per_vertex();
    let mut vertices: Vec<Vertex> = (raster.vertices.iter())
        .map(|v| {
            let (eye, normal) = (Vec3::from(v.eye), Vec3::from(v.normal));
            let intensity = gouraud.then(|| shader.light.illuminate(eye, normal));
            let corner = Corner {
                window: v.window.map(f64::from),
                rgb: intensity.unwrap_or_default().to_array(),
                eye: v.eye,
                normal: v.normal,
                uv: v.uv,
            };
            // Close2GL's own corners are f32: they snap as the fast rasterizer snaps them.
            Vertex {
                exact: None,
                ..corner.vertex(None)
            }
        })
        .collect();
    for cut in &raster.cuts {
        let corner = |i: usize| &vertices[cut.corners[i] as usize].varyings;
        let varyings = std::array::from_fn(|k| (0..3).map(|i| cut.weights[i] * corner(i)[k]).sum());
        vertices.push(Vertex {
            window: cut.window,
            varyings,
            snapped: None,
            exact: None,
        });
    }
    vertices
}

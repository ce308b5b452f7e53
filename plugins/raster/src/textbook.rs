//! The straightforward rasterizer, to read first. Each vertex is lit (Gouraud) or passed on
//! (Phong); then each primitive the pipeline drew, in order, becomes its triangles (a line's
//! and a point's rectangle are two), and for each triangle every pixel of its bounding box, one
//! at a time: inside when all three edge functions are positive at its centre (the top-left
//! rule settles a centre exactly on an edge), drawn when it is nearer than the depth buffer,
//! and coloured by the shading (none, Gouraud's interpolated intensity, or Phong lit at the
//! pixel), times the texel the filter finds. No threads, no tiles, no lanes: slow, and easy to
//! check. The fast rasterizer ([`crate::SoftwareRasterizer`]) must draw exactly its pixels and
//! depths (`tests/golden.rs`).
//!
//! It shares with the fast one what defines a pixel, not what makes it fast: the vertex stage's
//! lighting and blending of one vertex (`vertex`); the triangle setup (`primitives` and
//! `setup`: the corners snapped to 1/256 pixel, the edge functions with the top-left rule's
//! bias in their constant (`edge`), the bounding box, and the planes of depth, 1/w and each
//! varying times 1/w, set up once per triangle); the value of a plane at a pixel centre
//! (`varyings`: in f32 the order of a sum decides its last bit, so both sum alike); the
//! lighting equation (`lighting`); and the texture's level of detail and filters (`sampling`).
//! The last two work on eight lanes at once: here one pixel is given to all eight and the
//! first is read back.

use close2gl_core::{
    Camera, Close2glFrame, Image, Lighting, RasterGeometry, RenderSettings, Shading, Texture,
    TextureFilter,
};
use close2gl_pipeline::matrices::ClipTransform;
use glam::Vec3;

use crate::lanes::{F8, V8};
use crate::lighting::Light;
use crate::primitives::{SetupParams, set_up, triangles_per_primitive};
use crate::sampling::{Bilinear, Filter, Mips, Nearest, Trilinear};
use crate::setup::Triangle;
use crate::target::{TILE, pack};
use crate::varyings::{EYE, INTENSITY, NORMAL, Planes, UV, Used, varyings_used};
use crate::vertex::Vertex;

/// The colour, depth and owner buffers the textbook rasterizer drew, row after row from the top.
#[derive(Clone, Debug, PartialEq)]
pub struct Buffers {
    pub image: Image,
    /// The depth buffer (1, the far plane, where nothing drew).
    pub depth: Vec<f32>,
    /// The mesh triangle that drew each pixel (the depth test's winner): None where none drew,
    /// and everywhere when the pipeline did not record which triangle each primitive came from.
    pub owners: Vec<Option<u32>>,
}

/// Draws the pipeline's output `geometry` (made with the software rasterizer on, for `camera`)
/// as [`crate::SoftwareRasterizer::draw`] does, `texture` sampled when there is one, the
/// settings ask for it and the mesh has texture coordinates.
pub fn draw(
    geometry: &Close2glFrame,
    camera: &Camera,
    settings: &RenderSettings,
    lighting: &Lighting,
    texture: Option<&Texture>,
) -> Buffers {
    let raster = &geometry.raster;
    let light_eye = ClipTransform::new(camera).eye(lighting.light_position);
    let light = Light::new(lighting, light_eye, settings.shading);
    let vertices = vertex_stage(raster, settings.shading, &light);
    let mut mips = Mips::default();
    mips.set(texture);
    let textured = settings.texture && raster.textured && mips.is_set();
    let shader = Shader {
        shading: settings.shading,
        color: settings.color,
        light,
        texture: textured.then_some((&mips, settings.texture_filter)),
    };
    let (width, height) = (geometry.viewport.width, geometry.viewport.height);
    let pixels = (width * height) as usize;
    let mut buffers = Buffers {
        image: Image::filled(width, height, pack(settings.background).to_le_bytes()),
        depth: vec![1.0; pixels],
        owners: vec![None; pixels],
    };
    let params = SetupParams {
        size: [width as i32, height as i32],
        used: Used {
            shading: varyings_used(settings.shading),
            textured,
        },
        drop_uncovered: false,
    };
    let per_primitive = triangles_per_primitive(geometry.topology);
    let (topology, indices) = (geometry.topology, &raster.primitives);
    set_up(
        topology,
        indices,
        0,
        &vertices,
        params,
        |set_up, triangle| {
            let owner = raster
                .triangles
                .get(set_up as usize / per_primitive)
                .copied();
            draw_triangle(triangle, owner, &shader, &mut buffers);
        },
    );
    buffers
}

/// Every vertex of `raster` with its varyings: the mesh's, then those clipping made.
fn vertex_stage(raster: &RasterGeometry, shading: Shading, light: &Light) -> Vec<Vertex> {
    let mut vertices: Vec<Vertex> = raster
        .vertices
        .iter()
        .map(|v| Vertex::lit(v, shading, light))
        .collect();
    let mesh = raster.vertices.len();
    for cut in &raster.cuts {
        let vertex = Vertex::cut(cut, &vertices[..mesh]);
        vertices.push(vertex);
    }
    vertices
}

/// One triangle, pixel by pixel over its bounding box (already within the viewport).
fn draw_triangle(t: &Triangle, owner: Option<u32>, shader: &Shader<'_>, buffers: &mut Buffers) {
    let [x0, y0, x1, y1] = t.footprint.bbox;
    let width = buffers.image.width as usize;
    for y in y0..=y1 {
        for x in x0..=x1 {
            // Each edge's constant holds the top-left rule: +1 for a left or a horizontal top
            // edge, so that a centre exactly on it is inside (> 0) and, on the neighbour's
            // right or bottom edge, outside.
            let inside = t.footprint.edges.iter().all(|e| e.at(x, y) > 0);
            if !inside {
                continue;
            }
            let z = depth(&t.planes, x, y);
            let i = y as usize * width + x as usize;
            // The depth test: less, as the reference's.
            if z < buffers.depth[i] {
                buffers.depth[i] = z;
                buffers.image.pixels[i] = shader.colour(&t.planes, x, y).to_le_bytes();
                buffers.owners[i] = owner;
            }
        }
    }
}

/// The depth at the centre of pixel (x, y): in exact arithmetic the plane's value there. In
/// f32 the last bit depends on where the sum starts, and the depth buffer sums as the fast
/// rasterizer's rows do, from the first column of the pixel's 64-pixel tile, then x's share.
fn depth(planes: &Planes, x: i32, y: i32) -> f32 {
    planes.depth_in_tile(x - x % TILE, x, y)
}

/// The frame's shading and texture.
struct Shader<'a> {
    shading: Shading,
    color: Vec3,
    light: Light,
    texture: Option<(&'a Mips, TextureFilter)>,
}

impl Shader<'_> {
    /// The colour of pixel (x, y) of the triangle whose `planes` these are, packed as the
    /// target stores it.
    fn colour(&self, planes: &Planes, x: i32, y: i32) -> u32 {
        let at = Pixel { planes, x, y };
        let colour = match self.shading {
            Shading::None => self.color,
            Shading::GouraudAd | Shading::GouraudAds => self.color * at.varying3(INTENSITY),
            Shading::Phong => {
                let (eye, normal) = (V8::splat(at.varying3(EYE)), V8::splat(at.varying3(NORMAL)));
                self.color * self.light.illumination(eye, normal).first()
            }
        };
        pack(match self.texture {
            Some((mips, filter)) => colour * texel(mips, filter, planes, x, y),
            None => colour,
        })
    }
}

/// One pixel centre of a triangle, where its planes are interpolated.
struct Pixel<'a> {
    planes: &'a Planes,
    x: i32,
    y: i32,
}

impl Pixel<'_> {
    /// Varying `k`, perspective-correct: its plane (the varying times 1/w) divided by 1/w's.
    fn varying(&self, k: usize) -> f32 {
        let (planes, x, y) = (self.planes, self.x, self.y);
        let w = 1.0 / planes.value_at(&planes.inv_w, x, y);
        planes.value_at(&planes.varyings[k], x, y) * w
    }

    fn varying3(&self, first: usize) -> Vec3 {
        Vec3::new(
            self.varying(first),
            self.varying(first + 1),
            self.varying(first + 2),
        )
    }

    /// The texture coordinates (s, t).
    fn st(&self) -> (f32, f32) {
        (self.varying(UV), self.varying(UV + 1))
    }
}

/// The texel at pixel (x, y) through `filter`, its level of detail taken, as GPUs take it,
/// from the differences of (s, t) across the 2×2 quad of pixels the pixel is in (from an even
/// column and row), whether or not the triangle covers the quad's other pixels.
fn texel(mips: &Mips, filter: TextureFilter, planes: &Planes, x: i32, y: i32) -> Vec3 {
    let st = |x: i32, y: i32| Pixel { planes, x, y }.st();
    let lod = || {
        let (left, top) = (x & !1, y & !1);
        let corner = st(left, top);
        let (right, below) = (st(left + 1, top), st(left, top + 1));
        let difference = |(s, t): (f32, f32)| (F8::splat(s - corner.0), F8::splat(t - corner.1));
        mips.footprint_log2(difference(right), difference(below))
    };
    let (s, t) = st(x, y);
    let (s, t) = (F8::splat(s), F8::splat(t));
    let texel = match filter {
        TextureFilter::Nearest => Nearest.sample(mips, s, t, lod),
        TextureFilter::Bilinear => Bilinear.sample(mips, s, t, lod),
        TextureFilter::Trilinear => Trilinear.sample(mips, s, t, lod),
    };
    texel.first()
}

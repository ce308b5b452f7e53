//! The rasterizer as the textbook writes it: the place to start reading. No threads, no tiles, no
//! SIMD lanes, nothing shared with the fast rasterizer ([`crate::SoftwareRasterizer`]) but the
//! pipeline's output it reads. It goes as the textbook's chapters go, one file each:
//! each vertex gets its varyings, lit for Gouraud ([`vertex`]); each primitive becomes triangles
//! (a line's and a point's rectangle are two: [`primitives`]); for each triangle every pixel of
//! its bounding box, one at a time, is inside when its centre is inside all three edges, the
//! top-left rule settling a centre exactly on one ([`coverage`]); it is drawn when nearer than
//! the depth buffer ([`depth`]), with its varyings interpolated perspective-correctly
//! ([`interpolation`]), coloured by the shading ([`lighting`]) times the texel the filter finds
//! ([`texturing`]), and stored as 8 bits ([`output`]).
//!
//! Every stage can make the classic mistakes of the rasterizer assignment on purpose
//! ([`RasterMistakes`], pinned in docs/raster-trace-format.md), so that the viewer shows each
//! beside the reference and `close2gl check` can tell which one a student's program made: it
//! draws the program's own triangles ([`draw_corners`]) with each and compares.
//!
//! `tests/golden.rs` holds the fast rasterizer to it on every golden scene: the same pixels
//! covered, exactly (both snap the corners to 1/256 pixel and decide coverage in integers); the
//! same triangle seen wherever the depth test is not a near tie; depth within 1e-6 and each
//! colour channel within one step of 255, the rounding of f32 planes against f64 here (and a
//! nearest texel may differ where (s, t) falls exactly on a texel's edge).

mod coverage;
mod depth;
mod interpolation;
mod lighting;
mod output;
mod primitives;
mod texturing;
mod vertex;

use close2gl_core::{
    Appearance, Camera, Close2glFrame, Image, Lighting, RasterMistakes, RasterRules, Shading,
    Texture, TextureFilter, Topology,
};
use close2gl_pipeline::matrices::ClipTransform;
use glam::Vec3;

pub use lighting::Light;
pub use vertex::Corner;
use vertex::Vertex;

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

/// How this drawing rasterizes: the legal choices it makes, the mistakes it makes on purpose,
/// which way its window's y runs (some mistakes are the program's own loops, which count rows
/// from where its origin is) and how finely it snaps corners for coverage.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rasterization {
    pub rules: RasterRules,
    pub mistakes: RasterMistakes,
    /// The program's y grows upwards (OpenGL's window coordinates); the picture's rows still run
    /// from the top.
    pub y_up: bool,
    /// Corners are snapped to 1/2^bits pixel for coverage (8, as GPUs and the fast rasterizer
    /// do; 2 to 8).
    pub subpixel_bits: u32,
    /// Only the rows `first..end` (from the top, before the output stage) are drawn, as
    /// `glScissor` would: every pixel is decided alone, so a band costs its share of the frame
    /// (check tries a mistake on one before the whole frame). None: every row.
    pub scissor: Option<[u32; 2]>,
}

impl Default for Rasterization {
    fn default() -> Self {
        Rasterization {
            rules: RasterRules::default(),
            mistakes: RasterMistakes::NONE,
            y_up: false,
            subpixel_bits: 8,
            scissor: None,
        }
    }
}

/// The frame's shading and texture.
pub struct Shader {
    pub shading: Shading,
    pub color: Vec3,
    pub light: Light,
    pub texture: Option<texturing::Mips>,
    pub filter: TextureFilter,
}

impl Shader {
    /// A shader for `shading` of `color`, lit by `light`, sampling `texture` (when given) with
    /// `filter`.
    pub fn new(
        shading: Shading,
        color: Vec3,
        light: Light,
        texture: Option<&Image>,
        filter: TextureFilter,
    ) -> Shader {
        let texture = texture.map(|t| texturing::Mips::new(t.mip_chain()));
        Shader {
            shading,
            color,
            light,
            texture,
            filter,
        }
    }
}

/// Draws the pipeline's output `geometry` (made with the software rasterizer on, for `camera`)
/// as [`crate::SoftwareRasterizer::draw`] does, `texture` sampled when there is one, the
/// settings ask for it and the mesh has texture coordinates.
pub fn draw(
    geometry: &Close2glFrame,
    camera: &Camera,
    settings: &Appearance,
    lighting: &Lighting,
    texture: Option<&Texture>,
) -> Buffers {
    draw_mistaken(
        geometry,
        camera,
        settings,
        lighting,
        texture,
        RasterMistakes::NONE,
    )
}

/// [`draw`], making `mistakes` on purpose (the picture in y-down window pixels, as Close2GL's).
pub fn draw_mistaken(
    geometry: &Close2glFrame,
    camera: &Camera,
    settings: &Appearance,
    lighting: &Lighting,
    texture: Option<&Texture>,
    mistakes: RasterMistakes,
) -> Buffers {
    let raster = &geometry.raster;
    let textured = settings.texture && raster.textured;
    let clip = ClipTransform::new(camera);
    let light = Light::new(
        lighting,
        clip.eye(lighting.light_position),
        lighting.light_position,
        settings.shading,
        mistakes,
    );
    let image = texture.filter(|_| textured).map(|t| &t.image);
    let shader = Shader::new(
        settings.shading,
        settings.color,
        light,
        image,
        settings.texture_filter,
    );
    let how = Rasterization {
        mistakes,
        ..Rasterization::default()
    };
    let vertices = vertex::stage(raster, &shader);
    let per_primitive = match geometry.topology {
        Topology::Triangles => 3,
        Topology::Lines => 2,
        Topology::Points => 1,
    };
    let mut triangles = Vec::new();
    for (i, primitive) in raster.primitives.chunks_exact(per_primitive).enumerate() {
        let corners: Vec<Vertex> = primitive.iter().map(|&k| vertices[k as usize]).collect();
        let owner = raster.triangles.get(i).copied();
        for triangle in primitives::triangles(&corners) {
            triangles.push((triangle, owner));
        }
    }
    let size = (geometry.viewport.width, geometry.viewport.height);
    rasterize(size, settings.background, &triangles, &shader, &how)
}

/// Draws triangles given corner by corner, in window pixels (y as `how.y_up` says) with each
/// corner's values, as a student's rasterizer received them: the colour of Gouraud's corners is
/// the corner's own (`Corner::rgb`, lit already), so `shader.color` multiplies only the other
/// shadings. Triangles are drawn in the order given, each with its mesh triangle's index.
pub fn draw_corners(
    size: (u32, u32),
    background: Vec3,
    triangles: &[([Corner; 3], u32)],
    shader: &Shader,
    how: &Rasterization,
) -> Buffers {
    let height = f64::from(size.1);
    let triangles: Vec<([Vertex; 3], Option<u32>)> = triangles
        .iter()
        .map(|(corners, owner)| {
            let vertex = |c: &Corner| c.vertex(how.y_up.then_some(height));
            (corners.each_ref().map(vertex), Some(*owner))
        })
        .collect();
    rasterize(size, background, &triangles, shader, how)
}

/// The textbook's loop: every triangle, in order, onto buffers cleared to `background` and the
/// far plane.
fn rasterize(
    (width, height): (u32, u32),
    background: Vec3,
    triangles: &[([Vertex; 3], Option<u32>)],
    shader: &Shader,
    how: &Rasterization,
) -> Buffers {
    let pixels = (width * height) as usize;
    let mut buffers = Buffers {
        image: Image::filled(width, height, output::background(background, how)),
        depth: vec![depth::clear_value(how.mistakes); pixels],
        owners: vec![None; pixels],
    };
    let window = coverage::Window::new(width, height, how);
    for (triangle, owner) in triangles {
        let Some(triangle) = coverage::Setup::new(triangle, &window) else {
            continue;
        };
        for (x, y) in triangle.pixels(&window) {
            let at = (y as u32 * width + x as u32) as usize;
            let weights = triangle.weights(x, y);
            let z = depth::interpolate(&triangle.corners, &weights, how.mistakes);
            if !depth::test(z, &mut buffers.depth[at], how) {
                continue;
            }
            let here = interpolation::Pixel::new(&triangle, x, y, how.mistakes);
            buffers.image.pixels[at] = output::pack(shader.colour(&here), how);
            buffers.owners[at] = *owner;
        }
    }
    output::finish(&mut buffers, how.mistakes);
    buffers
}

impl Shader {
    /// The colour of a pixel, in 0..1 (unclamped: the output stage converts it).
    fn colour(&self, here: &interpolation::Pixel) -> Vec3 {
        let colour = match self.shading {
            Shading::None => self.color,
            Shading::GouraudAd | Shading::GouraudAds => self.color * here.vec3(vertex::INTENSITY),
            Shading::Phong => {
                self.color
                    * (self.light).illuminate(here.vec3(vertex::EYE), here.vec3(vertex::NORMAL))
            }
        };
        match &self.texture {
            Some(mips) => colour * mips.sample(here, self.filter),
            None => colour,
        }
    }
}

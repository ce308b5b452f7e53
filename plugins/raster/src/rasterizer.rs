//! One software frame, top to bottom: the vertex stage (`vertex`), setup of every primitive to
//! triangles binned into tiles in one pass (`bin`, with `primitives` and `setup`), the tiles drawn in parallel
//! (`tile`: clear, then each triangle's rows, depth-tested and shaded in blocks of eight lanes),
//! and the tiles copied out as an image (`target`); while fates are recorded, which triangles
//! covered no pixel centre and which won none (`fates`).

use bevy_ecs::prelude::Resource;
use close2gl_core::{
    Camera, Close2glFrame, Fates, Lighting, RenderSettings, Shading, SoftwareFrame, Texture,
    TextureFilter,
};
use close2gl_pipeline::matrices::ClipTransform;
use rayon::iter::Either;
use rayon::prelude::*;

use crate::bin::{Bins, Primitives};
use crate::fates::Rasterized;
use crate::lighting::Light;
use crate::primitives::{SetupParams, triangles_per_primitive};
use crate::shading::{Colour, Flat, Gouraud, Phong, PixelShader, Shaded, Textured, Untextured};
use crate::target::{NO_TRIANGLE, TILE_PIXELS, Target, pack};
use crate::texture::{Bilinear, Filter, Mips, Nearest, Trilinear};
use crate::tile::{TileBuffers, draw_tile};
use crate::varyings::{Used, varyings_used};
use crate::vertex::{Vertex, vertex_stage};

/// The rasterizer's buffers, reused from frame to frame: a steady frame allocates nothing.
#[derive(Resource, Default)]
pub struct SoftwareRasterizer {
    vertices: Vec<Vertex>,
    bins: Bins,
    target: Target,
    mips: Mips,
    /// Scratch space for recording fates.
    flags: Vec<u8>,
}

/// A frame's constants.
struct Frame<'a> {
    geometry: &'a Close2glFrame,
    shading: Shading,
    light: Light,
    /// Whether the texture applies: asked for, and the mesh has texture coordinates.
    textured: bool,
}

impl SoftwareRasterizer {
    /// Takes `texture` (or none) as the one to sample from now on. Its mipmap chain is built
    /// here, once, not each frame: call it when the texture changes.
    pub fn set_texture(&mut self, texture: Option<&Texture>) {
        self.mips.set(texture);
    }

    /// Whether a texture is set.
    pub fn has_texture(&self) -> bool {
        self.mips.is_set()
    }

    /// Draws the pipeline's output `geometry` (which must have been made with the software
    /// rasterizer on, for `camera`) into `out`, textured with the texture set when there is
    /// one, the settings ask for it and the mesh has texture coordinates. While `fates.record` is set
    /// (and `fates` holds the pipeline's fates for `geometry`), also notes who drew each pixel
    /// ([`Self::owner`]) and moves the drawn triangles that covered no pixel centre or won
    /// none to `no_pixels` and `hidden`.
    pub fn draw(
        &mut self,
        geometry: &Close2glFrame,
        camera: &Camera,
        settings: &RenderSettings,
        lighting: &Lighting,
        out: &mut SoftwareFrame,
        fates: &mut Fates,
    ) {
        let light_eye = ClipTransform::new(camera).eye(lighting.light_position);
        let frame = Frame {
            geometry,
            shading: settings.shading,
            light: Light::new(lighting, light_eye, settings.shading),
            textured: settings.texture && geometry.raster.textured && self.mips.is_set(),
        };
        let size = geometry.viewport;
        self.target.resize(size.width, size.height, fates.record);
        vertex_stage(
            &geometry.raster,
            frame.shading,
            &frame.light,
            &mut self.vertices,
        );
        self.setup(&frame);
        self.shade(&frame, settings);
        self.target.resolve(&mut out.image.pixels);
        (out.image.width, out.image.height) = (size.width, size.height);
        if fates.record {
            self.record(geometry, fates);
        }
    }

    /// The mesh triangle that drew pixel (x, y) (the depth test's winner) in the last frame
    /// drawn while fates were recorded; None where no triangle drew, or when not recorded.
    pub fn owner(&self, x: u32, y: u32) -> Option<u32> {
        let id = *self.target.ids.get(self.target.index(x, y)?)?;
        (id != NO_TRIANGLE).then_some(id)
    }

    /// The depth buffer at pixel (x, y) after the last frame (1 where nothing drew).
    pub fn depth(&self, x: u32, y: u32) -> Option<f32> {
        self.target.depth.get(self.target.index(x, y)?).copied()
    }

    /// Every primitive to its triangles (two for a line or a point), binned, in order.
    fn setup(&mut self, frame: &Frame<'_>) {
        let geometry = frame.geometry;
        let params = SetupParams {
            size: [
                geometry.viewport.width as i32,
                geometry.viewport.height as i32,
            ],
            used: Used {
                shading: varyings_used(frame.shading),
                textured: frame.textured,
            },
            drop_uncovered: true,
        };
        let primitives = Primitives {
            topology: geometry.topology,
            indices: &geometry.raster.primitives,
            vertices: &self.vertices,
        };
        self.bins.fill(self.target.grid, primitives, params);
    }

    /// The tiles drawn with the frame's shading.
    fn shade(&mut self, frame: &Frame<'_>, settings: &RenderSettings) {
        let background = pack(settings.background);
        let color = settings.color;
        match settings.shading {
            Shading::None => self.shade_tiles(background, Flat(color), frame, settings),
            Shading::GouraudAd | Shading::GouraudAds => {
                self.shade_tiles(background, Gouraud { color }, frame, settings)
            }
            Shading::Phong => {
                let light = frame.light;
                self.shade_tiles(background, Phong { color, light }, frame, settings)
            }
        }
    }

    /// Moves the drawn triangles that covered no pixel centre or won none to `no_pixels` and
    /// `hidden`, and turns the id buffer's set-up triangles into mesh triangles.
    fn record(&mut self, geometry: &Close2glFrame, fates: &mut Fates) {
        let rasterized = Rasterized {
            bins: &self.bins,
            per_primitive: triangles_per_primitive(geometry.topology),
            mesh_triangles: &geometry.raster.triangles,
        };
        rasterized.record(&mut self.target.ids, &mut self.flags, fates);
    }

    /// The tiles drawn with a shading's colour, textured or not.
    fn shade_tiles<C: Colour>(
        &mut self,
        background: u32,
        colour: C,
        frame: &Frame<'_>,
        settings: &RenderSettings,
    ) {
        let tiles = Tiles {
            target: &mut self.target,
            bins: &self.bins,
            background,
        };
        if frame.textured {
            let mips = &self.mips;
            match settings.texture_filter {
                TextureFilter::Nearest => tiles.draw_textured(colour, mips, Nearest),
                TextureFilter::Bilinear => tiles.draw_textured(colour, mips, Bilinear),
                TextureFilter::Trilinear => tiles.draw_textured(colour, mips, Trilinear),
            }
        } else {
            tiles.draw(&Shaded {
                colour,
                texturing: Untextured,
            });
        }
    }
}

/// What every tile is drawn from, and into.
struct Tiles<'a> {
    target: &'a mut Target,
    bins: &'a Bins,
    background: u32,
}

impl Tiles<'_> {
    /// Every tile, with `colour` modulated by the texture sampled through `filter`.
    fn draw_textured<C: Colour, F: Filter>(self, colour: C, mips: &Mips, filter: F) {
        self.draw(&Shaded {
            colour,
            texturing: Textured { mips, filter },
        });
    }

    /// Every tile, in parallel: cleared, then its bin drawn with `shader`. Each tile gets its
    /// own piece of the id buffer, or an empty one when it is not recorded.
    fn draw<S: PixelShader>(self, shader: &S) {
        let grid = self.target.grid;
        let (bins, background) = (self.bins, self.background);
        let ids = match self.target.ids.is_empty() {
            true => Either::Left(
                (0..grid.tiles())
                    .into_par_iter()
                    .map(|_| <&mut [u32]>::default()),
            ),
            false => Either::Right(self.target.ids.par_chunks_mut(TILE_PIXELS)),
        };
        self.target
            .color
            .par_chunks_mut(TILE_PIXELS)
            .zip(self.target.depth.par_chunks_mut(TILE_PIXELS))
            .zip(ids)
            .enumerate()
            .for_each(|(tile, ((color, depth), ids))| {
                let rect = grid.tile_rect(tile);
                let buffers = TileBuffers { color, depth, ids };
                draw_tile(rect, buffers, background, bins, tile, shader);
            });
    }
}

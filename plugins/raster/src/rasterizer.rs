//! One software frame, top to bottom: the vertex stage (varyings for each vertex), setup (each
//! primitive to triangles with edges and planes), binning into tiles, the tiles drawn in
//! parallel (clear, rasterize, depth test, shade), and the tiles copied out as an image; while
//! fates are recorded, which triangles covered no pixel centre and which won none.

use bevy_ecs::prelude::Resource;
use close2gl_core::{
    Camera, Close2glFrame, Fates, Lighting, RenderSettings, Shading, SoftwareFrame, Texture,
    TextureFilter, Topology,
};
use close2gl_pipeline::matrices::ClipTransform;
use glam::Vec3;
use rayon::iter::Either;
use rayon::prelude::*;

use crate::bin::Bins;
use crate::fates::Rasterized;
use crate::primitives::{self, SetupParams, Vertex};
use crate::setup::{Triangle, Used, VARYINGS};
use crate::shading::{
    Colour, Flat, Gouraud, Light, Phong, PixelShader, Shaded, Textured, Untextured, pack,
    varyings_used, vertex_varyings,
};
use crate::target::{NO_TRIANGLE, TILE_PIXELS, Target};
use crate::texture::{Bilinear, Filter, Mips, Nearest, Trilinear};
use crate::tile::{TileBuffers, draw_tile};

/// Primitives set up per parallel task.
const SETUP_CHUNK: usize = 4096;

/// The rasterizer's buffers, reused from frame to frame: a steady frame allocates nothing.
#[derive(Resource, Default)]
pub struct SoftwareRasterizer {
    vertices: Vec<Vertex>,
    triangles: Vec<Triangle>,
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
    /// Draws the pipeline's output `geometry` (which must have been made with the software
    /// rasterizer on, for `camera`) into `out`, textured with `texture` when there is one, the
    /// settings ask for it and the mesh has texture coordinates. While `fates.record` is set
    /// (and `fates` holds the pipeline's fates for `geometry`), also notes who drew each pixel
    /// ([`Self::owner`]) and moves the drawn triangles that covered no pixel centre or won
    /// none to `no_pixels` and `hidden`.
    #[allow(clippy::too_many_arguments)]
    pub fn draw(
        &mut self,
        geometry: &Close2glFrame,
        camera: &Camera,
        settings: &RenderSettings,
        lighting: &Lighting,
        texture: Option<&Texture>,
        out: &mut SoftwareFrame,
        fates: &mut Fates,
    ) {
        let light_eye = ClipTransform::new(camera).eye(lighting.light_position);
        if let Some(texture) = texture {
            self.mips.update(texture);
        }
        let frame = Frame {
            geometry,
            shading: settings.shading,
            light: Light::new(lighting, light_eye, settings.shading),
            textured: settings.texture && geometry.raster.textured && texture.is_some(),
        };
        let size = geometry.viewport;
        self.target.resize(size.width, size.height, fates.record);
        self.vertex_stage(&frame);
        self.setup(&frame);
        self.bins.fill(self.target.grid, &self.triangles);
        let background = pack(settings.background);
        let color = settings.color;
        match settings.shading {
            Shading::None => self.shade_tiles(background, Flat(color), &frame, settings),
            Shading::GouraudAd | Shading::GouraudAds => {
                self.shade_tiles(background, Gouraud { color }, &frame, settings)
            }
            Shading::Phong => {
                let light = frame.light;
                self.shade_tiles(background, Phong { color, light }, &frame, settings)
            }
        }
        self.target.resolve(&mut out.pixels);
        (out.width, out.height) = (size.width, size.height);
        if fates.record {
            let rasterized = Rasterized {
                triangles: &self.triangles,
                per_primitive: triangles_per_primitive(geometry.topology),
                mesh_triangles: &geometry.raster.triangles,
            };
            rasterized.record(&mut self.target.ids, &mut self.flags, fates);
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

    /// Each vertex's window position and varyings: the mesh's vertices lit in parallel, then
    /// the vertices clipping made, interpolated from their triangle's corners.
    fn vertex_stage(&mut self, frame: &Frame<'_>) {
        let raster = &frame.geometry.raster;
        let mesh_vertices = raster.vertices.len();
        self.vertices.resize(
            mesh_vertices + raster.cuts.len(),
            Vertex {
                window: [0.0; 4],
                varyings: [0.0; VARYINGS],
            },
        );
        let (mesh, cuts) = self.vertices.split_at_mut(mesh_vertices);
        let (shading, light) = (frame.shading, &frame.light);
        mesh.par_chunks_mut(SETUP_CHUNK * 4)
            .zip(raster.vertices.par_chunks(SETUP_CHUNK * 4))
            .for_each(|(out, vertices)| {
                for (o, v) in out.iter_mut().zip(vertices) {
                    *o = Vertex {
                        window: v.window,
                        varyings: vertex_varyings(
                            shading,
                            light,
                            Vec3::from(v.eye),
                            Vec3::from(v.normal),
                            v.uv,
                        ),
                    };
                }
            });
        for (o, cut) in cuts.iter_mut().zip(&raster.cuts) {
            let mut varyings = [0.0; VARYINGS];
            for (corner, weight) in cut.corners.iter().zip(cut.weights) {
                let from = &mesh[*corner as usize].varyings;
                for (v, f) in varyings.iter_mut().zip(from) {
                    *v += weight * f;
                }
            }
            *o = Vertex {
                window: cut.window,
                varyings,
            };
        }
    }

    /// Every primitive to its triangles (two for a line or a point), in order.
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
        };
        let per_primitive = match geometry.topology {
            Topology::Triangles => 3,
            Topology::Lines => 2,
            Topology::Points => 1,
        };
        let triangles_per = triangles_per_primitive(geometry.topology);
        let indices = &geometry.raster.primitives;
        let count = indices.len() / per_primitive;
        self.triangles
            .resize(count * triangles_per, Triangle::EMPTY);
        let vertices = &self.vertices;
        let vertex = |i: u32| vertices[i as usize];
        self.triangles
            .par_chunks_mut(SETUP_CHUNK * triangles_per)
            .zip(indices.par_chunks(SETUP_CHUNK * per_primitive))
            .for_each(|(out, indices)| {
                let primitives = indices.chunks_exact(per_primitive);
                match geometry.topology {
                    Topology::Triangles => {
                        for (o, p) in out.iter_mut().zip(primitives) {
                            *o = primitives::triangle([p[0], p[1], p[2]].map(vertex), params);
                        }
                    }
                    Topology::Lines => {
                        for (o, p) in out.chunks_exact_mut(2).zip(primitives) {
                            o.copy_from_slice(&primitives::line(
                                vertex(p[0]),
                                vertex(p[1]),
                                params,
                            ));
                        }
                    }
                    Topology::Points => {
                        for (o, p) in out.chunks_exact_mut(2).zip(primitives) {
                            o.copy_from_slice(&primitives::point(vertex(p[0]), params));
                        }
                    }
                }
            });
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
            triangles: &self.triangles,
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

/// How many triangles setup makes of each primitive: a line's and a point's rectangles are two.
fn triangles_per_primitive(topology: Topology) -> usize {
    match topology {
        Topology::Triangles => 1,
        Topology::Lines | Topology::Points => 2,
    }
}

/// What every tile is drawn from, and into.
struct Tiles<'a> {
    target: &'a mut Target,
    bins: &'a Bins,
    triangles: &'a [Triangle],
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
        let (bins, triangles, background) = (&self.bins.tiles, self.triangles, self.background);
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
                draw_tile(rect, buffers, background, &bins[tile], triangles, shader);
            });
    }
}

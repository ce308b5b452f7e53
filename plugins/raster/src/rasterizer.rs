//! One software frame, top to bottom: the vertex stage (`vertex`), setup of every primitive to
//! triangles binned into tiles in one pass (`bin`, with `primitives` and `setup`), the tiles
//! shared out between the threads (`tile_runs`) and drawn in parallel, each one of three ways:
//! cleared, then each triangle's rows depth-tested and shaded in blocks of eight lanes as they
//! pass (`tile`); the same with a small triangle's partial blocks queued and shaded eight
//! pixels together (`queue`, Phong); or every triangle depth-tested first and each pixel shaded
//! once after (`deferred`, Phong in tiles of small triangles). Then the tiles are copied out as
//! an image (`target`); while fates are recorded, which triangles covered no pixel centre and
//! which won none (`pixel_fates`).

use bevy_ecs::prelude::Resource;
use close2gl_core::{
    Appearance, Camera, Close2glFrame, Fates, Lighting, Shading, SoftwareFrame, Texture,
    TextureFilter,
};
use close2gl_pipeline::matrices::ClipTransform;

use crate::bin::{Bins, Primitives};
use crate::deferred::draw_tile_deferred;
use crate::lighting::Light;
use crate::pixel_fates::Rasterized;
use crate::primitives::{SetupParams, triangles_per_primitive};
use crate::queue::Pending;
use crate::sampling::{Bilinear, Filter, Mips, Nearest, Trilinear};
use crate::shading::{
    Colour, Flat, Gouraud, LaneShader, Phong, PixelShader, Shaded, Textured, Untextured,
};
use crate::target::{NO_TRIANGLE, Target, pack_background};
use crate::tile::{TileJob, draw_tile, draw_tile_unqueued};
use crate::tile_runs::TileRuns;
use crate::varyings::{Used, varyings_used};
use crate::vertex::{Vertex, vertex_stage};

/// The rasterizer's buffers, reused from frame to frame: a steady frame allocates nothing.
#[derive(Resource, Default)]
pub struct SoftwareRasterizer {
    vertices: Vec<Vertex>,
    bins: Bins,
    target: Target,
    runs: TileRuns,
    mips: Mips,
    /// Scratch space for recording fates.
    flags: Vec<u8>,
}

/// What stays the same for every triangle of a frame.
struct RasterConstants<'a> {
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
        settings: &Appearance,
        lighting: &Lighting,
        out: &mut SoftwareFrame,
        fates: &mut Fates,
    ) {
        let light_eye = ClipTransform::new(camera).eye(lighting.light_position);
        let light = Light::new(lighting, light_eye, settings.shading);
        let farthest = vertex_stage(
            &geometry.raster,
            settings.shading,
            &light,
            &mut self.vertices,
        );
        // Gouraud has lit its vertices by then, in the pass that found the farthest.
        let light = match settings.shading {
            Shading::Phong => light.reaching(farthest),
            _ => light,
        };
        let constants = RasterConstants {
            geometry,
            shading: settings.shading,
            light,
            textured: settings.texture && geometry.raster.textured && self.mips.is_set(),
        };
        let size = geometry.viewport;
        self.target.resize(size.width, size.height, fates.record);
        self.setup(&constants);
        self.shade(&constants, settings);
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
    fn setup(&mut self, constants: &RasterConstants<'_>) {
        let geometry = constants.geometry;
        let params = SetupParams {
            size: [
                geometry.viewport.width as i32,
                geometry.viewport.height as i32,
            ],
            used: Used {
                shading: varyings_used(constants.shading),
                textured: constants.textured,
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
    fn shade(&mut self, constants: &RasterConstants<'_>, settings: &Appearance) {
        let background = pack_background(settings.background);
        let color = settings.color;
        match settings.shading {
            Shading::None => self.shade_tiles(background, Flat(color), constants, settings),
            Shading::GouraudAd | Shading::GouraudAds => {
                self.shade_tiles(background, Gouraud { color }, constants, settings)
            }
            Shading::Phong => {
                let light = constants.light;
                self.shade_tiles(background, Phong { color, light }, constants, settings)
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
        constants: &RasterConstants<'_>,
        settings: &Appearance,
    ) {
        let tiles = Tiles {
            target: &mut self.target,
            runs: &mut self.runs,
            bins: &self.bins,
            background,
            defer_from: DEFER_FROM,
        };
        if constants.textured {
            let mips = &self.mips;
            match settings.texture_filter {
                TextureFilter::Nearest => tiles.draw_textured(colour, mips, Nearest),
                TextureFilter::Bilinear => tiles.draw_textured(colour, mips, Bilinear),
                TextureFilter::Trilinear => tiles.draw_textured(colour, mips, Trilinear),
            }
        } else {
            let shader = Shaded {
                colour,
                texturing: Untextured,
            };
            // Only Phong's lighting at every pixel costs more than a second pass over the tile
            // or queueing partial blocks (Gouraud's interpolated colour measured slower either
            // way: docs/performance.md#big-models-a-million-sub-pixel-triangles).
            match constants.shading {
                Shading::Phong => tiles.draw_deferred(&shader),
                _ => tiles.draw(&shader),
            }
        }
    }
}

/// Triangles binned in a tile from which it is shaded after its depth test: a whole tile
/// (4,096 pixels) of them would average 8 pixels or less. Larger triangles fill whole blocks
/// of eight lanes as they pass, or their partial blocks are queued, and the second pass over
/// the tile would only add work (from 256, the knot measured slower:
/// docs/performance.md#big-models-a-million-sub-pixel-triangles).
const DEFER_FROM: usize = 512;

/// What every tile is drawn from, and into.
struct Tiles<'a> {
    target: &'a mut Target,
    runs: &'a mut TileRuns,
    bins: &'a Bins,
    background: u32,
    /// Triangles binned in a tile from which `draw_deferred` defers it ([`DEFER_FROM`]).
    defer_from: usize,
}

impl Tiles<'_> {
    /// Every tile, with `colour` modulated by the texture sampled through `filter`.
    fn draw_textured<C: Colour, F: Filter>(self, colour: C, mips: &Mips, filter: F) {
        self.draw(&Shaded {
            colour,
            texturing: Textured { mips, filter },
        });
    }

    /// Every tile, in parallel, drawn with `shader` as each fragment passes the depth test.
    fn draw<S: PixelShader>(self, shader: &S) {
        self.each(|job| draw_tile_unqueued(job, shader));
    }

    /// Every tile, in parallel, shaded with `shader` once per pixel after the depth test where
    /// its triangles are small, else as each fragment passes, partial blocks queued (see
    /// `queue`): the same pixels either way.
    fn draw_deferred<S: PixelShader + LaneShader>(self, shader: &S) {
        let defer_from = self.defer_from;
        self.each(|job| match job.bins.binned(job.tile) >= defer_from {
            true => draw_tile_deferred(job, shader),
            false => {
                let mut queue = Pending::new(job.rect);
                draw_tile(job, shader, &mut queue)
            }
        });
    }

    /// `draw(job)` for every tile, in parallel, shared between the threads by what is binned
    /// in each (see `tile_runs`). Each tile gets its own piece of the id buffer, or an empty one
    /// when it is not recorded.
    fn each(self, draw: impl Fn(TileJob<'_>) + Sync) {
        let grid = self.target.grid;
        let (bins, background) = (self.bins, self.background);
        self.runs.draw(
            self.target,
            |tile| bins.binned(tile),
            |tile, buffers| {
                draw(TileJob {
                    tile,
                    rect: grid.tile_rect(tile),
                    buffers,
                    background,
                    bins,
                })
            },
        );
    }
}

#[cfg(test)]
mod tests {
    use close2gl_core::{Lighting, Mesh, Viewport};
    use close2gl_pipeline::FastPipeline;
    use glam::{Vec2, Vec3};

    use crate::bin::{Batch, NO_PLANES};

    use super::*;

    /// A grid of small triangles with normals that vary from corner to corner, and two large
    /// triangles across part of it, nearer the eye: tiles of small triangles, of large ones
    /// and of both.
    fn scene() -> (Mesh, Camera) {
        let mut mesh = Mesh::default();
        let n = 90;
        for j in 0..=n {
            for i in 0..=n {
                let (x, y) = (
                    i as f32 / n as f32 * 4.0 - 2.0,
                    j as f32 / n as f32 * 3.0 - 1.5,
                );
                mesh.positions
                    .push(Vec3::new(x, y, -2.0 - 0.1 * (x * 3.0).sin()));
                let tilt = Vec2::new((i * 7 % 5) as f32, (j * 3 % 7) as f32) * 0.1;
                mesh.normals
                    .push(Vec3::new(tilt.x, tilt.y, 1.0).normalize());
            }
        }
        let at = |i: u32, j: u32| j * (n + 1) + i;
        for j in 0..n {
            for i in 0..n {
                mesh.triangles
                    .push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                mesh.triangles
                    .push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
            }
        }
        let first = mesh.positions.len() as u32;
        for p in [[-0.6, -0.5], [0.7, -0.4], [0.1, 0.6]] {
            mesh.positions.push(Vec3::new(p[0], p[1], -1.5));
            mesh.normals.push(Vec3::new(0.3, 0.2, 1.0).normalize());
        }
        mesh.triangles.push([first, first + 1, first + 2]);
        let camera = Camera {
            hfov: 90.0,
            vfov: 75.0,
            near: 0.5,
            far: 10.0,
            ..Camera::default()
        };
        (mesh, camera)
    }

    #[test]
    fn phong_shaded_after_the_depth_test_or_queued_is_phong_shaded_as_fragments_pass() {
        let (mesh, camera) = scene();
        let pipeline = close2gl_core::PipelineSettings {
            close2gl_raster: close2gl_core::Rasterizer::Software,
            ..Default::default()
        };
        let look = close2gl_core::Appearance {
            shading: Shading::Phong,
            ..Default::default()
        };
        let lighting = Lighting::default();
        let viewport = Viewport {
            width: 333,
            height: 201,
        };
        let (mut geometry, mut fates) = (Close2glFrame::default(), Fates::default());
        FastPipeline::default().run(
            &mesh,
            &camera,
            &pipeline,
            viewport,
            &mut geometry,
            &mut fates,
        );
        let mut rasterizer = SoftwareRasterizer::default();
        let mut image = SoftwareFrame::default();
        rasterizer.draw(&geometry, &camera, &look, &lighting, &mut image, &mut fates);
        let drawn = rasterizer.target.color.clone();
        let background = pack_background(look.background);
        let covered = drawn.iter().filter(|&&c| c != background).count();
        assert!(
            covered > drawn.len() / 2,
            "{covered} of {} pixels",
            drawn.len()
        );
        let deferred = (0..rasterizer.target.grid.tiles())
            .filter(|&t| rasterizer.bins.binned(t) >= DEFER_FROM)
            .count();
        assert!(deferred > 0 && deferred < rasterizer.target.grid.tiles());
        // Small triangles whose fragments carry their values, with no planes stored.
        let values_only = |b: &Batch| b.slots.contains(&NO_PLANES);
        assert!(rasterizer.bins.batches.iter().any(values_only));

        let light_eye = ClipTransform::new(&camera).eye(lighting.light_position);
        let light = Light::new(&lighting, light_eye, Shading::Phong);
        let shader = Shaded {
            colour: Phong {
                color: look.color,
                light,
            },
            texturing: Untextured,
        };
        // Every tile deferred, every tile queued, and every tile shaded block by block as it
        // passes, with no queue.
        for way in ["deferred", "queued", "unqueued"] {
            let tiles = Tiles {
                target: &mut rasterizer.target,
                runs: &mut rasterizer.runs,
                bins: &rasterizer.bins,
                background,
                defer_from: if way == "deferred" { 0 } else { usize::MAX },
            };
            match way {
                "unqueued" => tiles.draw(&shader),
                _ => tiles.draw_deferred(&shader),
            }
            let differing = drawn
                .iter()
                .zip(&rasterizer.target.color)
                .filter(|(a, b)| a != b)
                .count();
            assert_eq!(differing, 0, "every tile {way}");
        }
    }
}

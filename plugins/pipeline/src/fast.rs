//! The Close2GL frame for big meshes. Same stage, same output as the textbook path, but each
//! unique vertex is transformed once (the mesh is indexed), and both the vertices and the
//! triangles are processed in parallel chunks whose outputs are joined in order, so the 2D buffer
//! is the same whatever the thread count. All buffers live in [`FastPipeline`] and are reused:
//! a steady frame allocates nothing.

use bevy_ecs::prelude::Resource;
use close2gl_core::{
    Camera, Close2glFrame, Mesh, RasterGeometry, RasterVertex, Rasterizer, RenderSettings,
    StageCounts, Viewport,
};
use glam::Vec3;
use rayon::prelude::*;

use crate::clip::Outcode;
use crate::matrices::ClipTransform;
use crate::stage::{CUT, Emit, RasterEmit, RasterOut, Stage, corner, process, to_window_depth};
use crate::tally;

/// Vertices and triangles per parallel task: big enough to amortise scheduling, small enough to
/// balance two cores when one side of the model is clipped away.
const VERTEX_CHUNK: usize = 16 * 1024;
const TRIANGLE_CHUNK: usize = 16 * 1024;

/// One task's share of the output.
#[derive(Default)]
struct Chunk {
    vertices: Vec<[f32; 2]>,
    raster: RasterOut,
    counts: StageCounts,
}

/// The reusable buffers of the fast path.
/// Per-vertex data is kept as structure-of-arrays: the common trivially-inside triangle reads
/// only three outcodes and three window positions. Clip coordinates are not kept: the few
/// triangles that straddle the view volume's border transform their corners again, which costs
/// less than writing and reading back 16 bytes for every vertex.
#[derive(Resource, Default)]
pub struct FastPipeline {
    codes: Vec<Outcode>,
    window: Vec<[f32; 2]>,
    chunks: Vec<Chunk>,
}

impl FastPipeline {
    /// Fills `frame` with exactly what [`crate::textbook::run`] returns.
    pub fn run(
        &mut self,
        mesh: &Mesh,
        camera: &Camera,
        settings: &RenderSettings,
        viewport: Viewport,
        frame: &mut Close2glFrame,
    ) {
        let transform = ClipTransform::new(camera);
        let stage = Stage::new(settings, viewport);
        let raster = settings.close2gl_raster == Rasterizer::Software;
        self.transform_vertices(&mesh.positions, &transform, &stage);

        if raster {
            raster_vertices(mesh, &transform, &stage, &mut frame.raster.vertices);
            frame.raster.textured = !mesh.uvs.is_empty();
        }

        // Clip, divide, map, cull and emit the triangles, chunk by chunk.
        let (positions, codes, window) = (&mesh.positions, &self.codes, &self.window);
        let tasks = mesh.triangles.len().div_ceil(TRIANGLE_CHUNK);
        self.chunks.resize_with(tasks, Chunk::default);
        self.chunks
            .par_iter_mut()
            .zip(mesh.triangles.par_chunks(TRIANGLE_CHUNK))
            .for_each(|(chunk, triangles)| {
                chunk.vertices.clear();
                chunk.raster.primitives.clear();
                chunk.raster.cuts.clear();
                let corners = Corners {
                    positions,
                    codes,
                    window,
                    transform: &transform,
                };
                chunk.counts = if raster {
                    let mut out = RasterEmit {
                        window: &mut chunk.vertices,
                        raster: &mut chunk.raster,
                    };
                    corners.process(triangles, &stage, &mut out)
                } else {
                    corners.process(triangles, &stage, &mut chunk.vertices)
                };
            });

        // Join the chunks in mesh order. In a steady frame the buffer already has about the
        // right length, so resizing costs nothing and the copy runs in parallel.
        let chunks = &self.chunks[..tasks];
        frame
            .vertices
            .resize(chunks.iter().map(|c| c.vertices.len()).sum(), [0.0; 2]);
        join(chunks, &mut frame.vertices);
        if raster {
            join_raster(chunks, &mut frame.raster);
        } else {
            frame.raster.vertices.clear();
            frame.raster.cuts.clear();
            frame.raster.primitives.clear();
        }
        frame.topology = stage.topology();
        frame.viewport = viewport;
        frame.counts = total_counts(chunks);
    }

    /// Transforms every unique vertex once, into its outcode and window position.
    fn transform_vertices(&mut self, positions: &[Vec3], transform: &ClipTransform, stage: &Stage) {
        let vertices = positions.len();
        self.codes.resize(vertices, 0);
        self.window.resize(vertices, [0.0; 2]);
        self.codes
            .par_chunks_mut(VERTEX_CHUNK)
            .zip(self.window.par_chunks_mut(VERTEX_CHUNK))
            .zip(positions.par_chunks(VERTEX_CHUNK))
            .for_each(|((codes, window), positions)| {
                for (i, p) in positions.iter().enumerate() {
                    (codes[i], window[i]) = corner(transform.apply(*p), stage);
                }
            });
    }
}

/// The chunks' counts added up.
fn total_counts(chunks: &[Chunk]) -> StageCounts {
    let mut counts = StageCounts::default();
    for chunk in chunks {
        counts.triangles_in += chunk.counts.triangles_in;
        counts.clipped += chunk.counts.clipped;
        counts.culled += chunk.counts.culled;
        counts.drawn += chunk.counts.drawn;
        counts.output_primitives += chunk.counts.output_primitives;
    }
    counts
}

/// Copies the chunks' vertices, in order, into `out` (exactly as long as all of them), splitting
/// the work in halves across threads.
fn join(chunks: &[Chunk], out: &mut [[f32; 2]]) {
    if chunks.len() <= 2 {
        let mut at = 0;
        for chunk in chunks {
            out[at..at + chunk.vertices.len()].copy_from_slice(&chunk.vertices);
            at += chunk.vertices.len();
        }
        return;
    }
    let (left, right) = chunks.split_at(chunks.len() / 2);
    let (left_out, right_out) = out.split_at_mut(left.iter().map(|c| c.vertices.len()).sum());
    rayon::join(|| join(left, left_out), || join(right, right_out));
}

/// What the triangle loop reads per corner: positions (for the few triangles clipping cuts),
/// outcodes and window positions.
struct Corners<'a> {
    positions: &'a [Vec3],
    codes: &'a [Outcode],
    window: &'a [[f32; 2]],
    transform: &'a ClipTransform,
}

impl Corners<'_> {
    /// Clip, divide, map, cull and emit `triangles` into `out`; their counts.
    #[inline(always)]
    fn process(&self, triangles: &[[u32; 3]], stage: &Stage, out: &mut impl Emit) -> StageCounts {
        let mut counts = StageCounts::default();
        for triangle in triangles {
            let [a, b, c] = triangle.map(|i| i as usize);
            let fate = process(
                *triangle,
                [self.codes[a], self.codes[b], self.codes[c]],
                [self.window[a], self.window[b], self.window[c]],
                || [a, b, c].map(|i| self.transform.apply(self.positions[i])),
                stage,
                out,
            );
            tally(&mut counts, fate);
        }
        counts
    }
}

/// Each mesh vertex as the rasterizer needs it: window position, depth and 1/w (for vertices
/// inside the view volume; the others are only reached through clipping), eye-space position
/// and normal, texture coordinates.
fn raster_vertices(
    mesh: &Mesh,
    transform: &ClipTransform,
    stage: &Stage,
    out: &mut Vec<RasterVertex>,
) {
    out.resize(mesh.positions.len(), RasterVertex::default());
    let uvs = &mesh.uvs;
    out.par_chunks_mut(VERTEX_CHUNK)
        .zip(mesh.positions.par_chunks(VERTEX_CHUNK))
        .zip(mesh.normals.par_chunks(VERTEX_CHUNK))
        .enumerate()
        .for_each(|(chunk, ((out, positions), normals))| {
            let first = chunk * VERTEX_CHUNK;
            for (i, ((v, p), n)) in out.iter_mut().zip(positions).zip(normals).enumerate() {
                *v = RasterVertex {
                    window: to_window_depth(transform.apply(*p), &stage.viewport),
                    eye: transform.eye(*p).to_array(),
                    normal: transform.eye_normal(*n).to_array(),
                    uv: uvs.get(first + i).map_or([0.0; 2], |uv| uv.to_array()),
                };
            }
        });
}

/// Joins the chunks' primitives and cut vertices in mesh order, turning each chunk's own cut
/// indices into indices past the mesh vertices.
fn join_raster(chunks: &[Chunk], out: &mut RasterGeometry) {
    out.cuts.clear();
    out.primitives.clear();
    let mut base = out.vertices.len() as u32;
    for chunk in chunks {
        out.cuts.extend_from_slice(&chunk.raster.cuts);
        out.primitives
            .extend(chunk.raster.primitives.iter().map(|&i| match i & CUT {
                0 => i,
                _ => base + (i & !CUT),
            }));
        base += chunk.raster.cuts.len() as u32;
    }
}

//! The Close2GL frame for big meshes. Same constants, same output as the textbook path, but each
//! unique vertex is transformed once (the mesh is indexed), and both the vertices and the
//! triangles are processed in parallel chunks whose outputs are joined in order, so the 2D buffer
//! is the same whatever the thread count. All buffers live in [`FastPipeline`] and are reused:
//! a steady frame allocates nothing.

use bevy_ecs::prelude::Resource;
use close2gl_core::{
    Camera, Close2glFrame, FateCounts, Fates, Mesh, PipelineSettings, RasterGeometry, RasterVertex,
    Rasterizer, TriangleFate, Viewport,
};
use glam::Vec3;
use rayon::iter::Either;
use rayon::prelude::*;

use crate::Tally;
use crate::clip::Outcode;
use crate::matrices::ClipTransform;
use crate::stage::{
    CUT, Emit, FrameConstants, RasterEmit, RasterOut, corner, process, to_window_depth,
};

/// Vertices and triangles per parallel task: big enough to amortise scheduling, small enough to
/// balance two cores when one side of the model is clipped away, and to split a cow-sized model
/// (8,192 triangles, 4,096 vertices) across them (measured faster than 16 Ki each, for the knot
/// and for a million triangles: docs/performance.md#big-models-a-million-sub-pixel-triangles).
const VERTEX_CHUNK: usize = 2 * 1024;
const TRIANGLE_CHUNK: usize = 4 * 1024;

/// One task's share of the output.
#[derive(Default)]
struct Chunk {
    vertices: Vec<[f32; 2]>,
    raster: RasterOut,
    counts: Tally,
}

impl Chunk {
    /// Empty, its buffers kept for the next frame.
    fn clear(&mut self) {
        self.vertices.clear();
        self.raster.primitives.clear();
        self.raster.cuts.clear();
        self.raster.triangles.clear();
    }
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
    /// Fills `frame` and `fates` with exactly what [`crate::textbook::run_recording`] returns
    /// (each triangle's fate only when `fates.record` is set): the vertices transformed, the
    /// triangles clipped, divided, mapped, culled and emitted in parallel chunks, then joined.
    pub fn run(
        &mut self,
        mesh: &Mesh,
        camera: &Camera,
        settings: &PipelineSettings,
        viewport: Viewport,
        frame: &mut Close2glFrame,
        fates: &mut Fates,
    ) {
        let transform = ClipTransform::new(camera);
        let constants = FrameConstants::new(settings, viewport);
        let raster = settings.close2gl_raster == Rasterizer::Software;
        self.transform_vertices(&mesh.positions, &transform, &constants);
        if raster {
            raster_vertices(mesh, &transform, &constants, &mut frame.raster.vertices);
            frame.raster.textured = !mesh.uvs.is_empty();
        }
        let tasks = self.process_triangles(mesh, &transform, &constants, raster, fates);
        let total = self.join_into(tasks, raster, frame);
        frame.topology = constants.topology();
        frame.viewport = viewport;
        frame.counts = total.stage_counts();
        fates.counts = match fates.record {
            true => total.fate_counts(),
            false => FateCounts::default(),
        };
    }

    /// Clips, divides, maps, culls and emits the triangles chunk by chunk, in parallel; each
    /// chunk writes its triangles' fates into its own slice of `fates` when they are recorded.
    /// Returns the number of chunks.
    fn process_triangles(
        &mut self,
        mesh: &Mesh,
        transform: &ClipTransform,
        constants: &FrameConstants,
        raster: bool,
        fates: &mut Fates,
    ) -> usize {
        let (positions, codes, window) = (&mesh.positions, &self.codes, &self.window);
        let tasks = mesh.triangles.len().div_ceil(TRIANGLE_CHUNK);
        self.chunks.resize_with(tasks, Chunk::default);
        let record = fates.record;
        let recorded = if record { mesh.triangles.len() } else { 0 };
        fates.triangles.resize(recorded, TriangleFate::default());
        let fate_slices = match record {
            true => Either::Left(fates.triangles.par_chunks_mut(TRIANGLE_CHUNK)),
            false => Either::Right((0..tasks).into_par_iter().map(|_| <&mut [_]>::default())),
        };
        self.chunks
            .par_iter_mut()
            .zip(mesh.triangles.par_chunks(TRIANGLE_CHUNK))
            .zip(fate_slices)
            .enumerate()
            .for_each(|(task, ((chunk, triangles), fates))| {
                chunk.clear();
                let corners = Corners {
                    first: (task * TRIANGLE_CHUNK) as u32,
                    positions,
                    codes,
                    window,
                    transform,
                };
                let mut out = RasterEmit {
                    window: &mut chunk.vertices,
                    raster: &mut chunk.raster,
                };
                chunk.counts = match (raster, record) {
                    (true, true) => corners.process::<true>(triangles, constants, &mut out, fates),
                    (true, false) => {
                        corners.process::<false>(triangles, constants, &mut out, fates)
                    }
                    (false, true) => {
                        corners.process::<true>(triangles, constants, out.window, fates)
                    }
                    (false, false) => {
                        corners.process::<false>(triangles, constants, out.window, fates)
                    }
                };
            });
        tasks
    }

    /// Joins the first `tasks` chunks into `frame` in mesh order, and their counts. In a steady
    /// frame the buffers already have about the right length, so resizing costs nothing and the
    /// copies run in parallel.
    fn join_into(&self, tasks: usize, raster: bool, frame: &mut Close2glFrame) -> Tally {
        let chunks = &self.chunks[..tasks];
        join(chunks, &mut frame.vertices, &|c| &c.vertices);
        if raster {
            join_raster(chunks, &mut frame.raster);
        } else {
            frame.raster.vertices.clear();
            frame.raster.cuts.clear();
            frame.raster.primitives.clear();
            frame.raster.triangles.clear();
        }
        let mut total = Tally::default();
        chunks.iter().for_each(|chunk| total.merge(&chunk.counts));
        total
    }

    /// Transforms every unique vertex once, into its outcode and window position.
    fn transform_vertices(
        &mut self,
        positions: &[Vec3],
        transform: &ClipTransform,
        constants: &FrameConstants,
    ) {
        let vertices = positions.len();
        self.codes.resize(vertices, 0);
        self.window.resize(vertices, [0.0; 2]);
        self.codes
            .par_chunks_mut(VERTEX_CHUNK)
            .zip(self.window.par_chunks_mut(VERTEX_CHUNK))
            .zip(positions.par_chunks(VERTEX_CHUNK))
            .for_each(|((codes, window), positions)| {
                for (i, p) in positions.iter().enumerate() {
                    (codes[i], window[i]) = corner(transform.apply(*p), constants);
                }
            });
    }
}

/// Copies one part of every chunk (`part`) into `out`, in mesh order.
fn join<T: Copy + Default + Send + Sync>(
    chunks: &[Chunk],
    out: &mut Vec<T>,
    part: &(impl Fn(&Chunk) -> &[T] + Sync),
) {
    join_mapped(chunks, 0, out, part, &|_, from, to| {
        to.copy_from_slice(from)
    });
}

/// Copies one part of every chunk (`part`) into `out`, in mesh order, by `copy(cuts_before,
/// part, out)`, where `cuts_before` counts the cut vertices of the chunks before its own. The
/// work is split in halves across threads: copied on one thread, a million triangles'
/// primitives took much of the geometry stage (measured:
/// docs/performance.md#snapping-each-vertex-once-setup-inlined-the-geometrys-join-in-parallel).
fn join_mapped<T: Copy + Default + Send + Sync>(
    chunks: &[Chunk],
    cuts_before: u32,
    out: &mut Vec<T>,
    part: &(impl Fn(&Chunk) -> &[T] + Sync),
    copy: &(impl Fn(u32, &[T], &mut [T]) + Sync),
) {
    out.resize(chunks.iter().map(|c| part(c).len()).sum(), T::default());
    join_halves(chunks, cuts_before, out, part, copy);
}

/// [`join_mapped`] into `out`, exactly as long as the chunks' parts.
fn join_halves<T: Copy + Send + Sync>(
    chunks: &[Chunk],
    cuts_before: u32,
    out: &mut [T],
    part: &(impl Fn(&Chunk) -> &[T] + Sync),
    copy: &(impl Fn(u32, &[T], &mut [T]) + Sync),
) {
    if chunks.len() <= 2 {
        let (mut at, mut cuts) = (0, cuts_before);
        for chunk in chunks {
            let part = part(chunk);
            copy(cuts, part, &mut out[at..at + part.len()]);
            at += part.len();
            cuts += chunk.raster.cuts.len() as u32;
        }
        return;
    }
    let (left, right) = chunks.split_at(chunks.len() / 2);
    let (left_out, right_out) = out.split_at_mut(left.iter().map(|c| part(c).len()).sum());
    let right_cuts = cuts_before + left.iter().map(|c| c.raster.cuts.len() as u32).sum::<u32>();
    rayon::join(
        || join_halves(left, cuts_before, left_out, part, copy),
        || join_halves(right, right_cuts, right_out, part, copy),
    );
}

/// What the triangle loop reads per corner: positions (for the few triangles clipping cuts),
/// outcodes and window positions; and the mesh index of its first triangle.
struct Corners<'a> {
    first: u32,
    positions: &'a [Vec3],
    codes: &'a [Outcode],
    window: &'a [[f32; 2]],
    transform: &'a ClipTransform,
}

impl Corners<'_> {
    /// Clip, divide, map, cull and emit `triangles` into `out`; their counts. With `RECORD`, also
    /// their fates into `fates` (one per triangle), and the rasterizer is told each primitive's
    /// mesh triangle.
    #[inline(always)]
    fn process<const RECORD: bool>(
        &self,
        triangles: &[[u32; 3]],
        constants: &FrameConstants,
        out: &mut impl Emit,
        fates: &mut [TriangleFate],
    ) -> Tally {
        let mut counts = Tally::default();
        for (i, triangle) in triangles.iter().enumerate() {
            let [a, b, c] = triangle.map(|i| i as usize);
            let fate = process::<RECORD>(
                *triangle,
                [self.codes[a], self.codes[b], self.codes[c]],
                [self.window[a], self.window[b], self.window[c]],
                || [a, b, c].map(|i| self.transform.apply(self.positions[i])),
                constants,
                out,
            );
            counts.add(&fate);
            if RECORD {
                fates[i] = fate.fate;
                if let Some(raster) = out.raster() {
                    let index = self.first + i as u32;
                    raster
                        .triangles
                        .extend(std::iter::repeat_n(index, fate.primitives));
                }
            }
        }
        counts
    }
}

/// Each mesh vertex as the rasterizer needs it: window position, depth and 1/w (for vertices
/// inside the view volume; the others are only reached through clipping), eye-space position
/// and normal, texture coordinates.
/// The mesh's vertices as the software rasterizer takes them, for this camera and these frame constants.
pub(crate) fn raster_vertices_of(
    mesh: &Mesh,
    camera: &Camera,
    constants: &FrameConstants,
) -> Vec<RasterVertex> {
    let mut out = Vec::new();
    raster_vertices(mesh, &ClipTransform::new(camera), constants, &mut out);
    out
}

fn raster_vertices(
    mesh: &Mesh,
    transform: &ClipTransform,
    constants: &FrameConstants,
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
                    window: to_window_depth(transform.apply(*p), &constants.viewport),
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
    join(chunks, &mut out.cuts, &|c| &c.raster.cuts);
    join(chunks, &mut out.triangles, &|c| &c.raster.triangles);
    let base = out.vertices.len() as u32;
    join_mapped(
        chunks,
        base,
        &mut out.primitives,
        &|c| &c.raster.primitives,
        &|cuts_before, from, to| {
            for (o, &i) in to.iter_mut().zip(from) {
                *o = match i & CUT {
                    0 => i,
                    _ => cuts_before + (i & !CUT),
                };
            }
        },
    );
}

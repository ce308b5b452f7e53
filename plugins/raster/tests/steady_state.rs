//! A steady frame allocates nothing, in the pipeline's fast path and in the software rasterizer
//! after it: every buffer is reused. Counted with a global allocator that tallies every
//! allocation on the threads the frames run on (a rayon pool's workers).

use std::alloc::{GlobalAlloc, Layout, System};
use std::sync::atomic::{AtomicUsize, Ordering};

use close2gl_core::glam::Vec3;
use close2gl_core::{
    Appearance, Clipping, Mesh, PipelineSettings, Rasterizer, RenderMode, Shading, Viewport,
};

mod common;
use common::{Drawing, Scene};

struct Counting;

static ALLOCATIONS: AtomicUsize = AtomicUsize::new(0);

thread_local! {
    /// Set on the workers of the pool the frames run on: only their allocations are the
    /// frame's (the test harness's own thread allocates when it reports a slow test).
    static COUNTED: std::cell::Cell<bool> = const { std::cell::Cell::new(false) };
}

fn count() {
    if COUNTED.with(|c| c.get()) {
        ALLOCATIONS.fetch_add(1, Ordering::Relaxed);
    }
}

// SAFETY: forwards to the system allocator unchanged; only counts.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        // SAFETY: the caller upholds GlobalAlloc's contract, which System shares.
        unsafe { System.alloc(layout) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: as above.
        unsafe { System.dealloc(ptr, layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        // SAFETY: as above.
        unsafe { System.realloc(ptr, layout, new_size) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

/// A grid of quads big enough to be split across threads, seen so that some triangles straddle
/// the near and side planes (the clipping path runs too).
fn grid(n: u32) -> Mesh {
    let positions: Vec<Vec3> = (0..=n)
        .flat_map(|i| {
            (0..=n).map(move |j| {
                Vec3::new(
                    i as f32 / n as f32 * 4.0 - 2.0,
                    -0.5,
                    j as f32 / n as f32 * -8.0 + 1.0,
                )
            })
        })
        .collect();
    let at = |i: u32, j: u32| i * (n + 1) + j;
    let triangles = (0..n)
        .flat_map(|i| {
            (0..n).flat_map(move |j| {
                [
                    [at(i, j), at(i + 1, j), at(i + 1, j + 1)],
                    [at(i, j), at(i + 1, j + 1), at(i, j + 1)],
                ]
            })
        })
        .collect();
    Mesh {
        face_normals: Vec::new(),
        name: "grid".into(),
        normals: vec![Vec3::Y; positions.len()],
        positions,
        uvs: Vec::new(),
        triangles,
    }
}

/// Runs on one of rayon's workers. From any other thread, rayon's injector allocates a block for
/// every 63 jobs handed to the pool (one frame in several): rayon's bookkeeping, not a buffer of
/// the frame's.
#[test]
fn a_steady_frame_allocates_nothing() {
    rayon::ThreadPoolBuilder::new()
        .start_handler(|_| COUNTED.with(|c| c.set(true)))
        .build()
        .expect("a thread pool")
        .install(steady_frames);
}

fn steady_frames() {
    let mesh = grid(300);
    let texture = close2gl_core::Texture::default();
    let viewport = Viewport {
        width: 800,
        height: 600,
    };
    let scene = Scene::new(&mesh, viewport, Some(&texture));
    let mut drawing = Drawing::default();
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    drawing.draw(
        &scene,
        &PipelineSettings::default(),
        &Appearance::default(),
        false,
    );
    assert!(
        ALLOCATIONS.load(Ordering::SeqCst) > before,
        "the counter sees a first frame's buffers"
    );
    let software = [Shading::None, Shading::GouraudAds, Shading::Phong]
        .map(|shading| (Rasterizer::Software, shading));
    let every = [(Rasterizer::Gpu, Shading::None)]
        .into_iter()
        .chain(software);
    // The inspector off, then on: recording fates reuses its buffers too.
    for (record, (close2gl_raster, shading)) in [false, true]
        .into_iter()
        .flat_map(|record| every.clone().map(move |every| (record, every)))
    {
        for mode in [RenderMode::Solid, RenderMode::Wireframe, RenderMode::Points] {
            let pipeline = PipelineSettings {
                mode,
                clipping: Clipping::Full,
                backface_culling: false,
                close2gl_raster,
                ..PipelineSettings::default()
            };
            let look = Appearance {
                shading,
                ..Appearance::default()
            };
            let allocated =
                steady_frame_allocations(&mut drawing, &scene, &pipeline, &look, record);
            assert_eq!(
                allocated, 0,
                "{close2gl_raster:?} {shading:?} {mode:?} recording {record}: a steady frame allocated {allocated} times"
            );
        }
    }
}

/// How many times the third frame of `pipeline` and `look` allocates: two warm-up frames size every
/// buffer (and start rayon's pool).
fn steady_frame_allocations(
    drawing: &mut Drawing,
    scene: &Scene<'_>,
    pipeline: &PipelineSettings,
    look: &Appearance,
    record: bool,
) -> usize {
    drawing.draw(scene, pipeline, look, record);
    drawing.draw(scene, pipeline, look, record);
    let counts = drawing.frame.counts;
    assert!(counts.clipped > 0 && counts.drawn > 0, "{counts:?}");
    let before = ALLOCATIONS.load(Ordering::SeqCst);
    drawing.draw(scene, pipeline, look, record);
    ALLOCATIONS.load(Ordering::SeqCst) - before
}

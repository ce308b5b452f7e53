//! `close2gl bench`: times the Close2GL geometry stage (transform, full clipping, divide,
//! viewport, cull, 2D buffer written) against the straightforward version, in one run, and
//! prints medians and their ratio as JSON.

pub mod baseline;

use std::time::Instant;

use close2gl_core::limits::MAX_SEGMENTS;
use close2gl_core::{
    App, Camera, Clipping, Close2glFrame, Mesh, ModelSource, PrimitiveKind, RenderMode,
    RenderSettings, Viewport,
};
use close2gl_pipeline::FastPipeline;
use serde_json::json;

use super::CliError;
use super::scene::{SceneArgs, viewport};

#[derive(clap::Args, Debug, Default)]
pub struct BenchArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// With no MODEL: a generated sphere of about this many triangles.
    #[arg(long, default_value_t = 1_000_000)]
    pub triangles: usize,
    /// Frames timed for each version; the medians are reported.
    #[arg(long, default_value_t = 30)]
    pub frames: usize,
    /// Worker threads for the fast path (default: one per core).
    #[arg(long)]
    pub threads: Option<usize>,
    /// The viewport, WIDTHxHEIGHT (default: the configured window size).
    #[arg(long, value_name = "WxH")]
    pub size: Option<String>,
}

pub fn run(args: BenchArgs) -> Result<(), CliError> {
    if args.frames == 0 || args.triangles == 0 {
        return Err(CliError::Input(
            "bench: --frames and --triangles must be at least 1".into(),
        ));
    }
    let (mut app, settings, viewport) = scene(&args)?;
    let world = app.world_mut();
    let (mut meshes, mut cameras) = (world.query::<&Mesh>(), world.query::<&Camera>());
    let world = &*world;
    let (Ok(mesh), Ok(camera)) = (meshes.single(world), cameras.single(world)) else {
        return Err(CliError::Runtime(
            "bench: the scene has no mesh or camera".into(),
        ));
    };
    let threads = args
        .threads
        .unwrap_or_else(rayon::current_num_threads)
        .max(1);
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| CliError::Runtime(format!("bench: cannot start {threads} threads: {e}")))?;
    let mut pipeline = FastPipeline::default();
    let mut frame = Close2glFrame::default();
    let fast = pool.install(|| {
        median_ms(args.frames, || {
            pipeline.run(mesh, camera, &settings, viewport, &mut frame)
        })
    });
    let slow = median_ms(args.frames, || {
        std::hint::black_box(baseline::frame(mesh, camera, &settings, viewport));
    });

    let triangles = mesh.triangles.len();
    println!(
        "{}",
        json!({
            "triangles": triangles,
            "frames": args.frames,
            "threads": threads,
            "median_ms": fast,
            "triangles_per_sec": triangles as f64 / (fast / 1e3),
            "baseline_median_ms": slow,
            "speedup": slow / fast,
        })
    );
    Ok(())
}

/// The app for the model asked for (by default a sphere of about `--triangles` triangles) and
/// the settings the stage is measured with: solid triangles through full clipping.
fn scene(args: &BenchArgs) -> Result<(App, RenderSettings, Viewport), CliError> {
    let mut config = args.scene.config()?;
    if args.scene.model.is_none() {
        config.model = ModelSource::Primitive(PrimitiveKind::Sphere);
        (
            config.primitives.sphere_stacks,
            config.primitives.sphere_slices,
        ) = sphere_grid(args.triangles);
    }
    config.render.mode = RenderMode::Solid;
    config.render.clipping = Clipping::Full;
    let viewport = viewport(args.size.as_deref(), &config)?;
    let app = crate::build_app(&config, viewport).map_err(CliError::Input)?;
    Ok((app, config.render, viewport))
}

/// Sphere stacks and slices (slices = 2 · stacks) giving about `triangles` triangles.
pub fn sphere_grid(triangles: usize) -> (u32, u32) {
    let stacks = ((triangles as f64 / 4.0).sqrt().round() as u32).clamp(2, MAX_SEGMENTS);
    (stacks, (stacks * 2).min(MAX_SEGMENTS))
}

/// Runs `f` once to warm up, then `frames` times; the median wall time in milliseconds.
fn median_ms(frames: usize, mut f: impl FnMut()) -> f64 {
    f();
    let mut times: Vec<f64> = (0..frames)
        .map(|_| {
            let start = Instant::now();
            f();
            start.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    times.sort_by(f64::total_cmp);
    times[times.len() / 2]
}

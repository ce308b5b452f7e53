//! `close2gl bench`: times the Close2GL geometry stage (transform, full clipping, divide,
//! viewport, cull, 2D buffer written) against the straightforward version, in one run, and
//! prints medians and their ratio as JSON. `--raster` times the software rasterizer's whole
//! frame beside lavapipe's reference view of the same scene; `--fill` its fill rate; `--load` how
//! fast a model file loads.

pub mod baseline;
pub mod grid;
pub mod model_load;
pub mod raster;

use std::path::PathBuf;
use std::time::Instant;

use close2gl_config::Config;
use close2gl_core::limits::MAX_SEGMENTS;
use close2gl_core::{
    App, Camera, Clipping, Close2glFrame, Mesh, ModelSource, PrimitiveKind, RenderMode,
};
use close2gl_pipeline::FastPipeline;
use serde_json::json;

use super::CliError;
use super::scene_args::{SceneArgs, viewport};

/// `--raster`, `--fill` and `--load` time different things: at most one of them (clap says so,
/// with exit code 2, before anything runs).
#[derive(clap::Args, Debug, Default)]
#[command(group(clap::ArgGroup::new("mode").args(["raster", "fill", "load"])))]
pub struct BenchArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// With no MODEL: a generated sphere of about this many triangles (default for the geometry
    /// bench: 1,000,000; with --raster, the configured model unless this is given).
    #[arg(long)]
    pub triangles: Option<usize>,
    /// Time the software rasterizer's whole frame (geometry, raster, shading) beside the GPU
    /// reference view of the same scene (set the shading with --set render.shading=...).
    #[arg(long)]
    pub raster: bool,
    /// With --raster: instead of the model, a generated flat grid of about --triangles (default
    /// 1,000,000) triangles, each smaller than a pixel at 1920x1080.
    #[arg(long, requires = "raster", conflicts_with = "model")]
    pub grid: bool,
    /// Time the software rasterizer's fill rate on a screen of large triangles.
    #[arg(long)]
    pub fill: bool,
    /// Time loading this .in or .obj file into a mesh (reading, parsing, building the mesh).
    #[arg(long, value_name = "FILE")]
    pub load: Option<PathBuf>,
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
    if args.frames == 0 || args.triangles == Some(0) {
        return Err(CliError::Input(
            "bench: --frames and --triangles must be at least 1".into(),
        ));
    }
    let pool = thread_pool(args.threads)?;
    let report = if let Some(path) = &args.load {
        model_load::load(&args, path, &pool)?
    } else if args.fill {
        raster::fill(&args, &pool)?
    } else if args.raster {
        raster::frame(&args, &pool)?
    } else {
        geometry(&args, &pool)?
    };
    println!("{report}");
    Ok(())
}

/// The configuration, with the MODEL argument or, when there is none and `triangles` is given,
/// a sphere of about that many triangles.
fn scene_config(args: &BenchArgs, triangles: Option<usize>) -> Result<Config, CliError> {
    let mut config = args.scene.config()?;
    if let (None, Some(triangles)) = (&args.scene.model, triangles) {
        config.model = ModelSource::Primitive(PrimitiveKind::Sphere);
        (
            config.primitives.sphere_stacks,
            config.primitives.sphere_slices,
        ) = sphere_grid(triangles);
    }
    Ok(config)
}

/// The workers, `threads` of them (default: one per core).
fn thread_pool(threads: Option<usize>) -> Result<rayon::ThreadPool, CliError> {
    let threads = threads.unwrap_or_else(rayon::current_num_threads).max(1);
    rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .map_err(|e| CliError::Runtime(format!("bench: cannot start {threads} threads: {e}")))
}

/// The framed scene's mesh and camera.
fn scene(app: &mut App) -> Result<(Mesh, Camera), CliError> {
    let world = app.world_mut();
    let mesh = world.query::<&Mesh>().single(world).ok().cloned();
    let camera = world.query::<&Camera>().single(world).ok().copied();
    mesh.zip(camera)
        .ok_or_else(|| CliError::Runtime("bench: the scene has no mesh or camera".into()))
}

/// The geometry stage against the baseline.
fn geometry(args: &BenchArgs, pool: &rayon::ThreadPool) -> Result<serde_json::Value, CliError> {
    let mut config = scene_config(args, Some(args.triangles.unwrap_or(1_000_000)))?;
    // The stage the issue measures: solid triangles through full clipping.
    config.render.pipeline.mode = RenderMode::Solid;
    config.render.pipeline.clipping = Clipping::Full;
    let viewport = viewport(args.size.as_deref(), &config)?;
    let mut app = close2gl_app::build_app(&config, viewport).map_err(CliError::Input)?;
    let (mesh, camera) = &scene(&mut app)?;
    let settings = config.render.pipeline;
    let mut pipeline = FastPipeline::default();
    let mut frame = Close2glFrame::default();
    let mut fates = Default::default();
    let fast = pool.install(|| {
        median_ms(args.frames, || {
            pipeline.run(mesh, camera, &settings, viewport, &mut frame, &mut fates)
        })
    });
    let slow = median_ms(args.frames, || {
        std::hint::black_box(baseline::frame(mesh, camera, &settings, viewport));
    });

    let triangles = mesh.triangles.len();
    Ok(json!({
        "triangles": triangles,
        "frames": args.frames,
        "threads": pool.current_num_threads(),
        "median_ms": fast,
        "triangles_per_sec": triangles as f64 / (fast / 1e3),
        "baseline_median_ms": slow,
        "speedup": slow / fast,
    }))
}

/// Sphere stacks and slices (slices = 2 · stacks) giving about `triangles` triangles.
pub fn sphere_grid(triangles: usize) -> (u32, u32) {
    let stacks = ((triangles as f64 / 4.0).sqrt().round() as u32).clamp(2, MAX_SEGMENTS);
    (stacks, (stacks * 2).min(MAX_SEGMENTS))
}

/// Runs `f` once to warm up, then `frames` times; the median wall time in milliseconds.
pub fn median_ms(frames: usize, mut f: impl FnMut()) -> f64 {
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

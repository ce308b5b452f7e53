//! The Close2GL geometry stage (transform, full clipping, divide, viewport, cull, 2D buffer) on
//! spheres of 8 k (the course's cow), 100 k and 1 M triangles, and the straightforward baseline
//! on the same meshes; then the 1 M sphere with the near plane cutting through it, where full
//! clipping cuts thousands of triangles. Then the software rasterizer's whole frame (geometry,
//! raster, Phong shading) for the bundled knot at 640×480 and 1920×1080 beside the GPU's
//! reference view of the same scene, its fill rate on full-screen layers, the 1 M sphere at
//! 1920×1080, and the big-model grid (a million sub-pixel triangles) flat and Phong-shaded. Last, loading: a generated grid of 125 k triangles as a `.in` file and as an OBJ
//! file, file to mesh. `cargo bench` runs it; `close2gl bench` gives the same figures as JSON
//! (`close2gl bench --load FILE` for loading).

use std::time::Duration;

use close2gl::commands::bench::raster::{SoftwareTimer, layers};
use close2gl::commands::bench::{baseline, sphere_grid};
use close2gl::config::Config;
use close2gl::core::{
    Appearance, Camera, Close2glFrame, Mesh, ModelSource, PipelineSettings, PrimitiveKind,
    PrimitiveParams, Rasterizer, Shading, Viewport,
};
use close2gl::pipeline::FastPipeline;
use close2gl_gpu::{Gpu, OffscreenPlugin, render_offscreen};
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group, criterion_main};

fn scene(triangles: usize) -> (Mesh, Camera, Config) {
    let mut config = Config {
        model: ModelSource::Primitive(PrimitiveKind::Sphere),
        ..Config::default()
    };
    (
        config.primitives.sphere_stacks,
        config.primitives.sphere_slices,
    ) = sphere_grid(triangles);
    let viewport = Viewport {
        width: 1280,
        height: 720,
    };
    let mut app = close2gl::build_app(&config, viewport).expect("a sphere");
    let (mesh, camera) = parts(&mut app);
    (mesh, camera, config)
}

/// The framed scene's mesh and camera.
fn parts(app: &mut close2gl::core::App) -> (Mesh, Camera) {
    let world = app.world_mut();
    let mesh = world.query::<&Mesh>().single(world).expect("mesh").clone();
    let camera = *world.query::<&Camera>().single(world).expect("camera");
    (mesh, camera)
}

fn geometry_stage(c: &mut Criterion) {
    let mut group = c.benchmark_group("close2gl");
    group.sample_size(20);
    for size in [8_000, 100_000, 1_000_000] {
        let (mesh, camera, config) = scene(size);
        bench_fast_path(
            &mut group,
            BenchmarkId::new("fast", size),
            &mesh,
            &camera,
            &config,
        );
        group.bench_function(BenchmarkId::new("baseline", size), |b| {
            let settings = config.render.pipeline;
            b.iter(|| baseline::frame(&mesh, &camera, &settings, GEOMETRY_VIEWPORT))
        });
    }
    // The near plane a fifth of the radius into the sphere: its front cap is cut away.
    let (mesh, mut camera, config) = scene(1_000_000);
    camera.near = camera.distance() - 0.8 * config.primitives.sphere_radius;
    let id = BenchmarkId::new("fast_near_cut", 1_000_000);
    let frame = bench_fast_path(&mut group, id, &mesh, &camera, &config);
    assert!(frame.counts.clipped > 0, "the near plane cuts the sphere");
    group.finish();
}

const GEOMETRY_VIEWPORT: Viewport = Viewport {
    width: 1280,
    height: 720,
};

/// Times the fast path on one scene; returns its last frame.
fn bench_fast_path(
    group: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
    id: BenchmarkId,
    mesh: &Mesh,
    camera: &Camera,
    config: &close2gl::config::Config,
) -> Close2glFrame {
    group.throughput(Throughput::Elements(mesh.triangles.len() as u64));
    let mut pipeline = FastPipeline::default();
    let mut frame = Close2glFrame::default();
    let settings = config.render.pipeline;
    group.bench_function(id, |b| {
        b.iter(|| {
            let fates = &mut Default::default();
            pipeline.run(
                mesh,
                camera,
                &settings,
                GEOMETRY_VIEWPORT,
                &mut frame,
                fates,
            )
        })
    });
    frame
}

/// `close2gl bench --raster --grid`'s scene: a million sub-pixel triangles, framed.
fn grid_scene(viewport: Viewport) -> (Mesh, Camera) {
    let (.., config) = scene(12);
    let mut app = close2gl::build_app(&config, viewport).expect("a small sphere");
    let grid = close2gl::commands::bench::grid::grid(1_000_000);
    close2gl::commands::bench::grid::replace_model(&mut app, grid).expect("the grid");
    parts(&mut app)
}

/// The bundled knot (the course's cow's size), Phong, software.
fn knot(viewport: Viewport) -> close2gl::core::App {
    let mut config = Config {
        model: ModelSource::File(format!("{}/assets/knot.obj", env!("CARGO_MANIFEST_DIR")).into()),
        ..Config::default()
    };
    config.render.appearance.shading = Shading::Phong;
    config.render.pipeline.close2gl_raster = Rasterizer::Software;
    close2gl::build_app(&config, viewport).expect("the bundled knot")
}

fn software_raster(c: &mut Criterion) {
    let mut group = c.benchmark_group("raster");
    group.sample_size(20);
    let gpu = Gpu::headless(close2gl_gpu::wgpu::Backends::PRIMARY).ok();
    for (width, height) in [(640, 480), (1920, 1080)] {
        let viewport = Viewport { width, height };
        let mut app = knot(viewport);
        let (mesh, camera) = parts(&mut app);
        let pipeline = *app.world().resource::<PipelineSettings>();
        let look = *app.world().resource::<Appearance>();
        let lighting = *app.world().resource::<close2gl::core::Lighting>();
        let mut software = SoftwareTimer::default();
        let size = format!("{width}x{height}");
        group.bench_function(BenchmarkId::new("software_knot_phong", &size), |b| {
            b.iter(|| software.frame(&mesh, &camera, &pipeline, &look, &lighting, viewport))
        });
        // The GPU's reference view of the same scene, its work finished (lavapipe without a
        // GPU): the time render_offscreen measures around the reference draw alone.
        if let Some(gpu) = &gpu {
            app.add_plugins(OffscreenPlugin(gpu.clone()));
            group.bench_function(BenchmarkId::new("reference_knot_phong", &size), |b| {
                b.iter_custom(|iters| {
                    (0..iters)
                        .map(|_| render_offscreen(&mut app).expect("render").reference_ms)
                        .map(|ms| Duration::from_secs_f64(ms / 1e3))
                        .sum()
                })
            });
        }
    }
    let viewport = Viewport {
        width: 1920,
        height: 1080,
    };
    let (mesh, camera) = layers(8);
    let pipeline = PipelineSettings {
        close2gl_raster: Rasterizer::Software,
        ..Default::default()
    };
    let mut look = Appearance::default();
    let lighting = close2gl::core::Lighting::default();
    let mut software = SoftwareTimer::default();
    group.throughput(Throughput::Elements(8 * 1920 * 1080));
    group.bench_function("fill_8_layers_1920x1080", |b| {
        b.iter(|| software.frame(&mesh, &camera, &pipeline, &look, &lighting, viewport))
    });
    let (mesh, camera, _) = scene(1_000_000);
    look.shading = Shading::GouraudAds;
    group.throughput(Throughput::Elements(mesh.triangles.len() as u64));
    group.bench_function("sphere_1m_gouraud_1920x1080", |b| {
        b.iter(|| software.frame(&mesh, &camera, &pipeline, &look, &lighting, viewport))
    });
    let (mesh, camera) = grid_scene(viewport);
    for shading in [Shading::None, Shading::Phong] {
        look.shading = shading;
        let name = format!("grid_1m_{}_1920x1080", shading.name());
        group.bench_function(name, |b| {
            b.iter(|| software.frame(&mesh, &camera, &pipeline, &look, &lighting, viewport))
        });
    }
    group.finish();
}

/// A flat grid of 2 · 250² triangles written as a `.in` file (about 20 MB) and as an OBJ file,
/// loaded as the viewer loads a file; throughput in bytes of the file.
fn loading(c: &mut Criterion) {
    let dir = close2gl_testkit::TempDir::new("bench_loading");
    let mut group = c.benchmark_group("load");
    group.sample_size(10);
    let params = PrimitiveParams::default();
    for name in ["grid.in", "grid.obj"] {
        let path = dir.0.join(name);
        let grid = if name.ends_with(".in") {
            close2gl_testkit::write_grid_in(&path, "grid", 250)
        } else {
            close2gl_testkit::write_grid_obj(&path, "grid", 250)
        }
        .expect("write the grid");
        let source = ModelSource::File(path);
        group.throughput(Throughput::Bytes(grid.bytes));
        group.bench_function(name, |b| {
            b.iter(|| close2gl::model::load(&source, &params).expect("the grid loads"))
        });
    }
    group.finish();
}

criterion_group!(benches, geometry_stage, software_raster, loading);
criterion_main!(benches);

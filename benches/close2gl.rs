//! The Close2GL geometry stage (transform, full clipping, divide, viewport, cull, 2D buffer) on
//! spheres of 8 k (the course's cow), 100 k and 1 M triangles, and the straightforward baseline
//! on the same meshes; then the 1 M sphere with the near plane cutting through it, where full
//! clipping cuts thousands of triangles. `cargo bench` runs it; `close2gl bench` gives the framed
//! figures as JSON.

use close2gl::commands::bench::{baseline, sphere_grid};
use close2gl::config::Config;
use close2gl::core::{Camera, Close2glFrame, Mesh, ModelSource, PrimitiveKind, Viewport};
use close2gl::pipeline::FastPipeline;
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
    let mut app = close2gl::build_app(
        &config,
        Viewport {
            width: 1280,
            height: 720,
        },
    )
    .expect("a sphere");
    let world = app.world_mut();
    let mesh = world.query::<&Mesh>().single(world).expect("mesh").clone();
    let camera = *world.query::<&Camera>().single(world).expect("camera");
    (mesh, camera, config)
}

fn geometry_stage(c: &mut Criterion) {
    let viewport = Viewport {
        width: 1280,
        height: 720,
    };
    let mut group = c.benchmark_group("close2gl");
    group.sample_size(20);
    for size in [8_000, 100_000, 1_000_000] {
        let (mesh, camera, config) = scene(size);
        group.throughput(Throughput::Elements(mesh.triangles.len() as u64));
        let mut pipeline = FastPipeline::default();
        let mut frame = Close2glFrame::default();
        group.bench_function(BenchmarkId::new("fast", size), |b| {
            b.iter(|| pipeline.run(&mesh, &camera, &config.render, viewport, &mut frame))
        });
        group.bench_function(BenchmarkId::new("baseline", size), |b| {
            b.iter(|| baseline::frame(&mesh, &camera, &config.render, viewport))
        });
    }
    // The near plane a fifth of the radius into the sphere: its front cap is cut away.
    let (mesh, mut camera, config) = scene(1_000_000);
    camera.near = camera.distance() - 0.8 * config.primitives.sphere_radius;
    group.throughput(Throughput::Elements(mesh.triangles.len() as u64));
    let mut pipeline = FastPipeline::default();
    let mut frame = Close2glFrame::default();
    group.bench_function(BenchmarkId::new("fast_near_cut", 1_000_000), |b| {
        b.iter(|| pipeline.run(&mesh, &camera, &config.render, viewport, &mut frame))
    });
    assert!(frame.counts.clipped > 0, "the near plane cuts the sphere");
    group.finish();
}

criterion_group!(benches, geometry_stage);
criterion_main!(benches);

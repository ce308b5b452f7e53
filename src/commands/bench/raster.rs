//! `close2gl bench --raster` and `--fill`: the software rasterizer's whole frame (geometry,
//! raster, shading, the image finished) beside the GPU reference view of the same scene, and its
//! fill rate on a screen of large triangles.

use close2gl_core::{
    Appearance, Camera, Close2glFrame, Fates, Lighting, Mesh, PipelineSettings, Rasterizer,
    SoftwareFrame, Texture, Viewport,
};
use close2gl_gpu::{Gpu, OffscreenPlugin, render_offscreen};
use close2gl_pipeline::FastPipeline;
use close2gl_raster::SoftwareRasterizer;
use glam::Vec3;
use serde_json::{Value, json};

use super::{BenchArgs, median_ms, scene, scene_config};
use crate::commands::CliError;
use crate::commands::scene_args::viewport;

/// Geometry and raster, start to finish, on the configured scene.
pub fn frame(args: &BenchArgs, pool: &rayon::ThreadPool) -> Result<Value, CliError> {
    let mut config = match args.grid {
        // A small sphere stands in until the grid replaces it: no model file is read.
        true => scene_config(args, Some(12))?,
        false => scene_config(args, args.triangles)?,
    };
    config.render.pipeline.close2gl_raster = Rasterizer::Software;
    let viewport = viewport(args.size.as_deref(), &config)?;
    let mut app = close2gl_app::build_app(&config, viewport).map_err(CliError::Input)?;
    if args.grid {
        let mesh = super::grid::grid(args.triangles.unwrap_or(1_000_000));
        super::grid::replace_model(&mut app, mesh).map_err(CliError::Runtime)?;
    }
    let (mesh, camera) = scene(&mut app)?;
    let mut software = SoftwareTimer::default();
    software.set_texture(app.world().get_resource::<Texture>());
    let software_ms = pool.install(|| {
        median_ms(args.frames, || {
            let (pipeline, look) = (&config.render.pipeline, &config.render.appearance);
            software.frame(&mesh, &camera, pipeline, look, &config.lighting, viewport)
        })
    });
    let reference = reference_ms(&mut app, args.frames);
    let (reference_ms, adapter) = match &reference {
        Ok((ms, adapter)) => (json!(ms), json!(adapter)),
        Err(e) => (Value::Null, json!(format!("no GPU reference: {e}"))),
    };
    let ratio = reference.as_ref().ok().map(|(ms, _)| ms / software_ms);
    Ok(json!({
        "model": mesh.name,
        "triangles": mesh.triangles.len(),
        "size": [viewport.width, viewport.height],
        "mode": config.render.pipeline.mode.name(),
        "shading": config.render.appearance.shading.name(),
        "texture": (config.render.appearance.texture && !mesh.uvs.is_empty())
            .then(|| config.render.appearance.texture_filter.name()),
        "frames": args.frames,
        "threads": pool.current_num_threads(),
        "software_median_ms": software_ms,
        "triangles_per_sec": mesh.triangles.len() as f64 / (software_ms / 1e3),
        "reference_median_ms": reference_ms,
        "reference_over_software": ratio,
        "adapter": adapter,
    }))
}

/// Pixels per second on `layers` full-screen layers of large triangles, drawn back to front so
/// that every layer passes the depth test and every pixel is shaded `layers` times.
pub fn fill(args: &BenchArgs, pool: &rayon::ThreadPool) -> Result<Value, CliError> {
    const LAYERS: usize = 8;
    let config = args.scene.config()?;
    let viewport = viewport(args.size.as_deref().or(Some("1920x1080")), &config)?;
    let pipeline = PipelineSettings {
        close2gl_raster: Rasterizer::Software,
        ..config.render.pipeline
    };
    let look = config.render.appearance;
    let (mesh, camera) = layers(LAYERS);
    let mut software = SoftwareTimer::default();
    let ms = pool.install(|| {
        median_ms(args.frames, || {
            software.frame(&mesh, &camera, &pipeline, &look, &config.lighting, viewport)
        })
    });
    let pixels = (viewport.width * viewport.height) as f64 * LAYERS as f64;
    let covered = software.covered();
    Ok(json!({
        "size": [viewport.width, viewport.height],
        "layers": LAYERS,
        "triangles": mesh.triangles.len(),
        "shading": look.shading.name(),
        "frames": args.frames,
        "threads": pool.current_num_threads(),
        "median_ms": ms,
        "covered_fraction": covered,
        "pixels_per_sec": pixels / (ms / 1e3),
    }))
}

/// The pipeline, the rasterizer and their buffers, kept across frames as the app keeps them.
#[derive(Default)]
pub struct SoftwareTimer {
    pipeline: FastPipeline,
    rasterizer: SoftwareRasterizer,
    geometry: Close2glFrame,
    fates: Fates,
    image: SoftwareFrame,
}

impl SoftwareTimer {
    /// Samples `texture` from now on (none: untextured).
    pub fn set_texture(&mut self, texture: Option<&Texture>) {
        self.rasterizer.set_texture(texture);
    }

    /// One whole software frame: geometry, raster, shading, the image finished.
    pub fn frame(
        &mut self,
        mesh: &Mesh,
        camera: &Camera,
        pipeline: &PipelineSettings,
        look: &Appearance,
        lighting: &Lighting,
        viewport: Viewport,
    ) {
        self.pipeline.run(
            mesh,
            camera,
            pipeline,
            viewport,
            &mut self.geometry,
            &mut self.fates,
        );
        self.rasterizer.draw(
            &self.geometry,
            camera,
            look,
            lighting,
            &mut self.image,
            &mut self.fates,
        );
    }

    /// The share of the last image's pixels it covers.
    fn covered(&self) -> f64 {
        let covered = crate::commands::stats::covered(&self.image.image);
        covered as f64 / self.image.image.pixels.len().max(1) as f64
    }
}

/// Lavapipe's (or the adapter's) median time for the reference view, the GPU's work finished.
pub fn reference_ms(app: &mut close2gl_core::App, frames: usize) -> Result<(f64, String), String> {
    let gpu = Gpu::headless(close2gl_gpu::wgpu::Backends::PRIMARY)?;
    app.add_plugins(OffscreenPlugin(gpu.clone()));
    render_offscreen(app)?;
    let mut times = Vec::with_capacity(frames);
    for _ in 0..frames {
        times.push(render_offscreen(app)?.reference_ms);
    }
    times.sort_by(f64::total_cmp);
    Ok((times[times.len() / 2], gpu.adapter_name()))
}

/// `layers` squares filling a 90° view, one behind the other, listed back to front, each cut
/// into 8 large triangles; the camera at the origin looking down -z.
pub fn layers(layers: usize) -> (Mesh, Camera) {
    let mut mesh = Mesh {
        name: format!("{layers} full-screen layers"),
        ..Mesh::default()
    };
    for layer in 0..layers {
        let z = -2.0 + layer as f32 / layers as f32;
        let first = mesh.positions.len() as u32;
        for j in 0..3 {
            for i in 0..3 {
                let (x, y) = (i as f32 - 1.0, j as f32 - 1.0);
                mesh.positions
                    .push(Vec3::new(x * -z * 1.05, y * -z * 1.05, z));
                mesh.normals.push(Vec3::Z);
            }
        }
        for j in 0..2 {
            for i in 0..2 {
                let a = first + j * 3 + i;
                mesh.triangles.push([a, a + 1, a + 4]);
                mesh.triangles.push([a, a + 4, a + 3]);
            }
        }
    }
    let camera = Camera {
        hfov: 90.0,
        vfov: 90.0,
        near: 0.5,
        far: 10.0,
        ..Camera::default()
    };
    (mesh, camera)
}

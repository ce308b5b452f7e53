//! `close2gl inspect`: the pipeline inspector, headless. `--triangle N` prints one triangle's
//! journey through M, P, clipping, the division and V, beside the matrices (Close2GL's and the
//! reference's); `--pixel X,Y` prints who drew that pixel in each view, and for Close2GL every
//! triangle that reached it and why each lost. JSON, with the keys the panel shows.

use bevy_ecs::system::SystemState;
use close2gl_core::glam::DMat4;
use close2gl_core::{App, Camera, Fates, Mesh, Mistake, PipelineSettings, Viewport};
use close2gl_gpu::{Gpu, ProbedFrame};
use close2gl_pipeline::journey::{Journey, journey};
use close2gl_pipeline::matrices;
use close2gl_pipeline::mistakes::Mistakes;
use close2gl_pipeline::program::Program;
use close2gl_raster::coverage_probe::PixelProbe;
use glam::{Mat4, Vec3, Vec4};
use serde_json::{Value, json};

use super::CliError;
use super::scene_args::{SceneArgs, print_warnings, record_fates, viewport};

#[derive(clap::Args, Debug, Default)]
#[group(id = "question", required = true, multiple = false, args = ["pixel", "triangle"])]
pub struct InspectArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// The viewport, WIDTHxHEIGHT (default: the configured window size).
    #[arg(long, value_name = "WxH")]
    pub size: Option<String>,
    /// Who drew pixel X,Y (from the top-left) in each view, and who else reached it.
    #[arg(long, value_name = "X,Y")]
    pub pixel: Option<String>,
    /// Mesh triangle N's journey through the pipeline (0 is the first).
    #[arg(long, value_name = "N")]
    pub triangle: Option<usize>,
}

pub fn run(args: InspectArgs) -> Result<(), CliError> {
    let config = args.scene.config()?;
    let viewport = viewport(args.size.as_deref(), &config)?;
    let pixel = args
        .pixel
        .as_deref()
        .map(|p| parse_pixel(p, viewport))
        .transpose()?;
    let mut app = close2gl_app::build_app(&config, viewport).map_err(CliError::Input)?;
    print_warnings(&app);
    record_fates(&mut app);
    let report = match (args.triangle, pixel) {
        (Some(index), _) => triangle_report(&mut app, index, viewport)?,
        (None, Some(pixel)) => pixel_report(&mut app, pixel, viewport)?,
        (None, None) => {
            let text = "inspect: expected --pixel X,Y or --triangle N";
            return Err(CliError::Input(text.into()));
        }
    };
    println!("{report}");
    Ok(())
}

/// `X,Y`, inside the viewport.
fn parse_pixel(text: &str, viewport: Viewport) -> Result<(u32, u32), CliError> {
    let bad = || {
        CliError::Input(format!(
            "inspect: --pixel {text}: expected X,Y inside the {}x{} viewport (0,0 is the top-left)",
            viewport.width, viewport.height
        ))
    };
    let (x, y) = text.split_once(',').ok_or_else(bad)?;
    let (x, y) = (x.trim().parse::<u32>(), y.trim().parse::<u32>());
    match (x, y) {
        (Ok(x), Ok(y)) if x < viewport.width && y < viewport.height => Ok((x, y)),
        _ => Err(bad()),
    }
}

/// The scene as the app left it: mesh, camera, the pipeline's switches.
fn scene(app: &mut App) -> Result<(Mesh, Camera, PipelineSettings), CliError> {
    let world = app.world_mut();
    let mesh = world.query::<&Mesh>().single(world).ok().cloned();
    let camera = world.query::<&Camera>().single(world).ok().copied();
    match (mesh, camera) {
        (Some(mesh), Some(camera)) => Ok((mesh, camera, *world.resource::<PipelineSettings>())),
        _ => Err(no_scene()),
    }
}

fn no_scene() -> CliError {
    CliError::Runtime("inspect: no model or camera was set up".into())
}

fn triangle_report(app: &mut App, index: usize, viewport: Viewport) -> Result<Value, CliError> {
    let (mesh, camera, settings) = scene(app)?;
    let Some(j) = journey(&mesh, index, &camera, &settings, viewport) else {
        return Err(CliError::Input(format!(
            "inspect: --triangle {index}: the model has {} triangles (0..={})",
            mesh.triangles.len(),
            mesh.triangles.len() as i64 - 1
        )));
    };
    // The recorded fate: the pipeline's, with the rasterizer's no_pixels and hidden.
    let fate = app
        .world()
        .resource::<Fates>()
        .of(index)
        .copied()
        .unwrap_or(j.fate);
    let mut report = journey_json(&j);
    report["fate"] = json!(fate.kind.name());
    report["matrices"] = matrices_json(&camera, viewport);
    if settings.mistake != Mistake::None {
        report["mistake"] = mistake_json(&mesh, index, &camera, &settings, viewport);
    }
    Ok(report)
}

/// With `render.mistake` set, what Close2GL making it computes for the triangle: the mistaken
/// matrices (V into the view's pixels, y down), the clip coordinates, the fate and the polygon
/// drawn. The journey beside it is the right pipeline's, so that the two can be compared.
fn mistake_json(
    mesh: &Mesh,
    index: usize,
    camera: &Camera,
    settings: &PipelineSettings,
    viewport: Viewport,
) -> Value {
    let mistakes = Mistakes::one(settings.mistake);
    let program = Program::for_view(camera, settings, viewport, mistakes);
    let rows = |m: DMat4| -> Vec<[f64; 4]> { (0..4).map(|r| m.row(r).to_array()).collect() };
    let Some(outcome) = program.triangle(mesh, index) else {
        return Value::Null;
    };
    json!({
        "id": settings.mistake.name(),
        "M": rows(program.m),
        "P": rows(program.p),
        "V": rows(program.v),
        "clip": outcome.clip.map(|c| c.to_array()),
        "fate": outcome.fate.kind.name(),
        "window": outcome.polygon.iter().map(|p| p.to_array()).collect::<Vec<_>>(),
    })
}

/// The journey's numbers under the keys.
fn journey_json(j: &Journey) -> Value {
    let v3 = |v: &Vec3| v.to_array();
    let v4 = |v: &Vec4| v.to_array();
    let steps: Vec<Value> = j
        .clip_steps
        .iter()
        .map(|s| {
            json!({
                "plane": s.plane.name(),
                "polygon": s.polygon.iter().map(v4).collect::<Vec<_>>(),
                "weights": s.weights.iter().map(v3).collect::<Vec<_>>(),
            })
        })
        .collect();
    let planes: Vec<&str> = close2gl_core::ClipPlane::in_outcode(j.fate.planes)
        .map(|p| p.name())
        .collect();
    json!({
        "triangle": j.triangle,
        "planes": planes,
        "behind_eye": j.fate.behind_eye,
        "signed_area": finite(j.signed_area),
        "culling": j.culling.map(|k| k.name()),
        "world": j.world.iter().map(v3).collect::<Vec<_>>(),
        "eye": j.eye.iter().map(v3).collect::<Vec<_>>(),
        "clip": j.clip.iter().map(v4).collect::<Vec<_>>(),
        "outcodes": j.outcodes,
        "clip_steps": steps,
        "ndc": j.ndc.iter().map(v3).collect::<Vec<_>>(),
        "window": j.window.iter().map(v3).collect::<Vec<_>>(),
    })
}

/// A number, or null for NaN and infinities (which JSON cannot hold).
fn finite(x: f32) -> Value {
    if x.is_finite() { json!(x) } else { Value::Null }
}

/// M, P, V and the reference's view and projection (glam's), as rows, with the largest
/// differences between the two sides' matrices. The reference's projection maps depth to
/// wgpu's 0..1 where P maps it to OpenGL's -1..1, so P is compared after that remap
/// (z' = (z + w) / 2).
pub fn matrices_json(camera: &Camera, viewport: Viewport) -> Value {
    let m = matrices::modelview(camera);
    let p = matrices::projection(camera.hfov, camera.vfov, camera.near, camera.far);
    let v = matrices::viewport(viewport.width as f32, viewport.height as f32);
    let (view, projection) = close2gl_gpu::camera_matrices(camera);
    let rows = |m: Mat4| m.transpose().to_cols_array_2d();
    json!({
        "M": rows(m),
        "P": rows(p),
        "V": rows(v),
        "reference_view": rows(view),
        "reference_projection": rows(projection),
        "max_difference": {
            "view": max_difference(m, view),
            "projection": max_difference(depth_to_unit_range() * p, projection),
        },
    })
}

/// The largest absolute difference between two matrices' entries.
pub fn max_difference(a: Mat4, b: Mat4) -> f32 {
    let (a, b) = (a.to_cols_array(), b.to_cols_array());
    a.iter()
        .zip(&b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f32::max)
}

/// Clip z from OpenGL's -w..w to wgpu's 0..w: z' = (z + w) / 2.
fn depth_to_unit_range() -> Mat4 {
    Mat4::from_cols(
        Vec4::X,
        Vec4::Y,
        Vec4::new(0.0, 0.0, 0.5, 0.0),
        Vec4::new(0.0, 0.0, 0.5, 1.0),
    )
}

/// Both views' answers for the pixel, from the probe's one home (the viewer's Ctrl+click asks
/// the same), the reference's from a GPU of its own.
fn pixel_report(app: &mut App, (x, y): (u32, u32), viewport: Viewport) -> Result<Value, CliError> {
    let gpu = Gpu::headless(close2gl_gpu::wgpu::Backends::PRIMARY).map_err(CliError::Runtime)?;
    let world = app.world_mut();
    let mut state = SystemState::<ProbedFrame>::new(world);
    let frame = state
        .get(world)
        .map_err(|e| CliError::Runtime(format!("inspect: {e}")))?;
    let answer = frame.answer(&gpu, viewport, (x, y)).ok_or_else(no_scene)?;
    let reference = answer
        .reference
        .and_then(|probe| probe.wait(&gpu))
        .map_err(CliError::Runtime)?;
    let close2gl = answer.close2gl;
    let agree = reference.as_ref().map(|r| r.triangle) == close2gl.triangle;
    Ok(json!({
        "pixel": [x, y],
        "reference": {
            "triangle": reference.as_ref().map(|r| r.triangle),
            "depth": reference.as_ref().map_or(1.0, |r| r.depth),
        },
        "close2gl": close2gl_json(&close2gl),
        "agree": agree,
    }))
}

fn close2gl_json(probe: &PixelProbe) -> Value {
    let candidates: Vec<Value> = probe
        .candidates
        .iter()
        .map(|c| json!({"triangle": c.triangle, "outcome": c.outcome.name(), "depth": c.depth}))
        .collect();
    json!({
        "triangle": probe.triangle,
        "depth": probe.depth,
        "color": probe.color,
        "candidates": candidates,
    })
}

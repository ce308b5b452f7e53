//! `close2gl render`: both views offscreen, with exactly the systems and draw calls the windows
//! use, written as reference.png, close2gl.png (transparent where the view drew nothing: the
//! coverage the report compares), diff.png and report.json.

use std::f32::consts::TAU;
use std::path::{Path, PathBuf};

use close2gl_core::parity::{ColorComparison, CoverageComparison, diff_image};
use close2gl_core::{
    App, Camera, CameraAction, CameraActions, CameraRequest, Fates, OutsideView, RecordFates,
};
use close2gl_gpu::outside::render_outside;
use close2gl_gpu::{
    Gpu, OffscreenPlugin, ReferenceSkew, Snapshot, parse_backends, render_offscreen,
};
use close2gl_pipeline::frustum::world_corners;
use serde_json::{Value, json};

use super::CliError;
use super::scene_args::{SceneArgs, print_warnings, viewport};

#[derive(clap::Args, Debug, Default)]
pub struct RenderArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// The directory the images and report.json are written to (created when missing).
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
    /// The size of each view, WIDTHxHEIGHT (default: the configured window size).
    #[arg(long, value_name = "WxH")]
    pub size: Option<String>,
    /// Frames rendered per pose; the report gives the median times.
    #[arg(long, value_name = "N", default_value_t = 1)]
    pub frames: u32,
    /// N poses, turning 360/N degrees about the look-at point each time (yaw about v); images
    /// are numbered (reference_000.png, ...) and report.json is an array, one report per pose.
    #[arg(long, value_name = "N")]
    pub orbit: Option<u32>,
    /// vulkan, gl, metal, dx12 or all (default: the platform's primary backends, no GL).
    #[arg(long, value_name = "NAME")]
    pub backend: Option<String>,
    /// `outside`: also draw the pipeline seen from outside, as outside.png (as
    /// --set outside.show=true does); the report adds the view volume's corners.
    #[arg(long, value_name = "VIEW")]
    pub view: Option<String>,
    /// The outside view's stage: world, eye, ndc, or a number in 0..=2 (as --set
    /// outside.stage=...).
    #[arg(long, value_name = "STAGE")]
    pub stage: Option<String>,
    /// Moves the reference's background N steps of 1/255 (each channel), as a GPU that rounds
    /// the clear colour differently would (NVIDIA stores 0.1 as 25/255, lavapipe as 26): the
    /// coverage reported must not change.
    #[arg(
        long,
        value_name = "N",
        default_value_t = 0,
        allow_negative_numbers = true
    )]
    pub skew_background: i32,
    /// Moves the reference's model colour N steps of 1/255 (each channel), likewise.
    #[arg(
        long,
        value_name = "N",
        default_value_t = 0,
        allow_negative_numbers = true
    )]
    pub skew_color: i32,
}

pub fn run(args: RenderArgs) -> Result<(), CliError> {
    let backends = check(&args)?;
    let mut config = args.scene.config()?;
    outside_args(&args, &mut config)?;
    let viewport = viewport(args.size.as_deref(), &config)?;
    let mut app = close2gl_app::build_app(&config, viewport).map_err(CliError::Input)?;
    print_warnings(&app);
    let gpu = Gpu::headless(backends).map_err(CliError::Runtime)?;
    app.add_plugins(OffscreenPlugin(gpu.clone()));
    app.world_mut().resource_mut::<RecordFates>().0 = true;
    app.insert_resource(ReferenceSkew {
        background: args.skew_background,
        color: args.skew_color,
    });
    std::fs::create_dir_all(&args.out).map_err(|e| {
        CliError::Runtime(format!(
            "{}: cannot create the directory: {e}",
            args.out.display()
        ))
    })?;

    let poses = args.orbit.unwrap_or(1);
    let mut reports = Vec::new();
    for pose in 0..poses {
        reports.push(render_pose(&mut app, &args, &gpu, pose)?);
    }
    let report = match args.orbit {
        Some(_) => Value::Array(reports),
        None => reports.swap_remove(0),
    };
    let path = args.out.join("report.json");
    let text = serde_json::to_string_pretty(&report)
        .map_err(|e| CliError::Runtime(format!("cannot encode the report: {e}")))?;
    std::fs::write(&path, text + "\n").map_err(|e| unwritable(&path, e))?;
    println!("{report}");
    Ok(())
}

/// The arguments' own rules, and the backends `--backend` names.
fn check(args: &RenderArgs) -> Result<close2gl_gpu::wgpu::Backends, CliError> {
    if args.frames == 0 {
        return Err(CliError::Input(
            "render: --frames must be at least 1".into(),
        ));
    }
    if args.orbit == Some(0) {
        return Err(CliError::Input("render: --orbit must be at least 1".into()));
    }
    match &args.backend {
        Some(name) => {
            parse_backends(name).map_err(|e| CliError::Input(format!("render: --backend: {e}")))
        }
        None => Ok(close2gl_gpu::wgpu::Backends::PRIMARY),
    }
}

/// `--view outside` and `--stage`, into the config's `[outside]`.
fn outside_args(args: &RenderArgs, config: &mut close2gl_config::Config) -> Result<(), CliError> {
    match args.view.as_deref() {
        None => {}
        Some("outside") => config.outside.show = true,
        Some(other) => {
            return Err(CliError::Input(format!(
                "render: --view: expected \"outside\", found \"{other}\""
            )));
        }
    }
    if let Some(stage) = &args.stage {
        config.outside.stage = close2gl_config::parse_stage(stage)
            .map_err(|e| CliError::Input(format!("render: --stage: {e}")))?;
    }
    Ok(())
}

/// Pose number `pose` (turned that many steps around the look-at point with `--orbit`): its
/// images written and its report.
fn render_pose(app: &mut App, args: &RenderArgs, gpu: &Gpu, pose: u32) -> Result<Value, CliError> {
    let poses = args.orbit.unwrap_or(1);
    if pose > 0 {
        let step = TAU / poses as f32;
        app.world_mut()
            .resource_mut::<CameraActions>()
            .0
            .push(CameraAction::Orbit {
                yaw: step,
                pitch: 0.0,
            });
    }
    let (snapshot, reference_ms, close2gl_ms) = render_frames(app, args.frames)?;
    let suffix = args
        .orbit
        .map(|_| format!("_{pose:03}"))
        .unwrap_or_default();
    let mut report = write_pose(&args.out, &suffix, &snapshot, gpu)?;
    if app.world().resource::<OutsideView>().show {
        write_outside(app, &args.out, &suffix, &mut report)?;
    }
    report["reference_ms"] = json!(reference_ms);
    report["close2gl_ms"] = json!(close2gl_ms);
    report["frames"] = json!(args.frames);
    report["fates"] = json!(app.world().resource::<Fates>().counts);
    if args.orbit.is_some() {
        report["pose"] = json!(pose);
        report["yaw_degrees"] = json!(360.0 * pose as f64 / poses as f64);
    }
    Ok(report)
}

/// Renders `frames` frames of the current pose; returns the last one and the median times.
/// Every frame after the first asks the camera plugin to set the camera again (marking it
/// changed), so the Close2GL stage really runs again.
fn render_frames(
    app: &mut close2gl_core::App,
    frames: u32,
) -> Result<(Snapshot, f64, f64), CliError> {
    let mut reference_ms = Vec::new();
    let mut close2gl_ms = Vec::new();
    let mut last = None;
    for frame in 0..frames {
        if frame > 0 {
            let world = app.world_mut();
            if let Ok(&camera) = world.query::<&Camera>().single(world) {
                world.resource_mut::<CameraRequest>().edited = Some(camera);
            }
        }
        let snapshot = render_offscreen(app).map_err(CliError::Runtime)?;
        reference_ms.push(snapshot.reference_ms);
        close2gl_ms.push(snapshot.close2gl_ms);
        last = Some(snapshot);
    }
    let snapshot = last.ok_or_else(|| CliError::Runtime("no frame was rendered".into()))?;
    Ok((snapshot, median(reference_ms), median(close2gl_ms)))
}

fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    let mid = values.len() / 2;
    if values.len() % 2 == 1 {
        values[mid]
    } else {
        (values[mid - 1] + values[mid]) / 2.0
    }
}

/// Writes the three images of one pose and returns its report; the caller adds the times.
fn write_pose(dir: &Path, suffix: &str, snapshot: &Snapshot, gpu: &Gpu) -> Result<Value, CliError> {
    let (reference, close2gl) = (&snapshot.reference, &snapshot.close2gl);
    let comparison = CoverageComparison::of_images(reference, close2gl);
    let colors = ColorComparison::of_images(reference, close2gl, snapshot.tolerance);
    let diff = diff_image(reference, close2gl);
    let names = ["reference", "close2gl", "diff"].map(|n| format!("{n}{suffix}.png"));
    for (image, name) in [&snapshot.reference, &snapshot.close2gl, &diff]
        .iter()
        .zip(&names)
    {
        image
            .write_png(&dir.join(name))
            .map_err(CliError::Runtime)?;
    }
    Ok(json!({
        "adapter": gpu.adapter_name(),
        "backend": gpu.backend_name(),
        "polygon_modes": gpu.has_polygon_modes(),
        "size": [snapshot.reference.width, snapshot.reference.height],
        "coverage_agreement": comparison.coverage_agreement,
        "mismatched_pixels": comparison.mismatched_pixels,
        "covered_pixels": comparison.covered_pixels,
        "reference_only_pixels": comparison.only_first,
        "close2gl_only_pixels": comparison.only_second,
        "color_tolerance": {
            "feature": colors.tolerance.name(),
            "steps": colors.tolerance.steps(),
            "share": colors.tolerance.share(),
        },
        "color_compared_pixels": colors.compared_pixels,
        "color_mean_abs_diff": colors.mean_abs_diff,
        "color_max_abs_diff": colors.max_abs_diff,
        "color_within_tolerance": colors.within_fraction,
        "color_agrees": colors.agrees(),
        "stats": snapshot.counts,
        "images": {"reference": names[0], "close2gl": names[1], "diff": names[2]},
    }))
}

/// The outside view of the frame just rendered, as outside{suffix}.png, and the view volume's
/// world corners in the report.
fn write_outside(
    app: &mut App,
    dir: &Path,
    suffix: &str,
    report: &mut Value,
) -> Result<(), CliError> {
    let image = render_outside(app).map_err(CliError::Runtime)?;
    let name = format!("outside{suffix}.png");
    image
        .write_png(&dir.join(&name))
        .map_err(CliError::Runtime)?;
    let world = app.world_mut();
    let camera = *world
        .query::<&Camera>()
        .single(world)
        .map_err(|e| CliError::Runtime(format!("no camera: {e}")))?;
    let corners = world_corners(&camera).map(|c| c.to_array());
    report["frustum_world"] = json!(corners);
    report["outside_stage"] = json!(world.resource::<OutsideView>().stage);
    report["images"]["outside"] = json!(name);
    Ok(())
}

fn unwritable(path: &Path, e: std::io::Error) -> CliError {
    CliError::Runtime(format!("{}: cannot write: {e}", path.display()))
}

//! `close2gl stats`: the Close2GL pipeline once, headless; its counts as one JSON object (and,
//! with the software rasterizer, its time and the pixels it covered), and how many triangles
//! met each fate (`no_pixels` and `hidden` only with the software rasterizer).

use std::path::{Path, PathBuf};

use close2gl_core::{Close2glFrame, Fates, Image, Rasterizer, SoftwareFrame};
use serde_json::json;

use super::CliError;
use super::scene_args::{SceneArgs, print_warnings, record_fates, viewport};

#[derive(clap::Args, Debug, Default)]
pub struct StatsArgs {
    #[command(flatten)]
    pub scene: SceneArgs,
    /// The viewport, WIDTHxHEIGHT (default: the configured window size).
    #[arg(long, value_name = "WxH")]
    pub size: Option<String>,
    /// Also write the 2D buffer: .json (an object) or anything else (CSV, one vertex a line).
    #[arg(long, value_name = "FILE")]
    pub dump: Option<PathBuf>,
}

pub fn run(args: StatsArgs) -> Result<(), CliError> {
    let config = args.scene.config()?;
    let viewport = viewport(args.size.as_deref(), &config)?;
    let mut app = close2gl_app::build_app(&config, viewport).map_err(CliError::Input)?;
    print_warnings(&app);
    record_fates(&mut app);
    let frame = app.world().resource::<Close2glFrame>();
    if let Some(path) = &args.dump {
        dump(frame, path)
            .map_err(|e| CliError::Input(format!("{}: cannot write: {e}", path.display())))?;
    }
    let mut report = json!(frame.counts);
    report["bounds_px"] = json!(frame.bounds_px());
    report["fates"] = json!(app.world().resource::<Fates>().counts);
    if config.render.pipeline.close2gl_raster == Rasterizer::Software {
        report["geometry_ms"] = json!(frame.geometry_ms);
        let image = app.world().resource::<SoftwareFrame>();
        report["raster_ms"] = json!(image.raster_ms);
        report["covered_pixels"] = json!(covered(&image.image));
    }
    println!("{report}");
    Ok(())
}

/// The pixels the software image covers (its alpha says which).
pub fn covered(image: &Image) -> usize {
    let covered = close2gl_core::parity::is_covered;
    image.pixels.iter().filter(|p| covered(p)).count()
}

/// The 2D buffer as JSON (when the file ends in .json) or as CSV, one vertex a line.
fn dump(frame: &Close2glFrame, path: &Path) -> std::io::Result<()> {
    let text = if path
        .extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("json"))
    {
        json!({
            "topology": frame.topology,
            "viewport": [frame.viewport.width, frame.viewport.height],
            "vertices": frame.vertices,
        })
        .to_string()
    } else {
        let mut csv = String::from("x,y\n");
        for [x, y] in &frame.vertices {
            csv.push_str(&format!("{x},{y}\n"));
        }
        csv
    };
    std::fs::write(path, text)
}

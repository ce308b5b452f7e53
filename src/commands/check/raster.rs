//! `close2gl check RASTER_TRACE`: a student's own rasterizer, its buffers held against close2gl's
//! textbook rasterizer drawing the same triangles (docs/checking.md, "The rasterizer
//! assignment"); `--pixel X Y` probes one pixel.

use std::path::Path;

use close2gl_check::raster::diagnose::Judge;
use close2gl_check::raster::{self, pictures, report};
use close2gl_core::RasterMistakes;
use close2gl_trace_format::{RasterFrame, is_raster_trace, read_raster_frame};

use super::{CheckArgs, CliError, write_files};

/// Exit 0 when the program agrees under legal rules, 1 when it differs, 2 for bad input.
pub fn run(args: &CheckArgs) -> Result<(), CliError> {
    let path = Path::new(&args.model);
    let head = std::fs::read(path)
        .map_err(|e| CliError::Input(format!("{}: cannot read: {e}", path.display())))?;
    if !is_raster_trace(&String::from_utf8_lossy(&head[..head.len().min(4096)])) {
        return Err(CliError::Input(format!(
            "{}: expected a raster trace ('close2gl-raster 1') when no TRACE follows; a geometry \
             trace is checked as 'close2gl check MODEL TRACE'",
            path.display()
        )));
    }
    let frame = read_raster_frame(path).map_err(|e| CliError::Input(e.to_string()))?;
    if let Some(pixel) = &args.pixel {
        return probe(&frame, pixel[0], pixel[1]);
    }
    let report = raster::check_raster(&frame);
    let name = path.display().to_string();
    let text = report::text(&report, &name);
    let json = report::json(&report);
    if let Some(dir) = &args.out {
        let judge = raster::judge(&frame);
        let drawn = judge.redraw.draw(report.rules(), RasterMistakes::NONE);
        let mut files = vec![
            ("report.txt".to_string(), text.clone().into_bytes()),
            (
                "report.json".to_string(),
                format!("{json:#}\n").into_bytes(),
            ),
        ];
        for (picture, image) in pictures::pictures(&judge, &drawn) {
            files.push((
                format!("{picture}.png"),
                image.to_png().map_err(CliError::Runtime)?,
            ));
        }
        let files: Vec<(&str, Vec<u8>)> =
            files.iter().map(|(n, b)| (n.as_str(), b.clone())).collect();
        write_files(dir, &files)?;
    }
    match args.json {
        true => println!("{json}"),
        false => print!("{text}"),
    }
    match report.agrees() {
        true => Ok(()),
        false => Err(CliError::Verdict),
    }
}

/// One pixel: the program's colour and depth, close2gl's, and each mistake that would give
/// something else there.
fn probe(frame: &RasterFrame, x: u32, y: u32) -> Result<(), CliError> {
    let (width, height) = frame.trace.window;
    if x >= width || y >= height {
        return Err(CliError::Input(format!(
            "--pixel {x} {y}: expected a pixel of the {width}×{height} window"
        )));
    }
    let row = if frame.trace.y_up { height - 1 - y } else { y };
    let at = (row * width + x) as usize;
    let judge: Judge = raster::judge(frame);
    let depth = |values: &[f32]| format!("depth {:.6}", values[at]);
    let colour = |p: [u8; 4]| format!("colour {} {} {}", p[0], p[1], p[2]);
    let theirs_depth = frame
        .depth
        .as_ref()
        .map(|d| depth(&d.values))
        .unwrap_or_default();
    println!(
        "pixel ({x}, {y}): yours {} {theirs_depth}",
        colour(frame.framebuffer.pixels[at])
    );
    let rules = judge.diagnose().legal.rules;
    let ours = judge.redraw.draw(rules, RasterMistakes::NONE);
    let say = |b: &close2gl_raster::textbook::Buffers| {
        format!("{} {}", colour(b.image.pixels[at]), depth(&b.depth))
    };
    println!("close2gl: {}", say(&ours));
    for m in judge.candidates() {
        let drawn = judge.redraw.draw(rules, RasterMistakes::one(m));
        if say(&drawn) != say(&ours) {
            println!("  {} would give: {}", m.name(), say(&drawn));
        }
    }
    Ok(())
}

//! `close2gl check RASTER_TRACE`: a student's own rasterizer, its buffers held against close2gl's
//! textbook rasterizer drawing the same triangles (docs/checking.md, "The rasterizer
//! assignment"); `--pixel X Y` probes one pixel.

use std::path::Path;

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
    let lines = raster::probe::probe(frame, x, y).map_err(CliError::Input)?;
    lines.iter().for_each(|line| println!("{line}"));
    Ok(())
}

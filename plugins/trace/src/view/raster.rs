//! A raster trace in the viewer (`close2gl-raster 1`, docs/raster-trace-format.md): what a
//! student's own rasterizer drew. It has no camera, so neither view can draw the scene from it:
//! the Close2GL view shows the program's framebuffer and the reference close2gl's textbook
//! rasterizer drawing the program's own triangles (what a correct rasterizer draws from the
//! same input, to the pixel what the GPU draws), both as fixed images (`ViewImages`); check's
//! raster report goes to the panel and its probe answers for a pixel.

use std::io::Read;
use std::path::Path;

use bevy_ecs::prelude::*;
use close2gl_check::raster::{self, RasterReport};
use close2gl_core::{FixedFrame, Letterbox, RasterMistakes, ViewImages, Viewport};
use close2gl_trace_format::{RasterFrame, is_raster_trace, read_raster_frame};

use super::{TraceRequest, TraceView};

/// A raster trace that was read and checked, with the two images its views show.
#[derive(Debug)]
pub struct RasterShown {
    pub frame: RasterFrame,
    pub report: RasterReport,
    pub images: FixedFrame,
}

/// Takes a pending `TraceRequest` whose file starts as a raster trace (before the geometry
/// trace's reader, which waits for a mesh this needs not); one that does not read leaves its
/// one-line error in `TraceView` and what was shown in place.
pub fn load_requested_raster_trace(mut request: ResMut<TraceRequest>, mut view: ResMut<TraceView>) {
    let Some(path) = request.0.take_if(|p| is_raster_file(p)) else {
        return;
    };
    match read(&path) {
        Ok(raster) => {
            view.taken(path);
            view.raster = Some(raster);
        }
        Err(error) => view.error = Some(error),
    }
}

/// Whether the file's first line is a raster trace's magic. A file that cannot be read is left
/// to the geometry trace's reader, whose error names it.
fn is_raster_file(path: &Path) -> bool {
    let mut head = Vec::new();
    let read = std::fs::File::open(path).and_then(|f| f.take(4096).read_to_end(&mut head));
    read.is_ok() && is_raster_trace(&String::from_utf8_lossy(&head))
}

fn read(path: &Path) -> Result<RasterShown, String> {
    // The page reads no files from a folder, and a raster trace's buffers are files beside it:
    // the browser build leaves check's raster search out (the module's size budget).
    if cfg!(target_arch = "wasm32") {
        return Err(format!(
            "{}: the browser page opens geometry traces only (a raster trace's buffers are \
             files beside it): open it in the desktop app",
            path.display()
        ));
    }
    let frame = read_raster_frame(path).map_err(|e| e.to_string())?;
    let judge = raster::judge(&frame);
    let report = judge.report();
    let drawn = judge.redraw.draw(report.rules(), RasterMistakes::NONE);
    // The program's pixels are covered where check's coverage says so (not one of the
    // background's colours): the views' coverage is their alpha, which the live difference
    // compares, and a PPM has none.
    let mut close2gl = frame.framebuffer.clone();
    for pixel in &mut close2gl.pixels {
        let covered = judge.background.iter().all(|b| pixel[..3] != b[..3]);
        pixel[3] = if covered { 255 } else { 0 };
    }
    let images = FixedFrame {
        reference: drawn.image,
        close2gl,
    };
    Ok(RasterShown {
        frame,
        report,
        images,
    })
}

/// The shown raster trace's images as the views', whenever `TraceView` changed; none once no
/// raster trace is shown.
pub fn raster_images_system(view: Res<TraceView>, mut images: ResMut<ViewImages>) {
    if !view.is_changed() {
        return;
    }
    let fixed = view.raster.as_ref().map(|r| r.images.clone());
    if images.0 != fixed {
        images.0 = fixed;
    }
}

/// Check's probe of the pixel under `pixel` (a view's pixel, from the top), or None when no
/// raster trace is shown. The frame is letterboxed over the view as the views show it
/// (`Letterbox`); on a bar, the answer says so.
pub fn raster_probe(
    view: &TraceView,
    pixel: (u32, u32),
    viewport: Viewport,
) -> Option<Vec<String>> {
    if cfg!(target_arch = "wasm32") {
        return None;
    }
    let frame = &view.raster.as_ref()?.frame;
    let (width, height) = frame.trace.window;
    let letterbox = Letterbox::new((width, height), viewport);
    let Some((x, row)) = letterbox.frame_pixel(pixel, viewport, (width, height)) else {
        return Some(vec!["outside the trace's frame".to_string()]);
    };
    let y = if frame.trace.y_up {
        height.saturating_sub(row + 1)
    } else {
        row
    };
    Some(raster::probe::probe(frame, x, y).unwrap_or_else(|e| vec![e]))
}

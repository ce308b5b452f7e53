//! One pixel of a raster trace, in words: the program's colour and depth there, close2gl's (its
//! textbook rasterizer under the legal rules the program was found to use), and each candidate
//! mistake that would give something else there. `close2gl check RASTER_TRACE --pixel X Y`
//! prints it; the viewer's probe shows it.

use close2gl_core::RasterMistakes;
use close2gl_raster::textbook::Buffers;
use close2gl_trace_format::RasterFrame;

use super::judge;

/// The lines for pixel (`x`, `y`) in the trace's own pixel coordinates (row 0 at the bottom when
/// it says `y_up`); an error when the pixel is outside its window.
pub fn probe(frame: &RasterFrame, x: u32, y: u32) -> Result<Vec<String>, String> {
    let (width, height) = frame.trace.window;
    if x >= width || y >= height {
        return Err(format!(
            "--pixel {x} {y}: expected a pixel of the {width}×{height} window"
        ));
    }
    let row = if frame.trace.y_up { height - 1 - y } else { y };
    let at = (row * width + x) as usize;
    let judge = judge(frame);
    let depth = |values: &[f32]| format!("depth {:.6}", values[at]);
    let colour = |p: [u8; 4]| format!("colour {} {} {}", p[0], p[1], p[2]);
    let theirs_depth = frame
        .depth
        .as_ref()
        .map(|d| depth(&d.values))
        .unwrap_or_default();
    let mut lines = vec![format!(
        "pixel ({x}, {y}): yours {} {theirs_depth}",
        colour(frame.framebuffer.pixels[at])
    )];
    let rules = judge.diagnose().legal.rules;
    let ours = judge.redraw.draw(rules, RasterMistakes::NONE);
    let say = |b: &Buffers| format!("{} {}", colour(b.image.pixels[at]), depth(&b.depth));
    lines.push(format!("close2gl: {}", say(&ours)));
    for m in judge.candidates() {
        let drawn = judge.redraw.draw(rules, RasterMistakes::one(m));
        if say(&drawn) != say(&ours) {
            lines.push(format!("  {} would give: {}", m.name(), say(&drawn)));
        }
    }
    Ok(lines)
}

//! Pictures of the stage that differs: the program's frame and close2gl's drawing of the same
//! triangles, where their coverage differs, their depth as a heat map of the difference, and
//! their colours' difference.

use close2gl_core::Image;
use close2gl_raster::textbook::Buffers;

use super::diagnose::Judge;

/// Named pictures: `yours`, `close2gl`, `coverage`, `depth` (when the trace gives depth),
/// `colour`.
pub fn pictures(judge: &Judge, drawn: &Buffers) -> Vec<(&'static str, Image)> {
    let frame = judge.input;
    let theirs = &frame.framebuffer;
    let (width, height) = (theirs.width, theirs.height);
    let blank = || Image::filled(width, height, [0, 0, 0, 255]);
    let covered = |p: [u8; 4]| judge.background.iter().all(|b| p[..3] != b[..3]);
    let mut coverage = blank();
    let mut colour = blank();
    for (at, (&t, &o)) in theirs.pixels.iter().zip(&drawn.image.pixels).enumerate() {
        coverage.pixels[at] = match (covered(t), covered(o)) {
            _ if judge.ties[at] => [90, 90, 40, 255],
            (true, true) => [110, 110, 110, 255],
            (false, true) => [255, 0, 255, 255],
            (true, false) => [0, 255, 0, 255],
            (false, false) => [20, 20, 24, 255],
        };
        if covered(t) && covered(o) {
            let d = (0..3).map(|k| t[k].abs_diff(o[k])).max().unwrap_or(0);
            colour.pixels[at] = [
                d.saturating_mul(8),
                d.saturating_mul(8),
                d.saturating_mul(8),
                255,
            ];
        }
    }
    let mut ours = drawn.image.clone();
    ours.pixels.iter_mut().for_each(|p| p[3] = 255);
    let mut all = vec![
        ("yours", theirs.clone()),
        ("close2gl", ours),
        ("coverage", coverage),
    ];
    if let Some(depth) = &frame.depth {
        all.push(("depth", heat(&depth.values, &drawn.depth, width, height)));
    }
    all.push(("colour", colour));
    all
}

/// |a − b| as a heat map: black where equal, through red to yellow at the largest difference.
fn heat(a: &[f32], b: &[f32], width: u32, height: u32) -> Image {
    let difference: Vec<f32> = a.iter().zip(b).map(|(a, b)| (a - b).abs()).collect();
    let largest = difference
        .iter()
        .copied()
        .filter(|d| d.is_finite())
        .fold(0.0, f32::max);
    let mut image = Image::filled(width, height, [0, 0, 0, 255]);
    for (pixel, d) in image.pixels.iter_mut().zip(difference) {
        let t = if largest > 0.0 {
            (d / largest).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let t = if d.is_nan() { 1.0 } else { t };
        *pixel = [
            (t * 2.0).min(1.0) * 255.0,
            (t * 2.0 - 1.0).max(0.0) * 255.0,
            0.0,
            255.0,
        ]
        .map(|c| c as u8);
    }
    image
}

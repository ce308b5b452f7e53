//! The depth buffer: window depth z/w is affine on screen, so a pixel's depth is its corners'
//! blended by the barycentric weights, no 1/w; cleared to 1, the far plane; a fragment is drawn
//! when nearer ("less") than what the buffer holds, and then written.

use close2gl_core::{DepthFunction, RasterMistake as M, RasterMistakes};

use super::Rasterization;
use super::vertex::Vertex;

/// What the buffer is cleared to.
pub(super) fn clear_value(mistakes: RasterMistakes) -> f32 {
    match mistakes.has(M::DepthClearedToZero) || mistakes.has(M::FarthestWins) {
        true => 0.0,
        false => 1.0,
    }
}

/// The depth of the point with barycentric `weights`, as the buffer stores it.
pub(super) fn interpolate(
    corners: &[Vertex; 3],
    weights: &[f64; 3],
    mistakes: RasterMistakes,
) -> f32 {
    let z = |i: usize| corners[i].window[2] as f64;
    let depth = match mistakes.has(M::DepthPerspective) {
        false => (0..3).map(|i| weights[i] * z(i)).sum::<f64>(),
        true => {
            let q = |i: usize| weights[i] * corners[i].window[3] as f64;
            (0..3).map(|i| q(i) * z(i)).sum::<f64>() / (0..3).map(q).sum::<f64>()
        }
    };
    match mistakes.has(M::DepthNdc) {
        true => (2.0 * depth - 1.0) as f32,
        false => depth as f32,
    }
}

/// The depth test of a fragment at depth `z` against the buffer's `stored`, which it updates:
/// whether the fragment is drawn.
pub(super) fn test(z: f32, stored: &mut f32, how: &Rasterization) -> bool {
    let mistakes = how.mistakes;
    let passes = match () {
        _ if mistakes.has(M::NoDepthTest) => true,
        _ if mistakes.has(M::FarthestWins) => z > *stored,
        _ => match how.rules.depth {
            DepthFunction::Less => z < *stored,
            DepthFunction::LessEqual => z <= *stored,
        },
    };
    if passes && !mistakes.has(M::DepthNotWritten) {
        *stored = z;
    }
    passes
}

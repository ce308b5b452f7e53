//! What a program computes from what it is given, before it sends any triangle: the M, P and V
//! it builds from the camera it holds and the 2D system it draws in (`gluOrtho2D`'s L R B T),
//! in double precision, and the planes it clips against as an outcode. Each matrix is the
//! textbook's ([`crate::matrices`]), with the entries its mistakes change applied beside it.

use close2gl_core::Mistake::{
    AspectFromAngles, DepthRowSign, FovInDegrees, FovNotHalved, FovsSwapped, ModelviewTransposed,
    TranslationSign, TranslationUnrotated, ViewportFullScale, ViewportYFlipped,
};
use close2gl_core::declaration::{ClipPlanes, ProgramCamera, System2d};
use glam::DMat4;

use crate::clip::{FAR, NEAR, Outcode};
use crate::matrices::{Real, modelview_rows, projection_rows, viewport_rows};
use crate::mistakes::Mistakes;

/// M, with what `mistakes` change: the translation left unrotated (d = -c) or of the wrong
/// sign, or the whole matrix transposed.
pub fn modelview(camera: &ProgramCamera, mistakes: Mistakes) -> DMat4 {
    let axes = [camera.u, camera.v, camera.n].map(|axis| axis.to_array());
    let c = camera.position.to_array();
    let mut rows = modelview_rows(axes, c);
    if mistakes.has(TranslationUnrotated) {
        (0..3).for_each(|i| rows[i][3] = -c[i]);
    }
    if mistakes.has(TranslationSign) {
        rows[..3].iter_mut().for_each(|row| row[3] = -row[3]);
    }
    let m = f64::from_rows(rows);
    match mistakes.has(ModelviewTransposed) {
        true => m.transpose(),
        false => m,
    }
}

/// P, with what `mistakes` change: the near window from the fields of view swapped, taken as
/// radians, not halved, or its width from the angles' ratio; the depth row negated.
pub fn projection(camera: &ProgramCamera, mistakes: Mistakes) -> DMat4 {
    let (near, far) = (camera.near, camera.far);
    let (h, v) = match mistakes.has(FovsSwapped) {
        true => (camera.vfov, camera.hfov),
        false => (camera.hfov, camera.vfov),
    };
    // The textbook's near window (`near_window`), each of its steps open to a mistake.
    let half_angle = |degrees: f64| {
        let radians = match mistakes.has(FovInDegrees) {
            true => degrees,
            false => degrees.to_radians(),
        };
        match mistakes.has(FovNotHalved) {
            true => radians,
            false => radians * 0.5,
        }
    };
    let top = near * half_angle(v).tan();
    let right = match mistakes.has(AspectFromAngles) {
        true => top * h / v,
        false => near * half_angle(h).tan(),
    };
    let mut rows = projection_rows([right, top], [near, far]);
    if mistakes.has(DepthRowSign) {
        rows[2][2] = -rows[2][2];
        rows[2][3] = -rows[2][3];
    }
    f64::from_rows(rows)
}

/// V onto `system`, with what `mistakes` change: the full extent as the scale instead of
/// half of it, or y's scale negated.
pub fn viewport(system: &System2d, mistakes: Mistakes) -> DMat4 {
    let (width, height) = (system.right - system.left, system.top - system.bottom);
    let mut rows = viewport_rows([system.left, system.right, system.bottom, system.top]);
    if mistakes.has(ViewportFullScale) {
        (rows[0][0], rows[1][1]) = (width, height);
    }
    if mistakes.has(ViewportYFlipped) {
        rows[1][1] = -rows[1][1];
    }
    f64::from_rows(rows)
}

/// The planes' bits in an outcode.
pub fn planes_mask(planes: ClipPlanes) -> Outcode {
    match planes {
        ClipPlanes::All => 0x3f,
        ClipPlanes::NearFar => NEAR | FAR,
    }
}

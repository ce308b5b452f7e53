//! What a program computes from what it is given, before it sends any triangle: the M, P and V
//! it builds from the camera it holds and the 2D system it draws in (`gluOrtho2D`'s L R B T),
//! in double precision, with its mistakes, and the planes it clips against as an outcode.

use close2gl_core::declaration::{ClipPlanes, ProgramCamera, System2d};
use glam::DMat4;

use crate::clip::{FAR, NEAR, Outcode};
use crate::matrices::{modelview_of, projection_of, viewport_of};
use crate::mistakes::Mistakes;

/// M, or what `mistakes` make of it.
pub fn modelview(camera: &ProgramCamera, mistakes: Mistakes) -> DMat4 {
    let axes = [camera.u, camera.v, camera.n].map(|axis| axis.to_array());
    modelview_of(axes, camera.position.to_array(), mistakes)
}

/// P, or what `mistakes` make of it.
pub fn projection(camera: &ProgramCamera, mistakes: Mistakes) -> DMat4 {
    projection_of(
        [camera.hfov, camera.vfov],
        [camera.near, camera.far],
        mistakes,
    )
}

/// V onto `system`, or what `mistakes` make of it.
pub fn viewport(system: &System2d, mistakes: Mistakes) -> DMat4 {
    viewport_of(
        [system.left, system.right, system.bottom, system.top],
        mistakes,
    )
}

/// The planes' bits in an outcode.
pub fn planes_mask(planes: ClipPlanes) -> Outcode {
    match planes {
        ClipPlanes::All => 0x3f,
        ClipPlanes::NearFar => NEAR | FAR,
    }
}

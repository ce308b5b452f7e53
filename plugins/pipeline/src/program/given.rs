//! What a program is given before it computes anything: the camera it holds and the 2D system
//! it draws in (`gluOrtho2D`'s L R B T), and the M, P and V it builds from them, in double
//! precision, with its mistakes.

use glam::{DMat4, DVec2, DVec3};

use crate::matrices::{modelview_of, projection_of, viewport_of};
use crate::mistakes::Mistakes;

/// The 2D system the program draws in: the arguments it gave `gluOrtho2D`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct System2d {
    pub left: f64,
    pub right: f64,
    pub bottom: f64,
    pub top: f64,
}

impl System2d {
    /// Window pixels as close2gl's 2D buffer holds them, `0 W H 0`: the origin top-left, y down.
    pub fn pixels(width: u32, height: u32) -> Self {
        Self {
            left: 0.0,
            right: f64::from(width),
            bottom: f64::from(height),
            top: 0.0,
        }
    }

    /// A point of this system in window pixels (origin top-left, y down) of a `width` ×
    /// `height` window: where it shows on screen, whichever way the system's axes run.
    pub fn to_pixels(&self, p: DVec2, width: u32, height: u32) -> DVec2 {
        DVec2::new(
            (p.x - self.left) / (self.right - self.left) * f64::from(width),
            (self.top - p.y) / (self.top - self.bottom) * f64::from(height),
        )
    }

    /// V onto this system, or what `mistakes` make of it.
    pub fn viewport(&self, mistakes: Mistakes) -> DMat4 {
        viewport_of([self.left, self.right, self.bottom, self.top], mistakes)
    }
}

/// The camera as the program holds it, in double precision.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ProgramCamera {
    pub position: DVec3,
    pub u: DVec3,
    pub v: DVec3,
    pub n: DVec3,
    pub hfov: f64,
    pub vfov: f64,
    pub near: f64,
    pub far: f64,
}

impl ProgramCamera {
    /// M, or what `mistakes` make of it.
    pub fn modelview(&self, mistakes: Mistakes) -> DMat4 {
        let axes = [self.u, self.v, self.n].map(|axis| axis.to_array());
        modelview_of(axes, self.position.to_array(), mistakes)
    }

    /// P, or what `mistakes` make of it.
    pub fn projection(&self, mistakes: Mistakes) -> DMat4 {
        projection_of([self.hfov, self.vfov], [self.near, self.far], mistakes)
    }
}

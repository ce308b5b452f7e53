//! The words a program's declaration is written in, shared by the trace format (which reads
//! them from a program's files) and the pipeline (which runs a program that says them): how it
//! clips ([`ClipRule`], against which planes: [`ClipPlanes`]), where it tests the winding
//! ([`WindingSpace`]), the 2D system it draws in ([`System2d`]) and the camera it holds
//! ([`ProgramCamera`]). Plain values: what they compute (M, P and V, the planes' outcode) is
//! the pipeline's.

use glam::{DVec2, DVec3};

use crate::Camera;

/// How the program clips: what a scene or a trace says (`clipping simple|full|none`), and
/// what it does unless it divides first (`close2gl_pipeline`'s
/// `divide_before_clip`).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ClipRule {
    /// The assignment's: drop a triangle with any corner outside the view volume.
    Simple,
    /// Cut against the six planes, as a GPU does.
    Full,
    /// Nothing clipped, but a corner at w = 0 exactly (no division is possible).
    Nothing,
}

/// Where a program tests a triangle's winding (`trace-format.md`, culling's space).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum WindingSpace {
    /// As seen on screen (version 1's `culling ccw`): the 2D output mapped to the window.
    Screen,
    /// NDC x, y, y up, before V: a mistake in V does not change it.
    Ndc,
    /// The 2D output's own numbers (x right, y growing upward in the numbers): with a y-down
    /// system, the mirror of the screen.
    Window,
}

impl WindingSpace {
    pub const ALL: [WindingSpace; 3] = [Self::Screen, Self::Ndc, Self::Window];
}

/// Which planes the program clips against itself.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum ClipPlanes {
    /// All six.
    #[default]
    All,
    /// Near and far only: x and y are left to the 2D rasteriser, which cuts at the window.
    NearFar,
}

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

impl From<&Camera> for ProgramCamera {
    fn from(c: &Camera) -> Self {
        Self {
            position: c.position.as_dvec3(),
            u: c.u.as_dvec3(),
            v: c.v.as_dvec3(),
            n: c.n.as_dvec3(),
            hfov: f64::from(c.hfov),
            vfov: f64::from(c.vfov),
            near: f64::from(c.near),
            far: f64::from(c.far),
        }
    }
}

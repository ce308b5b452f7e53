//! The pixel stage: a shading's colour at eight pixels of a row (flat, the interpolated Gouraud
//! intensity, or Phong lit per pixel), modulated by the texture or not, packed as the target
//! stores it. Each shading and texturing is a type, so that every combination's row loop is
//! compiled on its own and pays only for what it uses.

use glam::Vec3;

use crate::lanes::{F8, LANES, V8};
use crate::lighting::Light;
use crate::sampling::{Filter, Mips};
use crate::target::{pack, pack8};
use crate::varyings::{AT_PIXEL, AtPixels, EYE, INTENSITY, Interpolant, NORMAL, Planes};

/// The colours of eight pixels of a triangle (its `planes`), centred at (x, y). Inlined into
/// the row loop (see `row::draw_span`).
pub(crate) trait PixelShader: Sync {
    fn shade(&self, planes: &Planes, x: F8, y: f32) -> [u32; LANES];

    /// The colour of every pixel, when it is the same everywhere: a fragment then takes it
    /// without a block of lanes shaded for it.
    fn uniform(&self) -> Option<u32> {
        None
    }

    /// A pixel's colour from its `values` alone (`Planes::at_pixel`), for the shading whose
    /// fragments carry them (`Used::at_pixel`: Phong without a texture), as its triangle's rows
    /// would colour it; None for the others.
    fn at_pixel(&self, _: &[f32; AT_PIXEL]) -> Option<u32> {
        None
    }
}

/// A shading's colour at eight pixels before texturing, given w there.
pub(crate) trait Colour: Sync {
    fn colour<P: Interpolant>(&self, planes: &P, x: F8, y: f32, w: F8) -> V8;

    /// The colour, when it is the same at every pixel.
    fn uniform(&self) -> Option<Vec3> {
        None
    }

    /// Whether it is coloured from a pixel's values alone (`Planes::at_pixel`: Phong's).
    const FROM_VALUES: bool = false;
}

/// A shading that colours eight pixels that need not be a row of one triangle: of different
/// triangles (`AtPixels`), as a tile does after its depth test (see `deferred`), or of one
/// triangle's different rows (`AtPoints`), as queued pixels are (see `queue`). Untextured
/// only: texturing's level of detail takes differences across each quad of pixels of one
/// triangle.
pub(crate) trait LaneShader: Sync {
    fn shade_lanes<P: Interpolant>(&self, planes: &P, x: F8, y: f32) -> [u32; LANES];
}

/// What the texture does to a colour: nothing, or modulate it by the texel.
pub(crate) trait Texturing: Sync {
    fn modulate(&self, colour: V8, planes: &Planes, x: F8, y: f32, w: F8) -> V8;

    /// Whether it leaves every colour as it is.
    const NONE: bool = false;
}

/// A shading and a texturing, packed as the target stores them.
pub(crate) struct Shaded<C, T> {
    pub colour: C,
    pub texturing: T,
}

impl<C: Colour, T: Texturing> PixelShader for Shaded<C, T> {
    #[inline(always)]
    fn shade(&self, planes: &Planes, x: F8, y: f32) -> [u32; LANES] {
        // Unused (flat colour, no texture), the division is compiled away.
        let w = planes.w(x, y);
        let colour = self.colour.colour(planes, x, y, w);
        pack8(self.texturing.modulate(colour, planes, x, y, w))
    }

    fn uniform(&self) -> Option<u32> {
        match T::NONE {
            true => self.colour.uniform().map(pack),
            false => None,
        }
    }

    #[inline(always)]
    fn at_pixel(&self, values: &[f32; AT_PIXEL]) -> Option<u32> {
        if !(C::FROM_VALUES && T::NONE) {
            return None;
        }
        // The values are the pixel's own: where it is plays no part.
        let (planes, x, y) = (AtPixels::splat(values), F8::splat(0.0), 0.0);
        let w = planes.w(x, y);
        Some(pack8(self.colour.colour(&planes, x, y, w))[0])
    }
}

impl<C: Colour> LaneShader for Shaded<C, Untextured> {
    #[inline(always)]
    fn shade_lanes<P: Interpolant>(&self, planes: &P, x: F8, y: f32) -> [u32; LANES] {
        let w = planes.w(x, y);
        pack8(self.colour.colour(planes, x, y, w))
    }
}

/// The user's colour, unlit.
pub(crate) struct Flat(pub Vec3);

impl Colour for Flat {
    #[inline(always)]
    fn colour<P: Interpolant>(&self, _: &P, _: F8, _: f32, _: F8) -> V8 {
        V8::splat(self.0)
    }

    fn uniform(&self) -> Option<Vec3> {
        Some(self.0)
    }
}

/// The interpolated intensity times the user's colour.
pub(crate) struct Gouraud {
    pub color: Vec3,
}

impl Colour for Gouraud {
    #[inline(always)]
    fn colour<P: Interpolant>(&self, planes: &P, x: F8, y: f32, w: F8) -> V8 {
        multiply(self.color, planes.varying3(INTENSITY, x, y, w))
    }
}

/// Lit at every pixel from the interpolated eye position and normal.
pub(crate) struct Phong {
    pub color: Vec3,
    pub light: Light,
}

impl Colour for Phong {
    const FROM_VALUES: bool = true;

    #[inline(always)]
    fn colour<P: Interpolant>(&self, planes: &P, x: F8, y: f32, w: F8) -> V8 {
        let eye = planes.varying3(EYE, x, y, w);
        let normal = planes.varying3(NORMAL, x, y, w);
        multiply(self.color, self.light.illumination(eye, normal))
    }
}

/// The user's colour times a light, channel by channel.
#[inline(always)]
fn multiply(color: Vec3, light: V8) -> V8 {
    V8 {
        x: F8::splat(color.x) * light.x,
        y: F8::splat(color.y) * light.y,
        z: F8::splat(color.z) * light.z,
    }
}

/// No texture.
pub(crate) struct Untextured;

impl Texturing for Untextured {
    const NONE: bool = true;

    #[inline(always)]
    fn modulate(&self, colour: V8, _: &Planes, _: F8, _: f32, _: F8) -> V8 {
        colour
    }
}

/// The colour times the texel at the pixel's texture coordinates.
pub(crate) struct Textured<'a, F> {
    pub mips: &'a Mips,
    pub filter: F,
}

impl<F: Filter> Texturing for Textured<'_, F> {
    #[inline(always)]
    fn modulate(&self, colour: V8, planes: &Planes, x: F8, y: f32, w: F8) -> V8 {
        let (s, t) = planes.texture_coordinates(x, y, w);
        let lod = || self.mips.level_of_detail(planes, x, y, (s, t));
        let texel = self.filter.sample(self.mips, s, t, lod);
        V8 {
            x: colour.x * texel.x,
            y: colour.y * texel.y,
            z: colour.z * texel.z,
        }
    }
}

//! The varyings: what a vertex carries to the pixels, where each sits in its array (the one
//! layout the vertex stage writes and the pixel shaders read), and how a triangle interpolates
//! them: as planes on screen of each varying times 1/w, set up once per triangle and divided by
//! the plane of 1/w at each pixel (perspective-correct), eight pixels of a row at a time.

use close2gl_core::Shading;

use crate::lanes::map3;
use crate::lanes::{F8, LANES, V8};

/// How many floats a vertex carries for shading: eye position and normal (Phong), or the
/// Gouraud intensity in the first three; then the texture coordinates.
pub(crate) const VARYINGS: usize = 8;

/// Gouraud: the intensity lit at the vertex (red, green, blue).
pub(crate) const INTENSITY: usize = 0;
/// Phong: the eye-space position, then the normal.
pub(crate) const EYE: usize = 0;
pub(crate) const NORMAL: usize = 3;
/// The texture coordinates (s, t), after the most any shading uses (Phong's six).
pub(crate) const UV: usize = 6;

/// What a pixel shaded after the depth test (Phong without a texture, see `deferred`) is shaded
/// from: 1/w, then the eye position and normal times 1/w, at its centre.
pub(crate) const AT_PIXEL: usize = 1 + UV;

/// How many varyings, from the first, a shading uses: none (flat colour), the Gouraud
/// intensity, or the eye position and normal (Phong). The texture coordinates come on top.
pub(crate) fn varyings_used(shading: Shading) -> usize {
    match shading {
        Shading::None => 0,
        Shading::GouraudAd | Shading::GouraudAds => 3,
        Shading::Phong => UV,
    }
}

/// Which varyings get planes: the first `shading` ones, and the texture coordinates when
/// `textured` (see `for_each_stored`).
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct Used {
    pub shading: usize,
    pub textured: bool,
}

impl Used {
    fn any(self) -> bool {
        self.shading > 0 || self.textured
    }

    /// Whether these are the planes of a shading that tiles of small triangles shade after
    /// their depth test (Phong without a texture): a small triangle's fragments then carry their
    /// values at their pixel ([`Planes::at_pixel`]).
    pub(crate) fn at_pixel(self) -> bool {
        self.shading == UV && !self.textured
    }

    /// Each varying whose plane is stored, `f(slot, k)`, in the order they are packed: `slot`
    /// counts the stored planes, depth and 1/w being the first two. The one statement of the
    /// packed layout, which packing and both kinds of unpacking follow.
    #[inline(always)]
    fn for_each_stored(self, mut f: impl FnMut(usize, usize)) {
        for k in 0..self.shading {
            f(2 + k, k);
        }
        if self.textured {
            f(2 + self.shading, UV);
            f(3 + self.shading, UV + 1);
        }
    }

    /// How many floats [`Planes::pack`] writes: the origin and depth always, 1/w and the used
    /// varyings' planes when there are any.
    pub(crate) fn packed_floats(self) -> usize {
        let planes = match self.any() {
            true => 2 + self.shading + 2 * self.textured as usize,
            false => 1,
        };
        2 + 3 * planes
    }
}

/// Where stored plane number `slot` starts in a packed triangle: after the origin's two floats,
/// three floats a plane.
#[inline(always)]
const fn packed_at(slot: usize) -> usize {
    2 + 3 * slot
}

/// a + dadx·(x − ox) + dady·(y − oy), where (ox, oy) is the triangle's origin.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Plane {
    pub a: f32,
    pub dadx: f32,
    pub dady: f32,
}

impl Plane {
    const ZERO: Plane = Plane {
        a: 0.0,
        dadx: 0.0,
        dady: 0.0,
    };
}

/// A triangle's planes, anchored at its first corner: depth, 1/w, and each varying times 1/w
/// (these, not the varyings, are affine on screen).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Planes {
    /// Where the planes are anchored (a corner, in window pixels).
    pub origin: [f32; 2],
    pub depth: Plane,
    pub inv_w: Plane,
    pub varyings: [Plane; VARYINGS],
}

impl Planes {
    pub(crate) const ZERO: Planes = Planes {
        origin: [0.0; 2],
        depth: Plane::ZERO,
        inv_w: Plane::ZERO,
        varyings: [Plane::ZERO; VARYINGS],
    };

    /// The planes through three corners' window positions (x, y, depth, 1/w) and varyings:
    /// depth always, 1/w and the varyings `used` when there are any.
    #[inline(always)]
    pub(crate) fn new(
        window: [[f32; 4]; 3],
        varyings: [&[f32; VARYINGS]; 3],
        used: Used,
    ) -> Planes {
        let [p0, p1, p2] = window;
        let (ex, ey) = (p1[0] - p0[0], p1[1] - p0[1]);
        let (fx, fy) = (p2[0] - p0[0], p2[1] - p0[1]);
        let area = ex * fy - fx * ey;
        let plane = |v: [f32; 3]| {
            let (dv1, dv2) = (v[1] - v[0], v[2] - v[0]);
            Plane {
                a: v[0],
                dadx: (dv1 * fy - dv2 * ey) / area,
                dady: (dv2 * ex - dv1 * fx) / area,
            }
        };
        let mut planes = Planes {
            origin: [p0[0], p0[1]],
            depth: plane([p0[2], p1[2], p2[2]]),
            ..Planes::ZERO
        };
        if used.any() {
            let inv_w = map3(&window, |p| p[3]);
            planes.inv_w = plane(inv_w);
            let planes = &mut planes.varyings;
            used.for_each_stored(|_, k| {
                planes[k] = plane(map3(&[0, 1, 2], |&i| varyings[i][k] * inv_w[i]));
            });
        }
        planes
    }

    /// Appends the planes `used` to `out`, [`Used::packed_floats`] of them: a triangle stored
    /// for the tiles takes the room its shading needs, not the room every shading could.
    #[inline(always)]
    pub(crate) fn pack(&self, used: Used, out: &mut Vec<f32>) {
        let start = out.len();
        out.resize(start + used.packed_floats(), 0.0);
        let out = &mut out[start..];
        out[..2].copy_from_slice(&self.origin);
        let mut put = |slot: usize, p: &Plane| {
            out[packed_at(slot)..][..3].copy_from_slice(&[p.a, p.dadx, p.dady]);
        };
        put(0, &self.depth);
        if used.any() {
            put(1, &self.inv_w);
            used.for_each_stored(|slot, k| put(slot, &self.varyings[k]));
        }
    }

    /// The planes [`Self::pack`] wrote (the others zero).
    #[inline(always)]
    pub(crate) fn unpack(packed: &[f32], used: Used) -> Planes {
        let plane = |slot: usize| {
            let at = packed_at(slot);
            Plane {
                a: packed[at],
                dadx: packed[at + 1],
                dady: packed[at + 2],
            }
        };
        let mut planes = Planes {
            origin: [packed[0], packed[1]],
            depth: plane(0),
            ..Planes::ZERO
        };
        if used.any() {
            planes.inv_w = plane(1);
            used.for_each_stored(|slot, k| planes.varyings[k] = plane(slot));
        }
        planes
    }

    /// The depth at the centre of pixel (x, y). Summed in its own order (a, then x, then y):
    /// the depth buffer and the probe take it so, and the reference's pixels agree with it.
    #[inline(always)]
    pub(crate) fn depth_at(&self, x: f32, y: f32) -> f32 {
        let plane = &self.depth;
        plane.a + plane.dadx * (x - self.origin[0]) + plane.dady * (y - self.origin[1])
    }

    /// The depth at the centre of pixel (x, y) as a tile whose first column is x0 takes it, a
    /// block of eight at a time (`row::draw_span`): the value at the row's first pixel, then
    /// x's share. What a small triangle's fragment carries, bit for bit the same.
    #[inline(always)]
    pub(crate) fn depth_in_tile(&self, x0: i32, x: i32, y: i32) -> f32 {
        let row = self.depth_at(x0 as f32 + 0.5, y as f32 + 0.5);
        (x - x0) as f32 * self.depth.dadx + row
    }

    /// 1/w and the eye position and normal times 1/w at the centre of pixel (x, y): what a
    /// lane of `lanes_at` gives there, bit for bit (the same operations in the same order).
    #[inline(always)]
    pub(crate) fn at_pixel(&self, x: i32, y: i32) -> [f32; AT_PIXEL] {
        let mut values = [self.value_at(&self.inv_w, x, y); AT_PIXEL];
        for (value, plane) in values[1..].iter_mut().zip(&self.varyings) {
            *value = self.value_at(plane, x, y);
        }
        values
    }

    /// One of these planes at the centre of pixel (x, y): the row's value, then x's share, as a
    /// lane of `lanes_at` sums them (the same operations in the same order).
    #[inline(always)]
    pub(crate) fn value_at(&self, plane: &Plane, x: i32, y: i32) -> f32 {
        let (x, y) = (x as f32 + 0.5, y as f32 + 0.5);
        let row = plane.a + plane.dady * (y - self.origin[1]);
        (x - self.origin[0]) * plane.dadx + row
    }

    /// A plane's value at eight pixel centres of one row: the row's value, then x's share.
    #[inline(always)]
    fn lanes_at(&self, plane: &Plane, x: F8, y: f32) -> F8 {
        let row = plane.a + plane.dady * (y - self.origin[1]);
        (x - F8::splat(self.origin[0])).mul_add(F8::splat(plane.dadx), F8::splat(row))
    }

    /// The texture coordinates (s, t) at eight pixels, given w there.
    #[inline(always)]
    pub(crate) fn texture_coordinates(&self, x: F8, y: f32, w: F8) -> (F8, F8) {
        (self.varying(UV, x, y, w), self.varying(UV + 1, x, y, w))
    }
}

/// What the pixel shaders interpolate from: one triangle's planes for all eight lanes
/// ([`Planes`]), or each lane its own triangle's values at its pixel ([`AtPixels`]). Both give a
/// lane the same value by the same operations in the same order, so a pixel's colour does not
/// depend on which.
pub(crate) trait Interpolant {
    /// 1/w at eight pixel centres of row y.
    fn inv_w_at(&self, x: F8, y: f32) -> F8;
    /// Varying `k` times 1/w at eight pixel centres of row y.
    fn varying_at(&self, k: usize, x: F8, y: f32) -> F8;

    /// w at eight pixels, from the plane of 1/w.
    #[inline(always)]
    fn w(&self, x: F8, y: f32) -> F8 {
        F8::splat(1.0) / self.inv_w_at(x, y)
    }

    /// Varying `k`, perspective-correct, at eight pixels, given w there.
    #[inline(always)]
    fn varying(&self, k: usize, x: F8, y: f32, w: F8) -> F8 {
        self.varying_at(k, x, y) * w
    }

    /// Varyings `first..first + 3` at eight pixels, given w there.
    #[inline(always)]
    fn varying3(&self, first: usize, x: F8, y: f32, w: F8) -> V8 {
        V8 {
            x: self.varying(first, x, y, w),
            y: self.varying(first + 1, x, y, w),
            z: self.varying(first + 2, x, y, w),
        }
    }
}

impl Interpolant for Planes {
    #[inline(always)]
    fn inv_w_at(&self, x: F8, y: f32) -> F8 {
        self.lanes_at(&self.inv_w, x, y)
    }

    #[inline(always)]
    fn varying_at(&self, k: usize, x: F8, y: f32) -> F8 {
        self.lanes_at(&self.varyings[k], x, y)
    }
}

/// Eight pixels' values at their centres ([`Planes::at_pixel`]), each lane its own triangle's:
/// what a block shaded after the depth test interpolates from when its pixels show different
/// triangles (a big mesh's small ones).
#[derive(Clone, Copy, Debug)]
pub(crate) struct AtPixels {
    inv_w: F8,
    varyings: [F8; UV],
}

impl AtPixels {
    /// Lane by lane from `values`, `values[k][lane]` being value k ([`AT_PIXEL`]) of the lane's
    /// pixel.
    #[inline(always)]
    pub(crate) fn new(values: [&[f32; LANES]; AT_PIXEL]) -> AtPixels {
        AtPixels {
            inv_w: F8(*values[0]),
            varyings: std::array::from_fn(|k| F8(*values[1 + k])),
        }
    }

    /// Every lane the same pixel's `values`.
    #[inline(always)]
    pub(crate) fn splat(values: &[f32; AT_PIXEL]) -> AtPixels {
        AtPixels {
            inv_w: F8::splat(values[0]),
            varyings: std::array::from_fn(|k| F8::splat(values[1 + k])),
        }
    }

    /// Lane `lane` takes `values`.
    #[inline(always)]
    pub(crate) fn set_lane(&mut self, lane: usize, values: &[f32; AT_PIXEL]) {
        self.inv_w.0[lane] = values[0];
        for (varying, &value) in self.varyings.iter_mut().zip(&values[1..]) {
            varying.0[lane] = value;
        }
    }
}

impl Interpolant for AtPixels {
    #[inline(always)]
    fn inv_w_at(&self, _: F8, _: f32) -> F8 {
        self.inv_w
    }

    #[inline(always)]
    fn varying_at(&self, k: usize, _: F8, _: f32) -> F8 {
        self.varyings[k]
    }
}

/// One triangle's planes at eight pixel centres anywhere in a tile, lane i's at
/// (x_i, y + dy_i): what the pixels of small spans, queued (see `queue`), are shaded from.
/// With y = 0 a lane's value is the one [`Planes`] gives in its own row, bit for bit.
pub(crate) struct AtPoints<'a> {
    pub planes: &'a Planes,
    pub dy: F8,
}

impl AtPoints<'_> {
    /// As [`Planes`]' `lanes_at`, each lane in its own row.
    #[inline(always)]
    fn lanes_at(&self, plane: &Plane, x: F8, y: f32) -> F8 {
        let [ox, oy] = self.planes.origin.map(F8::splat);
        let y = F8::splat(y) + self.dy;
        let row = F8::splat(plane.a) + F8::splat(plane.dady) * (y - oy);
        (x - ox).mul_add(F8::splat(plane.dadx), row)
    }
}

impl Interpolant for AtPoints<'_> {
    #[inline(always)]
    fn inv_w_at(&self, x: F8, y: f32) -> F8 {
        self.lanes_at(&self.planes.inv_w, x, y)
    }

    #[inline(always)]
    fn varying_at(&self, k: usize, x: F8, y: f32) -> F8 {
        self.lanes_at(&self.planes.varyings[k], x, y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn packed_planes_come_back_as_they_went_for_every_shading() {
        let plane = |k: f32| Plane {
            a: k,
            dadx: k + 0.25,
            dady: k + 0.5,
        };
        let mut planes = Planes {
            origin: [3.0, 4.0],
            depth: plane(1.0),
            inv_w: plane(2.0),
            varyings: [0.0; VARYINGS].map(|_| plane(0.0)),
        };
        for (k, p) in planes.varyings.iter_mut().enumerate() {
            *p = plane(10.0 + k as f32);
        }
        for shading in [0, 3, UV] {
            for textured in [false, true] {
                let used = Used { shading, textured };
                let mut packed = vec![-1.0];
                planes.pack(used, &mut packed);
                assert_eq!(packed.len(), 1 + used.packed_floats());
                let back = Planes::unpack(&packed[1..], used);
                assert_eq!((back.origin, back.depth.a), (planes.origin, 1.0));
                let mut kept = Vec::new();
                used.for_each_stored(|_, k| kept.push(k));
                for k in 0..VARYINGS {
                    let expected = match kept.contains(&k) {
                        true => planes.varyings[k],
                        false => Plane::ZERO,
                    };
                    assert_eq!(back.varyings[k], expected, "{used:?}, varying {k}");
                }
                assert_eq!(back.inv_w.a, if used.any() { 2.0 } else { 0.0 });
            }
        }
    }
}

//! What happened to each mesh triangle in the Close2GL pipeline: the fate view, its
//! counts and the outside view's colours all read this one record, so they cannot disagree.

use bevy_ecs::prelude::*;
use serde::Serialize;

named_enum!(
    /// A triangle's fate, in the order a triangle can meet them on its way down the pipeline.
    FateKind {
        /// Inside the view volume and drawn whole.
        Drawn = "drawn",
        /// Drawn after clipping cut it (the planes in [`TriangleFate::planes`]).
        Cut = "cut",
        /// Removed whole by clipping: outside one plane with all three corners, or, with the
        /// assignment's simple clipping, touching the border at all.
        Clipped = "clipped",
        /// A back face (its signed window area in [`TriangleFate::signed_area`]).
        Culled = "culled",
        /// No area to speak of on screen (`limits::ZERO_AREA`): no facing, culled as a back face.
        ZeroArea = "zero_area",
        /// Drawn, but it covers no pixel centre (the software rasterizer says so).
        NoPixels = "no_pixels",
        /// Covers pixel centres but wins none of them in the depth test.
        Hidden = "hidden"
    }
);

named_enum!(
    /// The six planes of the view volume, in clip space; bit i of an outcode is plane i.
    ClipPlane {
        Left = "left",
        Right = "right",
        Bottom = "bottom",
        Top = "top",
        Near = "near",
        Far = "far"
    }
);

impl ClipPlane {
    /// The planes whose bits are set in `outcode`.
    pub fn in_outcode(outcode: u8) -> impl Iterator<Item = ClipPlane> {
        Self::ALL
            .iter()
            .copied()
            .enumerate()
            .filter(move |(bit, _)| outcode & (1 << bit) != 0)
            .map(|(_, plane)| plane)
    }
}

impl FateKind {
    /// The fate view's colour for this fate, RGB: one legend for every view that shows fates.
    pub fn color(self) -> [u8; 3] {
        match self {
            FateKind::Drawn => [90, 190, 90],
            FateKind::Cut => [240, 200, 40],
            FateKind::Clipped => [230, 70, 60],
            FateKind::Culled => [80, 130, 240],
            FateKind::ZeroArea => [200, 90, 220],
            FateKind::NoPixels => [60, 210, 220],
            FateKind::Hidden => [150, 150, 150],
        }
    }
}

/// One triangle's fate and what decided it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TriangleFate {
    pub kind: FateKind,
    /// Outcode bits ([`ClipPlane`]): the planes that cut a `Cut` triangle, or the planes that
    /// all three corners of a `Clipped` one lie outside of (with simple clipping, the planes any
    /// corner lies outside of). Zero otherwise.
    pub planes: u8,
    /// Whether every corner has w <= 0: at or behind the eye, where no division means anything.
    pub behind_eye: bool,
    /// Twice the signed window area (y down) when culling looked at it; NaN when it never got
    /// that far (clipped).
    pub signed_area: f32,
}

impl Default for TriangleFate {
    fn default() -> Self {
        Self {
            kind: FateKind::Drawn,
            planes: 0,
            behind_eye: false,
            signed_area: f32::NAN,
        }
    }
}

/// How many triangles met each fate. `no_pixels` and `hidden` are counted only when the
/// software rasterizer draws (they are drawn triangles the rasterizer then found wanting), and
/// are then taken out of `drawn` and `cut`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct FateCounts {
    pub drawn: usize,
    pub cut: usize,
    pub clipped: usize,
    pub culled: usize,
    pub zero_area: usize,
    pub no_pixels: usize,
    pub hidden: usize,
}

impl FateCounts {
    /// Counts one more triangle of `kind`. Inlined: the pipeline calls it for every triangle.
    #[inline]
    pub fn add(&mut self, kind: FateKind) {
        *self.get_mut(kind) += 1;
    }

    /// The counts `count` gives each fate.
    pub fn from_fn(count: impl Fn(FateKind) -> usize) -> Self {
        let mut counts = Self::default();
        for &kind in FateKind::ALL {
            *counts.get_mut(kind) = count(kind);
        }
        counts
    }

    pub fn get(&self, kind: FateKind) -> usize {
        let mut copy = *self;
        *copy.get_mut(kind)
    }

    #[inline]
    fn get_mut(&mut self, kind: FateKind) -> &mut usize {
        match kind {
            FateKind::Drawn => &mut self.drawn,
            FateKind::Cut => &mut self.cut,
            FateKind::Clipped => &mut self.clipped,
            FateKind::Culled => &mut self.culled,
            FateKind::ZeroArea => &mut self.zero_area,
            FateKind::NoPixels => &mut self.no_pixels,
            FateKind::Hidden => &mut self.hidden,
        }
    }
}

/// The request to record every triangle's fate ([`Fates`]): set while the fate view is shown, and
/// by the headless commands and tests that read the fates. The request only: its writers never
/// touch the result, which only the pipeline (and, for pixels, the rasterizer) write.
#[derive(Resource, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RecordFates(pub bool);

/// Every mesh triangle's fate, in mesh order, for the last Close2GL frame. Recorded only while
/// asked ([`RecordFates`], which the pipeline copies into `record` before it runs): the steady
/// frame otherwise writes nothing here.
#[derive(Resource, Clone, Debug, Default)]
pub struct Fates {
    /// Whether this frame records them (for a pipeline run outside the world, the caller's ask).
    pub record: bool,
    /// One per mesh triangle when recorded; empty otherwise.
    pub triangles: Vec<TriangleFate>,
    pub counts: FateCounts,
}

impl Fates {
    /// The fate of mesh triangle `index`, when the last frame recorded it.
    pub fn of(&self, index: usize) -> Option<&TriangleFate> {
        self.triangles.get(index)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_outcode_names_its_planes_in_bit_order() {
        let planes: Vec<_> = ClipPlane::in_outcode(0b10_0101).collect();
        assert_eq!(planes, [ClipPlane::Left, ClipPlane::Bottom, ClipPlane::Far]);
        assert_eq!(ClipPlane::in_outcode(0).count(), 0);
    }

    #[test]
    fn every_fate_has_its_own_colour_and_counter() {
        let mut counts = FateCounts::default();
        for (i, kind) in FateKind::ALL.iter().enumerate() {
            for _ in 0..=i {
                counts.add(*kind);
            }
            let others = &FateKind::ALL[i + 1..];
            assert!(others.iter().all(|o| o.color() != kind.color()), "{kind:?}");
        }
        for (i, kind) in FateKind::ALL.iter().enumerate() {
            assert_eq!(counts.get(*kind), i + 1, "{kind:?}");
        }
    }
}

/// The mesh triangle the inspector follows (its journey in the panel, highlighted in both
/// views), or none. A Ctrl+click probe selects its winner; the panel selects by index.
#[derive(Resource, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SelectedTriangle(pub Option<u32>);

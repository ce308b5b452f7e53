//! How far the two views' colours may differ where both cover, by the feature drawn: the
//! tolerances that hold on every GPU, stated in docs/rasterizer.md ("Colour tolerances").

use crate::{Rasterizer, Shading, TextureFilter};

/// The colour tolerance of one scene: how many steps of 1/255 a channel may differ by, on what
/// share of the pixels both views cover.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ColorTolerance {
    /// Flat, Gouraud and Phong without a texture: both views do the same arithmetic in f32, so a
    /// channel differs by at most the last rounding to 8 bits (a value at x.5 rounds either way:
    /// NVIDIA stores 0.1 as 25/255, lavapipe as 26).
    Exact,
    /// A texture sampled with this filter: each GPU computes the level of detail and the filter
    /// weights with its own precision (llvmpipe's weights are 8-bit), and with `nearest` a
    /// coordinate on a texel's edge may take the texel across it.
    Textured(TextureFilter),
    /// Close2GL drawn by the GPU in flat colour, the assignment's rule, beside a lit or
    /// textured reference: their colours differ by design, and only coverage is compared.
    NotCompared,
}

impl ColorTolerance {
    /// The tolerance for two views drawn with `shading` and, when the model is textured,
    /// `texture`'s filter, Close2GL rasterized by `rasterizer`.
    pub fn for_views(
        rasterizer: Rasterizer,
        shading: Shading,
        texture: Option<TextureFilter>,
    ) -> ColorTolerance {
        match (rasterizer, texture) {
            (Rasterizer::Gpu, None) if shading == Shading::None => ColorTolerance::Exact,
            (Rasterizer::Gpu, _) => ColorTolerance::NotCompared,
            (Rasterizer::Software, None) => ColorTolerance::Exact,
            (Rasterizer::Software, Some(filter)) => ColorTolerance::Textured(filter),
        }
    }

    /// Its name in reports: `exact`, `texture_nearest`, `texture_bilinear`,
    /// `texture_trilinear` or `not_compared`.
    pub fn name(self) -> &'static str {
        match self {
            ColorTolerance::Exact => "exact",
            ColorTolerance::Textured(TextureFilter::Nearest) => "texture_nearest",
            ColorTolerance::Textured(TextureFilter::Bilinear) => "texture_bilinear",
            ColorTolerance::Textured(TextureFilter::Trilinear) => "texture_trilinear",
            ColorTolerance::NotCompared => "not_compared",
        }
    }

    /// The most a channel may differ, in steps of 1/255.
    pub fn steps(self) -> u8 {
        match self {
            ColorTolerance::Exact => 1,
            ColorTolerance::Textured(_) | ColorTolerance::NotCompared => 2,
        }
    }

    /// The share of the pixels both views cover that must be within [`Self::steps`]; `None`
    /// when colours are not compared.
    pub fn share(self) -> Option<f64> {
        match self {
            ColorTolerance::Exact => Some(0.999),
            // A checkerboard turns a rounding at a square's edge into a whole colour step.
            ColorTolerance::Textured(TextureFilter::Nearest | TextureFilter::Bilinear) => {
                Some(0.97)
            }
            ColorTolerance::Textured(TextureFilter::Trilinear) => Some(0.95),
            ColorTolerance::NotCompared => None,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_gpu_drawn_close2gl_is_compared_only_in_flat_untextured_colour() {
        let gpu = |shading, texture| ColorTolerance::for_views(Rasterizer::Gpu, shading, texture);
        assert_eq!(gpu(Shading::None, None), ColorTolerance::Exact);
        assert_eq!(gpu(Shading::Phong, None), ColorTolerance::NotCompared);
        let textured = gpu(Shading::None, Some(TextureFilter::Nearest));
        assert_eq!(textured, ColorTolerance::NotCompared);
        assert_eq!(textured.share(), None);
    }

    #[test]
    fn the_software_rasterizer_is_exact_without_a_texture_and_filtered_with_one() {
        let software =
            |shading, texture| ColorTolerance::for_views(Rasterizer::Software, shading, texture);
        assert_eq!(software(Shading::Phong, None).name(), "exact");
        let trilinear = software(Shading::GouraudAds, Some(TextureFilter::Trilinear));
        assert_eq!(trilinear.name(), "texture_trilinear");
        assert!(trilinear.steps() > ColorTolerance::Exact.steps());
    }
}

//! The words of the second assignment (the student's own rasterizer): its classic mistakes, the
//! stage each belongs to, and the legal rules a rasterizer may choose among. Shared here because
//! the textbook rasterizer makes the mistakes, check names them and the panel switches them;
//! every definition is pinned in docs/raster-trace-format.md ("The mistake catalogue").

named_enum!(
    /// The rasterizer's stages, in the order a fragment goes through them.
    RasterStage {
        Coverage = "coverage",
        Depth = "depth",
        Interpolation = "interpolation",
        Shading = "shading",
        Texturing = "texturing",
        Output = "output"
    }
);

named_enum!(
    /// A classic mistake of the rasterizer assignment, one line each (the pinned definitions
    /// are docs/raster-trace-format.md's).
    RasterMistake {
        /// The textbook rasterizer.
        None = "none",
        /// A centre on any edge is inside.
        FillRuleInclusive = "fill_rule_inclusive",
        /// A centre on any edge is outside.
        FillRuleExclusive = "fill_rule_exclusive",
        /// Sampled at the pixel's corner, not its centre.
        PixelCornerSamples = "pixel_corner_samples",
        /// Corners rounded to whole pixels.
        VerticesRounded = "vertices_rounded",
        /// Corners truncated to whole pixels.
        VerticesTruncated = "vertices_truncated",
        /// The bounding box's last column and row lost.
        BoundingBoxShort = "bounding_box_short",
        /// The window's last column and row never drawn.
        ViewportEdgeSkipped = "viewport_edge_skipped",
        /// Depth interpolated perspective-correctly.
        DepthPerspective = "depth_perspective",
        /// The depth buffer cleared to 0.
        DepthClearedToZero = "depth_cleared_to_zero",
        /// Test "greater", cleared to 0.
        FarthestWins = "farthest_wins",
        /// Every fragment drawn, in order.
        NoDepthTest = "no_depth_test",
        /// Tested, never written.
        DepthNotWritten = "depth_not_written",
        /// NDC z stored.
        DepthNdc = "depth_ndc",
        /// Gouraud's colours affine on screen.
        ColourAffine = "colour_affine",
        /// Texture coordinates affine on screen.
        UvAffine = "uv_affine",
        /// Phong's position and normal affine on screen.
        PhongAffine = "phong_affine",
        /// Each corner's weight applied to the next corner's values.
        WeightsRotated = "weights_rotated",
        /// Every pixel takes the first corner's values.
        NoInterpolation = "no_interpolation",
        /// Phong's normal not normalised.
        NormalNotRenormalized = "normal_not_renormalized",
        /// The light's world position taken as eye space.
        LightInWorld = "light_in_world",
        /// No specular term.
        NoSpecular = "no_specular",
        /// N·L not clamped.
        DiffuseUnclamped = "diffuse_unclamped",
        /// V·R not clamped.
        SpecularUnclamped = "specular_unclamped",
        /// (N·H)^n in place of (V·R)^n.
        BlinnPhong = "blinn_phong",
        /// f_att = 1.
        NoAttenuation = "no_attenuation",
        /// V = (0, 0, 1).
        ViewerAtInfinity = "viewer_at_infinity",
        /// t = 0 at the image's top row.
        TNotFlipped = "t_not_flipped",
        /// Nearest rounds s·W.
        NearestRounds = "nearest_rounds",
        /// Bilinear without the half-texel shift.
        BilinearNoHalfTexel = "bilinear_no_half_texel",
        /// Outside [0, 1] is black.
        NoWrapBlack = "no_wrap_black",
        /// Clamped to the edge, not repeated.
        ClampNotRepeat = "clamp_not_repeat",
        /// The level is |λ|.
        LodAbsolute = "lod_absolute",
        /// ρ from the step across only.
        LodOneAxis = "lod_one_axis",
        /// ρ in texture coordinates, not texels.
        LodUnscaled = "lod_unscaled",
        /// Trilinear without the blend between levels.
        MipNearestLevel = "mip_nearest_level",
        /// Written bottom row first.
        RowsBottomFirst = "rows_bottom_first",
        /// A channel above 1 wraps around.
        ColourNotClamped = "colour_not_clamped",
        /// Red and blue exchanged.
        ChannelsSwapped = "channels_swapped"
    }
);

impl RasterMistake {
    /// The stage whose rule it breaks (`None`: coverage, the first).
    pub fn stage(self) -> RasterStage {
        use RasterMistake as M;
        match self {
            M::None
            | M::FillRuleInclusive
            | M::FillRuleExclusive
            | M::PixelCornerSamples
            | M::VerticesRounded
            | M::VerticesTruncated
            | M::BoundingBoxShort
            | M::ViewportEdgeSkipped => RasterStage::Coverage,
            M::DepthPerspective
            | M::DepthClearedToZero
            | M::FarthestWins
            | M::NoDepthTest
            | M::DepthNotWritten
            | M::DepthNdc => RasterStage::Depth,
            M::ColourAffine
            | M::UvAffine
            | M::PhongAffine
            | M::WeightsRotated
            | M::NoInterpolation => RasterStage::Interpolation,
            M::NormalNotRenormalized
            | M::LightInWorld
            | M::NoSpecular
            | M::DiffuseUnclamped
            | M::SpecularUnclamped
            | M::BlinnPhong
            | M::NoAttenuation
            | M::ViewerAtInfinity => RasterStage::Shading,
            M::TNotFlipped
            | M::NearestRounds
            | M::BilinearNoHalfTexel
            | M::NoWrapBlack
            | M::ClampNotRepeat
            | M::LodAbsolute
            | M::LodOneAxis
            | M::LodUnscaled
            | M::MipNearestLevel => RasterStage::Texturing,
            M::RowsBottomFirst | M::ColourNotClamped | M::ChannelsSwapped => RasterStage::Output,
        }
    }

    /// The catalogue: every mistake, `None` left out.
    pub fn catalogue() -> &'static [RasterMistake] {
        &Self::ALL[1..]
    }
}

/// A set of rasterizer mistakes (check tries each alone and in pairs).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct RasterMistakes(u64);

impl RasterMistakes {
    pub const NONE: RasterMistakes = RasterMistakes(0);

    pub fn one(mistake: RasterMistake) -> Self {
        Self::NONE.with(mistake)
    }

    /// This set and `mistake` (`None` adds nothing).
    pub fn with(self, mistake: RasterMistake) -> Self {
        match mistake {
            RasterMistake::None => self,
            m => RasterMistakes(self.0 | 1 << m as u32),
        }
    }

    pub fn has(self, mistake: RasterMistake) -> bool {
        mistake != RasterMistake::None && self.0 & (1 << mistake as u32) != 0
    }

    pub fn is_empty(self) -> bool {
        self.0 == 0
    }

    /// The mistakes in the set, in the catalogue's order.
    pub fn iter(self) -> impl Iterator<Item = RasterMistake> {
        RasterMistake::catalogue()
            .iter()
            .copied()
            .filter(move |&m| self.has(m))
    }

    /// The ids joined with " + " ("none" for the empty set).
    pub fn names(self) -> String {
        let names: Vec<&str> = self.iter().map(RasterMistake::name).collect();
        match names.is_empty() {
            true => "none".into(),
            false => names.join(" + "),
        }
    }
}

named_enum!(
    /// Which triangle a pixel centre exactly on a shared edge belongs to, in the picture's own
    /// terms (rows from the top): any of the four gives it to exactly one, so each is legal.
    #[derive(Default)]
    TieRule {
        /// D3D's and Vulkan's: left edges and horizontal top edges own their centres.
        #[default]
        TopLeft = "top_left",
        TopRight = "top_right",
        BottomLeft = "bottom_left",
        BottomRight = "bottom_right"
    }
);

named_enum!(
    /// How a colour in 0..1 becomes 8 bits: OpenGL asks for rounding, truncation is common and
    /// never more than one step off.
    #[derive(Default)]
    ByteConversion {
        #[default]
        Round = "round",
        Truncate = "truncate"
    }
);

named_enum!(
    /// The depth test's function: "less" (OpenGL's default) or "less or equal", which differ only
    /// where two fragments have the same depth.
    #[derive(Default)]
    DepthFunction {
        #[default]
        Less = "less",
        LessEqual = "less_equal"
    }
);

/// The legal choices a rasterizer makes where the rules leave one open.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub struct RasterRules {
    pub tie: TieRule,
    pub conversion: ByteConversion,
    pub depth: DepthFunction,
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_catalogue_has_every_stage_and_a_set_holds_what_it_is_given() {
        assert!(RasterMistake::catalogue().len() >= 24);
        for stage in RasterStage::ALL {
            assert!(
                RasterMistake::catalogue()
                    .iter()
                    .any(|m| m.stage() == *stage)
            );
        }
        let set = RasterMistakes::one(RasterMistake::UvAffine).with(RasterMistake::DepthNdc);
        assert_eq!(set.names(), "depth_ndc + uv_affine");
        assert!(!set.has(RasterMistake::None));
        assert_eq!(RasterMistakes::NONE.names(), "none");
    }
}

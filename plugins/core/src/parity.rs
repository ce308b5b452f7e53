//! How far the two views agree: coverage (the pixels each view drew, which it says in its alpha
//! channel), the pixels whose coverage differs, the colours where both cover (held to the
//! tolerance of the feature drawn, [`ColorTolerance`]), and a diff image that shows them. Pure
//! image arithmetic: the `render` command, the live difference's legend, the app's figures and
//! the tests use it without a GPU.
//!
//! Coverage is never read from colour: GPUs round a clear colour to 8 bits differently (0.1 is
//! 25/255 on NVIDIA, 26 on lavapipe and in the software rasterizer), so a pixel that differs
//! from the background colour may be background all the same. Every view clears its alpha to 0
//! and draws alpha 1, which every GPU stores exactly (0 and 255).

use glam::Vec3;

use crate::Image;

mod tolerance;

pub use tolerance::ColorTolerance;

/// A colour in 0..1 as the 8-bit value a UNORM target stores for it (round to nearest).
pub fn to_rgb8(color: Vec3) -> [u8; 3] {
    color
        .to_array()
        .map(|c| (c.clamp(0.0, 1.0) * 255.0).round() as u8)
}

/// Whether a pixel was drawn: its alpha, 0 where its view drew nothing.
pub fn is_covered(pixel: &[u8; 4]) -> bool {
    pixel[3] != 0
}

/// Which pixels of a view's image were drawn.
pub fn coverage(image: &Image) -> Vec<bool> {
    image.pixels.iter().map(is_covered).collect()
}

/// The coverage of two images of one scene compared.
#[derive(Clone, Debug, PartialEq)]
pub struct CoverageComparison {
    /// Pixels covered in one image and not in the other.
    pub mismatched_pixels: usize,
    /// Pixels covered in either image.
    pub covered_pixels: usize,
    /// Covered in the first image only, and in the second only.
    pub only_first: usize,
    pub only_second: usize,
    /// 1 - mismatched / covered; 0 when neither image covers any pixel, so that an empty or
    /// off-screen model cannot score high.
    pub coverage_agreement: f64,
}

impl CoverageComparison {
    pub fn new(first: &[bool], second: &[bool]) -> CoverageComparison {
        let (mut only_first, mut only_second, mut covered) = (0, 0, 0);
        for (&a, &b) in first.iter().zip(second) {
            covered += usize::from(a || b);
            only_first += usize::from(a && !b);
            only_second += usize::from(b && !a);
        }
        let mismatched = only_first + only_second;
        let coverage_agreement = if covered == 0 {
            0.0
        } else {
            1.0 - mismatched as f64 / covered as f64
        };
        CoverageComparison {
            mismatched_pixels: mismatched,
            covered_pixels: covered,
            only_first,
            only_second,
            coverage_agreement,
        }
    }

    /// Compares the coverage of two images of the same size.
    pub fn of_images(first: &Image, second: &Image) -> CoverageComparison {
        CoverageComparison::new(&coverage(first), &coverage(second))
    }
}

/// How far the colours of two images of one scene agree, over the pixels both cover, against
/// the tolerance of what they show.
#[derive(Clone, Debug, PartialEq)]
pub struct ColorComparison {
    /// The tolerance applied.
    pub tolerance: ColorTolerance,
    /// Pixels covered in both images.
    pub compared_pixels: usize,
    /// The mean of |a − b| over those pixels' channels (RGB), in 0..255.
    pub mean_abs_diff: f64,
    /// The largest |a − b| of any channel of those pixels, in 0..255.
    pub max_abs_diff: u8,
    /// The share of those pixels whose every channel differs by at most the tolerance's
    /// steps; 0 when no pixel is covered in both.
    pub within_fraction: f64,
}

impl ColorComparison {
    pub fn of_images(first: &Image, second: &Image, tolerance: ColorTolerance) -> ColorComparison {
        let steps = tolerance.steps();
        let (mut compared, mut sum, mut max, mut within) = (0usize, 0u64, 0u8, 0usize);
        for (a, b) in first.pixels.iter().zip(&second.pixels) {
            if !is_covered(a) || !is_covered(b) {
                continue;
            }
            compared += 1;
            let diffs = [0, 1, 2].map(|c| a[c].abs_diff(b[c]));
            sum += diffs.iter().map(|&d| d as u64).sum::<u64>();
            let worst = diffs.into_iter().max().unwrap_or(0);
            max = max.max(worst);
            within += usize::from(worst <= steps);
        }
        let share = |n: f64, of: f64| if of == 0.0 { 0.0 } else { n / of };
        ColorComparison {
            tolerance,
            compared_pixels: compared,
            mean_abs_diff: share(sum as f64, 3.0 * compared as f64),
            max_abs_diff: max,
            within_fraction: share(within as f64, compared as f64),
        }
    }

    /// Whether the colours are within the tolerance: its share of the pixels both cover within
    /// its steps (true when the tolerance compares no colours, or no pixel is covered in both).
    pub fn agrees(&self) -> bool {
        match self.tolerance.share() {
            None => true,
            Some(_) if self.compared_pixels == 0 => true,
            Some(share) => self.within_fraction >= share,
        }
    }
}

/// Covered only in the reference: magenta. Covered only in Close2GL: green.
pub const ONLY_REFERENCE: [u8; 4] = [255, 0, 255, 255];
pub const ONLY_CLOSE2GL: [u8; 4] = [0, 255, 0, 255];

/// The reference faded three quarters of the way to white, with the pixels whose coverage
/// differs painted [`ONLY_REFERENCE`] or [`ONLY_CLOSE2GL`].
pub fn diff_image(reference: &Image, close2gl: &Image) -> Image {
    let pixels = reference
        .pixels
        .iter()
        .zip(&close2gl.pixels)
        .map(|(r, c)| match (is_covered(r), is_covered(c)) {
            (true, false) => ONLY_REFERENCE,
            (false, true) => ONLY_CLOSE2GL,
            _ => {
                let fade = |x: u8| ((x as u16 + 3 * 255) / 4) as u8;
                [fade(r[0]), fade(r[1]), fade(r[2]), 255]
            }
        })
        .collect();
    Image {
        width: reference.width,
        height: reference.height,
        pixels,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The background a GPU cleared to, alpha 0; covered pixels are drawn opaque.
    const BG: [u8; 4] = [20, 20, 26, 0];

    fn image(covered: &[bool]) -> Image {
        let mut image = Image::filled(covered.len() as u32, 1, BG);
        for (p, &c) in image.pixels.iter_mut().zip(covered) {
            if c {
                *p = [200, 100, 50, 255];
            }
        }
        image
    }

    #[test]
    fn agreement_counts_mismatches_over_pixels_covered_in_either() {
        let a = image(&[true, true, true, false, false]);
        let b = image(&[true, true, false, true, false]);
        let c = CoverageComparison::of_images(&a, &b);
        assert_eq!(
            (c.only_first, c.only_second, c.mismatched_pixels),
            (1, 1, 2)
        );
        assert_eq!(c.covered_pixels, 4);
        assert!((c.coverage_agreement - 0.5).abs() < 1e-12);
    }

    #[test]
    fn nothing_covered_scores_zero_and_identical_coverage_scores_one() {
        let empty = image(&[false; 4]);
        assert_eq!(
            CoverageComparison::of_images(&empty, &empty).coverage_agreement,
            0.0
        );
        let full = image(&[true, false, true, true]);
        assert_eq!(
            CoverageComparison::of_images(&full, &full).coverage_agreement,
            1.0
        );
    }

    /// What NVIDIA did to the background (25/255 where lavapipe stores 26), and a model drawn
    /// in the background's own colour: neither changes which pixels are covered.
    #[test]
    fn coverage_is_the_alpha_whatever_the_colours() {
        let software = image(&[true, false, false]);
        let mut gpu = software.clone();
        gpu.pixels[1] = [19, 19, 25, 0];
        gpu.pixels[2] = [19, 19, 25, 0];
        assert_eq!(
            CoverageComparison::of_images(&gpu, &software).coverage_agreement,
            1.0
        );
        let mut camouflaged = software.clone();
        camouflaged.pixels[0] = [BG[0], BG[1], BG[2], 255];
        assert_eq!(coverage(&camouflaged), [true, false, false]);
    }

    #[test]
    fn colours_are_compared_where_both_images_cover() {
        let mut a = image(&[true, true, true, false]);
        let mut b = image(&[true, true, false, true]);
        a.pixels[0] = [100, 100, 100, 255];
        b.pixels[0] = [101, 99, 100, 255];
        a.pixels[1] = [100, 100, 100, 255];
        b.pixels[1] = [100, 110, 100, 255];
        let c = ColorComparison::of_images(&a, &b, ColorTolerance::Exact);
        assert_eq!(c.compared_pixels, 2);
        assert!((c.mean_abs_diff - 12.0 / 6.0).abs() < 1e-12);
        assert_eq!((c.max_abs_diff, c.within_fraction), (10, 0.5));
        assert!(!c.agrees());
        let empty = image(&[false; 4]);
        let none = ColorComparison::of_images(&empty, &a, ColorTolerance::Exact);
        assert_eq!(none.within_fraction, 0.0);
        assert!(
            none.agrees(),
            "nothing covered in both: no colour disagrees"
        );
        let flat_beside_lit = ColorComparison::of_images(&a, &b, ColorTolerance::NotCompared);
        assert!(flat_beside_lit.agrees());
    }

    #[test]
    fn the_diff_paints_each_side_and_fades_the_rest() {
        let a = image(&[true, true, false, false]);
        let b = image(&[true, false, true, false]);
        let diff = diff_image(&a, &b);
        assert_eq!(diff.pixels[1], ONLY_REFERENCE);
        assert_eq!(diff.pixels[2], ONLY_CLOSE2GL);
        assert_eq!(diff.pixels[0], [241, 216, 203, 255]);
        assert_eq!(diff.pixels[3][..3], [196, 196, 197]);
    }

    #[test]
    fn colours_round_like_a_unorm_target() {
        assert_eq!(to_rgb8(Vec3::new(0.0, 1.0, 0.5)), [0, 255, 128]);
        assert_eq!(to_rgb8(Vec3::new(0.08, 0.08, 0.1)), [20, 20, 26]);
    }
}

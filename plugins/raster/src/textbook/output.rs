//! The output: a colour in 0..1 stored as the RGBA8 a UNORM target stores it (clamped, rounded
//! to nearest), alpha 1 where drawn and 0 on the background, which says that nothing was drawn
//! there (the views' coverage is their alpha, never their colour); rows from the top.

use close2gl_core::{ByteConversion, RasterMistake as M, RasterMistakes};
use glam::Vec3;

use super::{Buffers, Rasterization};

/// The background: its colour with alpha 0.
pub(super) fn background(rgb: Vec3, how: &Rasterization) -> [u8; 4] {
    let [r, g, b, _] = pack(rgb, how);
    [r, g, b, 0]
}

/// A drawn colour, as the target stores it.
pub(super) fn pack(rgb: Vec3, how: &Rasterization) -> [u8; 4] {
    let mistakes = how.mistakes;
    let rounding = match how.rules.conversion {
        ByteConversion::Round => 0.5,
        ByteConversion::Truncate => 0.0,
    };
    let byte = |c: f32| match mistakes.has(M::ColourNotClamped) {
        // As C's (unsigned char) of a value past 255 in practice: the low 8 bits.
        true => ((c.max(0.0) * 255.0 + rounding) as u32 % 256) as u8,
        false => (c.clamp(0.0, 1.0) * 255.0 + rounding) as u8,
    };
    let [r, g, b] = [byte(rgb.x), byte(rgb.y), byte(rgb.z)];
    match mistakes.has(M::ChannelsSwapped) {
        true => [b, g, r, 255],
        false => [r, g, b, 255],
    }
}

/// What happens to the buffers as they are written out: turned upside down by
/// `rows_bottom_first`.
pub(super) fn finish(buffers: &mut Buffers, mistakes: RasterMistakes) {
    if !mistakes.has(M::RowsBottomFirst) {
        return;
    }
    let width = buffers.image.width as usize;
    upside_down(&mut buffers.image.pixels, width);
    upside_down(&mut buffers.depth, width);
    upside_down(&mut buffers.owners, width);
}

/// Turns the rows of `width` values of `rows` upside down.
fn upside_down<T: Copy>(rows: &mut Vec<T>, width: usize) {
    *rows = rows.chunks(width).rev().flatten().copied().collect();
}

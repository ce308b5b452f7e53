//! A GPU that rounds colours differently, emulated on any GPU: the reference view's background
//! and model colour moved whole steps of 1/255 away from what Close2GL draws. NVIDIA stores a
//! clear colour of 0.1 as 25/255 where lavapipe and the software rasterizer store 26; `close2gl
//! render --skew-background` and the parity tests move the reference the same way on lavapipe,
//! so that a comparison that depends on how a GPU rounds colours fails here, not only on
//! someone's laptop.

use bevy_ecs::prelude::*;
use close2gl_core::Appearance;
use close2gl_core::parity::to_rgb8;
use glam::Vec3;

/// Steps of 1/255 added to each channel of the reference view's colours (none by default).
/// Owned by [`crate::GpuPlugin`]; `close2gl render` and the tests set it. Offscreen and in the
/// live difference each view clears its own target, so both colours move; a window clears once
/// for both views, so there only the model colour would.
#[derive(Resource, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ReferenceSkew {
    /// Added to the reference's background (its clear colour).
    pub background: i32,
    /// Added to the reference's model colour.
    pub color: i32,
}

impl ReferenceSkew {
    /// The appearance the reference draws with: `look`, its two colours moved by the skew.
    pub(crate) fn apply(self, look: Appearance) -> Appearance {
        Appearance {
            color: moved(look.color, self.color),
            background: moved(look.background, self.background),
            ..look
        }
    }
}

/// `color` moved `steps` whole steps of 1/255 from the byte a target stores for it, kept in
/// 0..255, as an exact byte over 255: adding the steps to the float could land on x.5 (the
/// default background's blue, 0.1, is 25.5 steps), which one GPU rounds up and another down.
fn moved(color: Vec3, steps: i32) -> Vec3 {
    if steps == 0 {
        return color;
    }
    let byte = |b: u8| (i32::from(b) + steps).clamp(0, 255) as f32 / 255.0;
    Vec3::from(to_rgb8(color).map(byte))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bytes each channel moved from `from` to `to`.
    fn steps(from: Vec3, to: Vec3) -> [i32; 3] {
        let (a, b) = (to_rgb8(from), to_rgb8(to));
        [0, 1, 2].map(|k| i32::from(b[k]) - i32::from(a[k]))
    }

    #[test]
    fn a_step_moves_each_stored_byte_by_one() {
        let look = Appearance::default();
        let skew = ReferenceSkew {
            background: 1,
            color: -1,
        };
        let moved = skew.apply(look);
        assert_eq!(steps(look.background, moved.background), [1; 3]);
        assert_eq!(steps(look.color, moved.color), [-1; 3]);
        assert_eq!(ReferenceSkew::default().apply(look), look);
        let white = ReferenceSkew {
            background: 300,
            color: 0,
        };
        assert_eq!(white.apply(look).background, Vec3::ONE, "kept in 0..255");
    }
}

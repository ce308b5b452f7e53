//! A GPU that rounds colours differently, emulated on any GPU: the reference view's background
//! and model colour moved whole steps of 1/255 away from what Close2GL draws. NVIDIA stores a
//! clear colour of 0.1 as 25/255 where lavapipe and the software rasterizer store 26; `close2gl
//! render --skew-background` and the parity tests move the reference the same way on lavapipe,
//! so that a comparison that depends on how a GPU rounds colours fails here, not only on
//! someone's laptop.

use bevy_ecs::prelude::*;
use close2gl_core::Appearance;
use glam::Vec3;

/// Steps of 1/255 added to each channel of the reference view's colours (none by default).
/// Owned by [`crate::GpuPlugin`]; the headless commands and the tests set it.
#[derive(Resource, Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ReferenceSkew {
    /// Added to the reference's background (its clear colour).
    pub background: i32,
    /// Added to the reference's model colour.
    pub color: i32,
}

impl ReferenceSkew {
    /// The appearance the reference draws with: `look`, its two colours moved by the skew and
    /// kept in 0..1.
    pub(crate) fn apply(self, look: Appearance) -> Appearance {
        let moved = |c: Vec3, steps: i32| {
            (c + Vec3::splat(steps as f32 / 255.0)).clamp(Vec3::ZERO, Vec3::ONE)
        };
        Appearance {
            color: moved(look.color, self.color),
            background: moved(look.background, self.background),
            ..look
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use close2gl_core::parity::to_rgb8;

    #[test]
    fn a_step_moves_each_stored_byte_by_one() {
        let look = Appearance::default();
        let skew = ReferenceSkew {
            background: 1,
            color: -1,
        };
        let moved = skew.apply(look);
        let bytes = |c| to_rgb8(c).map(i32::from);
        let [before, after] = [look.background, moved.background].map(bytes);
        assert_eq!(
            [
                after[0] - before[0],
                after[1] - before[1],
                after[2] - before[2]
            ],
            [1; 3]
        );
        let [before, after] = [look.color, moved.color].map(bytes);
        assert_eq!(
            [
                after[0] - before[0],
                after[1] - before[1],
                after[2] - before[2]
            ],
            [-1; 3]
        );
        assert_eq!(ReferenceSkew::default().apply(look), look);
    }
}

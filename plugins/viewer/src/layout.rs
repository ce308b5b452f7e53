//! Where the views go in a window, in physical pixels.

use close2gl_core::Viewport;

/// A rectangle of a window in physical pixels, origin top-left.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PixelRect {
    pub x: u32,
    pub y: u32,
    pub width: u32,
    pub height: u32,
}

impl PixelRect {
    pub fn whole(width: u32, height: u32) -> Self {
        Self {
            x: 0,
            y: 0,
            width,
            height,
        }
    }

    pub fn is_empty(&self) -> bool {
        self.width == 0 || self.height == 0
    }

    pub fn size(&self) -> Viewport {
        Viewport {
            width: self.width,
            height: self.height,
        }
    }

    /// The part of an egui rectangle (points) inside a `width` x `height` window, in pixels.
    pub fn from_points(rect: egui::Rect, pixels_per_point: f32, width: u32, height: u32) -> Self {
        let px = |v: f32, max: u32| ((v * pixels_per_point).round().max(0.0) as u32).min(max);
        let (x0, y0) = (px(rect.min.x, width), px(rect.min.y, height));
        let (x1, y1) = (px(rect.max.x, width), px(rect.max.y, height));
        Self {
            x: x0,
            y: y0,
            width: x1.saturating_sub(x0),
            height: y1.saturating_sub(y0),
        }
    }

    /// Two equal halves side by side (an odd pixel column is left over on the right), so that
    /// both views have the same size.
    pub fn halves(&self) -> [PixelRect; 2] {
        let width = self.width / 2;
        let left = PixelRect { width, ..*self };
        let right = PixelRect {
            x: self.x + width,
            width,
            ..*self
        };
        [left, right]
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_odd_area_splits_into_two_equal_views() {
        let area = PixelRect::whole(991, 720);
        let [left, right] = area.halves();
        assert_eq!(
            left,
            PixelRect {
                x: 0,
                y: 0,
                width: 495,
                height: 720
            }
        );
        assert_eq!(
            right,
            PixelRect {
                x: 495,
                y: 0,
                width: 495,
                height: 720
            }
        );
        assert_eq!(left.size(), right.size());
    }

    #[test]
    fn points_become_pixels_clamped_to_the_window() {
        let rect = egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(500.4, 400.0));
        assert_eq!(
            PixelRect::from_points(rect, 2.0, 900, 700),
            PixelRect {
                x: 0,
                y: 0,
                width: 900,
                height: 700
            }
        );
        assert_eq!(
            PixelRect::from_points(rect, 1.0, 900, 700),
            PixelRect {
                x: 0,
                y: 0,
                width: 500,
                height: 400
            }
        );
        assert!(
            PixelRect::whole(1, 5).halves()[0].is_empty(),
            "one column has no halves"
        );
    }
}

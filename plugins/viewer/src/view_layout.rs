//! Where the views go in a window, in physical pixels: pure functions of the window sizes and
//! the area the panel leaves, so the rules are tested without a window.

use close2gl_core::{View, Viewport};

/// A view and where it goes in its window.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Placed {
    pub view: View,
    pub rect: PixelRect,
}

/// Where each view goes in each window, and the `Viewport` both views share (`None` while there
/// is no room for them).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Placement {
    /// In the panel's window.
    pub main: Vec<Placed>,
    /// In the Close2GL window of the windows layout.
    pub close2gl: Vec<Placed>,
    /// In the outside view's own window of the windows layout.
    pub outside: Vec<Placed>,
    pub viewport: Option<Viewport>,
}

/// The split layout: the reference view on the left half of `area` (what the panel leaves of the
/// window), Close2GL on the right half; with the `outside` view, three equal columns, the
/// outside view on the right.
pub fn split(area: PixelRect, outside: bool) -> Placement {
    let rects = if outside {
        area.thirds().to_vec()
    } else {
        area.halves().to_vec()
    };
    if rects[0].is_empty() {
        return Placement::default();
    }
    let views = [View::Reference, View::Close2gl, View::Outside];
    Placement {
        main: views
            .into_iter()
            .zip(&rects)
            .map(|(view, rect)| Placed { view, rect: *rect })
            .collect(),
        close2gl: Vec::new(),
        outside: Vec::new(),
        viewport: Some(rects[0].size()),
    }
}

/// The windows layout: the reference view in `area` of the panel's window, never larger than the
/// Close2GL window (`width` x `height`), so the two views match even before (or without) the
/// window manager honouring a resize; Close2GL fills its own window, which sets the viewport. The
/// outside view, when its window is open (`outside`: its size), fills that window.
pub fn two_windows(
    area: PixelRect,
    width: u32,
    height: u32,
    outside: Option<(u32, u32)>,
) -> Placement {
    let own = PixelRect::whole(width, height);
    let reference = PixelRect {
        width: area.width.min(width),
        height: area.height.min(height),
        ..area
    };
    let main = (!reference.is_empty()).then_some(Placed {
        view: View::Reference,
        rect: reference,
    });
    let other = (!own.is_empty()).then_some(Placed {
        view: View::Close2gl,
        rect: own,
    });
    Placement {
        main: main.into_iter().collect(),
        close2gl: other.into_iter().collect(),
        outside: outside
            .map(|(w, h)| PixelRect::whole(w, h))
            .filter(|rect| !rect.is_empty())
            .map(|rect| Placed {
                view: View::Outside,
                rect,
            })
            .into_iter()
            .collect(),
        viewport: other.or(main).map(|p| p.rect.size()),
    }
}

/// In the windows layout, the size the other window must take when one is resized to `width` x
/// `height`, so that both views stay equal: the panel's window is the Close2GL window plus the
/// panel's `panel_width`.
pub fn matching_size(main_resized: bool, width: u32, height: u32, panel_width: u32) -> (u32, u32) {
    if main_resized {
        (width.saturating_sub(panel_width).max(1), height)
    } else {
        (width + panel_width, height)
    }
}

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

    /// Whether pixel (`x`, `y`) of the window lies in the rectangle.
    pub fn contains(&self, x: u32, y: u32) -> bool {
        (self.x..self.x + self.width).contains(&x) && (self.y..self.y + self.height).contains(&y)
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

    /// Three equal columns side by side (the pixel columns left over go on the right).
    pub fn thirds(&self) -> [PixelRect; 3] {
        let width = self.width / 3;
        [0, 1, 2].map(|i| PixelRect {
            x: self.x + i * width,
            width,
            ..*self
        })
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

    #[test]
    fn the_split_layout_shares_the_area_and_needs_two_columns() {
        let placement = split(PixelRect::whole(991, 720), false);
        assert_eq!(placement.main.len(), 2);
        assert!(placement.close2gl.is_empty());
        assert_eq!(
            placement.viewport,
            Some(Viewport {
                width: 495,
                height: 720
            })
        );
        assert_eq!(split(PixelRect::whole(1, 720), false), Placement::default());
    }

    #[test]
    fn the_outside_view_takes_a_third_column_of_the_same_size() {
        let placement = split(PixelRect::whole(992, 720), true);
        let views: Vec<View> = placement.main.iter().map(|p| p.view).collect();
        assert_eq!(views, [View::Reference, View::Close2gl, View::Outside]);
        let rects: Vec<PixelRect> = placement.main.iter().map(|p| p.rect).collect();
        assert!(
            rects
                .iter()
                .all(|r| r.size() == rects[0].size() && r.width == 330)
        );
        assert_eq!(rects[2].x, 660, "side by side, no overlap");
        assert_eq!(placement.viewport, Some(rects[0].size()));
        assert_eq!(split(PixelRect::whole(2, 720), true), Placement::default());
    }

    #[test]
    fn in_two_windows_the_reference_never_outgrows_the_close2gl_window() {
        let area = PixelRect::whole(700, 800);
        let placement = two_windows(area, 600, 500, None);
        assert_eq!(placement.main[0].rect, PixelRect::whole(600, 500));
        assert_eq!(placement.close2gl[0].rect, PixelRect::whole(600, 500));
        assert!(
            placement.outside.is_empty(),
            "no outside window, no outside view"
        );
        let outside = two_windows(area, 600, 500, Some((400, 300))).outside;
        assert_eq!(outside[0].view, View::Outside);
        assert_eq!(
            outside[0].rect,
            PixelRect::whole(400, 300),
            "it fills its own window"
        );
        assert_eq!(
            placement.viewport.map(|v| (v.width, v.height)),
            Some((600, 500))
        );

        let minimised = two_windows(area, 0, 0, Some((0, 0)));
        assert!(minimised.outside.is_empty());
        assert!(minimised.close2gl.is_empty());
        assert_eq!(
            minimised.viewport, None,
            "a reference capped to an empty window is empty too"
        );
    }

    #[test]
    fn a_window_of_zero_or_one_pixel_places_no_view() {
        let panel = egui::Rect::from_min_max(egui::pos2(0.0, 0.0), egui::pos2(500.0, 400.0));
        for (width, height) in [(0, 0), (0, 400), (800, 0), (1, 1)] {
            let area = PixelRect::from_points(panel, 1.0, width, height);
            assert!(area.width <= width && area.height <= height);
            assert_eq!(split(area, false), Placement::default(), "{width}x{height}");
            assert_eq!(split(area, true), Placement::default(), "{width}x{height}");
            let two = two_windows(area, width, height, None);
            assert_eq!(two.viewport.is_some(), width == 1, "{width}x{height}");
        }
        assert_eq!(
            two_windows(PixelRect::whole(0, 0), 0, 0, None),
            Placement::default()
        );
    }

    #[test]
    fn the_other_window_follows_a_resize_keeping_the_views_equal() {
        assert_eq!(matching_size(true, 1000, 700, 290), (710, 700));
        assert_eq!(matching_size(false, 710, 700, 290), (1000, 700));
        assert_eq!(
            matching_size(true, 100, 50, 290),
            (1, 50),
            "never zero wide"
        );
    }
}

//! Where each view ([`View`]) is in the window, as the panel paints over them.

use bevy_ecs::prelude::*;
use close2gl_core::{OutsideView, View, ViewImages};

/// The views' part of the window and whether they share it: what the parts painted over the
/// views are handed.
#[derive(Clone, Copy, Debug)]
pub struct ViewArea {
    /// The window but the panel, in points.
    pub area: egui::Rect,
    /// The split layout: the reference, Close2GL and the outside view side by side in `area`;
    /// otherwise `area` is the reference's alone.
    pub shared: bool,
}

/// Where each view is: the reference alone, or, when the views share the area, the reference,
/// Close2GL and the outside view (when it shows) in columns.
pub fn view_rects(views: ViewArea, outside: bool) -> Vec<(View, egui::Rect)> {
    let ViewArea { area, shared } = views;
    if !shared {
        return vec![(View::Reference, area)];
    }
    let shown: &[View] = match outside {
        true => &[View::Reference, View::Close2gl, View::Outside],
        false => &[View::Reference, View::Close2gl],
    };
    let width = area.width() / shown.len() as f32;
    shown
        .iter()
        .enumerate()
        .map(|(i, &view)| {
            let min = area.left_top() + egui::vec2(i as f32 * width, 0.0);
            (
                view,
                egui::Rect::from_min_size(min, egui::vec2(width, area.height())),
            )
        })
        .collect()
}

/// Names the views in their top-left corners: while a raster trace is open they show its frame,
/// not the model (`ViewImages`), and say whose drawing each is.
pub fn labels(
    (InRef(ui), In(views)): (InRef<egui::Ui>, In<ViewArea>),
    outside: Option<Res<OutsideView>>,
    images: Option<Res<ViewImages>>,
) {
    let outside = outside.is_some_and(|o| o.show);
    let fixed = images.is_some_and(|i| i.0.is_some());
    let painter = ui.painter();
    for (view, rect) in view_rects(views, outside) {
        let text = match (view, fixed) {
            (View::Reference, false) => "Reference (wgpu)",
            (View::Reference, true) => "close2gl's textbook rasterizer, the program's triangles",
            (View::Close2gl, false) => "Close2GL",
            (View::Close2gl, true) => "The program's framebuffer",
            (View::Outside, _) => "Outside (drag, scroll)",
        };
        painter.text(
            rect.left_top() + egui::vec2(10.0, 8.0),
            egui::Align2::LEFT_TOP,
            text,
            egui::FontId::proportional(14.0),
            ui.visuals().weak_text_color(),
        );
    }
}

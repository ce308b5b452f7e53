//! check's pictures: close2gl's 2D output, the trace's, and where they differ coloured by the
//! kind of disagreement, each filled into the trace's window as it shows on screen.

use close2gl_core::Image;
use close2gl_trace_format::Trace;
use glam::DVec2;

use crate::compare::triangle::pieces_by_triangle;
use crate::region::covers;
use crate::report::Report;
use crate::vocabulary::Kind;

const BACKGROUND: [u8; 4] = [20, 20, 26, 255];
const OURS: [u8; 4] = [217, 166, 64, 255];
const THEIRS: [u8; 4] = [90, 150, 230, 255];
const AGREE: [u8; 4] = [90, 90, 96, 255];

/// The colour of a kind of disagreement in the difference picture.
pub fn kind_color(kind: Kind) -> [u8; 4] {
    match kind {
        Kind::ClipCoordinates => [200, 200, 200, 255],
        Kind::DrawnBehindEye => [255, 40, 200, 255],
        Kind::DrawnOutside => [230, 70, 60, 255],
        Kind::NotDrawn => [240, 200, 40, 255],
        Kind::FrontCulled => [80, 130, 240, 255],
        Kind::BackDrawn => [60, 210, 220, 255],
        Kind::InsideNotDrawn => [40, 90, 200, 255],
        Kind::Moved => [240, 120, 30, 255],
        Kind::Depth => [150, 90, 220, 255],
    }
}

/// The three pictures: close2gl's, the trace's, the difference.
pub fn pictures(report: &Report, trace: &Trace) -> [Image; 3] {
    let (w, h) = trace.window;
    let system = trace.ortho2d;
    let to_pixels = |polygon: &[DVec2]| -> Vec<DVec2> {
        polygon.iter().map(|&p| system.to_pixels(p, w, h)).collect()
    };
    // A hostile trace may list millions of window-sized polygons: each picture stops filling
    // after a hundred windows' worth of pixels looked at, well after any real frame.
    let budget = 100 * u64::from(w) * u64::from(h);
    let mut ours = Canvas::new(w, h, budget);
    let mut theirs = Canvas::new(w, h, budget);
    let mut difference = Canvas::new(w, h, budget);
    for outcome in report.expected.iter().filter(|o| o.drawn()) {
        ours.fill(&to_pixels(&outcome.polygon), OURS);
        difference.fill(&to_pixels(&outcome.polygon), AGREE);
    }
    for piece in &trace.pieces {
        theirs.fill(&to_pixels(&piece.corners), THEIRS);
    }
    let pieces = pieces_by_triangle(trace, report.expected.len());
    for (kind, triangles) in &report.comparison.triangles {
        for &t in triangles {
            let color = kind_color(*kind);
            let expected = &report.expected[t];
            if expected.drawn() {
                difference.fill(&to_pixels(&expected.polygon), color);
            }
            for &i in &pieces[t] {
                difference.fill(&to_pixels(&trace.pieces[i].corners), color);
            }
        }
    }
    [ours.image, theirs.image, difference.image]
}

/// An image being painted, and how many more pixels it may look at.
struct Canvas {
    image: Image,
    budget: u64,
}

impl Canvas {
    fn new(width: u32, height: u32, budget: u64) -> Self {
        Self {
            image: Image::filled(width, height, BACKGROUND),
            budget,
        }
    }

    /// Fills a polygon (any winding, convex) given in window pixels: the pixels whose centres
    /// it covers, clipped to the image; nothing once the budget is spent.
    fn fill(&mut self, polygon: &[DVec2], color: [u8; 4]) {
        let (image, budget) = (&mut self.image, &mut self.budget);
        if polygon.len() < 3 || polygon.iter().any(|p| !p.is_finite()) {
            return;
        }
        let (w, h) = (f64::from(image.width), f64::from(image.height));
        let min = polygon
            .iter()
            .fold(DVec2::splat(f64::INFINITY), |a, &p| a.min(p));
        let max = polygon
            .iter()
            .fold(DVec2::splat(f64::NEG_INFINITY), |a, &p| a.max(p));
        let x0 = (min.x - 0.5).ceil().clamp(0.0, w) as u32;
        let x1 = (max.x - 0.5).floor().clamp(-1.0, w - 1.0);
        let y0 = (min.y - 0.5).ceil().clamp(0.0, h) as u32;
        let y1 = (max.y - 0.5).floor().clamp(-1.0, h - 1.0);
        if x1 < 0.0 || y1 < 0.0 {
            return;
        }
        let area_box = (x1 + 1.0 - f64::from(x0)).max(0.0) * (y1 + 1.0 - f64::from(y0)).max(0.0);
        match budget.checked_sub(area_box as u64) {
            Some(left) => *budget = left,
            None => return,
        }
        for y in y0..=y1 as u32 {
            for x in x0..=x1 as u32 {
                let centre = DVec2::new(f64::from(x) + 0.5, f64::from(y) + 0.5);
                if covers(polygon, centre) {
                    image.pixels[(y * image.width + x) as usize] = color;
                }
            }
        }
    }
}

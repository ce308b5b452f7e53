//! Close2GL's pixel probe: for one pixel, which mesh triangle won it, at what depth and colour, and
//! every triangle whose coverage reached its centre with why each lost. Coverage is the
//! rasterizer's own: the same snapping to fixed point, edge functions and top-left rule (`edge`,
//! `setup`), on the polygon the pipeline drew (its clipped piece), or, for a triangle that clipping
//! removed, on where it would have projected: the whole triangle when every corner has w > 0, and
//! otherwise the part in front of the near plane, since behind the eye (w <= 0) nothing projects at
//! all, which is why every GPU cuts at the near plane. Candidates are found by the triangles'
//! areas, as in solid mode; in wireframe and point modes the winner is still the rasterizer's own
//! when it drew the view.

use close2gl_core::{
    Clipping, FateKind, Fates, PipelineSettings, Rasterizer, Scene, SoftwareFrame, Viewport,
};
use close2gl_pipeline::clip::{NEAR, Polygon, clip_polygon, outcode};
use close2gl_pipeline::matrices::{ClipTransform, viewport as viewport_matrix};
use close2gl_pipeline::stage::to_window_depth;
use glam::Mat4;

use crate::primitives::{SetupParams, triangle};
use crate::rasterizer::SoftwareRasterizer;
use crate::setup::{Coverage, Triangle};
use crate::varyings::{Used, VARYINGS};
use crate::vertex::Vertex;

/// Why a triangle whose coverage reached the pixel centre did or did not draw it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PixelOutcome {
    /// It drew the pixel last: the depth test's winner.
    Won,
    /// Covered, but lost the depth test.
    Depth,
    /// Removed by backface culling (a back face, or no area).
    Culled,
    /// It would project onto the pixel, but clipping removed it.
    Clipped,
    /// The centre lies exactly on its edge, and the top-left rule gave it to the neighbour.
    FillRule,
}

impl PixelOutcome {
    pub fn name(self) -> &'static str {
        match self {
            PixelOutcome::Won => "won",
            PixelOutcome::Depth => "depth",
            PixelOutcome::Culled => "culled",
            PixelOutcome::Clipped => "clipped",
            PixelOutcome::FillRule => "fill_rule",
        }
    }
}

/// One triangle whose coverage reached the pixel centre.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Candidate {
    pub triangle: u32,
    pub outcome: PixelOutcome,
    /// Its depth (0..1) at the pixel centre.
    pub depth: f32,
}

/// What Close2GL drew at one pixel.
#[derive(Clone, Debug, PartialEq)]
pub struct PixelProbe {
    pub pixel: [u32; 2],
    /// The winning mesh triangle; None where nothing drew.
    pub triangle: Option<u32>,
    /// The depth buffer's value there (1, the far plane, where nothing drew).
    pub depth: f32,
    /// The pixel's colour, RGBA, when the software rasterizer drew the view.
    pub color: Option<[u8; 4]>,
    /// In mesh order.
    pub candidates: Vec<Candidate>,
}

/// The software rasterizer's last frame, recorded (its id and depth buffers, and the image).
#[derive(Clone, Copy)]
pub struct Drawn<'a> {
    pub rasterizer: &'a SoftwareRasterizer,
    pub image: &'a SoftwareFrame,
}

impl<'a> Drawn<'a> {
    /// What the software rasterizer drew in the world's last frame (its `rasterizer` and
    /// `image` resources), when it is the one drawing Close2GL's view: the viewer's Ctrl+click
    /// and `close2gl inspect` probe the same image.
    pub fn last_frame(
        settings: &PipelineSettings,
        rasterizer: Option<&'a SoftwareRasterizer>,
        image: Option<&'a SoftwareFrame>,
    ) -> Option<Self> {
        let (rasterizer, image) = (rasterizer?, image?);
        (settings.close2gl_raster == Rasterizer::Software).then_some(Drawn { rasterizer, image })
    }
}

/// Probes pixel (x, y) of `scene`, whose pipeline recorded `fates`. The winner is the software rasterizer's own (its id buffer) when it
/// drew the frame; otherwise it is worked out as the depth test would: the first triangle in
/// mesh order with the smallest depth among those that drew the centre.
pub fn probe(
    scene: Scene<'_>,
    fates: &Fates,
    (x, y): (u32, u32),
    drawn: Option<Drawn<'_>>,
) -> PixelProbe {
    let mut candidates = covering(scene, fates, x, y);
    let (triangle, depth, color) = match drawn {
        Some(drawn) => (
            drawn.rasterizer.owner(x, y),
            drawn.rasterizer.depth(x, y).unwrap_or(1.0),
            pixel_color(drawn.image, x, y),
        ),
        None => {
            let winner = candidates
                .iter()
                .filter(|c| c.outcome == PixelOutcome::Depth && c.depth < 1.0)
                .fold(None::<&Candidate>, |best, c| match best {
                    Some(b) if b.depth <= c.depth => Some(b),
                    _ => Some(c),
                });
            (
                winner.map(|w| w.triangle),
                winner.map_or(1.0, |w| w.depth),
                None,
            )
        }
    };
    for c in candidates.iter_mut() {
        if c.outcome == PixelOutcome::Depth && Some(c.triangle) == triangle {
            c.outcome = PixelOutcome::Won;
        }
    }
    PixelProbe {
        pixel: [x, y],
        triangle,
        depth,
        color,
        candidates,
    }
}

fn pixel_color(frame: &SoftwareFrame, x: u32, y: u32) -> Option<[u8; 4]> {
    let image = &frame.image;
    if x >= image.width || y >= image.height {
        return None;
    }
    image.pixels.get((y * image.width + x) as usize).copied()
}

/// Every triangle whose coverage reaches the centre of (x, y), with its outcome before the
/// depth test is settled: `Depth` for every one that drew it (the winner is among them).
fn covering(scene: Scene<'_>, fates: &Fates, x: u32, y: u32) -> Vec<Candidate> {
    let transform = ClipTransform::new(scene.camera);
    let viewport = viewport_matrix(scene.viewport.width as f32, scene.viewport.height as f32);
    let mut candidates = Vec::new();
    for (index, corners) in scene.mesh.triangles.iter().enumerate() {
        let Some(fate) = fates.of(index) else {
            continue;
        };
        let clip = corners.map(|i| transform.apply(scene.mesh.positions[i as usize]));
        let removed = fate.kind == FateKind::Clipped;
        let polygon = projected(clip, removed, scene.pipeline.clipping);
        let Some((coverage, depth)) = cover(&polygon, &viewport, scene.viewport, x, y) else {
            continue;
        };
        let outcome = match (fate.kind, coverage) {
            (FateKind::Clipped, _) => PixelOutcome::Clipped,
            (FateKind::Culled | FateKind::ZeroArea, _) => PixelOutcome::Culled,
            (_, Coverage::LostToFillRule) => PixelOutcome::FillRule,
            _ => PixelOutcome::Depth,
        };
        candidates.push(Candidate {
            triangle: index as u32,
            outcome,
            depth,
        });
    }
    candidates
}

/// The polygon whose coverage counts: the piece the pipeline cut (with full clipping), or for a
/// triangle clipping removed, where it would project (see the module's comment).
fn projected(clip: [glam::Vec4; 3], removed: bool, clipping: Clipping) -> Polygon {
    let triangle = Polygon::triangle(clip[0], clip[1], clip[2]);
    let outside_any = clip.iter().fold(0, |code, p| code | outcode(*p));
    if removed || clipping == Clipping::Simple {
        if clip.iter().all(|p| p.w > 0.0) {
            return triangle;
        }
        return clip_polygon(&triangle, outside_any & NEAR);
    }
    clip_polygon(&triangle, outside_any)
}

/// How the polygon's fan, set up as the rasterizer sets it up, covers the centre of (x, y), and
/// its depth there; None when it does not reach it.
fn cover(
    polygon: &Polygon,
    viewport: &Mat4,
    size: Viewport,
    x: u32,
    y: u32,
) -> Option<(Coverage, f32)> {
    let vertex = |i: usize| {
        Vertex::new(
            to_window_depth(polygon.points[i], viewport),
            [0.0; VARYINGS],
        )
    };
    let params = SetupParams {
        size: [size.width as i32, size.height as i32],
        used: Used::default(),
        drop_uncovered: false,
    };
    let mut lost = None;
    for i in 1..polygon.len.saturating_sub(1) {
        let t: Triangle = triangle([&vertex(0), &vertex(i), &vertex(i + 1)], params);
        let depth = t.planes.depth_at(x as f32 + 0.5, y as f32 + 0.5);
        match t.footprint.coverage(x as i32, y as i32) {
            Coverage::Inside => return Some((Coverage::Inside, depth)),
            Coverage::LostToFillRule => lost = Some((Coverage::LostToFillRule, depth)),
            Coverage::Outside => {}
        }
    }
    lost
}

//! What one Close2GL frame hands on: the viewport, the 2D vertex buffer with its stage counts,
//! and the software rasterizer's image.

use crate::Image;
use bevy_ecs::prelude::*;
use serde::Serialize;

/// The pixel size of the Close2GL view (and of the reference view beside it).
#[derive(Resource, Clone, Copy, Debug, PartialEq, Eq)]
pub struct Viewport {
    pub width: u32,
    pub height: u32,
}

impl Default for Viewport {
    fn default() -> Self {
        Self {
            width: 640,
            height: 480,
        }
    }
}

/// What the 2D buffer's vertices form.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Topology {
    Points,
    Lines,
    #[default]
    Triangles,
}

/// How many triangles each stage of the Close2GL pipeline saw.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct StageCounts {
    /// Triangles in the mesh.
    pub triangles_in: usize,
    /// Removed whole by clipping (outside the view volume, or touching its border in simple mode).
    pub clipped: usize,
    /// Removed by backface culling.
    pub culled: usize,
    /// Survivors: `triangles_in - clipped - culled`.
    pub drawn: usize,
    /// Points, lines or triangles in the 2D buffer (clipping may cut one triangle into several).
    pub output_primitives: usize,
}

/// A mesh vertex after the transform, for the software rasterizer: its window position, depth in
/// 0..1 (the reference's depth range) and 1/w, and what lighting needs in eye space. Meaningful
/// only for vertices inside the view volume (the others are reached only through [`CutVertex`]).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RasterVertex {
    /// x, y in window pixels, depth, 1/w.
    pub window: [f32; 4],
    pub eye: [f32; 3],
    pub normal: [f32; 3],
    /// Texture coordinates (s, t); (0, 0) for a model without them.
    pub uv: [f32; 2],
}

/// A vertex that clipping made: its window position, and where it lies in the triangle it was
/// cut from (weights of the triangle's corners, summing to 1), so that anything computed at the
/// corners (a Gouraud intensity, say) is interpolated to it exactly as a GPU's clipper does.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CutVertex {
    pub window: [f32; 4],
    pub corners: [u32; 3],
    pub weights: [f32; 3],
}

/// The Close2GL pipeline's output for its own rasterizer: the same primitives as the 2D buffer,
/// as indices. Index i < `vertices.len()` is mesh vertex i; above it, `cuts[i - vertices.len()]`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RasterGeometry {
    pub vertices: Vec<RasterVertex>,
    pub cuts: Vec<CutVertex>,
    /// One index per point, two per line, three per triangle (the frame's topology).
    pub primitives: Vec<u32>,
    /// The mesh triangle each primitive came from, one per primitive; filled only while
    /// `Fates::record` is set (the rasterizer then finds which triangles cover no pixel centre
    /// and which win none), empty otherwise.
    pub triangles: Vec<u32>,
    /// Whether the mesh has texture coordinates.
    pub textured: bool,
}

/// A shown trace's 2D output, in the Close2GL view's pixels and the frame's topology: the GPU
/// draws it in place of the pipeline's 2D buffer. Its one writer is the trace plugin; `None`
/// while no trace is shown.
#[derive(Resource, Clone, Debug, Default, PartialEq)]
pub struct TraceOutput(pub Option<Vec<[f32; 2]>>);

/// Two images the views show in place of their own drawing while a raster trace is open: its
/// frame is fixed (a raster trace has no camera), so the Close2GL view shows the program's own
/// framebuffer and the reference close2gl's drawing of the same triangles, each letterboxed in
/// its view ([`Letterbox`]). Its one writer is the trace plugin; `None` while no raster trace is shown.
#[derive(Resource, Clone, Debug, Default, PartialEq)]
pub struct ViewImages(pub Option<FixedFrame>);

/// A fixed frame's two images, both of the trace's window size.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FixedFrame {
    pub reference: Image,
    pub close2gl: Image,
}

/// What check found in the shown trace, in the words the panel shows, so that the panel reads
/// no check types. Its one writer is the trace plugin, whenever it takes or refuses a trace;
/// empty while none is shown or refused.
#[derive(Resource, Clone, Debug, Default, PartialEq)]
pub struct TraceFindings {
    /// The trace shown.
    pub path: Option<std::path::PathBuf>,
    /// Why the last trace requested was refused (the one shown before stays).
    pub error: Option<String>,
    pub agrees: bool,
    /// The first stage that differs, by name, with its details.
    pub first_difference: Option<(&'static str, Vec<String>)>,
    /// The catalogue mistakes check named.
    pub mistakes: Vec<&'static str>,
    /// When no mistake explains the trace: its first difference, as precisely as it can say.
    pub unexplained: Option<String>,
    /// Every stage by name, with its status in a few words (`agrees (12)`).
    pub stages: Vec<(&'static str, String)>,
    /// A raster trace's report, as check writes it for a person, line by line; `None` for a
    /// geometry trace. A raster trace's frame is fixed: the camera moves nothing in its views.
    pub raster_report: Option<Vec<String>>,
}

/// The Close2GL pipeline's output: 2D positions in window pixels (origin top-left, y down), ready
/// for a pass-through GPU pipeline, and the stage counts; with the software rasterizer, also the
/// same primitives with depth and what shading needs.
#[derive(Resource, Clone, Debug, Default, PartialEq)]
pub struct Close2glFrame {
    pub topology: Topology,
    pub vertices: Vec<[f32; 2]>,
    /// Filled only when `PipelineSettings::close2gl_raster` is `Software`.
    pub raster: RasterGeometry,
    pub counts: StageCounts,
    /// Viewport the vertices were mapped to.
    pub viewport: Viewport,
    /// Wall time of the geometry stage, milliseconds.
    pub geometry_ms: f64,
}

impl Close2glFrame {
    /// `[xmin, ymin, xmax, ymax]` of the emitted vertices, or `None` when nothing was emitted.
    pub fn bounds_px(&self) -> Option<[f32; 4]> {
        let mut it = self.vertices.iter();
        let first = it.next()?;
        Some(it.fold([first[0], first[1], first[0], first[1]], |b, p| {
            [
                b[0].min(p[0]),
                b[1].min(p[1]),
                b[2].max(p[0]),
                b[3].max(p[1]),
            ]
        }))
    }
}

/// The software rasterizer's image of the Close2GL view, and how long it took.
#[derive(Resource, Clone, Debug, Default, PartialEq)]
pub struct SoftwareFrame {
    pub image: Image,
    /// Rasterization, depth test, shading and the copy into the image, in milliseconds (the
    /// geometry before it is `Close2glFrame::geometry_ms`).
    pub raster_ms: f64,
}

/// What one frame of the views is drawn from, borrowed: the mesh, the camera, the pipeline's
/// switches and the viewport (what decides which triangle covers a pixel; colours are not
/// asked). Both views' pixel probes take it, so that they ask about the same frame.
#[derive(Clone, Copy)]
pub struct Scene<'a> {
    pub mesh: &'a crate::Mesh,
    pub camera: &'a crate::Camera,
    pub pipeline: &'a crate::PipelineSettings,
    pub viewport: crate::Viewport,
}

/// Where a fixed frame sits in a view so that, stretched over the view, it keeps its own shape:
/// in the middle of a canvas of the view's shape, its pixels from `offset` on, bars beside it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Letterbox {
    pub canvas: (u32, u32),
    pub offset: (u32, u32),
}

impl Letterbox {
    /// The letterbox of a frame of `size` pixels in `view`.
    pub fn new(size: (u32, u32), view: Viewport) -> Letterbox {
        let (width, height) = (u64::from(size.0), u64::from(size.1));
        let (across, down) = (u64::from(view.width.max(1)), u64::from(view.height.max(1)));
        // A view wider than the frame: bars left and right; else above and below.
        let canvas = match across * height >= width * down {
            true => (((height * across + down / 2) / down).max(width), height),
            false => (width, ((width * down + across / 2) / across).max(height)),
        };
        let canvas = (canvas.0 as u32, canvas.1 as u32);
        Letterbox {
            canvas,
            offset: ((canvas.0 - size.0) / 2, (canvas.1 - size.1) / 2),
        }
    }

    /// `image` on its canvas, the bars `fill`.
    pub fn place(&self, image: &Image, fill: [u8; 4]) -> Image {
        let mut canvas = Image::filled(self.canvas.0, self.canvas.1, fill);
        let (width, left) = (image.width as usize, self.offset.0 as usize);
        for (y, row) in image.pixels.chunks(width.max(1)).enumerate() {
            let start = (y + self.offset.1 as usize) * self.canvas.0 as usize + left;
            canvas.pixels[start..start + row.len()].copy_from_slice(row);
        }
        canvas
    }

    /// The frame's pixel (column, row from the top) that view pixel `pixel` shows, the canvas
    /// stretched over `view`; None on a bar. A frame of `size`.
    pub fn frame_pixel(
        &self,
        pixel: (u32, u32),
        view: Viewport,
        size: (u32, u32),
    ) -> Option<(u32, u32)> {
        let on_canvas = |p: u32, view: u32, canvas: u32| {
            let at = (f64::from(p) + 0.5) / f64::from(view.max(1)) * f64::from(canvas);
            (at as u32).min(canvas.saturating_sub(1))
        };
        let x = on_canvas(pixel.0, view.width, self.canvas.0).checked_sub(self.offset.0)?;
        let y = on_canvas(pixel.1, view.height, self.canvas.1).checked_sub(self.offset.1)?;
        (x < size.0 && y < size.1).then_some((x, y))
    }
}

#[cfg(test)]
mod letterbox_tests {
    use super::{Image, Letterbox, Viewport};

    #[test]
    fn a_frame_keeps_its_shape_in_a_view_of_another() {
        let tall = Viewport {
            width: 100,
            height: 200,
        };
        let boxed = Letterbox::new((40, 30), tall);
        assert_eq!(boxed.canvas, (40, 80));
        assert_eq!(boxed.offset, (0, 25));
        let wide = Viewport {
            width: 300,
            height: 100,
        };
        assert_eq!(Letterbox::new((40, 30), wide).canvas, (90, 30));
        let same = Letterbox::new((40, 30), Viewport::default());
        assert_eq!((same.canvas, same.offset), ((40, 30), (0, 0)));
    }

    #[test]
    fn a_view_pixel_finds_the_frame_pixel_it_shows_and_none_on_the_bars() {
        let view = Viewport {
            width: 80,
            height: 160,
        };
        let boxed = Letterbox::new((40, 30), view);
        let mut image = Image::filled(40, 30, [1, 2, 3, 255]);
        image.pixels[3 * 40 + 5] = [9, 9, 9, 255];
        let canvas = boxed.place(&image, [0; 4]);
        // View pixel (11, 56) is canvas pixel (5, 28): the frame's (5, 3).
        assert_eq!(boxed.frame_pixel((11, 56), view, (40, 30)), Some((5, 3)));
        assert_eq!(canvas.pixel(5, 28), [9, 9, 9, 255]);
        assert_eq!(boxed.frame_pixel((11, 10), view, (40, 30)), None);
        assert_eq!(canvas.pixel(5, 5), [0; 4]);
    }
}

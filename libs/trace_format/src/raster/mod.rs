//! A raster trace (`close2gl-raster 1`, docs/raster-trace-format.md): what a student's own
//! rasterizer wrote about one frame, the triangles it rasterized with each corner's values, its
//! shading and texture settings, and the files of the buffers it filled ([`images`] reads them).

pub mod images;
mod keys;

use std::path::Path;

use close2gl_core::{Image, Shading, TextureFilter};

use super::magic::{Format, check_magic};
use super::read;
use super::syntax::{FormatError, last_line, records};
use images::DepthImage;
use keys::Reader;

/// The values a corner of a `tri` line may carry, in the order they are written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Attribute {
    /// x y z q: window position, depth in 0..1 and 1/w.
    Window,
    /// The corner's colour (Gouraud's, lit).
    Rgb,
    /// The corner's position in eye space.
    Eye,
    /// Its normal in eye space.
    Normal,
    /// Its texture coordinates s t.
    Uv,
}

impl Attribute {
    pub const ALL: [Attribute; 5] = [Self::Window, Self::Rgb, Self::Eye, Self::Normal, Self::Uv];

    pub fn name(self) -> &'static str {
        match self {
            Self::Window => "window",
            Self::Rgb => "rgb",
            Self::Eye => "eye",
            Self::Normal => "normal",
            Self::Uv => "uv",
        }
    }

    /// How many numbers it takes.
    pub fn numbers(self) -> usize {
        match self {
            Self::Window => 4,
            Self::Uv => 2,
            _ => 3,
        }
    }
}

/// One corner of a rasterized triangle: what the `attributes` line says it carries (zero where
/// it carries nothing).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RasterCorner {
    pub window: [f64; 4],
    pub rgb: [f64; 3],
    pub eye: [f64; 3],
    pub normal: [f64; 3],
    pub uv: [f64; 2],
}

/// A `tri` line: mesh triangle `mesh`'s piece, as rasterized.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RasterTriangle {
    pub mesh: usize,
    pub corners: [RasterCorner; 3],
    /// The line it was read from (for messages).
    pub line: usize,
}

/// The lecture's lighting as a `lighting` line gives it: Ia, Il, ka, kd, ks, the shininess and
/// the attenuation's c0, c1, c2.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightingLine {
    pub ia: [f64; 3],
    pub il: [f64; 3],
    pub ka: f64,
    pub kd: f64,
    pub ks: f64,
    pub shininess: f64,
    pub attenuation: [f64; 3],
}

/// What a lit shading needs: the light's world position, the modelview matrix that takes it
/// to eye space (row by row), and the constants.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Lit {
    pub light: [f64; 3],
    pub modelview: [f64; 16],
    pub lighting: LightingLine,
}

/// One raster trace.
#[derive(Clone, Debug, PartialEq)]
pub struct RasterTrace {
    /// The label errors and messages name the file by.
    pub file: String,
    pub model: Option<String>,
    pub window: (u32, u32),
    /// `origin bottom-left` (OpenGL's, the default): y grows upwards.
    pub y_up: bool,
    /// `subpixel B`: corners snapped to 1/2^B pixel before coverage.
    pub subpixel: Option<u32>,
    pub shading: Shading,
    pub color: [f64; 3],
    pub background: [f64; 3],
    /// Given for lit shadings (required for them).
    pub lit: Option<Lit>,
    /// The texture's path as written (relative to the trace's folder) and its filter.
    pub texture: Option<(String, TextureFilter)>,
    /// The colour buffer's path as written.
    pub framebuffer: String,
    pub depthbuffer: Option<String>,
    pub attributes: Vec<Attribute>,
    pub triangles: Vec<RasterTriangle>,
}

impl RasterTrace {
    /// Whether each corner carries `attribute`.
    pub fn has(&self, attribute: Attribute) -> bool {
        self.attributes.contains(&attribute)
    }
}

/// Whether `text` starts as a raster trace does (comments and blank lines before it allowed).
pub fn is_raster_trace(text: &str) -> bool {
    records(text, "")
        .next()
        .is_some_and(|l| l.key() == "close2gl-raster")
}

/// Reads a raster trace from `text`; `file` labels its errors.
pub fn parse_raster_trace(text: &str, file: &str) -> Result<RasterTrace, FormatError> {
    let mut lines = records(text, file);
    let last = last_line(text);
    check_magic(lines.next().as_ref(), Format::Raster, file, last)?;
    let mut reader = Reader::default();
    for line in lines {
        reader.read(&line)?;
    }
    reader.finish(file, last)
}

/// Reads the raster trace at `path`, labelled as the path is given.
pub fn read_raster_trace(path: &Path) -> Result<RasterTrace, FormatError> {
    let (text, file) = read::text(path)?;
    parse_raster_trace(&text, &file)
}

/// A raster trace with the files it names, read and checked against each other: what check
/// judges.
#[derive(Clone, Debug)]
pub struct RasterFrame {
    pub trace: RasterTrace,
    /// The colour buffer it wrote, rows from the top.
    pub framebuffer: Image,
    pub depth: Option<DepthImage>,
    pub texture: Option<Image>,
}

impl RasterFrame {
    /// The frame of `trace`, its files' bytes given by `read` (their names as the trace writes
    /// them; an error is the reason it could not be read).
    pub fn read_with(
        trace: RasterTrace,
        read: impl Fn(&str) -> Result<Vec<u8>, String>,
    ) -> Result<RasterFrame, FormatError> {
        let bytes = |name: &str| {
            read(name).map_err(|why| FormatError {
                file: name.to_string(),
                line: 0,
                message: format!("cannot read: {why}"),
            })
        };
        let size = |name: &str, (w, h): (u32, u32)| {
            let (width, height) = trace.window;
            match (w, h) == (width, height) {
                true => Ok(()),
                false => Err(FormatError {
                    file: name.to_string(),
                    line: 0,
                    message: format!(
                        "expected {width}×{height} pixels (the trace's window), found {w}×{h}"
                    ),
                }),
            }
        };
        let name = &trace.framebuffer;
        let framebuffer = images::read_ppm(&bytes(name)?, name)?;
        size(name, (framebuffer.width, framebuffer.height))?;
        let depth = match &trace.depthbuffer {
            Some(name) => {
                let depth = images::read_pfm(&bytes(name)?, name)?;
                size(name, (depth.width, depth.height))?;
                Some(depth)
            }
            None => None,
        };
        let texture = match &trace.texture {
            Some((name, _)) => Some(images::read_ppm(&bytes(name)?, name)?),
            None => None,
        };
        Ok(RasterFrame {
            trace,
            framebuffer,
            depth,
            texture,
        })
    }
}

impl RasterFrame {
    /// The texture filter the frame was drawn with: None when it is not textured (no texture
    /// named, or none read).
    pub fn filter(&self) -> Option<TextureFilter> {
        let filter = self.trace.texture.as_ref().map(|(_, f)| *f);
        filter.filter(|_| self.texture.is_some())
    }
}

/// Reads the raster trace at `path` and the files it names, beside it.
pub fn read_raster_frame(path: &Path) -> Result<RasterFrame, FormatError> {
    let trace = read_raster_trace(path)?;
    let folder = path.parent().unwrap_or(Path::new("")).to_path_buf();
    RasterFrame::read_with(trace, |name| {
        let (bytes, _) = read::bytes(&folder.join(name)).map_err(|e| e.message)?;
        Ok(bytes)
    })
}

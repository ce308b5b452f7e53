//! A trace (`close2gl-trace 1`): what a program wrote about one frame of its own Close2GL, its
//! camera, its matrices and the 2D triangles it drew.

use std::collections::HashMap;
use std::path::Path;

use close2gl_core::FrontFace;
use close2gl_core::RenderMode;
use close2gl_core::declaration::{ClipPlanes, ClipRule, WindingSpace};
use glam::DMat4;

use super::camera_lines::shape;
use super::common::{Common, Ends};
use super::magic::{Format, check_magic};
use super::output::{self, ClipLine, MATRIX_NAMES, Piece};
use super::syntax::{FormatError, Line, Slot, last_line, records, set_once};
use super::{CameraLines, MAX_RECORDS, System2d, read};

/// One trace file. What the file leaves out is `None` (or empty), so that a checker can say
/// what it did not check.
#[derive(Clone, Debug, PartialEq)]
pub struct Trace {
    /// The label errors and messages name the file by.
    pub file: String,
    pub model: Option<String>,
    /// The `triangles N` count and its line.
    pub triangles: Option<(usize, usize)>,
    pub window: (u32, u32),
    /// `0 W 0 H` when not given.
    pub ortho2d: System2d,
    pub camera: CameraLines,
    /// None: culling off (the default).
    pub culling: Option<FrontFace>,
    /// `simple` when not given.
    pub clipping: ClipRule,
    pub mode: Option<RenderMode>,
    /// Where the program tests the winding, when the trace says (`culling ccw ndc`).
    pub winding: Option<WindingSpace>,
    /// The planes the program clipped against (`clipping simple near_far`: near and far only).
    pub planes: ClipPlanes,
    pub m: Option<DMat4>,
    pub p: Option<DMat4>,
    pub v: Option<DMat4>,
    /// `matrix model`: what the program applied to the file's vertices before M.
    pub model_matrix: Option<DMat4>,
    pub clip: Vec<ClipLine>,
    /// The `tri` and `poly` lines, in file order.
    pub pieces: Vec<Piece>,
    /// `drawn N`: the count of `tri` and `poly` lines, said to be complete, and its line.
    pub drawn: Option<(usize, usize)>,
    /// Whether an `end` line said the trace is complete.
    pub ended: bool,
}

impl Trace {
    /// Whether the trace gives its 2D output: `tri` or `poly` lines, a `drawn` line, or `clip`
    /// lines (a program that computed its triangles' clip coordinates and wrote no 2D triangle
    /// drew nothing).
    pub fn gives_output(&self) -> bool {
        !self.pieces.is_empty() || self.drawn.is_some() || !self.clip.is_empty()
    }
}

/// Reads a trace from `text`; `file` labels its errors.
pub fn parse_trace(text: &str, file: &str) -> Result<Trace, FormatError> {
    parse_limited(text, file, MAX_RECORDS)
}

/// Reads the trace file at `path`, labelled as the path is given.
pub fn read_trace(path: &Path) -> Result<Trace, FormatError> {
    let (text, file) = read::text(path)?;
    parse_trace(&text, &file)
}

/// Reads a trace from the bytes of a file (read by the caller: a program's, read only as its
/// own); `file` labels its errors.
pub fn parse_trace_bytes(bytes: Vec<u8>, file: &str) -> Result<Trace, FormatError> {
    parse_trace(&read::decode(bytes, file)?, file)
}

/// [`parse_trace`] with `limit` in place of [`MAX_RECORDS`], so that a test can reach it.
pub(crate) fn parse_limited(text: &str, file: &str, limit: usize) -> Result<Trace, FormatError> {
    let mut lines = records(text, file);
    let ends = Ends {
        format: Format::Trace,
        file,
        last_line: last_line(text),
    };
    check_magic(lines.next().as_ref(), Format::Trace, file, ends.last_line)?;
    let mut reader = Reader {
        limit,
        ..Reader::default()
    };
    reader.common.trace_additions = true;
    for line in lines {
        reader.read(&line)?;
    }
    reader.finish(&ends)
}

/// The trace read so far.
#[derive(Default)]
struct Reader {
    common: Common,
    triangles: Slot<usize>,
    ortho2d: Slot<System2d>,
    matrices: [Slot<DMat4>; 4],
    drawn: Slot<usize>,
    clip: Vec<ClipLine>,
    /// The line of each triangle's `clip`, to refuse a second.
    clip_lines: HashMap<usize, usize>,
    pieces: Vec<Piece>,
    limit: usize,
}

impl Reader {
    fn read(&mut self, line: &Line) -> Result<(), FormatError> {
        if self.common.read(line, "model NAME")? {
            return Ok(());
        }
        match line.key() {
            "triangles" => {
                line.expect_fields(2, "triangles N")?;
                let n = line.integer(1, "N", "triangles N")?;
                set_once(&mut self.triangles, n, line, "triangles")
            }
            "ortho2d" => set_once(&mut self.ortho2d, ortho2d(line)?, line, "ortho2d"),
            "drawn" => {
                line.expect_fields(2, "drawn N")?;
                let n = line.integer(1, "N", "drawn N")?;
                set_once(&mut self.drawn, n, line, "drawn")
            }
            "matrix" => {
                let (i, m) = output::matrix(line)?;
                let key = format!("matrix {}", MATRIX_NAMES[i]);
                set_once(&mut self.matrices[i], m, line, &key)
            }
            "clip" | "tri" | "poly" => self.read_output(line),
            _ => Err(line.expected(
                "a trace line (model, triangles, window, ortho2d, camera, culling, clipping, \
                 mode, matrix, clip, tri, poly, drawn or end)",
            )),
        }
    }

    /// A `clip`, `tri` or `poly` line, of which there may be millions, up to the limit.
    fn read_output(&mut self, line: &Line) -> Result<(), FormatError> {
        if self.clip.len() + self.pieces.len() >= self.limit {
            let limit = self.limit;
            let what = format!("at most {limit} 'clip', 'tri' and 'poly' lines in all");
            return Err(line.expected(&what));
        }
        match line.key() {
            "clip" => {
                let clip = output::clip(line)?;
                if let Some(first) = self.clip_lines.insert(clip.triangle, line.number) {
                    let t = clip.triangle;
                    return Err(
                        line.expected(&format!("one 'clip {t}' line (the first is line {first})"))
                    );
                }
                self.clip.push(clip);
            }
            "tri" => self.pieces.push(output::tri(line)?),
            _ => self.pieces.push(output::poly(line)?),
        }
        Ok(())
    }

    fn finish(self, ends: &Ends) -> Result<Trace, FormatError> {
        let common = self.common;
        let (culling, clipping) = (common.culling(), common.clipping());
        let window = common.window(ends)?;
        let camera = common
            .camera
            .lines()
            .map_err(|i| ends.without(&format!("'{}'", shape(i))))?;
        if let Some((n, line)) = self.drawn
            && n != self.pieces.len()
        {
            let pieces = self.pieces.len();
            let message = format!(
                "expected 'drawn {pieces}' (the trace has {pieces} 'tri' and 'poly' lines), \
                 found 'drawn {n}'"
            );
            return Err(FormatError::new(ends.file, line, message));
        }
        let [m, p, v, model_matrix] = self.matrices.map(|slot| slot.map(|(m, _)| m));
        Ok(Trace {
            file: ends.file.to_string(),
            model: common.model.map(|(name, _)| name),
            triangles: self.triangles,
            window,
            ortho2d: self.ortho2d.map_or(
                System2d {
                    left: 0.0,
                    right: f64::from(window.0),
                    bottom: 0.0,
                    top: f64::from(window.1),
                },
                |(o, _)| o,
            ),
            camera,
            culling,
            clipping,
            mode: common.mode.map(|(m, _)| m),
            winding: common.winding,
            planes: common.planes,
            m,
            p,
            v,
            model_matrix,
            clip: self.clip,
            pieces: self.pieces,
            drawn: self.drawn,
            ended: common.end.is_some(),
        })
    }
}

/// `ortho2d L R B T`, a system of some width and height (`gluOrtho2D` divides by both).
fn ortho2d(line: &Line) -> Result<System2d, FormatError> {
    const SHAPE: &str = "ortho2d L R B T";
    line.expect_fields(5, SHAPE)?;
    let x = line.numbers(1, SHAPE, |k| ["L", "R", "B", "T"][k].to_string())?;
    if x[0] == x[1] || x[2] == x[3] {
        return Err(line.expected(&format!("'{SHAPE}' with L != R and B != T")));
    }
    Ok(System2d {
        left: x[0],
        right: x[1],
        bottom: x[2],
        top: x[3],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const HEAD: &str = "close2gl-trace 1\nwindow 4 4\ncamera position 0 0 5\ncamera u 1 0 0\n\
                        camera v 0 1 0\ncamera n 0 0 1\ncamera hfov 60\ncamera vfov 60\n\
                        camera near 1\ncamera far 10\n";

    #[test]
    fn past_the_limit_of_output_lines_is_an_error_at_the_line_past_it() {
        let text = format!("{HEAD}tri 0 0 0 1 0 0 1\nclip 0 0 0 0 1 0 0 0 1 0 0 0 1\n");
        assert_eq!(parse_limited(&text, "t", 2).unwrap().pieces.len(), 1);
        let text = format!("{text}poly 1 3 0 0 1 0 0 1\n");
        let error = parse_limited(&text, "t", 2).unwrap_err();
        assert_eq!(
            error.to_string(),
            "t:13: expected at most 2 'clip', 'tri' and 'poly' lines in all, \
             found 'poly 1 3 0 0 1 0 0 1'"
        );
    }
}

//! The lines both formats share (`model`, `window`, the camera, `culling`, `clipping`, `mode`,
//! `end`), and the rules every key follows: given once, nothing after `end`, the required ones
//! present.

use close2gl_core::declaration::{ClipPlanes, ClipRule, WindingSpace};
use close2gl_core::limits::MAX_PIXELS;
use close2gl_core::{FrontFace, RenderMode};

use super::camera_lines::CameraSlots;
use super::magic::Format;
use super::names::{CLIPPINGS, CULLINGS, choices, clipping_name, culling_name, from_word};
use super::syntax::{FormatError, Line, Slot, set_once};

/// What both formats read alike, as the lines come.
#[derive(Default)]
pub(crate) struct Common {
    pub(crate) model: Slot<String>,
    pub(crate) window: Slot<(u32, u32)>,
    pub(crate) camera: CameraSlots,
    pub(crate) culling: Slot<Option<FrontFace>>,
    /// Where the `culling` line says the winding is tested (a trace's addition).
    pub(crate) winding: Option<WindingSpace>,
    pub(crate) clipping: Slot<ClipRule>,
    /// The planes the `clipping` line says the program clipped against (a trace's addition).
    pub(crate) planes: ClipPlanes,
    /// Whether the additions only a trace may say are read: a culling space, `near_far`.
    pub(crate) trace_additions: bool,
    pub(crate) mode: Slot<RenderMode>,
    /// The `end` line's number: nothing but comments may follow it.
    pub(crate) end: Option<usize>,
}

impl Common {
    /// Reads `line` when its key is one both formats have; `Ok(false)` leaves it to the
    /// format's own keys. `model_shape` is how the format names its `model` line.
    pub(crate) fn read(&mut self, line: &Line, model_shape: &str) -> Result<bool, FormatError> {
        self.check_open(line)?;
        match line.key() {
            "model" => {
                // One field, as the C writer makes it: a name with blanks would be extra fields.
                line.expect_fields(2, model_shape)?;
                set_once(&mut self.model, line.fields[1].to_string(), line, "model")?;
            }
            "window" => set_once(&mut self.window, window(line)?, line, "window")?,
            "camera" => self.camera.read(line)?,
            "culling" => {
                let (culling, winding) = self.culling_line(line)?;
                set_once(&mut self.culling, culling, line, "culling")?;
                self.winding = winding;
            }
            "clipping" => {
                let (clipping, planes) = self.clipping_line(line)?;
                set_once(&mut self.clipping, clipping, line, "clipping")?;
                self.planes = planes;
            }
            "mode" => {
                let mode = one_of(line, RenderMode::ALL, RenderMode::name)?;
                set_once(&mut self.mode, mode, line, "mode")?;
            }
            "end" => {
                line.expect_fields(1, "end")?;
                self.end = Some(line.number);
            }
            _ => return Ok(false),
        }
        Ok(true)
    }

    /// `culling off|ccw|cw`, in a trace with an optional space: `culling ccw ndc`.
    fn culling_line(
        &self,
        line: &Line,
    ) -> Result<(Option<FrontFace>, Option<WindingSpace>), FormatError> {
        if !self.trace_additions || line.fields.len() != 3 {
            return Ok((one_of(line, &CULLINGS, culling_name)?, None));
        }
        const SHAPE: &str = "culling ccw|cw ndc|window";
        let space = match line.fields[2] {
            "ndc" => WindingSpace::Ndc,
            "window" => WindingSpace::Window,
            _ => return Err(line.wrong_shape(SHAPE)),
        };
        match FrontFace::from_name(line.fields[1]) {
            Some(front) => Ok((Some(front), Some(space))),
            None => Err(line.wrong_shape(SHAPE)),
        }
    }

    /// `clipping simple|full|none`, in a trace with an optional `near_far`.
    fn clipping_line(&self, line: &Line) -> Result<(ClipRule, ClipPlanes), FormatError> {
        if !self.trace_additions || line.fields.len() != 3 {
            return Ok((one_of(line, &CLIPPINGS, clipping_name)?, ClipPlanes::All));
        }
        const SHAPE: &str = "clipping simple|full near_far";
        let clip = from_word(&CLIPPINGS, clipping_name, line.fields[1]);
        match (clip, line.fields[2]) {
            (Some(c @ (ClipRule::Simple | ClipRule::Full)), "near_far") => {
                Ok((c, ClipPlanes::NearFar))
            }
            _ => Err(line.wrong_shape(SHAPE)),
        }
    }

    /// Refuses any line after `end`.
    pub(crate) fn check_open(&self, line: &Line) -> Result<(), FormatError> {
        match self.end {
            Some(end) => Err(line.expected(&format!("nothing after 'end' (line {end})"))),
            None => Ok(()),
        }
    }

    pub(crate) fn window(&self, ends: &Ends) -> Result<(u32, u32), FormatError> {
        self.window
            .map(|(size, _)| size)
            .ok_or_else(|| ends.without("'window W H'"))
    }

    /// The `culling` line's value; off when there is none.
    pub(crate) fn culling(&self) -> Option<FrontFace> {
        self.culling.and_then(|(c, _)| c)
    }

    /// The `clipping` line's value; the assignment's `simple` when there is none.
    pub(crate) fn clipping(&self) -> ClipRule {
        self.clipping.map_or(ClipRule::Simple, |(c, _)| c)
    }
}

/// `window W H`, each in 1..=16384 (the largest texture common adapters allow).
pub(crate) fn window(line: &Line) -> Result<(u32, u32), FormatError> {
    const SHAPE: &str = "window W H";
    line.expect_fields(3, SHAPE)?;
    let size = |i, name| {
        let x = line.integer(i, name, SHAPE)?;
        u32::try_from(x)
            .ok()
            .filter(|x| (1..=MAX_PIXELS).contains(x))
            .ok_or_else(|| line.expected(&format!("'{SHAPE}' with W and H in 1..={MAX_PIXELS}")))
    };
    Ok((size(1, "W")?, size(2, "H")?))
}

/// `KEY WORD` with WORD the name of one of `all`.
pub(crate) fn one_of<T: Copy>(
    line: &Line,
    all: &[T],
    name: fn(T) -> &'static str,
) -> Result<T, FormatError> {
    let shape = format!("{} {}", line.key(), choices(all, name));
    line.expect_fields(2, &shape)?;
    from_word(all, name, line.fields[1]).ok_or_else(|| line.wrong_shape(&shape))
}

/// Where a file that lacks a required line is reported: its last line.
pub(crate) struct Ends<'a> {
    pub(crate) format: Format,
    pub(crate) file: &'a str,
    pub(crate) last_line: usize,
}

impl Ends<'_> {
    /// `the trace ends without <what>`.
    pub(crate) fn without(&self, what: &str) -> FormatError {
        let message = format!("the {} ends without {what}", self.format.noun());
        FormatError::new(self.file, self.last_line, message)
    }
}

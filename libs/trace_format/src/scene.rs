//! A scene (`close2gl-scene 1`): what a grader hands a program to say which frame to draw, the
//! model, the window, the starting camera and the camera motions to apply in order.

use std::path::{Path, PathBuf};

use close2gl_core::declaration::ClipRule;
use close2gl_core::{FrontFace, NamedEnum, RenderMode, Shading, TextureFilter};
use glam::DVec3;

use super::camera_lines::shape;
use super::common::{Common, Ends, one_of};
use super::magic::{Format, check_magic};
use super::syntax::{FormatError, Line, Slot, last_line, records, set_once};
use super::{Axis, CameraLines, MAX_RECORDS, read};

/// Where the camera starts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SceneCamera {
    /// `camera framed`: placed as the assignment says, with the view volume's lines that were
    /// given (the program chooses the rest).
    Framed {
        hfov: Option<f64>,
        vfov: Option<f64>,
        near: Option<f64>,
        far: Option<f64>,
    },
    /// The eight camera lines of a trace.
    Given(CameraLines),
}

/// One camera motion, in the camera's own axes: `move` by world units, `rotate` by degrees
/// (right-hand rule), `orbit` by world units about the look-at point (along u or v only).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Motion {
    Move(Axis, f64),
    Rotate(Axis, f64),
    Orbit(Axis, f64),
}

/// One scene file.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneFile {
    /// The label errors and messages name the file by.
    pub file: String,
    /// The model's path as written: relative to the scene file's folder ([`SceneFile::model_path`]).
    pub model: String,
    pub window: (u32, u32),
    pub camera: SceneCamera,
    /// None: culling off (the default).
    pub culling: Option<FrontFace>,
    /// `simple` when not given.
    pub clipping: ClipRule,
    pub mode: Option<RenderMode>,
    /// The look-at point of `orbit`; `None`: the model's bounding-box centre.
    pub lookat: Option<DVec3>,
    pub motions: Vec<Motion>,
    /// What the rasterizer assignment's lines ask for (their defaults when none is given).
    pub look: SceneLook,
}

/// The rasterizer assignment's scene lines: how the frame looks.
#[derive(Clone, Debug, PartialEq)]
pub struct SceneLook {
    pub shading: Shading,
    pub color: DVec3,
    pub background: DVec3,
    /// The light's world position (the lecture's 10 10 3 by default).
    pub light: DVec3,
    /// The texture's path as written (relative to the scene file's folder) and its filter.
    pub texture: Option<String>,
    pub filter: TextureFilter,
}

impl Default for SceneLook {
    fn default() -> Self {
        SceneLook {
            shading: Shading::None,
            color: DVec3::ONE,
            background: DVec3::ZERO,
            light: DVec3::new(10.0, 10.0, 3.0),
            texture: None,
            filter: TextureFilter::Nearest,
        }
    }
}

impl SceneFile {
    /// The model file for a scene read from `scene_file`: relative to its folder, an absolute
    /// path as it is (`Path::join` keeps an absolute one whole).
    pub fn model_path(&self, scene_file: &Path) -> PathBuf {
        let folder = scene_file.parent().unwrap_or(Path::new(""));
        folder.join(&self.model)
    }
}

/// Reads a scene from `text`; `file` labels its errors.
pub fn parse_scene(text: &str, file: &str) -> Result<SceneFile, FormatError> {
    let mut lines = records(text, file);
    let ends = Ends {
        format: Format::Scene,
        file,
        last_line: last_line(text),
    };
    check_magic(lines.next().as_ref(), Format::Scene, file, ends.last_line)?;
    let mut reader = Reader::default();
    for line in lines {
        reader.read(&line)?;
    }
    reader.finish(&ends)
}

/// Reads the scene file at `path`, labelled as the path is given.
pub fn read_scene(path: &Path) -> Result<SceneFile, FormatError> {
    let (text, file) = read::text(path)?;
    parse_scene(&text, &file)
}

/// The scene read so far.
#[derive(Default)]
struct Reader {
    common: Common,
    framed: Slot<()>,
    lookat: Slot<DVec3>,
    motions: Vec<Motion>,
    shading: Slot<Shading>,
    color: Slot<DVec3>,
    background: Slot<DVec3>,
    light: Slot<DVec3>,
    texture: Slot<String>,
    filter: Slot<TextureFilter>,
}

impl Reader {
    fn read(&mut self, line: &Line) -> Result<(), FormatError> {
        self.common.check_open(line)?;
        if line.key() == "camera" && self.read_framing(line)? {
            return Ok(());
        }
        if self.common.read(line, "model PATH")? {
            return Ok(());
        }
        match line.key() {
            "lookat" => {
                const SHAPE: &str = "lookat X Y Z";
                set_once(
                    &mut self.lookat,
                    DVec3::from_array(line.three(SHAPE)?),
                    line,
                    "lookat",
                )
            }
            "move" | "rotate" | "orbit" => {
                if self.motions.len() >= MAX_RECORDS {
                    let what = format!("at most {MAX_RECORDS} motions");
                    return Err(line.expected(&what));
                }
                self.motions.push(motion(line)?);
                Ok(())
            }
            _ if self.read_look(line)? => Ok(()),
            _ => Err(line.expected(
                "a scene line (model, window, camera, culling, clipping, mode, lookat, move, \
                 rotate, orbit, shading, color, background, light, texture, filter or end)",
            )),
        }
    }

    /// The rasterizer assignment's lines (`shading`, `color`, `background`, `light`, `texture`,
    /// `filter`): `Ok(false)` for any other key.
    fn read_look(&mut self, line: &Line) -> Result<bool, FormatError> {
        match line.key() {
            "shading" => set_once(
                &mut self.shading,
                one_of(line, Shading::ALL, Shading::name)?,
                line,
                "shading",
            ),
            "filter" => {
                let filter = one_of(line, TextureFilter::ALL, TextureFilter::name)?;
                set_once(&mut self.filter, filter, line, "filter")
            }
            "color" => set_once(
                &mut self.color,
                unit_rgb(line, "color R G B")?,
                line,
                "color",
            ),
            "background" => {
                let rgb = unit_rgb(line, "background R G B")?;
                set_once(&mut self.background, rgb, line, "background")
            }
            "light" => set_once(
                &mut self.light,
                DVec3::from_array(line.three("light X Y Z")?),
                line,
                "light",
            ),
            "texture" => {
                line.expect_fields(2, "texture PATH")?;
                set_once(&mut self.texture, line.fields[1].into(), line, "texture")
            }
            _ => return Ok(false),
        }?;
        Ok(true)
    }

    /// `camera framed`, and the rule that a framed camera takes no pose: `Ok(true)` when the
    /// line was `camera framed`.
    fn read_framing(&mut self, line: &Line) -> Result<bool, FormatError> {
        let which = line.fields.get(1).copied();
        if which == Some("framed") {
            line.expect_fields(2, "camera framed")?;
            if let Some(at) = self.common.camera.pose_line() {
                let what = format!("'camera framed' or a pose (line {at}), not both");
                return Err(line.expected(&what));
            }
            set_once(&mut self.framed, (), line, "camera framed")?;
            return Ok(true);
        }
        if let (Some((_, at)), Some("position" | "u" | "v" | "n")) = (self.framed, which) {
            let what =
                format!("only 'camera hfov|vfov|near|far' after 'camera framed' (line {at})");
            return Err(line.expected(&what));
        }
        Ok(false)
    }

    fn finish(self, ends: &Ends) -> Result<SceneFile, FormatError> {
        let common = self.common;
        let (culling, clipping) = (common.culling(), common.clipping());
        let (model, _) = common
            .model
            .clone()
            .ok_or_else(|| ends.without("'model PATH'"))?;
        let window = common.window(ends)?;
        let slots = &common.camera;
        let camera = match (self.framed, slots.lines()) {
            (Some(_), _) => SceneCamera::Framed {
                hfov: slots.hfov.map(|(x, _)| x),
                vfov: slots.vfov.map(|(x, _)| x),
                near: slots.near.map(|(x, _)| x),
                far: slots.far.map(|(x, _)| x),
            },
            (None, Ok(lines)) => SceneCamera::Given(lines),
            (None, Err(_)) if slots.pose_line().is_none() => {
                return Err(ends.without("'camera framed' or 'camera position X Y Z'"));
            }
            (None, Err(i)) => return Err(ends.without(&format!("'{}'", shape(i)))),
        };
        Ok(SceneFile {
            file: ends.file.to_string(),
            model,
            window,
            camera,
            culling,
            clipping,
            mode: common.mode.map(|(m, _)| m),
            lookat: self.lookat.map(|(x, _)| x),
            motions: self.motions,
            look: SceneLook {
                shading: self.shading.map_or(Shading::None, |(s, _)| s),
                color: self.color.map_or(DVec3::ONE, |(c, _)| c),
                background: self.background.map_or(DVec3::ZERO, |(c, _)| c),
                light: self.light.map_or(SceneLook::default().light, |(l, _)| l),
                texture: self.texture.map(|(t, _)| t),
                filter: self.filter.map_or(TextureFilter::Nearest, |(f, _)| f),
            },
        })
    }
}

/// `move AXIS D`, `rotate AXIS DEG` or `orbit AXIS D` (orbit along u or v only: along n it
/// would be a move).
fn motion(line: &Line) -> Result<Motion, FormatError> {
    let (shape, name, make): (&str, &str, fn(Axis, f64) -> Motion) = match line.key() {
        "move" => ("move u|v|n D", "D", Motion::Move),
        "rotate" => ("rotate u|v|n DEG", "DEG", Motion::Rotate),
        _ => ("orbit u|v D", "D", Motion::Orbit),
    };
    line.expect_fields(3, shape)?;
    let axis = match (line.key(), Axis::from_name(line.fields[1])) {
        ("orbit", Some(Axis::N)) | (_, None) => return Err(line.wrong_shape(shape)),
        (_, Some(axis)) => axis,
    };
    Ok(make(axis, line.number(2, name, shape)?))
}

/// `KEY R G B`, each in [0, 1].
fn unit_rgb(line: &Line, shape: &str) -> Result<DVec3, FormatError> {
    let rgb = DVec3::from_array(line.three(shape)?);
    match rgb.cmpge(DVec3::ZERO).all() && rgb.cmple(DVec3::ONE).all() {
        true => Ok(rgb),
        false => Err(line.expected(&format!("'{shape}' with R, G and B in [0, 1]"))),
    }
}

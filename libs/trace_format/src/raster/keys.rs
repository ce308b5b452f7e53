//! A raster trace's lines, read one at a time into their slots, each checked as it comes; what
//! the trace lacks is checked at its end.

use close2gl_core::{Shading, TextureFilter};

use super::{Attribute, LightingLine, Lit, RasterCorner, RasterTrace, RasterTriangle};
use crate::MAX_RECORDS;
use crate::common::{one_of, window};
use crate::syntax::{FormatError, Line, Slot, set_once};

/// The raster trace read so far.
#[derive(Default)]
pub(super) struct Reader {
    model: Slot<String>,
    window: Slot<(u32, u32)>,
    origin: Slot<bool>,
    subpixel: Slot<u32>,
    shading: Slot<Shading>,
    color: Slot<[f64; 3]>,
    background: Slot<[f64; 3]>,
    light: Slot<[f64; 3]>,
    modelview: Slot<[f64; 16]>,
    lighting: Slot<LightingLine>,
    texture: Slot<String>,
    filter: Slot<TextureFilter>,
    framebuffer: Slot<String>,
    depthbuffer: Slot<String>,
    attributes: Slot<Vec<Attribute>>,
    triangles: Vec<RasterTriangle>,
    drawn: Slot<usize>,
    end: Option<usize>,
}

const LIGHTING: &str = "lighting IAR IAG IAB ILR ILG ILB KA KD KS N C0 C1 C2";

impl Reader {
    pub(super) fn read(&mut self, line: &Line) -> Result<(), FormatError> {
        if let Some(end) = self.end {
            return Err(line.expected(&format!("nothing after 'end' (line {end})")));
        }
        match line.key() {
            "model" => {
                line.expect_fields(2, "model NAME")?;
                set_once(&mut self.model, line.fields[1].into(), line, "model")
            }
            "window" => set_once(&mut self.window, window(line)?, line, "window"),
            "origin" => set_once(&mut self.origin, origin(line)?, line, "origin"),
            "subpixel" => set_once(&mut self.subpixel, subpixel(line)?, line, "subpixel"),
            "shading" => {
                let shading = one_of(line, Shading::ALL, Shading::name)?;
                set_once(&mut self.shading, shading, line, "shading")
            }
            "filter" => {
                let filter = one_of(line, TextureFilter::ALL, TextureFilter::name)?;
                set_once(&mut self.filter, filter, line, "filter")
            }
            "color" => set_once(&mut self.color, line.three("color R G B")?, line, "color"),
            "background" => {
                let rgb = line.three("background R G B")?;
                set_once(&mut self.background, rgb, line, "background")
            }
            "light" => set_once(&mut self.light, line.three("light X Y Z")?, line, "light"),
            "matrix" => {
                const SHAPE: &str = "matrix M m00 m01 ... m33";
                if line.fields.len() != 18 || line.fields[1] != "M" {
                    return Err(line.wrong_shape(SHAPE));
                }
                let m = line.numbers(2, SHAPE, |k| format!("m{}{}", k / 4, k % 4))?;
                let m: [f64; 16] = std::array::from_fn(|k| m[k]);
                set_once(&mut self.modelview, m, line, "matrix M")
            }
            "lighting" => set_once(&mut self.lighting, lighting(line)?, line, "lighting"),
            "texture" | "framebuffer" | "depthbuffer" => self.path(line),
            "attributes" => {
                let attributes = attributes(line)?;
                set_once(&mut self.attributes, attributes, line, "attributes")
            }
            "tri" => self.triangle(line),
            "drawn" => {
                line.expect_fields(2, "drawn N")?;
                let n = line.integer(1, "N", "drawn N")?;
                set_once(&mut self.drawn, n, line, "drawn")
            }
            "end" => {
                line.expect_fields(1, "end")?;
                self.end = Some(line.number);
                Ok(())
            }
            _ => Err(line.expected(
                "a raster trace line (model, window, origin, subpixel, shading, color, \
                 background, light, matrix, lighting, texture, filter, framebuffer, depthbuffer, \
                 attributes, tri, drawn or end)",
            )),
        }
    }

    /// `texture PATH`, `framebuffer PATH` or `depthbuffer PATH`: one field, as the C writer makes
    /// it.
    fn path(&mut self, line: &Line) -> Result<(), FormatError> {
        let key = line.key();
        line.expect_fields(2, &format!("{key} PATH"))?;
        let slot = match key {
            "texture" => &mut self.texture,
            "framebuffer" => &mut self.framebuffer,
            _ => &mut self.depthbuffer,
        };
        set_once(slot, line.fields[1].into(), line, key)
    }

    /// `tri T` and three corners of the `attributes` line's values.
    fn triangle(&mut self, line: &Line) -> Result<(), FormatError> {
        let Some((attributes, _)) = &self.attributes else {
            return Err(line.expected("an 'attributes' line before the first 'tri'"));
        };
        let per_corner: usize = attributes.iter().map(|a| a.numbers()).sum();
        let names: Vec<&str> = attributes.iter().map(|a| a.name()).collect();
        let shape = format!(
            "tri T and 3 corners of {} ({per_corner} numbers each)",
            names.join(" ")
        );
        if line.fields.len() != 2 + 3 * per_corner {
            return Err(line.expected(&format!("'{shape}'")));
        }
        if self.triangles.len() >= MAX_RECORDS {
            return Err(line.expected(&format!("at most {MAX_RECORDS} tri lines")));
        }
        let mesh = line.integer(1, "T", &shape)?;
        let numbers = line.numbers(2, &shape, |k| format!("number {}", k + 1))?;
        let corners = std::array::from_fn(|c| corner(attributes, &numbers[c * per_corner..]));
        self.triangles.push(RasterTriangle {
            mesh,
            corners,
            line: line.number,
        });
        Ok(())
    }

    pub(super) fn finish(self, file: &str, last_line: usize) -> Result<RasterTrace, FormatError> {
        let without = |what: &str| {
            let message = format!("the raster trace ends without {what}");
            FormatError::new(file, last_line, message)
        };
        let window = self.window.ok_or_else(|| without("'window W H'"))?.0;
        let framebuffer = self
            .framebuffer
            .ok_or_else(|| without("'framebuffer PATH'"))?
            .0;
        let attributes = self
            .attributes
            .ok_or_else(|| without("'attributes window ...'"))?
            .0;
        if let Some((n, at)) = self.drawn
            && n != self.triangles.len()
        {
            let message = format!(
                "expected {n} tri lines (as 'drawn {n}' on line {at} says), found {}",
                self.triangles.len()
            );
            return Err(FormatError::new(file, last_line, message));
        }
        let shading = self.shading.map_or(Shading::None, |(s, _)| s);
        let lit = match (self.light, self.modelview, self.lighting) {
            (Some((light, _)), Some((modelview, _)), Some((lighting, _))) => Some(Lit {
                light,
                modelview,
                lighting,
            }),
            _ if shading == Shading::None => None,
            (None, ..) => return Err(without("'light X Y Z' (the shading is lit)")),
            (_, None, _) => return Err(without("'matrix M ...' (the shading is lit)")),
            _ => return Err(without(&format!("'{LIGHTING}' (the shading is lit)"))),
        };
        let filter = self.filter.map_or(TextureFilter::Nearest, |(f, _)| f);
        Ok(RasterTrace {
            file: file.to_string(),
            model: self.model.map(|(m, _)| m),
            window,
            y_up: self.origin.is_none_or(|(up, _)| up),
            subpixel: self.subpixel.map(|(b, _)| b),
            shading,
            color: self.color.map_or([1.0; 3], |(c, _)| c),
            background: self.background.map_or([0.0; 3], |(c, _)| c),
            lit,
            texture: self.texture.map(|(path, _)| (path, filter)),
            framebuffer,
            depthbuffer: self.depthbuffer.map(|(p, _)| p),
            attributes,
            triangles: self.triangles,
        })
    }
}

/// `origin bottom-left|top-left`: whether y grows upwards.
fn origin(line: &Line) -> Result<bool, FormatError> {
    const SHAPE: &str = "origin bottom-left|top-left";
    line.expect_fields(2, SHAPE)?;
    match line.fields[1] {
        "bottom-left" => Ok(true),
        "top-left" => Ok(false),
        _ => Err(line.wrong_shape(SHAPE)),
    }
}

/// `subpixel B`, B in 0..=16.
fn subpixel(line: &Line) -> Result<u32, FormatError> {
    const SHAPE: &str = "subpixel B";
    line.expect_fields(2, SHAPE)?;
    match line.integer(1, "B", SHAPE)? {
        bits @ 0..=16 => Ok(bits as u32),
        _ => Err(line.expected("'subpixel B' with B in 0..=16")),
    }
}

/// `lighting` and its 13 numbers.
fn lighting(line: &Line) -> Result<LightingLine, FormatError> {
    line.expect_fields(14, LIGHTING)?;
    let names: Vec<&str> = LIGHTING.split(' ').skip(1).collect();
    let k = line.numbers(1, LIGHTING, |i| names[i].to_string())?;
    Ok(LightingLine {
        ia: [k[0], k[1], k[2]],
        il: [k[3], k[4], k[5]],
        ka: k[6],
        kd: k[7],
        ks: k[8],
        shininess: k[9],
        attenuation: [k[10], k[11], k[12]],
    })
}

/// `attributes window [rgb] [eye] [normal] [uv]`: `window` first, each at most once.
fn attributes(line: &Line) -> Result<Vec<Attribute>, FormatError> {
    const SHAPE: &str = "attributes window [rgb] [eye] [normal] [uv]";
    let mut found = Vec::new();
    for word in &line.fields[1..] {
        let attribute = Attribute::ALL.into_iter().find(|a| a.name() == *word);
        match attribute {
            Some(a) if !found.contains(&a) => found.push(a),
            _ => return Err(line.wrong_shape(SHAPE)),
        }
    }
    match found.first() {
        Some(Attribute::Window) => Ok(found),
        _ => Err(line.wrong_shape(SHAPE)),
    }
}

/// One corner's values, in the order `attributes` lists them.
fn corner(attributes: &[Attribute], numbers: &[f64]) -> RasterCorner {
    let mut corner = RasterCorner::default();
    let mut at = 0;
    for attribute in attributes {
        let values = &numbers[at..at + attribute.numbers()];
        at += attribute.numbers();
        let slot: &mut [f64] = match attribute {
            Attribute::Window => &mut corner.window,
            Attribute::Rgb => &mut corner.rgb,
            Attribute::Eye => &mut corner.eye,
            Attribute::Normal => &mut corner.normal,
            Attribute::Uv => &mut corner.uv,
        };
        slot.copy_from_slice(values);
    }
    corner
}

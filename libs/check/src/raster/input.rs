//! The program's own input to its rasterizer, as the textbook rasterizer takes it: the trace's
//! triangles as corners (snapped as the program says it snaps them), its shading, light and
//! texture; and a way to draw them again with any rules and mistakes.

use std::ops::Range;

use close2gl_core::{Lighting, RasterMistake, RasterMistakes, RasterRules, Shading, TextureFilter};
use close2gl_raster::textbook::{self, Buffers, Corner, Light, Rasterization, Shader};
use close2gl_trace_format::{RasterCorner, RasterFrame};
use glam::{DMat4, DVec3, Vec3};

/// The trace's triangles as the textbook takes them, ready to draw again.
pub struct Redraw<'a> {
    input: &'a RasterFrame,
    triangles: Vec<([Corner; 3], u32)>,
    lighting: Lighting,
    /// The light in eye space and in the world.
    light: (Vec3, Vec3),
}

impl<'a> Redraw<'a> {
    pub fn new(input: &'a RasterFrame) -> Redraw<'a> {
        let trace = &input.trace;
        let triangles = (trace.triangles.iter())
            .map(|t| (t.corners.map(|c| corner(&c)), t.mesh as u32))
            .collect();
        let (lighting, light) = match &trace.lit {
            Some(lit) => {
                let k = &lit.lighting;
                let lighting = Lighting {
                    light_position: as_vec3(lit.light),
                    ia: as_vec3(k.ia),
                    il: as_vec3(k.il),
                    ka: k.ka as f32,
                    kd: k.kd as f32,
                    ks: k.ks as f32,
                    shininess: k.shininess as f32,
                    attenuation: k.attenuation.map(|c| c as f32),
                };
                let m = DMat4::from_cols_array(&lit.modelview).transpose();
                let eye = m.transform_point3(DVec3::from_array(lit.light)).as_vec3();
                (lighting, (eye, as_vec3(lit.light)))
            }
            None => (Lighting::default(), (Vec3::ZERO, Vec3::ZERO)),
        };
        Redraw {
            input,
            triangles,
            lighting,
            light,
        }
    }

    /// The light, for `shading`, making `mistakes`.
    pub fn light(&self, mistakes: RasterMistakes) -> Light {
        let (eye, world) = self.light;
        Light::new(
            &self.lighting,
            eye,
            world,
            self.input.trace.shading,
            mistakes,
        )
    }

    /// The trace's triangles drawn with `rules`, making `mistakes`. Gouraud's corners carry the
    /// program's own lit colours, so its shader's colour is white.
    pub fn draw(&self, rules: RasterRules, mistakes: RasterMistakes) -> Buffers {
        self.draw_rows(rules, mistakes, None)
    }

    /// [`Redraw::draw`], only the picture's `rows` (from the top, as the program wrote them)
    /// drawn; the rest is background.
    pub fn draw_band(
        &self,
        rules: RasterRules,
        mistakes: RasterMistakes,
        rows: &Range<u32>,
    ) -> Buffers {
        let height = self.input.trace.window.1;
        // The rows the program wrote upside down were drawn at the other end.
        let scissor = match mistakes.has(RasterMistake::RowsBottomFirst) {
            true => [height - rows.end, height - rows.start],
            false => [rows.start, rows.end],
        };
        self.draw_rows(rules, mistakes, Some(scissor))
    }

    fn draw_rows(
        &self,
        rules: RasterRules,
        mistakes: RasterMistakes,
        scissor: Option<[u32; 2]>,
    ) -> Buffers {
        let trace = &self.input.trace;
        let color = match trace.shading.per_vertex() {
            true => Vec3::ONE,
            false => as_vec3(trace.color),
        };
        let filter = self.input.filter().unwrap_or(TextureFilter::Nearest);
        let shader = Shader::new(
            trace.shading,
            color,
            self.light(mistakes),
            self.input.texture.as_ref(),
            filter,
        );
        // Finer than 1/256 pixel, or not said: close2gl's 1/256, and the pixels whose centres are
        // that close to an edge are left out of coverage (`facts::ties`).
        let how = Rasterization {
            rules,
            mistakes,
            y_up: trace.y_up,
            subpixel_bits: trace.subpixel.unwrap_or(8).min(8),
            scissor,
        };
        let background = as_vec3(trace.background);
        textbook::draw_corners(trace.window, background, &self.triangles, &shader, &how)
    }

    /// Whether the frame is lit per pixel or per corner.
    pub fn shading(&self) -> Shading {
        self.input.trace.shading
    }
}

fn as_vec3(v: [f64; 3]) -> Vec3 {
    DVec3::from_array(v).as_vec3()
}

/// A corner as the textbook takes it.
fn corner(c: &RasterCorner) -> Corner {
    Corner {
        window: c.window,
        rgb: c.rgb.map(|x| x as f32),
        eye: c.eye.map(|x| x as f32),
        normal: c.normal.map(|x| x as f32),
        uv: c.uv.map(|x| x as f32),
    }
}

//! Gouraud's lighting, judged where the program lit: at each corner. The trace gives each
//! corner's eye-space position and normal and the colour the program lit it with; close2gl
//! lights the same position and normal, with each lighting mistake too. A corner that clipping
//! made lies on the view volume's border (window x or y at the window's edge, depth 0 or 1):
//! its colour is blended from lit corners, not lit itself, so it is left out.

use close2gl_core::{RasterMistake as M, RasterMistakes, RasterStage};
use close2gl_trace_format::{Attribute, RasterCorner};
use glam::{DVec3, Vec3};

use close2gl_trace_format::RasterFrame;

use super::input::Redraw;

/// How far a lit channel may differ: the program's float lighting and ours.
const LIT_TOLERANCE: f32 = 2e-3;

/// The corners' lighting against close2gl's.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CornerFacts {
    pub compared: usize,
    pub differing: usize,
    /// The first corner that differs: its `tri` line, its colour and close2gl's.
    pub first: Option<(usize, [f32; 3], [f32; 3])>,
    /// The lighting mistakes that reproduce every corner, when the program's differ.
    pub named: Vec<M>,
}

/// The corners judged, or None when the frame is not Gouraud-shaded or its corners do not carry
/// their colour, position and normal.
pub fn judge(input: &RasterFrame, redraw: &Redraw) -> Option<CornerFacts> {
    let trace = &input.trace;
    let carried = [Attribute::Rgb, Attribute::Eye, Attribute::Normal];
    if !trace.shading.per_vertex() || !carried.iter().all(|&a| trace.has(a)) {
        return None;
    }
    let lit = |mistakes: RasterMistakes| -> CornerFacts {
        let light = redraw.light(mistakes);
        let color = DVec3::from_array(trace.color).as_vec3();
        let mut facts = CornerFacts::default();
        for triangle in &trace.triangles {
            for corner in triangle
                .corners
                .iter()
                .filter(|c| !on_border(c, trace.window))
            {
                let eye = DVec3::from_array(corner.eye).as_vec3();
                let normal = DVec3::from_array(corner.normal).as_vec3();
                let ours = color * light.illuminate(eye, normal);
                let theirs = DVec3::from_array(corner.rgb).as_vec3();
                facts.compared += 1;
                if (ours - theirs).abs().max_element() > LIT_TOLERANCE {
                    facts.differing += 1;
                    let first = (triangle.line, theirs.to_array(), ours.to_array());
                    facts.first.get_or_insert(first);
                }
            }
        }
        facts
    };
    let mut facts = lit(RasterMistakes::NONE);
    if facts.differing > 0 {
        let lighting =
            (M::catalogue().iter().copied()).filter(|m| m.stage() == RasterStage::Shading);
        facts.named = lighting
            .filter(|&m| lit(RasterMistakes::one(m)).differing == 0)
            .collect();
    }
    Some(facts)
}

/// Whether a corner lies on the view volume's border, where clipping puts the corners it makes.
fn on_border(c: &RasterCorner, (width, height): (u32, u32)) -> bool {
    let near = |x: f64, edge: f64| (x - edge).abs() < 1e-3;
    let [x, y, z, _] = c.window;
    near(x, 0.0)
        || near(x, f64::from(width))
        || near(y, 0.0)
        || near(y, f64::from(height))
        || near(z, 0.0)
        || near(z, 1.0)
}

/// A colour as the report prints it.
pub fn describe(colour: [f32; 3]) -> String {
    let c = Vec3::from_array(colour);
    format!("({:.4}, {:.4}, {:.4})", c.x, c.y, c.z)
}

//! What check writes about numbers and triangles, in words: a number as a report prints it,
//! points, and what close2gl did with a triangle. The comparisons, the clues, the rubric and the
//! trace viewer's probe all say them the same way.

use close2gl_core::FateKind;
use close2gl_pipeline::program::TriangleOutcome;
use glam::{DVec2, DVec4};

/// What close2gl did with a triangle, in words.
pub fn fate_words(outcome: &TriangleOutcome) -> String {
    let planes: Vec<&str> = close2gl_core::ClipPlane::in_outcode(outcome.fate.planes)
        .map(|p| p.name())
        .collect();
    let behind = outcome.clip.iter().filter(|c| c.w <= 0.0).count();
    match outcome.fate.kind {
        FateKind::Drawn => "drew".into(),
        FateKind::Cut => format!("cut (by {}) and drew", planes.join(", ")),
        FateKind::Clipped if behind > 0 => format!(
            "clipped ({}; {behind} corner{} behind the eye)",
            planes.join(", "),
            if behind == 1 { "" } else { "s" }
        ),
        FateKind::Clipped => format!("clipped (outside {})", planes.join(", ")),
        FateKind::Culled => "culled as a back face".into(),
        FateKind::ZeroArea => "culled (no area)".into(),
        FateKind::NoPixels | FateKind::Hidden => "drew".into(),
    }
}

/// A number as reports print it: four decimals, or four significant digits in scientific
/// notation when it is very large or very small.
pub fn number(x: f64) -> String {
    match x.abs() {
        a if a != 0.0 && !(1e-3..1e6).contains(&a) => format!("{x:.4e}"),
        _ => format!("{x:.4}"),
    }
}

pub fn vec2(p: DVec2) -> String {
    format!("({}, {})", number(p.x), number(p.y))
}

pub fn vec4(p: DVec4) -> String {
    format!(
        "({}, {}, {}, {})",
        number(p.x),
        number(p.y),
        number(p.z),
        number(p.w)
    )
}

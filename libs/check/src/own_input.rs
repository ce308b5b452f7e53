//! The program's own geometry: close2gl's pipeline run from the clip coordinates and the
//! viewport the program itself computed, so that a stage after them (clipping, culling, the
//! window) is judged on what it was given: a wrong P shows at P, and a culling mistake beside
//! it still shows at culling (check), and costs the fov lines, not culling (grade).
//!
//! The clip coordinates come as one matrix: fitted to the trace's `clip` lines (least squares on
//! the mesh's corners, kept only when it reproduces every line), else the trace's own P·M, else
//! close2gl's.

use close2gl_core::Mesh;
use close2gl_pipeline::program::Program;
use close2gl_pipeline::rounding::{BOUND, PRINTED};
use close2gl_trace_format::{ClipLine, Trace};
use glam::{DMat4, DVec3, DVec4};

/// `ours` with the program's own clip matrix and, with `own_viewport`, its own V (a V that is
/// not the declared one, such as one turned upside down, then carries on into culling as it
/// does in the program).
pub fn own_program(ours: &Program, mesh: &Mesh, trace: &Trace, own_viewport: bool) -> Program {
    let mut program = *ours;
    let product = trace.p.zip(trace.m).map(|(p, m)| p * m);
    if let Some(matrix) = fitted_clip_matrix(ours, mesh, trace).or(product) {
        program.clip_matrix = matrix;
    }
    if let (true, Some(v)) = (own_viewport, trace.v) {
        program.v = v;
    }
    program
}

/// The matrix that takes the mesh's corners to the trace's clip coordinates, when one does.
fn fitted_clip_matrix(ours: &Program, mesh: &Mesh, trace: &Trace) -> Option<DMat4> {
    if trace.clip.is_empty() {
        return None;
    }
    let corners = |line: &ClipLine| corners(ours, mesh, line);
    // Centred and scaled corners keep the normal equations well conditioned far from the origin.
    let (low, high) = trace.clip.iter().flat_map(corners).fold(
        (DVec3::splat(f64::INFINITY), DVec3::splat(f64::NEG_INFINITY)),
        |(l, h), (p, _)| (l.min(p), h.max(p)),
    );
    let centre = 0.5 * (low + high);
    let scale = 0.5 * (high - low).max_element();
    // One point, or a flat mesh along every axis: no matrix to fit.
    if scale.is_nan() || scale <= 0.0 {
        return None;
    }
    let normalize = DMat4::from_scale(DVec3::splat(1.0 / scale)) * DMat4::from_translation(-centre);
    let mut gram = DMat4::ZERO;
    let mut moments = DMat4::ZERO;
    for (p, clip) in trace.clip.iter().flat_map(corners) {
        let q = normalize * p.extend(1.0);
        gram += outer(q, q);
        moments += outer(q, clip);
    }
    if gram.determinant().abs()
        < 1e-9
            * gram
                .to_cols_array()
                .iter()
                .map(|x| x.abs())
                .sum::<f64>()
                .powi(4)
    {
        return None;
    }
    // Each row r of X solves gram · x_r = Σ q·clip_r, so X = (gram⁻¹ · moments)ᵀ.
    let fitted = (gram.inverse() * moments).transpose() * normalize;
    let reproduces = trace.clip.iter().flat_map(corners).all(|(p, clip)| {
        let p = p.extend(1.0);
        let size = (0..4)
            .map(|row| {
                (0..4)
                    .map(|j| (fitted.col(j)[row] * p[j]).abs())
                    .sum::<f64>()
            })
            .fold(0.0, f64::max);
        // The fit's own rounding comes on top of the program's: four times its bound.
        ((fitted * p) - clip).abs().max_element() <= 4.0 * BOUND * size + PRINTED
    });
    reproduces.then_some(fitted)
}

/// A clip line's corners: the world point (the model matrix applied) and the trace's clip
/// coordinates for it.
fn corners(program: &Program, mesh: &Mesh, line: &ClipLine) -> [(DVec3, DVec4); 3] {
    let triangle = mesh.triangles[line.triangle];
    [0, 1, 2].map(|k| (program.world(mesh, triangle[k]), line.corners[k]))
}

/// a·bᵀ.
fn outer(a: DVec4, b: DVec4) -> DMat4 {
    DMat4::from_cols(a * b.x, a * b.y, a * b.z, a * b.w)
}

#[cfg(test)]
mod tests {
    use super::*;
    use close2gl_pipeline::matrices::Real;
    use close2gl_trace_format::parse_trace;

    /// A trace whose clip lines are `matrix` times the corners of a tetrahedron far from the
    /// origin (as course models are).
    fn trace_with_clip(mesh: &Mesh, matrix: DMat4) -> Trace {
        let mut text = String::from(
            "close2gl-trace 1\nwindow 4 4\ncamera position 0 0 5\ncamera u 1 0 0\n\
             camera v 0 1 0\ncamera n 0 0 1\ncamera hfov 60\ncamera vfov 60\n\
             camera near 1\ncamera far 10\n",
        );
        for (t, triangle) in mesh.triangles.iter().enumerate() {
            text.push_str(&format!("clip {t}"));
            for &i in triangle {
                let c = matrix * mesh.positions[i as usize].as_dvec3().extend(1.0);
                text.push_str(&format!(" {:?} {:?} {:?} {:?}", c.x, c.y, c.z, c.w));
            }
            text.push('\n');
        }
        parse_trace(&text, "t").expect("a trace")
    }

    fn tetrahedron() -> Mesh {
        let mut mesh = Mesh::default();
        for p in [
            [440.0, -224.0, 63.0],
            [1040.0, -224.0, 63.0],
            [440.0, 376.0, 63.0],
            [440.0, -224.0, 663.0],
        ] {
            mesh.positions.push(glam::Vec3::from_array(p));
        }
        mesh.triangles = vec![[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]];
        mesh
    }

    #[test]
    fn the_clip_matrix_is_found_from_the_clip_lines_even_in_the_wrong_order() {
        let mesh = tetrahedron();
        let m = f64::from_rows([
            [0.8, 0.0, -0.6, 100.0],
            [0.0, 1.0, 0.0, 200.0],
            [0.6, 0.0, 0.8, -900.0],
            [0.0, 0.0, 0.0, 1.0],
        ]);
        let p = f64::from_rows([
            [1.7, 0.0, 0.0, 0.0],
            [0.0, 1.7, 0.0, 0.0],
            [0.0, 0.0, -1.2, -2.2],
            [0.0, 0.0, -1.0, 0.0],
        ]);
        for matrix in [p * m, m * p] {
            let trace = trace_with_clip(&mesh, matrix);
            let fitted = fitted_clip_matrix(&ours(&trace), &mesh, &trace);
            let error = fitted.map(|f| {
                (f - matrix)
                    .to_cols_array()
                    .iter()
                    .map(|x| x.abs())
                    .fold(0.0, f64::max)
            });
            assert!(error.is_some_and(|e| e < 1e-6), "{error:?}");
        }
    }

    #[test]
    fn clip_lines_no_matrix_makes_are_not_fitted() {
        let mesh = tetrahedron();
        let mut trace = trace_with_clip(&mesh, DMat4::IDENTITY);
        trace.clip[2].corners[1].x += 50.0;
        assert_eq!(fitted_clip_matrix(&ours(&trace), &mesh, &trace), None);
    }

    fn ours(trace: &Trace) -> Program {
        crate::declared::program_for(trace, close2gl_pipeline::mistakes::Mistakes::NONE)
    }
}

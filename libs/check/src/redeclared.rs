//! A program can be right and its declaration wrong. One that clips against the near and far
//! planes only, leaving x and y to the GPU's 2D rasteriser, while it declares the assignment's
//! `clipping simple`, draws what `no_clipping` draws in any frame where nothing crosses the near
//! or far plane. When a set with `no_clipping` reproduces a trace, the same set without it is
//! tried under the declaration that fits (the trace's, with `near_far`), and both are named, with
//! what tells them apart.

use close2gl_core::{Mesh, Mistake};
use close2gl_pipeline::mistakes::Mistakes;
use close2gl_pipeline::program::{ClipPlanes, Declared, Program};
use close2gl_trace_format::{Trace, clipping_name};

use crate::compare::triangle::pieces_by_triangle;
use crate::declared::declared;
use crate::diagnose::{reproduces, spaces};

/// A set of mistakes that reproduces a trace when the program declares something else.
#[derive(Clone, Debug, PartialEq)]
pub struct Redeclared {
    pub mistakes: Mistakes,
    /// The line the program should have written (`clipping simple near_far`).
    pub declaration: String,
}

impl Redeclared {
    /// What it is, in words: the mistakes (or none) and the declaration that fits.
    pub fn words(&self) -> String {
        let mistakes = match self.mistakes.is_empty() {
            true => "no mistake".to_string(),
            false => self.mistakes.names(),
        };
        format!(
            "{mistakes}, clipping near and far only (x and y left to the 2D rasteriser), \
             declared '{}'",
            self.declaration
        )
    }
}

/// What tells `no_clipping` from clipping near and far only.
pub const APART: &str = "a frame with triangles across the near or far plane: no_clipping draws \
                         them, a program that clips near and far drops or cuts them";

/// For each of `diagnoses` (sets that reproduce `trace`) with `no_clipping`, the set without it
/// when it reproduces the trace clipping near and far only, as the trace's declaration with
/// `near_far` says; nothing for a trace that already declares `near_far`.
pub fn redeclared(mesh: &Mesh, trace: &Trace, diagnoses: &[Mistakes]) -> Vec<Redeclared> {
    if trace.planes == ClipPlanes::NearFar {
        return Vec::new();
    }
    let pieces = pieces_by_triangle(trace, mesh.triangles.len());
    let declaration = format!("clipping {} near_far", clipping_name(trace.clipping));
    let mut found: Vec<Redeclared> = Vec::new();
    for set in diagnoses.iter().filter(|set| set.has(Mistake::NoClipping)) {
        let without = (set.iter())
            .filter(|&m| m != Mistake::NoClipping)
            .fold(Mistakes::NONE, Mistakes::with);
        let near_far = |winding| Declared {
            planes: ClipPlanes::NearFar,
            ..declared(trace, winding)
        };
        let fits = spaces(trace, without).into_iter().any(|winding| {
            let program = Program::new(&trace.camera, near_far(winding), without);
            reproduces(&program, mesh, trace, &pieces)
        });
        let candidate = Redeclared {
            mistakes: without,
            declaration: declaration.clone(),
        };
        if fits && !found.contains(&candidate) {
            found.push(candidate);
        }
    }
    found
}

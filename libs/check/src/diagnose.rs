//! Naming the mistake: run close2gl's pipeline with every catalogue mistake, and every pair of
//! them, from the trace's camera, and keep those that reproduce the trace within tolerance. A
//! mistake is named only when it reproduces the trace; when none does, the first difference is
//! stated as precisely as the data allows.

use close2gl_core::{Mesh, Mistake};
use close2gl_pipeline::mistakes::Mistakes;
use close2gl_pipeline::program::{ClipPlanes, Program, TriangleOutcome, WindingSpace};
use close2gl_trace_format::Trace;
use rayon::prelude::*;

use crate::clues;
use crate::compare::triangle::{TriangleVerdict, judge_triangle, pieces_by_triangle};
use crate::compare::{self, camera, clip, matrices};
use crate::declared::{program_for, program_winding};
use crate::vocabulary::{Comparison, Kind, Stage, StageResult, Status};

/// The sets of mistakes that reproduce `trace`: single mistakes first; a pair only when neither
/// of its mistakes alone does (the other one would change nothing the trace shows).
pub fn diagnose(mesh: &Mesh, trace: &Trace) -> Vec<Mistakes> {
    let pieces = pieces_by_triangle(trace, mesh.triangles.len());
    let reproduces = |set: &Mistakes| {
        spaces(trace, *set).into_iter().any(|space| {
            let program = program_winding(trace, *set, space);
            reproduces(&program, mesh, trace, &pieces)
        })
    };
    let candidates = candidates(trace);
    let (singles, pairs): (Vec<Mistakes>, Vec<Mistakes>) =
        candidates.into_iter().partition(|s| s.iter().count() == 1);
    let found: Vec<Mistakes> = singles.into_par_iter().filter(reproduces).collect();
    if !found.is_empty() {
        return found;
    }
    pairs.into_par_iter().filter(reproduces).collect()
}

/// Where a program with `set` may test the winding: where the trace says; when it does not, on
/// screen (version 1's meaning), and also where it changes what `set` culls: in NDC when V is
/// flipped by the mistake, in the 2D numbers when the declared system runs mirrored on screen.
pub(crate) fn spaces(trace: &Trace, set: Mistakes) -> Vec<WindingSpace> {
    if let Some(space) = trace.winding {
        return vec![space];
    }
    let mut spaces = vec![WindingSpace::Screen];
    if trace.culling.is_none() {
        return spaces;
    }
    if set.has(Mistake::ViewportYFlipped) {
        spaces.push(WindingSpace::Ndc);
    }
    let o = trace.ortho2d;
    if (o.right - o.left) * (o.top - o.bottom) < 0.0 {
        spaces.push(WindingSpace::Window);
    }
    spaces
}

/// The sets a trace can be diagnosed with: every single and pair, but those that contradict
/// what it declares. A program that says it leaves x and y to the rasteriser (`near_far`) does
/// not test x/w and y/w (`divide_before_clip`).
fn candidates(trace: &Trace) -> Vec<Mistakes> {
    let near_far = trace.planes == ClipPlanes::NearFar;
    Mistakes::singles_and_pairs()
        .into_iter()
        .filter(|set| !(near_far && set.has(Mistake::DivideBeforeClip)))
        .collect()
}

/// Whether `program` reproduces the trace: what [`compare::compare`] would say agrees, found
/// stage by stage from the cheapest, stopping at the first difference (most mistakes show in a
/// matrix, before any triangle is sent down the pipeline).
pub(crate) fn reproduces(
    program: &Program,
    mesh: &Mesh,
    trace: &Trace,
    pieces: &[Vec<usize>],
) -> bool {
    let agrees = |s: &StageResult| s.status != Status::Differs;
    if !agrees(&camera::compare(program, trace))
        || !matrices::compare(program, trace).iter().all(agrees)
        || !agrees(&clip::compare(program, mesh, trace, &mut |_, _| {}))
    {
        return false;
    }
    if !trace.gives_output() {
        return true;
    }
    (0..mesh.triangles.len()).all(|t| {
        program.triangle(mesh, t).is_some_and(|ours| {
            matches!(
                judge_triangle(program, trace, t, &ours, &pieces[t]),
                TriangleVerdict::Agree { .. }
            )
        })
    })
}

/// For a trace no set reproduces whole: the single mistakes that explain some of its differing
/// stages (they agree there with the mistake made) and change nothing else, keeping only those
/// whose stages no other explains more of.
pub fn partial(mesh: &Mesh, trace: &Trace, comparison: &Comparison) -> Vec<(Mistakes, Vec<Stage>)> {
    let differing: Vec<Stage> = comparison
        .stages
        .iter()
        .filter(|s| s.status == Status::Differs)
        .map(|s| s.stage)
        .collect();
    let singles = candidates(trace)
        .into_iter()
        .filter(|s| s.iter().count() == 1);
    let explaining: Vec<(Mistakes, Vec<Stage>)> = singles
        .par_bridge()
        .filter_map(|set| {
            let with = compare::compare_own_input(&program_for(trace, set), mesh, trace);
            let differs = |s: Stage| with.stage(s).status == Status::Differs;
            let new = with
                .stages
                .iter()
                .any(|s| differs(s.stage) && !differing.contains(&s.stage));
            let explained: Vec<Stage> =
                differing.iter().copied().filter(|&s| !differs(s)).collect();
            (!new && !explained.is_empty()).then_some((set, explained))
        })
        .collect();
    let mut kept: Vec<(Mistakes, Vec<Stage>)> = explaining
        .iter()
        .filter(|(_, stages)| {
            !explaining.iter().any(|(_, other)| {
                other.len() > stages.len() && stages.iter().all(|s| other.contains(s))
            })
        })
        .cloned()
        .collect();
    kept.sort_by_key(|(set, _)| set.iter().next().map(|m| m as usize));
    kept
}

/// The first difference, in words a student can act on, for a trace no mistake explains;
/// `explained`: stages a named mistake explains, left out.
pub fn unexplained(
    program: &Program,
    mesh: &Mesh,
    comparison: &Comparison,
    expected: &[TriangleOutcome],
    explained: &[Stage],
) -> String {
    let first = comparison
        .stages
        .iter()
        .find(|s| s.status == Status::Differs && !explained.contains(&s.stage));
    let Some(first) = first else {
        return "the trace agrees".into();
    };
    let of_stage: Vec<(Kind, &[usize])> = comparison
        .triangles
        .iter()
        .filter(|(k, _)| k.stage() == first.stage)
        .map(|(k, t)| (*k, t.as_slice()))
        .collect();
    let Some(&(kind, triangles)) = of_stage.first() else {
        let what = match first.stage {
            Stage::Camera => "the camera's axes",
            Stage::M | Stage::P | Stage::V => "the matrix",
            _ => "the stage",
        };
        return format!(
            "no catalogue mistake explains it: {what} differs in {} of {} checked ({})",
            first.differing,
            first.checked,
            first.details.first().map_or("", String::as_str)
        );
    };
    let n = triangles.len();
    let (one, many) = happened(kind);
    let what = match n {
        1 => format!("1 triangle {one}"),
        _ => format!("{n} triangles {many}"),
    };
    format!(
        "no catalogue mistake explains it: {what}; {}",
        whereabouts(program, mesh, triangles, expected)
    )
}

/// What happened to triangles of `kind`, said of one and of several ("1 triangle was", "2
/// triangles were").
fn happened(kind: Kind) -> (&'static str, &'static str) {
    match kind {
        Kind::ClipCoordinates => ("has other clip coordinates", "have other clip coordinates"),
        Kind::DrawnBehindEye => (
            "with a corner behind the eye was drawn",
            "with a corner behind the eye were drawn",
        ),
        Kind::DrawnOutside => (
            "outside the view volume was drawn",
            "outside the view volume were drawn",
        ),
        Kind::NotDrawn => (
            "close2gl draws (at the volume's border) was not drawn",
            "close2gl draws (at the volume's border) were not drawn",
        ),
        Kind::FrontCulled => (
            "front-facing, inside the view volume, was not drawn",
            "front-facing, inside the view volume, were not drawn",
        ),
        Kind::InsideNotDrawn => (
            "inside the view volume, with culling off, was not drawn",
            "inside the view volume, with culling off, were not drawn",
        ),
        Kind::BackDrawn => (
            "back-facing, inside the view volume, was drawn",
            "back-facing, inside the view volume, were drawn",
        ),
        Kind::Moved => (
            "was drawn elsewhere or in another shape",
            "were drawn elsewhere or in another shape",
        ),
        Kind::Depth => ("was drawn at other depths", "were drawn at other depths"),
    }
}

/// Where some triangles lie and how big they are ([`clues::triangles`]).
fn whereabouts(
    program: &Program,
    mesh: &Mesh,
    triangles: &[usize],
    expected: &[TriangleOutcome],
) -> String {
    let seen: Vec<clues::Seen> = triangles
        .iter()
        .map(|&t| clues::seen(program, mesh, t, &expected[t]))
        .collect();
    clues::triangles(&seen, program.camera.near)
}

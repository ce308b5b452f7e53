//! `close2gl check` and the rubric `close2gl grade` scores by, as a library: a program's trace
//! (read by `close2gl_trace_format`) against close2gl's pipeline on the same mesh, in rooms a
//! reader can name. [`declared`] makes the program a trace declares; [`compare`] holds it to
//! the trace stage by stage, one file per stage (each stage on the program's own input,
//! [`own_input`]; one mesh triangle judged, [`compare::triangle`]; pieces against a polygon,
//! [`region`]), in the words of [`vocabulary`]; when it differs, [`diagnose`] names the
//! catalogue mistakes that reproduce it ([`apart`]: what tells them apart; [`redeclared`]: what
//! it may be under another declaration), and when none does, [`clues`] say what the differences
//! share. [`report`] and [`picture`] write what was found as text, JSON and images, in the
//! phrases of [`words`]. [`rubric`] makes the assignment's rubric into scenes, judges a
//! program's traces of them and scores the judged scenes into the lines' points. This file
//! holds the entry points only: no module calls back into it. It reads values (a mesh, traces,
//! scenes) and returns values: no files, processes, GPU or window.

pub mod apart;
pub mod clues;
pub mod compare;
pub mod declared;
pub mod diagnose;
pub mod own_input;
pub mod picture;
pub mod raster;
pub mod redeclared;
pub mod region;
pub mod report;
pub mod rubric;
pub mod vocabulary;
pub mod words;

use close2gl_core::Mesh;
use close2gl_pipeline::mistakes::Mistakes;
use close2gl_trace_format::{FormatError, Trace};

pub use declared::{declared, program_for, program_winding};
pub use redeclared::Redeclared;
pub use report::Report;
pub use vocabulary::{Comparison, Kind, Stage, StageResult, Status};

/// What a trace says about a model that is not a matter of its numbers: its triangle count and
/// every triangle index it uses must be the model's, and no triangle drawn in more than
/// [`MAX_PIECES`] pieces. An error names the trace's line.
pub fn fits(trace: &Trace, mesh: &Mesh) -> Result<(), FormatError> {
    let count = mesh.triangles.len();
    let error = |line: usize, message: String| FormatError {
        file: trace.file.clone(),
        line,
        message,
    };
    if let Some((n, line)) = trace.triangles
        && n != count
    {
        return Err(error(
            line,
            format!("expected 'triangles {count}' (the model has {count}), found 'triangles {n}'"),
        ));
    }
    let lines = trace
        .clip
        .iter()
        .map(|c| (c.triangle, c.line))
        .chain(trace.pieces.iter().map(|p| (p.triangle, p.line)));
    for (t, line) in lines {
        if t >= count {
            return Err(error(
                line,
                format!("expected a triangle index below {count} (the model's count), found {t}"),
            ));
        }
    }
    let mut pieces = vec![0usize; count];
    for piece in &trace.pieces {
        pieces[piece.triangle] += 1;
        if pieces[piece.triangle] > MAX_PIECES {
            return Err(error(
                piece.line,
                format!(
                    "expected at most {MAX_PIECES} 'tri' or 'poly' lines for one mesh triangle \
                     (a clipped triangle is at most 7), found more for triangle {}",
                    piece.triangle
                ),
            ));
        }
    }
    Ok(())
}

/// The most pieces a trace may draw for one mesh triangle: a triangle clipped by six planes is
/// a polygon of at most nine corners, a fan of seven triangles; the rest is room for clippers
/// that leave slivers. More is a trace that lies, and would make checking it quadratic.
pub const MAX_PIECES: usize = 64;

/// Checks `trace` against close2gl's pipeline on `mesh`, and diagnoses it when it differs.
pub fn check(mesh: &Mesh, trace: &Trace) -> Result<Report, FormatError> {
    let mut report = compare_only(mesh, trace)?;
    explain(&mut report, mesh, trace);
    Ok(report)
}

/// The comparison alone, no mistake named yet: a grader compares every scene but diagnoses
/// only those it reports, which is where the time goes on a big model.
pub fn compare_only(mesh: &Mesh, trace: &Trace) -> Result<Report, FormatError> {
    fits(trace, mesh)?;
    let program = program_for(trace, Mistakes::NONE);
    let expected = program.frame(mesh);
    let mut comparison = compare::compare_own_input(&program, mesh, trace);
    // The clues are for a reader: added to the comparison a report shows, not to each
    // candidate's.
    clues::add_matrix_clues(&mut comparison.stages, &program, trace);
    Ok(Report {
        comparison,
        expected,
        diagnoses: Vec::new(),
        redeclared: Vec::new(),
        unexplained: None,
        apart: Vec::new(),
        partial: Vec::new(),
    })
}

/// Names the mistakes that reproduce a trace that differs, or states its first difference
/// when none does; nothing for a trace that agrees.
pub fn explain(report: &mut Report, mesh: &Mesh, trace: &Trace) {
    if report.agrees() {
        return;
    }
    report.diagnoses = diagnose::diagnose(mesh, trace);
    report.apart = apart::tell_apart(trace, &report.diagnoses);
    report.redeclared = redeclared::redeclared(mesh, trace, &report.diagnoses);
    if !report.redeclared.is_empty() {
        report.apart.push(redeclared::APART.into());
    }
    if report.diagnoses.is_empty() {
        report.partial = diagnose::partial(mesh, trace, &report.comparison);
        let explained: Vec<Stage> = report
            .partial
            .iter()
            .flat_map(|(_, stages)| stages.iter().copied())
            .collect();
        let program = program_for(trace, Mistakes::NONE);
        report.unexplained = Some(diagnose::unexplained(
            &program,
            mesh,
            &report.comparison,
            &report.expected,
            &explained,
        ));
    }
}

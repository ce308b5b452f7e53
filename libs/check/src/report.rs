//! What check found ([`Report`]), and its report for a person (text) and for a script (one
//! JSON object, whose keys are binding: `agree`, `first_difference`, `mistakes`, `stages`,
//! `triangles`).

use close2gl_pipeline::mistakes::Mistakes;
use close2gl_pipeline::program::TriangleOutcome;
use serde_json::{Value, json};

use crate::redeclared::Redeclared;
use crate::vocabulary::{Comparison, Stage, StageResult, Status};

/// What check found: the comparison with close2gl, close2gl's own frame, and the mistakes that
/// reproduce the trace (each set on its own; empty when it agrees, or when none does).
#[derive(Clone, Debug)]
pub struct Report {
    pub comparison: Comparison,
    pub expected: Vec<TriangleOutcome>,
    pub diagnoses: Vec<Mistakes>,
    /// When the trace differs and no mistake reproduces it: the first difference, as precisely
    /// as the data allows.
    pub unexplained: Option<String>,
    /// Sets that reproduce the trace as well under another declaration than the trace's (a
    /// program that clips near and far only, where `no_clipping` is named).
    pub redeclared: Vec<Redeclared>,
    /// When several sets reproduce the trace: what would tell them apart.
    pub apart: Vec<String>,
    /// When none reproduces it whole: the mistakes that explain some of its differing stages,
    /// each with those stages.
    pub partial: Vec<(Mistakes, Vec<Stage>)>,
}

impl Report {
    pub fn agrees(&self) -> bool {
        self.comparison.agrees()
    }

    /// The catalogue ids named, each once, in the catalogue's order.
    pub fn mistakes(&self) -> Vec<&'static str> {
        let partial = self.partial.iter().map(|(set, _)| set);
        let all = self
            .diagnoses
            .iter()
            .chain(partial)
            .fold(Mistakes::NONE, |all, set| {
                set.iter().fold(all, |a, m| a.with(m))
            });
        all.iter().map(|m| m.name()).collect()
    }
}

/// The most triangle indices listed per kind of disagreement in the JSON (the totals are all).
pub const MAX_LISTED: usize = 100;

/// The report as text: each stage in order, the first difference in full, the mistakes named.
pub fn text(report: &Report, trace_name: &str) -> String {
    let verdict = match report.agrees() {
        true => "agrees with close2gl's pipeline",
        false => "differs from close2gl's pipeline",
    };
    let mut out = format!("{trace_name}: {verdict}\n");
    for s in &report.comparison.stages {
        stage_text(&mut out, s, &report.comparison);
    }
    if !report.agrees() {
        explanation_text(&mut out, report);
    }
    out
}

/// One stage's line and, where it differs, its details and its triangles by kind.
fn stage_text(out: &mut String, s: &StageResult, c: &Comparison) {
    let counts = match s.status {
        Status::NotChecked => s.note.clone().unwrap_or_default(),
        _ => format!("{} checked, {} differ", s.checked, s.differing),
    };
    out.push_str(&format!(
        "  {:<9} {:<12} {counts}\n",
        s.stage.name(),
        s.status.name()
    ));
    if s.status != Status::Differs {
        return;
    }
    for d in &s.details {
        out.push_str(&format!("      {d}\n"));
    }
    if s.differing > s.details.len() {
        out.push_str(&format!(
            "      ... and {} more\n",
            s.differing - s.details.len()
        ));
    }
    for (kind, triangles) in c.triangles.iter().filter(|(k, _)| k.stage() == s.stage) {
        out.push_str(&format!(
            "      {}: {} triangles\n",
            kind.name(),
            triangles.len()
        ));
    }
}

/// The mistakes named (with the declarations under which another set reproduces the trace,
/// and what would tell them apart), those explaining some stages, and what is left
/// unexplained.
fn explanation_text(out: &mut String, report: &Report) {
    match (report.diagnoses.as_slice(), report.redeclared.as_slice()) {
        ([], _) => {}
        ([one], []) => out.push_str(&format!("mistake: {}\n", one.names())),
        (many, redeclared) => {
            let names: Vec<String> = many.iter().map(|m| m.names()).collect();
            out.push_str(&format!(
                "mistakes (the trace cannot tell them apart): {}\n",
                names.join(", ")
            ));
            for other in redeclared {
                out.push_str(&format!("  or: {}\n", other.words()));
            }
            let hints = &report.apart;
            if !hints.is_empty() {
                out.push_str(&format!("  to tell them apart: {}\n", hints.join("; ")));
            }
        }
    }
    for (set, stages) in &report.partial {
        let stages: Vec<&str> = stages.iter().map(|s| s.name()).collect();
        out.push_str(&format!(
            "mistake: {} explains {}; the rest is unexplained\n",
            set.names(),
            stages.join(", ")
        ));
    }
    if let Some(unexplained) = &report.unexplained {
        out.push_str(&format!("{unexplained}\n"));
    }
}

/// The report as one JSON object.
pub fn json(report: &Report) -> Value {
    let c = &report.comparison;
    let first_difference = c.first_difference().map(|s| {
        json!({
            "stage": s.stage.name(),
            "detail": s.details.first().cloned().unwrap_or_default(),
            "details": s.details,
        })
    });
    let stages: serde_json::Map<String, Value> = c
        .stages
        .iter()
        .map(|s| {
            let mut stage = json!({
                "status": s.status.name(),
                "checked": s.checked,
                "differing": s.differing,
            });
            if let Some(note) = &s.note {
                stage["note"] = json!(note);
            }
            (s.stage.name().to_string(), stage)
        })
        .collect();
    let triangles: serde_json::Map<String, Value> = c
        .triangles
        .iter()
        .map(|(kind, list)| {
            let listed: Vec<usize> = list.iter().take(MAX_LISTED).copied().collect();
            (
                kind.name().to_string(),
                json!({"stage": kind.stage().name(), "total": list.len(), "indices": listed}),
            )
        })
        .collect();
    let diagnoses: Vec<Vec<&str>> = report
        .diagnoses
        .iter()
        .map(|set| set.iter().map(|m| m.name()).collect())
        .collect();
    json!({
        "agree": report.agrees(),
        "first_difference": first_difference,
        "mistakes": report.mistakes(),
        "diagnoses": diagnoses,
        "redeclared": report.redeclared.iter().map(|r| json!({
            "mistakes": r.mistakes.iter().map(|m| m.name()).collect::<Vec<_>>(),
            "declaration": r.declaration,
        })).collect::<Vec<_>>(),
        "tell_apart": report.apart,
        "explains": report.partial.iter().map(|(set, stages)| json!({
            "mistakes": set.iter().map(|m| m.name()).collect::<Vec<_>>(),
            "stages": stages.iter().map(|s| s.name()).collect::<Vec<_>>(),
        })).collect::<Vec<_>>(),
        "unexplained": report.unexplained,
        "stages": stages,
        "triangles": triangles,
    })
}

//! A raster check's report: for a person, one line per kind of fact and what was named; for a
//! script, one JSON object (`agree`, `rules`, `facts`, `corners`, `mistakes`, `nearest`).

use close2gl_core::{
    ByteConversion, DepthFunction, RasterMistake as M, RasterMistakes, RasterRules, TieRule,
};
use serde_json::{Value, json};

use super::RasterReport;
use super::corners::{CornerFacts, describe};
use super::facts::{Facts, Tally};

/// What each mistake does, in a line (docs/raster-trace-format.md pins each), in the
/// catalogue's order.
const MEANINGS: [(M, &str); 39] = [
    (M::None, "the textbook rasterizer"),
    (
        M::FillRuleInclusive,
        "a pixel centre on an edge is inside for both triangles (shared edges drawn twice)",
    ),
    (
        M::FillRuleExclusive,
        "a pixel centre on an edge is outside for both triangles (cracks along shared edges)",
    ),
    (
        M::PixelCornerSamples,
        "pixels are sampled at their corner (i, j), not their centre (i + 0.5, j + 0.5)",
    ),
    (
        M::VerticesRounded,
        "corners are rounded to whole pixels before setup (no sub-pixel precision)",
    ),
    (
        M::VerticesTruncated,
        "corners are truncated to whole pixels before setup",
    ),
    (
        M::BoundingBoxShort,
        "the bounding box loop stops before its last column and row",
    ),
    (
        M::ViewportEdgeSkipped,
        "the window's last column and row are never drawn",
    ),
    (
        M::DepthPerspective,
        "depth is interpolated with 1/w like a varying; window z is linear on screen",
    ),
    (
        M::DepthClearedToZero,
        "the depth buffer is cleared to 0, so no fragment passes 'less'",
    ),
    (
        M::FarthestWins,
        "the depth test is 'greater' on a buffer cleared to 0: the farthest surface shows",
    ),
    (
        M::NoDepthTest,
        "every fragment is drawn, later triangles over earlier ones",
    ),
    (M::DepthNotWritten, "the depth test never writes the buffer"),
    (
        M::DepthNdc,
        "the depth buffer holds NDC z in [-1, 1], not window z in [0, 1]",
    ),
    (
        M::ColourAffine,
        "Gouraud's colours are interpolated linearly on screen, without 1/w",
    ),
    (
        M::UvAffine,
        "texture coordinates are interpolated linearly on screen, without 1/w",
    ),
    (
        M::PhongAffine,
        "Phong's position and normal are interpolated linearly on screen, without 1/w",
    ),
    (
        M::WeightsRotated,
        "each corner's barycentric weight is applied to the next corner's values",
    ),
    (
        M::NoInterpolation,
        "every pixel takes the first corner's values",
    ),
    (
        M::NormalNotRenormalized,
        "Phong's interpolated normal is not normalised",
    ),
    (
        M::LightInWorld,
        "the light's world position is used as if it were in eye space",
    ),
    (M::NoSpecular, "the specular term is missing"),
    (M::DiffuseUnclamped, "N·L is not clamped at 0"),
    (M::SpecularUnclamped, "V·R is not clamped at 0"),
    (
        M::BlinnPhong,
        "the specular term is Blinn's (N·H)^n, not Phong's (V·R)^n",
    ),
    (
        M::NoAttenuation,
        "the light is not attenuated with distance",
    ),
    (
        M::ViewerAtInfinity,
        "V is (0, 0, 1) everywhere, not the direction to the eye",
    ),
    (
        M::TNotFlipped,
        "t = 0 is the image's top row (t grows upwards)",
    ),
    (
        M::NearestRounds,
        "nearest rounds s·W to the nearest integer instead of flooring it",
    ),
    (
        M::BilinearNoHalfTexel,
        "bilinear weights miss the half-texel shift (texel centres at i + 0.5)",
    ),
    (
        M::NoWrapBlack,
        "coordinates outside [0, 1] give black instead of repeating",
    ),
    (
        M::ClampNotRepeat,
        "coordinates are clamped to the edge instead of repeating",
    ),
    (
        M::LodAbsolute,
        "the level of detail is |log2 ρ|: magnified pixels take smaller levels",
    ),
    (
        M::LodOneAxis,
        "ρ is the footprint's step across only, not the longer of across and down",
    ),
    (
        M::LodUnscaled,
        "ρ is measured in texture coordinates, not texels: always level 0",
    ),
    (
        M::MipNearestLevel,
        "trilinear takes the nearest level, without blending two",
    ),
    (
        M::RowsBottomFirst,
        "the buffers are written bottom row first (the picture is upside down)",
    ),
    (
        M::ColourNotClamped,
        "colours above 1 wrap around instead of clamping at 255",
    ),
    (M::ChannelsSwapped, "red and blue are exchanged"),
];

/// What a mistake does, in a line.
pub fn meaning(m: M) -> &'static str {
    MEANINGS
        .iter()
        .find(|(k, _)| *k == m)
        .map_or("", |(_, text)| text)
}

/// The legal rules that differ from close2gl's own, as sentences.
pub fn legal_choices(rules: RasterRules) -> Vec<String> {
    let mut said = Vec::new();
    if rules.tie != TieRule::TopLeft {
        said.push(format!(
            "tie rule {} (legal: a centre on a shared edge goes to exactly one triangle; close2gl's is top_left)",
            rules.tie.name()
        ));
    }
    if rules.conversion == ByteConversion::Truncate {
        said.push("8-bit conversion by truncation (legal, at most one step below rounding)".into());
    }
    if rules.depth == DepthFunction::LessEqual {
        said.push("depth test 'less or equal' (legal: differs only at equal depths)".into());
    }
    said
}

fn tally_line(name: &str, tally: &Tally, what: &str) -> String {
    match (tally.compared, tally.differing, tally.first) {
        (0, _, _) => format!("{name:<10} not checked ({what})\n"),
        (n, 0, _) => format!("{name:<10} agrees on {n} pixels\n"),
        (n, d, Some((x, y))) => {
            format!(
                "{name:<10} differs at {d} of {n} pixels (first: column {x}, row {y} from the top)\n"
            )
        }
        (n, d, None) => format!("{name:<10} differs at {d} of {n} pixels\n"),
    }
}

fn corner_line(corners: &CornerFacts) -> String {
    match corners.first {
        None => format!(
            "{:<10} agrees on {} lit corners\n",
            "corners", corners.compared
        ),
        Some((line, theirs, ours)) => format!(
            "{:<10} differs at {} of {} lit corners (first: the tri on line {line}, yours {}, close2gl {})\n",
            "corners",
            corners.differing,
            corners.compared,
            describe(theirs),
            describe(ours)
        ),
    }
}

/// The report for a person.
pub fn text(report: &RasterReport, name: &str) -> String {
    let diagnosis = &report.diagnosis;
    let facts: &Facts = &diagnosis.legal.facts;
    let mut out = format!("raster trace {name}\n");
    out += &tally_line("coverage", &facts.coverage, "");
    out += &tally_line("depth", &facts.depth, "the trace gives no depth buffer");
    out += &tally_line("colour", &facts.colour, "no pixel drawn by both");
    if let Some(corners) = &report.corners {
        out += &corner_line(corners);
    }
    for choice in legal_choices(diagnosis.legal.rules) {
        out += &format!("rule      {choice}\n");
    }
    let named: Vec<RasterMistakes> = (diagnosis.named.iter().map(|a| a.mistakes))
        .chain(
            report
                .corners
                .iter()
                .flat_map(|c| c.named.iter().map(|&m| RasterMistakes::one(m))),
        )
        .collect();
    match (report.agrees(), named.is_empty()) {
        (true, _) => out += "agrees: every fact reproduced by close2gl's textbook rasterizer\n",
        (false, false) => {
            let one = named.len() == 1;
            out += match one {
                true => "named: the one catalogue mistake that reproduces every fact\n",
                false => {
                    "named: each of these reproduces every fact (this frame cannot tell them apart)\n"
                }
            };
            for set in &named {
                for m in set.iter() {
                    out += &format!("  {} ({}): {}\n", m.name(), m.stage().name(), meaning(m));
                }
                if set.iter().count() > 1 {
                    out += "  (together)\n";
                }
            }
        }
        (false, true) => {
            out +=
                "named: nothing; no catalogue mistake, alone or in a pair, reproduces every fact\n";
            for attempt in &diagnosis.nearest {
                out += &format!(
                    "  closest: {} ({} differing pixels left)\n",
                    attempt.mistakes.names(),
                    attempt.facts.distance()
                );
            }
        }
    }
    out
}

fn tally_json(tally: &Tally) -> Value {
    json!({
        "compared": tally.compared,
        "differing": tally.differing,
        "first": tally.first.map(|(x, y)| json!([x, y])),
    })
}

/// The report for a script.
pub fn json(report: &RasterReport) -> Value {
    let diagnosis = &report.diagnosis;
    let rules = diagnosis.legal.rules;
    let facts = &diagnosis.legal.facts;
    json!({
        "agree": report.agrees(),
        "rules": {
            "tie": rules.tie.name(),
            "conversion": rules.conversion.name(),
            "depth": rules.depth.name(),
        },
        "facts": {
            "coverage": tally_json(&facts.coverage),
            "depth": tally_json(&facts.depth),
            "colour": tally_json(&facts.colour),
        },
        "corners": report.corners.as_ref().map(|c| json!({
            "compared": c.compared,
            "differing": c.differing,
        })),
        "mistakes": report.mistakes(),
        "named": diagnosis.named.iter().map(|a| a.mistakes.names()).collect::<Vec<_>>(),
        "nearest": diagnosis.nearest.iter().map(|a| a.mistakes.names()).collect::<Vec<_>>(),
    })
}

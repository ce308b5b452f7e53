//! The rasterizer assignment's rubric, as a teacher writes it (`assets/rubrics/rasterizer/rubric.toml`):
//! lines with their points, the scenes each is judged on and the stages that decide it; each
//! scene of a program judged for its lines from check's report; the lines scored. Reading the
//! scenes and running the programs is the grade command's.

use close2gl_core::{RasterMistake, RasterStage};

use super::RasterReport;
use crate::rubric::file;

/// One line of a rubric.
#[derive(Clone, Debug, PartialEq)]
pub struct RubricLine {
    pub id: String,
    pub title: String,
    pub points: u32,
    pub stages: Vec<RasterStage>,
    /// The scenes it is judged on, by name (`*` in the file: every scene).
    pub scenes: Vec<String>,
}

/// A rubric: its lines, and every scene any line names, in the order first named.
#[derive(Clone, Debug, PartialEq)]
pub struct Rubric {
    pub lines: Vec<RubricLine>,
    pub scenes: Vec<String>,
}

impl Rubric {
    /// The rubric in `text`; `file` labels its errors, each naming the key that is wrong.
    pub fn parse(text: &str, file: &str) -> Result<Rubric, String> {
        let mut read = Vec::new();
        for (key, line) in file::lines(text, file, "rasterizer")? {
            read.push(rubric_line(&line, &key, file)?);
        }
        let mut scenes: Vec<String> = Vec::new();
        for name in read.iter().flat_map(|l| &l.scenes) {
            if name != "*" && !scenes.contains(name) {
                scenes.push(name.clone());
            }
        }
        for line in &mut read {
            if line.scenes.iter().any(|s| s == "*") {
                line.scenes = scenes.clone();
            }
        }
        Ok(Rubric {
            lines: read,
            scenes,
        })
    }

    /// The rubric's total.
    pub fn total(&self) -> u32 {
        self.lines.iter().map(|l| l.points).sum()
    }
}

fn rubric_line(line: &toml::Table, key: &str, file: &str) -> Result<RubricLine, String> {
    let known = ["id", "title", "points", "stages", "scenes"];
    let (id, title, points) = file::head(line, key, file, &known)?;
    let fail = |name: &str, what: &str| format!("{file}: {key}.{name}: expected {what}");
    let names = |name: &str| -> Result<Vec<String>, String> {
        let array = line
            .get(name)
            .and_then(|v| v.as_array())
            .filter(|a| !a.is_empty());
        let array = array.ok_or_else(|| fail(name, "a list of names"))?;
        (array.iter())
            .map(|v| {
                v.as_str()
                    .map(String::from)
                    .ok_or_else(|| fail(name, "a list of names"))
            })
            .collect()
    };
    let stages = stages(&names("stages")?, &|what| fail("stages", what))?;
    Ok(RubricLine {
        id,
        title,
        points,
        stages,
        scenes: names("scenes")?,
    })
}

/// The stages `names` name; `fail` words an error about them.
fn stages(names: &[String], fail: &dyn Fn(&str) -> String) -> Result<Vec<RasterStage>, String> {
    let all: Vec<&str> = RasterStage::ALL.iter().map(|s| s.name()).collect();
    let stage = |name: &String| {
        let what = format!("stages among {}, found '{name}'", all.join(", "));
        RasterStage::from_name(name).ok_or_else(|| fail(&what))
    };
    names.iter().map(stage).collect()
}

/// Whether a scene passes `line`, and why not: check names a mistake of the line's stages, or
/// names nothing and the facts those stages decide differ.
pub fn judge(line: &RubricLine, report: &RasterReport) -> Result<(), String> {
    let named: Vec<RasterMistake> = (report.mistakes().iter())
        .filter_map(|&name| RasterMistake::from_name(name))
        .filter(|m| line.stages.contains(&m.stage()))
        .collect();
    if !named.is_empty() {
        let names: Vec<&str> = named.iter().map(|m| m.name()).collect();
        return Err(format!("check names {}", names.join(", ")));
    }
    if report.agrees() || !report.mistakes().is_empty() {
        return Ok(());
    }
    let facts = &report.diagnosis.legal.facts;
    let has = |stage| line.stages.contains(&stage);
    let colour_stages =
        has(RasterStage::Interpolation) || has(RasterStage::Shading) || has(RasterStage::Texturing);
    let corners = report.corners.as_ref().is_some_and(|c| c.differing > 0);
    let differing = [
        (
            has(RasterStage::Coverage) || has(RasterStage::Output),
            facts.coverage.differing,
            "coverage",
        ),
        (
            has(RasterStage::Depth) || has(RasterStage::Output),
            facts.depth.differing,
            "depth",
        ),
        (
            colour_stages || has(RasterStage::Output),
            facts.colour.differing,
            "colour",
        ),
    ];
    let why: Vec<String> = (differing.iter())
        .filter(|(judged, count, _)| *judged && *count > 0)
        .map(|(_, count, what)| format!("{what} differs at {count} pixels"))
        .chain((colour_stages && corners).then(|| "Gouraud's lit corners differ".to_string()))
        .collect();
    match why.is_empty() {
        true => Ok(()),
        false => Err(format!(
            "{} (no catalogue mistake explains it)",
            why.join(", ")
        )),
    }
}

/// The points for `passed` of `scenes`: shared out evenly, rounded down.
pub fn points(line: &RubricLine, passed: usize, scenes: usize) -> u32 {
    match scenes {
        0 => 0,
        _ => (u64::from(line.points) * passed as u64 / scenes as u64) as u32,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const BUNDLED: &str = include_str!("../../../../assets/rubrics/rasterizer/rubric.toml");

    #[test]
    fn the_bundled_rubric_reads_and_adds_up_to_200() {
        let rubric = Rubric::parse(BUNDLED, "rubric.toml").expect("the bundled rubric");
        assert_eq!(rubric.total(), 200);
        let synchronized = rubric.lines.last().expect("lines");
        assert_eq!(synchronized.scenes, rubric.scenes);
        assert_eq!(points(&rubric.lines[1], 2, 3), 20);
    }

    #[test]
    fn a_wrong_key_or_value_is_an_error_naming_it() {
        let wrong = |text: &str| Rubric::parse(text, "r.toml").unwrap_err();
        assert_eq!(
            wrong("assignment = \"geometry\""),
            "r.toml: assignment: expected \"rasterizer\""
        );
        let line =
            "assignment = \"rasterizer\"\n[[line]]\nid = \"a\"\ntitle = \"A\"\nscenes = [\"s\"]\n";
        assert!(
            wrong(&format!("{line}points = -1\nstages = [\"depth\"]")).contains("line[1].points")
        );
        assert!(wrong(&format!("{line}points = 1\nstages = [\"dpth\"]")).contains("found 'dpth'"));
        assert!(
            wrong(&format!(
                "{line}points = 1\nstages = [\"depth\"]\nweight = 2"
            ))
            .contains("line[1].weight")
        );
        assert!(wrong("assignment = [").starts_with("r.toml:1:"));
    }
}

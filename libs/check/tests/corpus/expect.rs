//! The expectations a corpus program states in its header comment, before it is ever checked:
//! one line per run, `expect SCENE [FLAG ...]: OUTCOME`, where OUTCOME is `agree` or
//! `differs stage=S[,S...] [names=ID[,ID...]] [fits=DECLARATION[,...]] [unexplained]` (see
//! examples/corpus/README.md).

use std::path::Path;

use close2gl_check::{Report, Status};

/// One run of a program: on `scene`, built (C, C++) or started (Python) with `flags`.
#[derive(Clone, Debug)]
pub struct Expectation {
    pub scene: String,
    pub flags: Vec<String>,
    pub outcome: Outcome,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    Agree,
    /// `stages`: the first differing stage, then others that must differ too; `names`: exactly
    /// the catalogue ids named; `fits`: exactly the other declarations named, words joined by
    /// `_` (`clipping_simple_near_far`); `unexplained`: whether something is left unexplained.
    Differs {
        stages: Vec<String>,
        names: Vec<String>,
        fits: Vec<String>,
        unexplained: bool,
    },
}

/// The `expect` lines of the program at `path`, in order; an error names the file and line.
pub fn read(path: &Path) -> Result<Vec<Expectation>, String> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    let mut found = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let line = line.trim_start_matches([' ', '/', '*', '#']);
        if let Some(rest) = line.strip_prefix("expect ") {
            let expectation = parse(rest).ok_or_else(|| {
                format!(
                    "{}:{}: expected 'expect SCENE [FLAG ...]: agree|differs ...', found '{line}'",
                    path.display(),
                    number + 1
                )
            })?;
            found.push(expectation);
        }
    }
    Ok(found)
}

fn parse(rest: &str) -> Option<Expectation> {
    let (run, outcome) = rest.split_once(':')?;
    let mut run = run.split_whitespace().map(String::from);
    let scene = run.next()?;
    let flags = run.collect();
    let mut words = outcome.split_whitespace();
    let outcome = match words.next()? {
        "agree" => Outcome::Agree,
        "differs" => {
            let (mut stages, mut names, mut fits) = (Vec::new(), Vec::new(), Vec::new());
            let mut unexplained = false;
            for word in words.by_ref() {
                if let Some(list) = word.strip_prefix("stage=") {
                    stages = list.split(',').map(String::from).collect();
                } else if let Some(list) = word.strip_prefix("names=") {
                    names = list.split(',').map(String::from).collect();
                } else if let Some(list) = word.strip_prefix("fits=") {
                    fits = list.split(',').map(String::from).collect();
                } else if word == "unexplained" {
                    unexplained = true;
                } else {
                    return None;
                }
            }
            if stages.is_empty() || (names.is_empty() && !unexplained) {
                return None;
            }
            names.sort();
            Outcome::Differs {
                stages,
                names,
                fits,
                unexplained,
            }
        }
        _ => return None,
    };
    words.next().is_none().then_some(Expectation {
        scene,
        flags,
        outcome,
    })
}

/// What check said, in the expectation's terms.
pub fn observed(report: &Report) -> Outcome {
    if report.agrees() {
        return Outcome::Agree;
    }
    let stages = report
        .comparison
        .stages
        .iter()
        .filter(|s| s.status == Status::Differs)
        .map(|s| s.stage.name().to_string())
        .collect();
    let mut names: Vec<String> = report.mistakes().iter().map(|m| m.to_string()).collect();
    names.sort();
    let fits = (report.redeclared.iter())
        .map(|r| r.declaration.replace(' ', "_"))
        .collect();
    Outcome::Differs {
        stages,
        names,
        fits,
        unexplained: report.unexplained.is_some(),
    }
}

/// Whether `observed` holds `expected`: the same verdict; for a difference, the same first
/// stage, every stage listed among those that differ, exactly the names and the declarations
/// that fit, and "unexplained" exactly when expected.
pub fn holds(expected: &Outcome, observed: &Outcome) -> bool {
    match (expected, observed) {
        (Outcome::Agree, Outcome::Agree) => true,
        (
            Outcome::Differs {
                stages,
                names,
                fits,
                unexplained,
            },
            Outcome::Differs {
                stages: seen,
                names: named,
                fits: fitting,
                unexplained: left,
            },
        ) => {
            seen.first() == stages.first()
                && stages.iter().all(|s| seen.contains(s))
                && names == named
                && fits == fitting
                && unexplained == left
        }
        _ => false,
    }
}

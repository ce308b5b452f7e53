//! One program's grade delivered as the arguments ask, whichever assignment made it: the files
//! for the teachers' platforms and the page (`--gradescope`, `--classroom`, `--html`), then on
//! stdout `--line`'s summary, the student's table (`--classroom`: a log the student reads),
//! the JSON or the table.

use std::time::Duration;

use serde_json::Value;

use super::sandboxing::Sandboxing;
use super::sheet::Sheet;
use super::{CliError, GradeArgs, html, platforms};

/// Delivers `sheet`, graded in `took`; `json` and `table` are the assignment's own, made only
/// when asked for. With `--line`, exit status 1 when the line lost points.
pub(super) fn one(
    args: &GradeArgs,
    sandboxing: &Sandboxing,
    sheet: &Sheet,
    took: Duration,
    json: impl FnOnce() -> Value,
    table: impl FnOnce() -> String,
) -> Result<(), CliError> {
    let only = args.line.as_deref();
    if let Some(dir) = &args.gradescope {
        let results = platforms::gradescope(sheet, only, args.details, took);
        platforms::write_gradescope(dir, &results)?;
    }
    if args.classroom {
        platforms::write_classroom(&platforms::classroom(sheet, only))?;
    }
    if let Some(path) = &args.html {
        let page = html::page(sheet, "close2gl grade", &args.run, sandboxing);
        std::fs::write(path, page)
            .map_err(|e| CliError::Runtime(format!("{}: cannot write: {e}", path.display())))?;
    }
    // What the student's log shows (a CI step) holds no scene's numbers.
    match (only, args.classroom, args.json) {
        (Some(id), _, _) => return line_only(sheet, id),
        (None, true, _) => print!("{}", platforms::student_table(sheet, None)),
        (None, false, true) => println!("{}", json()),
        (None, false, false) => print!("{}", table()),
    }
    Ok(())
}

/// `--line`: its one line of summary; exit 1 when it lost points.
fn line_only(sheet: &Sheet, id: &str) -> Result<(), CliError> {
    let Some(line) = sheet.lines.iter().find(|l| l.id == id) else {
        return Ok(());
    };
    println!("{}", platforms::summary(line));
    match line.full() {
        true => Ok(()),
        false => Err(CliError::Verdict),
    }
}

/// `--line ID` naming no line of the rubric, whose lines are `ids`.
pub(super) fn unknown_line<'a>(id: &str, ids: impl IntoIterator<Item = &'a str>) -> CliError {
    let ids: Vec<&str> = ids.into_iter().collect();
    CliError::Input(format!("--line {id}: expected one of {}", ids.join(", ")))
}

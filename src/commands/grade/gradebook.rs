//! The class's grades as the CSV a gradebook imports: `plain` (ours: the folder, each rubric
//! line's points, the total), `moodle` (an identifier column to map to a user field, a column
//! per line and the total, each named for what it is) or `canvas` (Canvas's own first columns,
//! its "Points Possible" row, and one assignment column with the total). The student is the
//! submission's folder name, or who `--students FILE` says it is (`folder,identifier[,name]`
//! a row).

use std::collections::HashMap;
use std::fmt::Write;
use std::path::{Path, PathBuf};

use super::CliError;
use super::sheet::Sheet;

/// The gradebook a CSV is for.
#[derive(clap::ValueEnum, Clone, Copy, Debug, PartialEq, Eq)]
pub enum CsvFormat {
    Plain,
    Moodle,
    Canvas,
}

/// Who a submission is in the gradebook: its identifier there and, when known, a name.
pub struct Student {
    pub identifier: String,
    pub name: String,
}

/// The students of `--students FILE`, by folder: one `folder,identifier[,name]` row each; a
/// blank line or one starting with `#` is skipped.
pub fn read_students(path: &Path) -> Result<HashMap<String, Student>, CliError> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::Input(format!("{}: cannot read: {e}", path.display())))?;
    let mut students = HashMap::new();
    for (i, row) in text.lines().enumerate() {
        let row = row.trim();
        if row.is_empty() || row.starts_with('#') {
            continue;
        }
        let fields: Vec<&str> = row.split(',').map(str::trim).collect();
        let (Some(folder), Some(identifier)) = (fields.first(), fields.get(1)) else {
            return Err(CliError::Input(format!(
                "{}:{}: expected 'folder,identifier[,name]', found '{row}'",
                path.display(),
                i + 1
            )));
        };
        if folder.is_empty() || identifier.is_empty() {
            return Err(CliError::Input(format!(
                "{}:{}: expected a folder and an identifier, found '{row}'",
                path.display(),
                i + 1
            )));
        }
        let name = fields.get(2).unwrap_or(&"").to_string();
        let student = Student {
            identifier: identifier.to_string(),
            name,
        };
        students.insert(folder.to_string(), student);
    }
    Ok(students)
}

/// The CSV for the class: `submissions` (folder name and path) with their grades, in the
/// format asked; `students` maps folders to gradebook identifiers (a folder it lacks is its
/// own identifier); `assignment` names Canvas's column. The columns are the rubric's lines
/// as the grades hold them (every grade of a class is on the same rubric).
pub fn csv(
    format: CsvFormat,
    submissions: &[(String, PathBuf)],
    grades: &[Sheet],
    students: &HashMap<String, Student>,
    assignment: &str,
) -> String {
    let who = |folder: &str| {
        students
            .get(folder)
            .map_or((folder.to_string(), String::new()), |s| {
                (s.identifier.clone(), s.name.clone())
            })
    };
    let class = submissions.iter().map(|(folder, _)| folder).zip(grades);
    let rubric = grades.first();
    match format {
        CsvFormat::Plain => by_line(false, class, &who, rubric),
        CsvFormat::Moodle => by_line(true, class, &who, rubric),
        CsvFormat::Canvas => canvas(class, &who, assignment, rubric.map_or(0, |g| g.max)),
    }
}

/// Who a folder is in the gradebook: its identifier and name.
type Who<'a> = dyn Fn(&str) -> (String, String) + 'a;

/// Ours (`moodle` false: a row per folder, a column per line and the total) or Moodle's (the
/// identifier and full name first, each column titled for its import).
fn by_line<'a>(
    moodle: bool,
    class: impl Iterator<Item = (&'a String, &'a Sheet)>,
    who: &Who,
    rubric: Option<&Sheet>,
) -> String {
    let mut out = String::new();
    let mut header: Vec<String> = match moodle {
        true => vec!["Identifier".into(), "Full name".into()],
        false => vec!["submission".into()],
    };
    for line in rubric.iter().flat_map(|g| &g.lines) {
        header.push(match moodle {
            true => format!("{} (close2gl)", line.title),
            false => line.id.clone(),
        });
    }
    header.push(if moodle {
        "Total (close2gl)".into()
    } else {
        "total".into()
    });
    row(&mut out, &header);
    for (folder, grade) in class {
        let (identifier, name) = who(folder);
        let mut fields = match moodle {
            true => vec![identifier, name],
            false => vec![folder.clone()],
        };
        fields.extend(grade.lines.iter().map(|l| l.points.to_string()));
        fields.push(grade.total.to_string());
        row(&mut out, &fields);
    }
    out
}

/// Canvas's gradebook import: its five leading columns, the points possible, the total under
/// the assignment's column.
fn canvas<'a>(
    class: impl Iterator<Item = (&'a String, &'a Sheet)>,
    who: &Who,
    assignment: &str,
    possible_points: u32,
) -> String {
    let mut out = String::new();
    let first = ["Student", "ID", "SIS User ID", "SIS Login ID", "Section"];
    let mut header: Vec<String> = first.iter().map(|s| s.to_string()).collect();
    header.push(assignment.to_string());
    row(&mut out, &header);
    let mut possible = vec!["    Points Possible".to_string()];
    possible.extend(std::iter::repeat_n(String::new(), 4));
    possible.push(possible_points.to_string());
    row(&mut out, &possible);
    for (folder, grade) in class {
        let (identifier, name) = who(folder);
        let name = if name.is_empty() {
            folder.clone()
        } else {
            name
        };
        let fields = [
            name,
            String::new(),
            String::new(),
            identifier,
            String::new(),
            grade.total.to_string(),
        ];
        row(&mut out, &fields);
    }
    out
}

fn row(out: &mut String, fields: &[String]) {
    let quoted: Vec<String> = fields.iter().map(|f| field(f)).collect();
    let _ = writeln!(out, "{}", quoted.join(","));
}

/// A CSV field, quoted when it holds a comma, a quote or a line break (RFC 4180).
fn field(text: &str) -> String {
    match text.contains([',', '"', '\n', '\r']) {
        true => format!("\"{}\"", text.replace('"', "\"\"")),
        false => text.to_string(),
    }
}

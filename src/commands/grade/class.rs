//! `--submissions DIR`: every folder in DIR graded (`{dir}` in the command is that folder; for
//! the first assignment all their scenes sharing the jobs, for the rasterizer's `raster.rs`
//! grades each in turn), then `DIR/grades.csv` (one row per submission in name order,
//! in the gradebook format `--csv-format` asks: `gradebook`) and `DIR/NAME.html` for each.
//! Nothing in the CSV depends on timing or order of work: the same submissions give the same
//! file.

use std::collections::HashMap;
use std::path::{Path, PathBuf};

use super::graded::Grade;
use super::sandboxing::Sandboxing;
use super::sheet::Sheet;
use super::{CliError, GradeArgs, Plan, gradebook, html, run_tasks};

/// A class to grade, either assignment's: its submissions (folder name and path, by name) and
/// who each is in the gradebook.
pub(super) struct Class {
    pub submissions: Vec<(String, PathBuf)>,
    students: HashMap<String, gradebook::Student>,
}

/// The class in `dir`, once the arguments are known to suit a class.
pub(super) fn open(dir: &Path, args: &GradeArgs) -> Result<Class, CliError> {
    if args.html.is_some()
        || args.json
        || args.line.is_some()
        || args.gradescope.is_some()
        || args.classroom
    {
        return Err(CliError::Input(
            "--submissions writes grades.csv and one HTML page per submission: \
             --html, --json, --line, --gradescope and --classroom are for one program"
                .into(),
        ));
    }
    let submissions = folders(dir)?;
    if submissions.is_empty() {
        return Err(CliError::Input(format!(
            "{}: expected a folder per submission, found none",
            dir.display()
        )));
    }
    let students = students(args, &submissions)?;
    Ok(Class {
        submissions,
        students,
    })
}

/// The first assignment's class: every submission's scenes sharing the jobs.
pub(super) fn grade_class(dir: &Path, args: &GradeArgs, plan: &Plan) -> Result<(), CliError> {
    let class = open(dir, args)?;
    let dirs: Vec<Option<PathBuf>> = (class.submissions.iter())
        .map(|(_, p)| Some(p.clone()))
        .collect();
    let label = format!(
        "grading {} submissions ({} scenes each)",
        class.submissions.len(),
        plan.rubric.scenes.len()
    );
    // Said once the input is known to be good, before the first program runs.
    eprintln!("{}", plan.sandboxing.banner(plan.words, true));
    let results = run_tasks(plan, &dirs, label)?;
    let points = &plan.rubric.points;
    let sheets: Vec<Sheet> = (results.into_iter())
        .map(|r| Grade::new(r, points).sheet())
        .collect();
    write(dir, args, &plan.sandboxing, &class, &sheets)
}

/// Writes the class's grades (`sheets`, one per submission in order): DIR/NAME.html each, and
/// DIR/grades.csv as `--csv-format` asks; then says each total.
pub(super) fn write(
    dir: &Path,
    args: &GradeArgs,
    sandboxing: &Sandboxing,
    class: &Class,
    sheets: &[Sheet],
) -> Result<(), CliError> {
    let write = |path: PathBuf, text: String| {
        std::fs::write(&path, text)
            .map_err(|e| CliError::Runtime(format!("{}: cannot write: {e}", path.display())))
    };
    for ((name, _), sheet) in class.submissions.iter().zip(sheets) {
        write(
            dir.join(format!("{name}.html")),
            html::page(sheet, name, &args.run, sandboxing),
        )?;
    }
    let csv = gradebook::csv(
        args.csv_format,
        &class.submissions,
        sheets,
        &class.students,
        &args.assignment,
    );
    write(dir.join("grades.csv"), csv)?;
    println!("{}", sandboxing.summary());
    for ((name, _), sheet) in class.submissions.iter().zip(sheets) {
        println!("{name}: {}/{}", sheet.total, sheet.max);
    }
    println!("wrote {}", dir.join("grades.csv").display());
    Ok(())
}

/// Who each folder is in the gradebook (`--students`), with a warning for each folder it lacks.
fn students(
    args: &GradeArgs,
    submissions: &[(String, PathBuf)],
) -> Result<HashMap<String, gradebook::Student>, CliError> {
    let Some(path) = &args.students else {
        return Ok(Default::default());
    };
    let students = gradebook::read_students(path)?;
    for (folder, _) in submissions {
        if !students.contains_key(folder) {
            eprintln!("warning: {folder} is not in --students: its folder's name stands for it");
        }
    }
    Ok(students)
}

/// The folders in `dir` by name (absolute paths), hidden ones left out.
fn folders(dir: &Path) -> Result<Vec<(String, PathBuf)>, CliError> {
    let fail = |e: std::io::Error| CliError::Input(format!("{}: cannot read: {e}", dir.display()));
    let dir = std::path::absolute(dir).map_err(fail)?;
    let mut folders: Vec<(String, PathBuf)> = std::fs::read_dir(&dir)
        .map_err(fail)?
        .flatten()
        .filter(|entry| entry.path().is_dir())
        .map(|entry| {
            (
                entry.file_name().to_string_lossy().into_owned(),
                entry.path(),
            )
        })
        .filter(|(name, _)| !name.starts_with('.'))
        .collect();
    folders.sort();
    Ok(folders)
}

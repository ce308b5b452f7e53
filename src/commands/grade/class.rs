//! `--submissions DIR`: every folder in DIR graded (`{dir}` in the command is that folder), all
//! their scenes sharing the jobs, then `DIR/grades.csv` (one row per submission in name order,
//! in the gradebook format `--csv-format` asks: `gradebook`) and `DIR/NAME.html` for each.
//! Nothing in the CSV depends on timing or order of work: the same submissions give the same
//! file.

use std::path::{Path, PathBuf};

use super::graded::Grade;
use super::{CliError, GradeArgs, Plan, gradebook, html, run_tasks};

pub(super) fn grade_class(dir: &Path, args: &GradeArgs, plan: &Plan) -> Result<(), CliError> {
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
    let dirs: Vec<Option<PathBuf>> = submissions.iter().map(|(_, p)| Some(p.clone())).collect();
    let label = format!(
        "grading {} submissions ({} scenes each)",
        submissions.len(),
        plan.rubric.scenes.len()
    );
    // Said once the input is known to be good, before the first program runs.
    eprintln!("{}", plan.sandboxing.banner(plan.words, true));
    let results = run_tasks(plan, &dirs, label)?;
    let points = &plan.rubric.points;
    let grades: Vec<Grade> = (results.into_iter())
        .map(|r| Grade::new(r, points))
        .collect();
    let write = |path: PathBuf, text: String| {
        std::fs::write(&path, text)
            .map_err(|e| CliError::Runtime(format!("{}: cannot write: {e}", path.display())))
    };
    for ((name, _), grade) in submissions.iter().zip(&grades) {
        write(
            dir.join(format!("{name}.html")),
            html::page(grade, name, &args.run, &plan.sandboxing),
        )?;
    }
    let csv = gradebook::csv(
        args.csv_format,
        &submissions,
        &grades,
        &students,
        &args.assignment,
        points,
    );
    write(dir.join("grades.csv"), csv)?;
    println!("{}", plan.sandboxing.summary());
    for ((name, _), grade) in submissions.iter().zip(&grades) {
        println!("{name}: {}/{}", grade.total, grade.max);
    }
    println!("wrote {}", dir.join("grades.csv").display());
    Ok(())
}

/// Who each folder is in the gradebook (`--students`), with a warning for each folder it lacks.
fn students(
    args: &GradeArgs,
    submissions: &[(String, PathBuf)],
) -> Result<std::collections::HashMap<String, gradebook::Student>, CliError> {
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
pub(super) fn folders(dir: &Path) -> Result<Vec<(String, PathBuf)>, CliError> {
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

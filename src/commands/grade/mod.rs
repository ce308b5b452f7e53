//! `close2gl grade`: runs a student's program on the rubric's scenes (`close2gl_check::rubric`)
//! under the runner's limits, and scores the assignment's 200 points line by line with check's
//! evidence (docs/grading.md). One program (`--run`), or a class (`--submissions DIR`).
//!
//! The files follow a grading: `mod.rs` the arguments, the models and the scenes' workers;
//! `scene_run.rs` one scene through the runner and the judges; `graded.rs` the scenes' results
//! with the rubric's lines scored on them (the scoring is check's `rubric::score`);
//! `report.rs` the terminal table and the JSON; `raster.rs` the rasterizer assignment's
//! grade (`--rubric` with its rubric), with its own table and JSON; `sheet.rs` the one shape
//! both grades take for the teachers' writers (`raster_sheet.rs` fills it for the rasterizer):
//! `html.rs` the page, `platforms.rs` Gradescope and GitHub Classroom, `deliver.rs` one
//! program's outputs, `class.rs` a folder of submissions, with `gradebook.rs` its CSV for a
//! gradebook; `sandboxing.rs` the sandbox each run is in, and what every report says of it.

mod class;
mod deliver;
mod geometry_sheet;
mod gradebook;
mod graded;
mod html;
mod platforms;
mod raster;
mod raster_graded;
mod raster_sheet;
mod report;
mod sandboxing;
mod scene_run;
mod sheet;
mod to_fix;

use std::panic::AssertUnwindSafe;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Duration;

use close2gl_check::rubric::{self, LineId, LinePoints, RubricScene};
use close2gl_core::{Mesh, ModelSource, PrimitiveParams};
use close2gl_runner::Limits;

use super::CliError;
use close2gl_app::progress_bar::TerminalProgress;
use graded::Grade;
use sandboxing::Sandboxing;
use scene_run::{RunFailure, SceneResult};

#[derive(clap::Args, Debug)]
pub struct GradeArgs {
    /// The program's command line, with {scene} and {trace} (and {dir}, the submission's
    /// folder, with --submissions) standing for absolute paths. Split into words as a POSIX
    /// shell would, never run through a shell.
    #[arg(long, value_name = "COMMAND")]
    pub run: String,
    /// Grade on these models instead of the bundled ones (cube.in, far_away.in, knot.obj,
    /// textured_cube.in); repeat for several.
    #[arg(long = "model", value_name = "FILE")]
    pub models: Vec<PathBuf>,
    /// Print the grade as one JSON object.
    #[arg(long)]
    pub json: bool,
    /// Also write the report as one self-contained HTML page.
    #[arg(long, value_name = "FILE")]
    pub html: Option<PathBuf>,
    /// Seconds each scene's run may take before it is killed.
    #[arg(long, value_name = "SECONDS", default_value_t = 10.0)]
    pub time_limit: f64,
    /// Scenes run at once (default: one per core).
    #[arg(long, value_name = "N")]
    pub jobs: Option<usize>,
    /// Grade every folder in DIR, writing DIR/grades.csv and DIR/NAME.html.
    #[arg(long, value_name = "DIR")]
    pub submissions: Option<PathBuf>,
    /// Let every program read DIR too (a course's shared library folder); repeat for several.
    #[arg(long = "allow-read", value_name = "DIR")]
    pub allow_read: Vec<PathBuf>,
    /// Run the programs without a sandbox, as you: for a kernel without Landlock (before Linux
    /// 5.13, WSL1), where grade otherwise refuses. Only for programs you trust.
    #[arg(long)]
    pub unsandboxed: bool,
    /// Grade one rubric line only (its id, as --json names it: culling, hfov, ...): its scenes
    /// alone, one line of summary, exit status 1 when it lost points (a CI step's pass/fail).
    #[arg(long, value_name = "ID")]
    pub line: Option<String>,
    /// Also write Gradescope's results.json into DIR (default /autograder/results).
    #[arg(long, value_name = "DIR", num_args = 0..=1,
          default_missing_value = "/autograder/results")]
    pub gradescope: Option<PathBuf>,
    /// Who sees, on Gradescope, the scenes' exact numbers (why each scene failed, the scene
    /// files): the answer key. A line's points, scenes passed and mistakes are always visible.
    #[arg(long, value_name = "VISIBILITY", default_value = "hidden")]
    pub details: platforms::Visibility,
    /// Also write GitHub Classroom's grading-reporter result (partial credit, a test per line)
    /// to $GITHUB_OUTPUT as `result=`.
    #[arg(long)]
    pub classroom: bool,
    /// With --submissions, the gradebook grades.csv is for: plain (ours), moodle or canvas.
    #[arg(long, value_name = "FORMAT", default_value = "plain")]
    pub csv_format: gradebook::CsvFormat,
    /// With --submissions, who each folder is in the gradebook: a CSV of
    /// `folder,identifier[,name]` rows (otherwise the folder's name).
    #[arg(long, value_name = "FILE")]
    pub students: Option<PathBuf>,
    /// Grade on this rubric file (TOML): assets/rubrics/geometry/rubric.toml is the first
    /// assignment's, the default (edit its points and titles); assets/rubrics/rasterizer/
    /// rubric.toml grades the rasterizer assignment (lines, points, scenes, the stages deciding
    /// each), its program writing a raster trace (close2gl-raster 1) with its buffers.
    #[arg(long, value_name = "FILE")]
    pub rubric: Option<PathBuf>,
    /// With --csv-format canvas, the assignment's column as Canvas exported it
    /// ("Close2GL (12345)").
    #[arg(long, value_name = "NAME", default_value = "close2gl")]
    pub assignment: String,
}

/// A model the rubric's scenes are made on: its file (copied beside each scene, so that a
/// program can neither depend on where it lives nor change it for the next) and its mesh.
pub struct Model {
    /// Names it in scene ids: `cube`.
    pub stem: String,
    pub file_name: String,
    pub bytes: Vec<u8>,
    pub mesh: Mesh,
}

/// The scenes of every model, each with the index of its model, and what each line is worth.
pub struct Rubric {
    pub models: Vec<Model>,
    pub scenes: Vec<(usize, RubricScene)>,
    pub points: LinePoints,
}

/// A scene close2gl failed to judge (it panicked): the scene fails, grading goes on.
const BUG: &str = "close2gl could not judge this scene (a bug in close2gl: please report it \
                   with the scene and the program's trace)";

/// What every grading shares: the command's words, the scenes, the limits, the sandbox, how
/// many at once.
struct Plan<'a> {
    words: &'a [String],
    rubric: &'a Rubric,
    limits: Limits,
    sandboxing: Sandboxing,
    jobs: usize,
}

/// One scene to run: which submission (its folder for `{dir}`, if any), which scene.
struct Task {
    submission: usize,
    scene: usize,
}

/// Exit 0 once graded (the grade is the answer; with --line, 1 when the line lost points), 2
/// for bad input, 130 when interrupted.
pub fn run(args: GradeArgs) -> Result<(), CliError> {
    let mut words = close2gl_runner::split_words(&args.run).map_err(CliError::Input)?;
    // `./pipeline` means the one here, not one in each run's fresh directory.
    if let Some(program) = words.first_mut()
        && program.contains('/')
        && !program.starts_with('/')
        && !program.starts_with('{')
        && let Ok(absolute) = std::path::absolute(&*program)
    {
        *program = absolute.display().to_string();
    }
    if !(args.time_limit > 0.0 && args.time_limit <= 86_400.0) {
        return Err(CliError::Input(format!(
            "--time-limit: expected seconds in (0, 86400], found {}",
            args.time_limit
        )));
    }
    let limits = Limits {
        time: Duration::from_secs_f64(args.time_limit),
        ..Limits::default()
    };
    let jobs = match args.jobs {
        Some(0) => return Err(CliError::Input("--jobs: expected at least 1".into())),
        Some(n) => n,
        None => std::thread::available_parallelism().map_or(1, |n| n.get()),
    };
    let sandboxing = Sandboxing::new(args.unsandboxed, &args.allow_read)?;
    let rubric_file = read_rubric_file(&args)?;
    // Before the models: the rasterizer's scenes name their own.
    if let Some((path, text)) = &rubric_file
        && rubric::file::assignment(text).as_deref() == Some("rasterizer")
    {
        return grade_on_rubric_file(path, &args, &words, limits, sandboxing, jobs);
    }
    let mut rubric = load_rubric(&args.models)?;
    if let Some((path, text)) = &rubric_file {
        let file = path.display().to_string();
        rubric.points = LinePoints::parse(text, &file).map_err(CliError::Input)?;
    }
    if let Some(id) = &args.line {
        keep_line(&mut rubric, id)?;
    }
    let plan = Plan {
        words: &words,
        rubric: &rubric,
        limits,
        sandboxing,
        jobs,
    };
    close2gl_runner::install_interrupt_handler();
    let result = match &args.submissions {
        Some(dir) => class::grade_class(dir, &args, &plan),
        None => grade_one(&args, &plan),
    };
    close2gl_runner::reap_everything();
    result
}

/// `--rubric FILE` read: the file and its text.
fn read_rubric_file(args: &GradeArgs) -> Result<Option<(&PathBuf, String)>, CliError> {
    let Some(path) = &args.rubric else {
        return Ok(None);
    };
    let text = std::fs::read_to_string(path)
        .map_err(|e| CliError::Input(format!("{}: cannot read: {e}", path.display())))?;
    Ok(Some((path, text)))
}

/// `--line ID`: the rubric's scenes for that line alone.
fn keep_line(rubric: &mut Rubric, id: &str) -> Result<(), CliError> {
    let line = (LineId::ALL.iter())
        .find(|l| l.id() == id)
        .ok_or_else(|| deliver::unknown_line(id, LineId::ALL.iter().map(|l| l.id())))?;
    rubric
        .scenes
        .retain(|(_, scene)| scene.lines.contains(line));
    Ok(())
}

/// `--rubric FILE`: the rasterizer assignment's grade, one program or a class, with every
/// output the first assignment's has; only `--model` means nothing to it (its scenes name
/// their models).
fn grade_on_rubric_file(
    path: &Path,
    args: &GradeArgs,
    words: &[String],
    limits: Limits,
    sandboxing: Sandboxing,
    jobs: usize,
) -> Result<(), CliError> {
    if !args.models.is_empty() {
        return Err(CliError::Input(
            "--model: the rasterizer's rubric grades on the scenes beside it, which name their own models".into(),
        ));
    }
    let rubric = Rubric {
        models: Vec::new(),
        scenes: Vec::new(),
        points: LinePoints::default(),
    };
    let plan = Plan {
        words,
        rubric: &rubric,
        limits,
        sandboxing,
        jobs,
    };
    close2gl_runner::install_interrupt_handler();
    let result = match &args.submissions {
        Some(dir) => raster::grade_class(path, dir, args, &plan),
        None => raster::grade(path, args, &plan),
    };
    close2gl_runner::reap_everything();
    result
}

fn grade_one(args: &GradeArgs, plan: &Plan) -> Result<(), CliError> {
    let label = format!("grading {} scenes", plan.rubric.scenes.len());
    eprintln!("{}", plan.sandboxing.banner(plan.words, false));
    let started = std::time::Instant::now();
    let mut results = run_tasks(plan, &[None], label)?;
    let grade = Grade::new(results.remove(0), &plan.rubric.points);
    deliver::one(
        args,
        &plan.sandboxing,
        &grade.sheet(),
        started.elapsed(),
        || report::json(&grade, &plan.sandboxing),
        || report::table(&grade, &args.run, &plan.sandboxing),
    )
}

/// Runs every scene for every submission (`dirs`: each one's folder for `{dir}`, `None` for a
/// single program), the plan's jobs at a time, with a progress line; the results per submission, in
/// the rubric's order. Interrupted: the error that exits 130.
fn run_tasks(
    plan: &Plan,
    dirs: &[Option<PathBuf>],
    label: String,
) -> Result<Vec<Vec<SceneResult>>, CliError> {
    let rubric = plan.rubric;
    let tasks: Vec<Task> = (0..dirs.len())
        .flat_map(|submission| {
            (0..rubric.scenes.len()).map(move |scene| Task { submission, scene })
        })
        .collect();
    let slots: Vec<Mutex<Option<SceneResult>>> = tasks.iter().map(|_| Mutex::new(None)).collect();
    let next = AtomicUsize::new(0);
    let done = AtomicUsize::new(0);
    let progress = Mutex::new(TerminalProgress::labelled(label));
    std::thread::scope(|scope| {
        for _ in 0..plan.jobs.min(tasks.len()) {
            scope.spawn(|| {
                while let Some(task) = tasks.get(next.fetch_add(1, Ordering::Relaxed)) {
                    let (model, scene) = &rubric.scenes[task.scene];
                    let dir = dirs[task.submission].as_deref();
                    let model = &rubric.models[*model];
                    let sandbox = plan.sandboxing.for_run(dir);
                    // A bug of ours on one program's trace must not stop a class's grading.
                    let result = std::panic::catch_unwind(AssertUnwindSafe(|| {
                        let run = scene_run::Run::new(plan.words, dir, &plan.limits, &sandbox);
                        scene_run::run_scene(&run, model, scene)
                    }))
                    .unwrap_or_else(|_| SceneResult::failed(scene, RunFailure::plain(BUG.into())));
                    let i = task.submission * rubric.scenes.len() + task.scene;
                    *lock(&slots[i]) = Some(result);
                    let finished = done.fetch_add(1, Ordering::Relaxed) + 1;
                    lock(&progress).show(finished as f32 / tasks.len() as f32);
                }
            });
        }
    });
    let progress = progress.into_inner().unwrap_or_else(|e| e.into_inner());
    let interrupted = close2gl_runner::interrupted();
    progress.finish(!interrupted);
    if interrupted {
        return Err(CliError::Interrupted);
    }
    let mut results: Vec<SceneResult> = slots
        .into_iter()
        .filter_map(|slot| slot.into_inner().unwrap_or_else(|e| e.into_inner()))
        .collect();
    let mut per_submission = Vec::new();
    for _ in dirs {
        let rest = results.split_off(rubric.scenes.len().min(results.len()));
        per_submission.push(std::mem::replace(&mut results, rest));
    }
    Ok(per_submission)
}

fn lock<T>(mutex: &Mutex<T>) -> std::sync::MutexGuard<'_, T> {
    // A worker that panicked left a finished value or none: keep going with the others.
    mutex.lock().unwrap_or_else(|e| e.into_inner())
}

/// The bundled models, or those given; each loaded once, and its scenes made.
fn load_rubric(given: &[PathBuf]) -> Result<Rubric, CliError> {
    let bundled: Vec<PathBuf> = ["cube.in", "far_away.in", "knot.obj", "textured_cube.in"]
        .iter()
        .map(|name| {
            Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("assets")
                .join(name)
        })
        .collect();
    let paths = if given.is_empty() { &bundled } else { given };
    let mut models: Vec<Model> = Vec::new();
    for path in paths {
        let model = load_model(path)?;
        let taken = |stem: &str| models.iter().any(|m| m.stem == stem);
        let mut stem = model.stem.clone();
        let mut k = 2;
        while taken(&stem) {
            stem = format!("{}-{k}", model.stem);
            k += 1;
        }
        models.push(Model { stem, ..model });
    }
    let scenes = models
        .iter()
        .enumerate()
        .flat_map(|(i, m)| {
            rubric::scenes(&m.stem, &m.file_name, &m.mesh)
                .into_iter()
                .map(move |s| (i, s))
        })
        .collect();
    Ok(Rubric {
        models,
        scenes,
        points: LinePoints::default(),
    })
}

fn load_model(path: &Path) -> Result<Model, CliError> {
    let source = ModelSource::File(path.to_path_buf());
    let loaded =
        close2gl_model::load(&source, &PrimitiveParams::default()).map_err(CliError::Input)?;
    let bytes = std::fs::read(path)
        .map_err(|e| CliError::Input(format!("{}: cannot read: {e}", path.display())))?;
    let name = |p: Option<&std::ffi::OsStr>| p.map(|s| s.to_string_lossy().into_owned());
    let file_name = name(path.file_name()).unwrap_or_else(|| "model.in".into());
    // A name a scene's `model` line can hold: one field, no comment.
    let file_name: String = file_name
        .chars()
        .map(|c| {
            if c.is_whitespace() || c == '#' {
                '_'
            } else {
                c
            }
        })
        .collect();
    let stem = name(path.file_stem()).unwrap_or_else(|| "model".into());
    Ok(Model {
        stem,
        file_name,
        bytes,
        mesh: loaded.mesh,
    })
}

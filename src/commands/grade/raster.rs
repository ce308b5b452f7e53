//! `close2gl grade --rubric FILE`: the rasterizer assignment, on a rubric a teacher edits
//! (`assets/rubrics/rasterizer/rubric.toml`): each of its scenes run in the sandbox, the raster trace
//! and its buffers read as the program's own, checked, and every line the scene counts for
//! judged on the stages that decide it.

use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use close2gl_check::raster::check_raster;
use close2gl_check::raster::report::legal_choices;
use close2gl_check::raster::rubric::Rubric;
use close2gl_trace_format::{RasterFrame, parse_raster_trace, parse_scene};
use serde_json::json;

use super::raster_graded::{RubricScene, SceneOutcome, Scored, score, to_fix};
use super::scene_run::{Run, RunFailure, read_written, run_in_workspace};
use super::{CliError, GradeArgs, Plan, class, deliver, lock, raster_sheet};

/// The rubric at `path` and its scenes (`scenes/NAME.scene` beside it, with the files they name).
fn load(path: &Path) -> Result<(Rubric, Vec<RubricScene>), CliError> {
    let input = |e: String| CliError::Input(e);
    let text = std::fs::read_to_string(path)
        .map_err(|e| input(format!("{}: cannot read: {e}", path.display())))?;
    let rubric = Rubric::parse(&text, &path.display().to_string()).map_err(input)?;
    let folder = path.parent().unwrap_or(Path::new("")).join("scenes");
    let mut scenes = Vec::new();
    for name in &rubric.scenes {
        let file = folder.join(format!("{name}.scene"));
        let text = std::fs::read_to_string(&file).map_err(|e| {
            input(format!(
                "{}: cannot read: {e} (a scene the rubric names)",
                file.display()
            ))
        })?;
        let mut scene =
            parse_scene(&text, &file.display().to_string()).map_err(|e| input(e.to_string()))?;
        let mut files = Vec::new();
        let mut bring = |written: &str, slot: &str| -> Result<String, CliError> {
            let source: PathBuf = file.parent().unwrap_or(Path::new("")).join(written);
            let bytes = std::fs::read(&source).map_err(|e| {
                input(format!(
                    "{}: {slot} {}: cannot read: {e}",
                    file.display(),
                    source.display()
                ))
            })?;
            let base = source.file_name().map_or("file".into(), |n| {
                n.to_string_lossy().replace([' ', '#'], "_")
            });
            files.push((base.clone(), bytes));
            Ok(base)
        };
        scene.model = bring(&scene.model, "model")?;
        if let Some(texture) = scene.look.texture.take() {
            scene.look.texture = Some(bring(&texture, "texture")?);
        }
        scenes.push(RubricScene {
            name: name.clone(),
            text: scene.to_text(),
            files,
        });
    }
    Ok((rubric, scenes))
}

/// One scene run and checked.
fn run_scene(run: &Run, scene: &RubricScene) -> SceneOutcome {
    let files: Vec<(&str, &[u8])> = scene
        .files
        .iter()
        .map(|(n, b)| (n.as_str(), b.as_slice()))
        .collect();
    let (workspace, ran) = run_in_workspace(run, &files, &scene.text)?;
    let bytes = read_written(
        &workspace,
        "trace.txt",
        run.limits,
        "its raster trace",
        &ran,
    )?;
    let unreadable = |e: String| RunFailure {
        cause: "it wrote a raster trace close2gl cannot read".into(),
        reason: e,
    };
    let text = String::from_utf8(bytes)
        .map_err(|_| unreadable("its raster trace is not UTF-8 text".into()))?;
    let trace =
        parse_raster_trace(&text, "its raster trace").map_err(|e| unreadable(e.to_string()))?;
    let frame = RasterFrame::read_with(trace, |name| {
        if name.contains('/') || name == ".." {
            return Err("a file name beside the trace was expected, not a path".into());
        }
        read_written(&workspace, name, run.limits, name, &ran).map_err(|f| f.reason)
    })
    .map_err(|e| unreadable(e.to_string()))?;
    Ok(check_raster(&frame))
}

/// Every scene of `scenes` run for the program (in `dir`, `{dir}`, for a class's submission)
/// and checked, the plan's jobs at a time.
fn run_all(
    scenes: &[RubricScene],
    dir: Option<&Path>,
    plan: &Plan,
) -> Result<Vec<(String, SceneOutcome)>, CliError> {
    let slots: Vec<Mutex<Option<SceneOutcome>>> = scenes.iter().map(|_| Mutex::new(None)).collect();
    let next = AtomicUsize::new(0);
    std::thread::scope(|scope| {
        for _ in 0..plan.jobs.min(scenes.len()) {
            scope.spawn(|| {
                while let Some(i) =
                    Some(next.fetch_add(1, Ordering::Relaxed)).filter(|&i| i < scenes.len())
                {
                    let sandbox = plan.sandboxing.for_run(dir);
                    let run = Run::new(plan.words, dir, &plan.limits, &sandbox);
                    // A bug of ours on one program's trace must not stop a class's grading.
                    let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                        run_scene(&run, &scenes[i])
                    }))
                    .unwrap_or_else(|_| Err(RunFailure::plain(super::BUG.into())));
                    *lock(&slots[i]) = Some(outcome);
                }
            });
        }
    });
    if close2gl_runner::interrupted() {
        return Err(CliError::Interrupted);
    }
    Ok((scenes.iter().zip(slots))
        .filter_map(|(s, slot)| {
            Some((
                s.name.clone(),
                slot.into_inner().unwrap_or_else(|e| e.into_inner())?,
            ))
        })
        .collect())
}

/// Grades one program on the rubric at `path` (with `--line`, on that line alone), delivered
/// as the arguments ask.
pub fn grade(path: &Path, args: &GradeArgs, plan: &Plan) -> Result<(), CliError> {
    let (mut rubric, mut scenes) = load(path)?;
    if let Some(id) = &args.line {
        let Some(line) = rubric.lines.iter().find(|l| &l.id == id).cloned() else {
            return Err(deliver::unknown_line(
                id,
                rubric.lines.iter().map(|l| l.id.as_str()),
            ));
        };
        scenes.retain(|s| line.scenes.contains(&s.name));
        rubric.lines = vec![line];
    }
    eprintln!("{}", plan.sandboxing.banner(plan.words, false));
    let started = std::time::Instant::now();
    let outcomes = run_all(&scenes, None, plan)?;
    let scored = score(&rubric, &outcomes);
    let total: u32 = scored.iter().map(|s| s.points).sum();
    let max = rubric.total();
    let sheet = raster_sheet::sheet(&scored, &outcomes, &scenes, max);
    deliver::one(
        args,
        &plan.sandboxing,
        &sheet,
        started.elapsed(),
        || json(&scored, &outcomes, total, max),
        || table(&scored, &outcomes, total, max, path),
    )
}

/// Grades every folder in `dir` on the rubric at `path`, one submission after another (each
/// one's scenes sharing the jobs), written as the first assignment's class is.
pub fn grade_class(path: &Path, dir: &Path, args: &GradeArgs, plan: &Plan) -> Result<(), CliError> {
    let (rubric, scenes) = load(path)?;
    let class = class::open(dir, args)?;
    eprintln!("{}", plan.sandboxing.banner(plan.words, true));
    let mut sheets = Vec::new();
    for (_, folder) in &class.submissions {
        let outcomes = run_all(&scenes, Some(folder), plan)?;
        let scored = score(&rubric, &outcomes);
        sheets.push(raster_sheet::sheet(
            &scored,
            &outcomes,
            &scenes,
            rubric.total(),
        ));
    }
    class::write(dir, args, &plan.sandboxing, &class, &sheets)
}

fn table(
    scored: &[Scored],
    outcomes: &[(String, SceneOutcome)],
    total: u32,
    max: u32,
    path: &Path,
) -> String {
    let mut out = format!(
        "close2gl grade: the rasterizer assignment ({})\n\n",
        path.display()
    );
    out += &format!("{:<52} {:>7} {:>7}\n", "line", "points", "scenes");
    for s in scored {
        let points = format!("{}/{}", s.points, s.line.points);
        let scenes = format!("{}/{}", s.passed, s.line.scenes.len());
        out += &format!("{:<52} {points:>7} {scenes:>7}\n", s.line.title);
        for (scene, why) in &s.failures {
            out += &format!("    {scene}: {why}\n");
        }
    }
    out += &format!("\ntotal {total}/{max}\n");
    let bugs = to_fix(outcomes);
    if !bugs.is_empty() {
        out += &format!("\n{}\n", bugs.join("\n"));
    }
    let accepted: Vec<String> = (outcomes.iter())
        .filter_map(|(name, o)| o.as_ref().ok().map(|r| (name, legal_choices(r.rules()))))
        .filter(|(_, rules)| !rules.is_empty())
        .map(|(name, rules)| format!("  {name}: {}", rules.join("; ")))
        .collect();
    if !accepted.is_empty() {
        out += "\naccepted, the program's choice where the rules leave one:\n";
        out += &(accepted.join("\n") + "\n");
    }
    out
}

fn json(
    scored: &[Scored],
    outcomes: &[(String, SceneOutcome)],
    total: u32,
    max: u32,
) -> serde_json::Value {
    let lines: Vec<serde_json::Value> = (scored.iter())
        .map(|s| {
            json!({
                "id": s.line.id,
                "title": s.line.title,
                "points": s.points,
                "max": s.line.points,
                "passed": s.passed,
                "scenes": s.line.scenes.len(),
                "failures": s.failures.iter().map(|(scene, why)| json!({"scene": scene, "why": why})).collect::<Vec<_>>(),
            })
        })
        .collect();
    let scenes: Vec<serde_json::Value> = (outcomes.iter())
        .map(|(name, outcome)| match outcome {
            Ok(report) => {
                json!({"scene": name, "agree": report.agrees(), "mistakes": report.mistakes()})
            }
            Err(failure) => json!({"scene": name, "agree": false, "run_failed": failure.reason}),
        })
        .collect();
    json!({"assignment": "rasterizer", "total": total, "max": max, "lines": lines, "scenes": scenes})
}

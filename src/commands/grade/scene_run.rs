//! One scene of one program: a fresh directory holding the scene and its model, the program
//! run there under the limits, its trace read and compared (check), and every line the scene
//! counts for judged. A scene the program failed (a crash, a hang, no trace, garbage) fails
//! every line with the reason; a scene it got wrong keeps check's evidence, named mistakes and
//! pictures for the report.

use std::path::Path;

use close2gl_check::rubric::{self, Judged, LineId, RubricScene, Verdict};
use close2gl_check::{self as check, Report, picture, report};
use close2gl_runner::{Ending, Limits, NotItsOwn, Sandbox, Workspace};
use close2gl_trace_format::{Trace, parse_trace_bytes};

use super::Model;

/// The trace's name in the run's directory (`{trace}`).
const TRACE: &str = "trace.txt";

/// What one scene showed.
pub struct SceneResult {
    pub id: String,
    pub scene_text: String,
    /// Each line the scene counts for, judged.
    pub verdicts: Vec<(LineId, Verdict)>,
    /// Why the run itself failed (then every line failed with it).
    pub run_failure: Option<RunFailure>,
    /// Check's evidence, for a scene whose trace differs from close2gl or failed a line.
    pub evidence: Option<Evidence>,
}

/// Why a run failed before its trace could be judged.
pub struct RunFailure {
    /// The words every run that failed the same way shares ("timed out", "its trace is a link
    /// to /proc/self/environ, not a file it wrote"): one bug in the report, however many
    /// scenes and lines it cost.
    pub cause: String,
    /// The whole reason this scene shows, with its times and the program's last words.
    pub reason: String,
}

impl RunFailure {
    /// A failure whose reason is its cause.
    pub fn plain(why: String) -> Self {
        Self {
            cause: why.clone(),
            reason: why,
        }
    }
}

/// What check found in a trace the report shows.
pub struct Evidence {
    /// Check's first difference, `stage: detail`; none when check agrees.
    pub first_difference: Option<String>,
    /// The catalogue mistakes that reproduce the trace.
    pub mistakes: Vec<&'static str>,
    /// Check's report as text.
    pub text: String,
    /// close2gl's 2D output, the trace's, the difference (PNG); empty when they could not be
    /// encoded.
    pub pictures: Vec<Vec<u8>>,
}

impl SceneResult {
    /// A scene that could not be judged: every line it counts for fails with its reason.
    pub fn failed(scene: &RubricScene, failure: RunFailure) -> Self {
        Self {
            id: scene.id.clone(),
            scene_text: scene.scene.to_text(),
            verdicts: scene
                .lines
                .iter()
                .map(|&line| (line, Verdict::fail(failure.reason.clone())))
                .collect(),
            run_failure: Some(failure),
            evidence: None,
        }
    }

    /// The scene as the rubric scores it: its verdicts and the mistakes check named.
    pub fn judged(&mut self) -> Judged<'_> {
        Judged {
            verdicts: &mut self.verdicts,
            mistakes: self.evidence.as_ref().map_or(&[], |e| &e.mistakes),
        }
    }
}

/// How one submission's program runs: its command's words (with `{scene}`, `{trace}` and
/// `{dir}`), its folder for `{dir}`, the limits and the sandbox.
pub struct Run<'a> {
    words: &'a [String],
    dir: Option<&'a Path>,
    pub limits: &'a Limits,
    sandbox: &'a Sandbox,
}

impl<'a> Run<'a> {
    pub fn new(
        words: &'a [String],
        dir: Option<&'a Path>,
        limits: &'a Limits,
        sandbox: &'a Sandbox,
    ) -> Self {
        Self {
            words,
            dir,
            limits,
            sandbox,
        }
    }
}

/// Runs the program on `scene`.
pub fn run_scene(run: &Run, model: &Model, scene: &RubricScene) -> SceneResult {
    let scene_text = scene.scene.to_text();
    let trace = match run_program(run, model, &scene_text) {
        Ok(trace) => trace,
        Err(failure) => return SceneResult::failed(scene, failure),
    };
    let mut report = match check::compare_only(&model.mesh, &trace) {
        Ok(report) => report,
        Err(e) => {
            let why = format!("its trace does not fit the model: {}", e.message);
            return SceneResult::failed(scene, RunFailure::plain(why));
        }
    };
    let verdicts = rubric::judge(scene, &model.mesh, &trace, &report);
    let evidence = (!report.agrees() || verdicts.iter().any(|(_, v)| !v.passed)).then(|| {
        check::explain(&mut report, &model.mesh, &trace);
        evidence(&report, &trace, &scene.id)
    });
    SceneResult {
        id: scene.id.clone(),
        scene_text,
        verdicts,
        run_failure: None,
        evidence,
    }
}

/// The program run in a fresh directory holding `scene.txt` and the model; its trace, or why
/// there is none. The directory is gone when this returns.
fn run_program(run: &Run, model: &Model, scene_text: &str) -> Result<Trace, RunFailure> {
    let files = [(model.file_name.as_str(), model.bytes.as_slice())];
    let (workspace, ran) = run_in_workspace(run, &files, scene_text)?;
    let bytes = read_written(&workspace, TRACE, run.limits, "its trace", &ran)?;
    parse_trace_bytes(bytes, "its trace").map_err(|e| RunFailure {
        cause: "it wrote a trace close2gl cannot read".into(),
        reason: format!("{e}"),
    })
}

/// The program run in a fresh directory holding `files` (name, bytes) and `scene.txt`, with
/// `{trace}` standing for `trace.txt` there: the directory once the program exited 0, and the
/// run's outcome in words; or why it failed.
pub fn run_in_workspace(
    run: &Run,
    files: &[(&str, &[u8])],
    scene_text: &str,
) -> Result<(Workspace, String), RunFailure> {
    let workspace = Workspace::new()
        .map_err(|e| RunFailure::plain(format!("could not make its directory: {e}")))?;
    let (scene, trace) = (
        workspace.path().join("scene.txt"),
        workspace.path().join(TRACE),
    );
    let write = |path: &Path, bytes: &[u8]| {
        std::fs::write(path, bytes)
            .map_err(|e| RunFailure::plain(format!("could not write {}: {e}", path.display())))
    };
    for (name, bytes) in files {
        write(&workspace.path().join(name), bytes)?;
    }
    write(&scene, scene_text.as_bytes())?;
    let text = |p: &Path| p.to_string_lossy().into_owned();
    let dir = run.dir.map(text).unwrap_or_default();
    let values = [
        ("scene", text(&scene)),
        ("trace", text(&trace)),
        ("dir", dir),
    ];
    let values: Vec<(&str, &str)> = values.iter().map(|(k, v)| (*k, v.as_str())).collect();
    let command = close2gl_runner::substitute(run.words, &values);
    let outcome = close2gl_runner::run(&command, workspace.path(), run.limits, run.sandbox);
    if outcome.ended != Ending::Exited(0) {
        return Err(RunFailure {
            cause: outcome.in_brief(),
            reason: outcome.reason(),
        });
    }
    Ok((workspace, outcome.reason()))
}

/// The file `name` the program wrote in `workspace`, `what` it is in messages: read as the
/// program's own, never through a link it made (to the grader's environment, a classmate's
/// file), never a FIFO or a device. What it was is said; nothing of it quoted.
pub fn read_written(
    workspace: &Workspace,
    name: &str,
    limits: &Limits,
    what: &str,
    ran: &str,
) -> Result<Vec<u8>, RunFailure> {
    match workspace.read_own(name, limits.file_size) {
        Ok(bytes) => Ok(bytes),
        Err(NotItsOwn::Missing) => Err(RunFailure {
            cause: format!("it wrote no {}", what.trim_start_matches("its ")),
            reason: format!("it wrote no {} ({ran})", what.trim_start_matches("its ")),
        }),
        Err(not_its_own) => Err(RunFailure::plain(not_its_own.describe(what))),
    }
}

fn evidence(report: &Report, trace: &Trace, id: &str) -> Evidence {
    let first_difference = report.comparison.first_difference().map(|s| {
        format!(
            "{}: {}",
            s.stage.name(),
            s.details.first().map_or("", String::as_str)
        )
    });
    let pictures = picture::pictures(report, trace)
        .iter()
        .map(|image| image.to_png())
        .collect::<Result<Vec<_>, _>>()
        .unwrap_or_default();
    Evidence {
        first_difference,
        mistakes: report.mistakes(),
        text: report::text(report, id),
        pictures,
    }
}

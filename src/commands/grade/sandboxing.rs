//! What `grade` says about the sandbox its programs run in: whether there is one (`--unsandboxed`
//! or a kernel without Landlock: then it refuses unless told), what each run may read (its
//! submission's folder, what the command names, `--allow-read`), and the protections in force,
//! said at the start and in every report (text, JSON, HTML).

use std::path::{Path, PathBuf};

use close2gl_runner::{Protections, Sandbox};
use serde_json::{Value, json};

use super::CliError;

/// The sandbox of a grading: the kernel's protections (none with `--unsandboxed`) and the
/// folders every run may read beyond what its command names.
pub struct Sandboxing {
    pub protections: Option<&'static Protections>,
    pub allow_read: Vec<PathBuf>,
}

impl Sandboxing {
    /// From the flags: refuses, in one line, to run programs without a sandbox unless
    /// `--unsandboxed` says so; each `--allow-read` must be a folder.
    pub fn new(unsandboxed: bool, allow_read: &[PathBuf]) -> Result<Self, CliError> {
        let mut folders = Vec::new();
        for dir in allow_read {
            let folder = std::path::absolute(dir).ok().filter(|d| d.is_dir());
            folders.push(folder.ok_or_else(|| {
                CliError::Input(format!(
                    "--allow-read {}: expected a folder that exists",
                    dir.display()
                ))
            })?);
        }
        if unsandboxed {
            return Ok(Self {
                protections: None,
                allow_read: folders,
            });
        }
        let protections = Protections::current();
        if let Some(why) = protections.unavailable() {
            return Err(CliError::Runtime(format!(
                "cannot sandbox the programs: {why}; --unsandboxed runs them as you, \
                 with access to everything you can read and write"
            )));
        }
        Ok(Self {
            protections: Some(protections),
            allow_read: folders,
        })
    }

    /// One run's sandbox: with `--submissions`, the submission's folder is readable too.
    pub fn for_run(&self, submission: Option<&Path>) -> Sandbox {
        if self.protections.is_none() {
            return Sandbox::Off;
        }
        let mut readable = self.allow_read.clone();
        readable.extend(submission.map(Path::to_path_buf));
        Sandbox::On { readable }
    }

    /// The report's line: the protections in force and those missing.
    pub fn summary(&self) -> String {
        match self.protections {
            Some(protections) => protections.summary(),
            None => "sandbox: none (--unsandboxed): the programs ran as you".into(),
        }
    }

    /// What grading prints before it starts: the summary, then what a run may read.
    pub fn banner(&self, words: &[String], class: bool) -> String {
        let mut out = self.summary();
        if self.protections.is_none() {
            return out;
        }
        let path = std::env::var_os("PATH").unwrap_or_default();
        let mut reads: Vec<String> = close2gl_runner::SYSTEM_FOLDERS
            .iter()
            .map(|s| s.to_string())
            .collect();
        reads.extend(close2gl_runner::SYSTEM_FILES.iter().map(|s| s.to_string()));
        // With --submissions the command names `{dir}`: each run's own folder, said once.
        if class {
            reads.push("its submission's folder".into());
        }
        let named = close2gl_runner::command_folders(words, &path);
        reads.extend(
            named
                .iter()
                .chain(&self.allow_read)
                .map(|p| p.display().to_string()),
        );
        out.push_str(&format!(
            "\nsandbox: each run reads {}; writes only its own directory",
            reads.join(", ")
        ));
        out
    }

    /// The report's JSON: `enforced`, `landlock_abi`, and each protection with its words.
    pub fn json(&self) -> Value {
        let Some(protections) = self.protections else {
            return json!({"enforced": false, "landlock_abi": null, "protections": [],
                          "summary": self.summary()});
        };
        let list: Vec<Value> = protections
            .list()
            .iter()
            .map(|p| json!({"name": p.name, "enforced": p.enforced, "detail": p.detail}))
            .collect();
        json!({
            "enforced": true,
            "landlock_abi": protections.landlock_abi.as_ref().ok(),
            "protections": list,
            "summary": self.summary(),
        })
    }

    /// The protections as (name, enforced, detail) rows, for the HTML page.
    pub fn rows(&self) -> Vec<(&'static str, bool, String)> {
        match self.protections {
            Some(p) => p
                .list()
                .into_iter()
                .map(|p| (p.name, p.enforced, p.detail))
                .collect(),
            None => vec![("sandbox", false, self.summary())],
        }
    }
}

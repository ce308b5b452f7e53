//! The sandbox's rules as one run meets them, with real programs: it reads its own directory and
//! the folders it is given, not a file beside them; it writes only its directory; a denial is
//! named in its outcome; and a virtual environment's layout is found from its interpreter.
//! Skipped, saying why, only on a kernel without Landlock.

mod common;

use std::path::{Path, PathBuf};

use close2gl_runner::{Ending, Protections, Sandbox, Workspace, command_folders, run};
use common::{program, small_limits};

fn available() -> bool {
    match Protections::current().unavailable() {
        None => true,
        Some(why) => {
            eprintln!("skipped: {why}");
            false
        }
    }
}

/// A folder of the test's own beside the programs' (never the temporary folder, which the
/// sandbox refuses to open whole).
fn folder(name: &str) -> PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("sandbox")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("a test folder");
    dir
}

/// Runs `name` with `arg` in the sandbox. `arg` is given relative to the run's directory: an
/// absolute path in the command would make its folder readable.
fn sandboxed(name: &str, arg: &Path, readable: Vec<PathBuf>) -> close2gl_runner::Outcome {
    let workspace = Workspace::new().expect("a workspace");
    let up = "../".repeat(workspace.path().components().count() - 1);
    let relative = format!("{up}{}", arg.display().to_string().trim_start_matches('/'));
    let words = vec![program(name), relative];
    let sandbox = Sandbox::On { readable };
    run(&words, workspace.path(), &small_limits(), &sandbox)
}

#[test]
fn a_file_outside_is_denied_and_named_one_in_a_given_folder_is_read() {
    if !available() {
        return;
    }
    let secret = folder("secret").join("key.txt");
    std::fs::write(&secret, "KEY").expect("the key");
    let denied = sandboxed("cat_first_argument", &secret, Vec::new());
    assert_eq!(denied.ended, Ending::Exited(1));
    let expected = format!("tried to open {}: denied", secret.display());
    assert_eq!(denied.denied.as_deref(), Some(expected.as_str()));
    let reason = denied.reason();
    assert!(
        reason.contains("\nthe sandbox stopped it: tried to open "),
        "{reason}"
    );
    let parent = secret.parent().map(Path::to_path_buf).unwrap_or_default();
    let allowed = sandboxed("cat_first_argument", &secret, vec![parent]);
    assert_eq!(
        (allowed.ended, allowed.stdout_tail),
        (Ending::Exited(0), b"KEY".to_vec())
    );
}

#[test]
fn a_given_folder_is_read_only_and_the_run_directory_is_writable() {
    if !available() {
        return;
    }
    let shared = folder("shared");
    let target = shared.join("new.txt");
    let outcome = sandboxed("write_first_argument", &target, vec![shared.clone()]);
    assert_eq!(outcome.ended, Ending::Exited(1));
    assert!(!target.exists(), "it wrote into a read-only folder");
    let unsandboxed_words = vec![program("write_first_argument"), "here.txt".into()];
    let workspace = Workspace::new().expect("a workspace");
    let sandbox = Sandbox::On {
        readable: Vec::new(),
    };
    let own = run(
        &unsandboxed_words,
        workspace.path(),
        &small_limits(),
        &sandbox,
    );
    assert_eq!(own.ended, Ending::Exited(0));
    assert!(workspace.path().join("here.txt").is_file());
}

#[test]
fn a_virtual_environments_prefix_and_base_python_are_readable() {
    let base = folder("base-python");
    let venv = folder("venv");
    for bin in [base.join("bin"), venv.join("bin")] {
        std::fs::create_dir_all(&bin).expect("bin");
    }
    std::fs::copy("/bin/sh", base.join("bin/python3")).expect("an interpreter");
    std::os::unix::fs::symlink(base.join("bin/python3"), venv.join("bin/python"))
        .expect("the venv's link");
    let cfg = format!("home = {}\n", base.join("bin").display());
    std::fs::write(venv.join("pyvenv.cfg"), cfg).expect("pyvenv.cfg");
    let script = folder("course").join("close2gl.py");
    std::fs::write(&script, "print()\n").expect("a script");
    let words = [venv.join("bin/python"), script.clone()].map(|p| p.display().to_string());
    let folders = command_folders(&words, "".as_ref());
    let canonical = |p: PathBuf| p.canonicalize().unwrap_or(p);
    for expected in [
        venv.clone(),
        base.clone(),
        script.parent().map(Path::to_path_buf).unwrap_or_default(),
    ] {
        let expected = canonical(expected);
        assert!(
            folders.iter().any(|f| canonical(f.clone()) == expected),
            "{} not in {folders:?}",
            expected.display()
        );
    }
}

//! What a program finds when it starts: only PATH, HOME and LANG, stdin empty, its workspace as
//! working directory; and the workspace gone after it.

mod common;

use std::os::unix::fs::PermissionsExt;
use std::time::Duration;

use close2gl_runner::{Ending, Workspace};
use common::{run_expecting, small_limits};

const QUICK: Duration = Duration::from_secs(1);

#[test]
fn the_environment_is_path_home_and_lang_only() {
    let (outcome, workspace) =
        run_expecting("print_env", &small_limits(), Ending::Exited(0), QUICK);
    let printed = String::from_utf8_lossy(&outcome.stdout_tail);
    let mut lines: Vec<&str> = printed.lines().collect();
    lines.sort_unstable();
    let path = std::env::var("PATH").unwrap_or_else(|_| "/usr/bin:/bin".into());
    let lang = std::env::var("LANG").unwrap_or_else(|_| "C.UTF-8".into());
    let home = workspace.path().display();
    let expected = [
        format!("HOME={home}"),
        format!("LANG={lang}"),
        format!("PATH={path}"),
    ];
    assert_eq!(lines, expected);
}

#[test]
fn stdin_is_empty() {
    let (outcome, _workspace) =
        run_expecting("read_stdin", &small_limits(), Ending::Exited(0), QUICK);
    assert_eq!(outcome.stdout_tail, b"0\n");
}

#[test]
fn the_working_directory_is_the_workspace() {
    let (outcome, workspace) =
        run_expecting("print_cwd", &small_limits(), Ending::Exited(0), QUICK);
    let expected = format!("{}\n", workspace.path().display());
    assert_eq!(String::from_utf8_lossy(&outcome.stdout_tail), expected);
}

#[test]
fn a_workspace_is_fresh_private_and_removed_on_drop_even_when_locked() {
    let workspace = Workspace::new().expect("make a workspace");
    let other = Workspace::new().expect("make another");
    let path = workspace.path().to_path_buf();
    assert_ne!(path, other.path());
    let name = path.file_name().map(|n| n.to_string_lossy().into_owned());
    assert!(name.is_some_and(|n| n.starts_with("close2gl-grade-")));
    let mode = std::fs::metadata(&path).map(|m| m.permissions().mode() & 0o777);
    assert_eq!(mode.ok(), Some(0o700));
    assert_eq!(std::fs::read_dir(&path).map(Iterator::count).ok(), Some(0));
    let locked = path.join("locked");
    std::fs::create_dir_all(locked.join("inner")).expect("make directories");
    std::fs::write(locked.join("inner/file"), b"x").expect("write a file");
    for dir in [locked.join("inner"), locked.clone()] {
        let read_only = std::fs::Permissions::from_mode(0o500);
        std::fs::set_permissions(&dir, read_only).expect("lock a directory");
    }
    drop(workspace);
    assert!(!path.exists(), "{} is still there", path.display());
    assert!(other.path().exists());
}

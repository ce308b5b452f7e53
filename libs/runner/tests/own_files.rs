//! What a run left is read as its own and nothing else: a trace that is a link (to
//! `/proc/self/environ`, to a file elsewhere, to `/dev/zero`), a FIFO, a directory or a file with
//! another name is reported for what it is and never opened; a regular file is read even when
//! the program took its permissions; and a workspace whose directories the program locked and
//! linked elsewhere is removed without touching what the links lead to.

mod common;

use std::os::unix::fs::{PermissionsExt, symlink};
use std::path::Path;

use close2gl_runner::{Ending, NotItsOwn, Sandbox, Workspace, run};
use common::{program, small_limits};

const MAX: u64 = 1 << 20;

/// A folder of the test's own outside every workspace, holding `secret.txt`.
fn outside(name: &str) -> std::path::PathBuf {
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join("own_files")
        .join(name);
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("a folder outside");
    std::fs::write(dir.join("secret.txt"), "SECRET-OUTSIDE\n").expect("the secret");
    dir
}

#[test]
fn a_link_is_reported_with_where_it_points_and_never_opened() {
    let workspace = Workspace::new().expect("a workspace");
    let secret = outside("link").join("secret.txt");
    for target in [
        Path::new("/proc/self/environ"),
        Path::new("/dev/zero"),
        &secret,
    ] {
        let trace = workspace.path().join("trace.txt");
        let _ = std::fs::remove_file(&trace);
        symlink(target, &trace).expect("a link");
        let read = workspace.read_own("trace.txt", MAX);
        let expected = NotItsOwn::Link(target.display().to_string());
        assert_eq!(read, Err(expected.clone()));
        assert_eq!(
            expected.describe("its trace"),
            format!(
                "its trace is a link to {}, not a file it wrote",
                target.display()
            )
        );
    }
}

#[test]
fn a_program_that_links_its_trace_gets_the_link_reported() {
    let workspace = Workspace::new().expect("a workspace");
    let words = [program("links_its_trace"), "/proc/self/environ".into()];
    let outcome = run(&words, workspace.path(), &small_limits(), &Sandbox::Off);
    assert_eq!(outcome.ended, Ending::Exited(0));
    let read = workspace.read_own("trace.txt", MAX);
    assert_eq!(read, Err(NotItsOwn::Link("/proc/self/environ".into())));
}

#[test]
fn a_fifo_a_directory_and_a_second_name_are_not_files_it_wrote() {
    let workspace = Workspace::new().expect("a workspace");
    let fifo = workspace.path().join("fifo");
    let path = std::ffi::CString::new(fifo.as_os_str().as_encoded_bytes()).expect("a path");
    // SAFETY: mkfifo reads a live NUL-terminated path.
    assert_eq!(unsafe { libc::mkfifo(path.as_ptr(), 0o600) }, 0);
    // Opening a FIFO for reading would wait for a writer: the read must not even open it.
    assert_eq!(
        workspace.read_own("fifo", MAX),
        Err(NotItsOwn::NotAFile("a FIFO"))
    );
    std::fs::create_dir(workspace.path().join("dir")).expect("a directory");
    assert_eq!(
        workspace.read_own("dir", MAX),
        Err(NotItsOwn::NotAFile("a directory"))
    );
    std::fs::write(workspace.path().join("one"), "x").expect("a file");
    std::fs::hard_link(workspace.path().join("one"), workspace.path().join("two"))
        .expect("a hard link");
    assert_eq!(
        workspace.read_own("two", MAX),
        Err(NotItsOwn::OtherNames(2))
    );
    assert_eq!(workspace.read_own("none", MAX), Err(NotItsOwn::Missing));
}

#[test]
fn a_regular_file_is_read_even_locked_and_a_big_one_is_refused() {
    let workspace = Workspace::new().expect("a workspace");
    let trace = workspace.path().join("trace.txt");
    std::fs::write(&trace, "close2gl-trace 1\n").expect("a trace");
    std::fs::set_permissions(&trace, std::fs::Permissions::from_mode(0o000)).expect("chmod 000");
    assert_eq!(
        workspace.read_own("trace.txt", MAX).as_deref(),
        Ok(&b"close2gl-trace 1\n"[..])
    );
    assert_eq!(
        workspace.read_own("trace.txt", 4),
        Err(NotItsOwn::TooBig(17))
    );
}

#[test]
fn a_locked_workspace_linking_elsewhere_is_removed_without_touching_the_target() {
    let target = outside("locked");
    std::fs::set_permissions(&target, std::fs::Permissions::from_mode(0o751)).expect("chmod");
    let workspace = Workspace::new().expect("a workspace");
    let locked = workspace.path().join("locked");
    std::fs::create_dir_all(locked.join("deeper")).expect("directories");
    symlink(&target, locked.join("elsewhere")).expect("a link to a folder outside");
    symlink(&target, workspace.path().join("elsewhere")).expect("a link at the top");
    for dir in [locked.join("deeper"), locked.clone()] {
        std::fs::set_permissions(&dir, std::fs::Permissions::from_mode(0o000)).expect("chmod 000");
    }
    let path = workspace.path().to_path_buf();
    drop(workspace);
    assert!(!path.exists(), "the workspace is left");
    assert!(
        target.join("secret.txt").exists(),
        "a file behind a link was removed"
    );
    let mode = std::fs::metadata(&target)
        .expect("the target")
        .permissions()
        .mode();
    assert_eq!(mode & 0o777, 0o751, "the target's permissions changed");
}

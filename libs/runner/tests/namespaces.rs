//! Each sandboxed run in a PID namespace of its own, with real programs: a fork bomb is killed
//! at the process limit, quickly, with every one of its processes; a daemon that left its
//! session ends with the run; the program's own ending (an exit status, `abort`) comes through
//! the two processes above it unchanged. Skipped, saying why, only where the kernel allows no
//! unprivileged namespaces (or has no Landlock).

mod common;

use std::time::{Duration, Instant};

use close2gl_runner::{Ending, Limits, Protections, Sandbox, Workspace, run};
use common::{program, signalled, small_limits};

fn available() -> bool {
    let protections = Protections::current();
    let missing = protections
        .unavailable()
        .or_else(|| protections.namespaces.clone().err());
    match missing {
        None => true,
        Some(why) => {
            eprintln!("skipped: {why}");
            false
        }
    }
}

/// Runs `name` in the sandbox under `limits`; the outcome, its workspace and how long it took.
fn sandboxed(name: &str, limits: &Limits) -> (close2gl_runner::Outcome, Workspace, Duration) {
    let workspace = Workspace::new().expect("a workspace");
    let sandbox = Sandbox::On {
        readable: Vec::new(),
    };
    let started = Instant::now();
    let outcome = run(&[program(name)], workspace.path(), limits, &sandbox);
    (outcome, workspace, started.elapsed())
}

/// Whether the kernel limits a run's processes (a fork bomb's test would otherwise melt the
/// machine before the watcher sees it); says why not when it does not.
fn limited_by_the_kernel() -> bool {
    if !Protections::current().process_count_per_namespace() {
        eprintln!("skipped: the kernel does not count processes per namespace");
        return false;
    }
    true
}

#[test]
fn the_kernel_holds_a_run_to_its_process_limit_even_for_root() {
    if !available() || !limited_by_the_kernel() {
        return;
    }
    let limits = Limits {
        processes: 8,
        ..small_limits()
    };
    let (outcome, workspace, _) = sandboxed("fork_twenty", &limits);
    // A fork failed in the kernel a few past the limit (the relay and the init count too,
    // and a little room lets the watcher see the limit passed), not at the twentieth.
    let stderr = String::from_utf8_lossy(&outcome.stderr_tail);
    assert!(stderr.contains("fork failed after 1"), "{outcome:?}");
    assert_eq!(outcome.ended, Ending::TooManyProcesses(8), "{outcome:?}");
    assert!(common::processes_in(workspace.path()).is_empty());
}

#[test]
fn a_fork_bomb_is_killed_at_the_process_limit_with_all_its_processes() {
    if !available() || !limited_by_the_kernel() {
        return;
    }
    let limits = Limits {
        time: Duration::from_secs(5),
        processes: 64,
        ..small_limits()
    };
    let (outcome, workspace, took) = sandboxed("fork_bomb", &limits);
    assert_eq!(outcome.ended, Ending::TooManyProcesses(64), "{outcome:?}");
    assert!(
        outcome
            .reason()
            .contains("it made more than 64 processes at once"),
        "{}",
        outcome.reason()
    );
    // Long before its time limit: the watcher sees the limit passed within a tick or two.
    assert!(took < Duration::from_secs(3), "{took:?}");
    // The pids it wrote are its namespace's: no use here.
    assert!(common::processes_in(workspace.path()).is_empty());
}

#[test]
fn a_daemon_that_left_its_session_ends_with_the_run() {
    if !available() {
        return;
    }
    let (outcome, workspace, _) = sandboxed("daemon_then_exit", &small_limits());
    assert_eq!(outcome.ended, Ending::Exited(0), "{outcome:?}");
    assert!(common::processes_in(workspace.path()).is_empty());
}

#[test]
fn the_programs_own_ending_comes_through_unchanged() {
    if !available() {
        return;
    }
    let (exited, ..) = sandboxed("exit3", &small_limits());
    assert_eq!(exited.ended, Ending::Exited(3));
    assert!(exited.reason().contains("line 8"), "{}", exited.reason());
    // Not the namespace's init, which would ignore its own SIGABRT.
    let (aborted, workspace, _) = sandboxed("abort", &small_limits());
    assert_eq!(aborted.ended, signalled(libc::SIGABRT, "SIGABRT"));
    assert!(!workspace.path().join("core").exists());
    let (segfault, ..) = sandboxed("segfault", &small_limits());
    assert_eq!(segfault.ended, signalled(libc::SIGSEGV, "SIGSEGV"));
}

#[test]
fn the_protections_name_the_pid_namespace() {
    if !available() {
        return;
    }
    let processes = Protections::current()
        .list()
        .into_iter()
        .find(|p| p.name == "processes")
        .expect("a processes protection");
    assert!(processes.enforced);
    assert!(processes.detail.contains("PID namespace"), "{processes:?}");
}

//! Programs that crash, hang, flood their output, fill the disk or eat memory: each ends with the
//! right reason, within its limits, and leaves nothing running.

mod common;

use std::time::Duration;

use close2gl_runner::{Ending, Limits, Sandbox};
use common::{pids_written, run_expecting, signalled, small_limits};

const QUICK: Duration = Duration::from_secs(1);
/// A one-second time limit, and one more second for everything else.
const LIMIT_AND_A_SECOND: Duration = Duration::from_secs(2);

#[test]
fn a_program_that_sleeps_forever_times_out() {
    let limits = small_limits();
    let (outcome, workspace) = run_expecting(
        "sleep_forever",
        &limits,
        Ending::TimedOut,
        LIMIT_AND_A_SECOND,
    );
    assert!(outcome.elapsed >= limits.time, "{:?}", outcome.elapsed);
    assert_eq!(outcome.reason(), "timed out after 1 s");
    assert_eq!(pids_written(workspace.path()).len(), 1);
}

#[test]
fn a_program_that_spins_times_out_before_its_cpu_limit() {
    run_expecting(
        "spin",
        &small_limits(),
        Ending::TimedOut,
        LIMIT_AND_A_SECOND,
    );
}

#[test]
fn an_abort_is_reported_as_sigabrt_without_a_core_file() {
    let sigabrt = signalled(libc::SIGABRT, "SIGABRT");
    let (outcome, workspace) = run_expecting("abort", &small_limits(), sigabrt, QUICK);
    assert!(outcome.reason().starts_with("killed by SIGABRT after "));
    let files = std::fs::read_dir(workspace.path()).map(Iterator::count);
    assert_eq!(files.ok(), Some(0), "RLIMIT_CORE = 0: no core file");
}

#[test]
fn a_segfault_is_reported_as_sigsegv() {
    let sigsegv = signalled(libc::SIGSEGV, "SIGSEGV");
    run_expecting("segfault", &small_limits(), sigsegv, QUICK);
}

#[test]
fn an_exit_status_comes_with_the_last_lines_of_stderr() {
    let (outcome, _) = run_expecting("exit3", &small_limits(), Ending::Exited(3), QUICK);
    assert_eq!(outcome.stdout_tail, b"to stdout\n");
    assert_eq!(
        outcome.reason(),
        "exited with status 3\nline 4\nline 5\nline 6\nline 7\nline 8"
    );
}

#[test]
fn ten_megabytes_of_stdout_keep_only_the_last_64_kib_and_do_not_block() {
    let limits = Limits {
        time: Duration::from_secs(5),
        ..Limits::default()
    };
    let (outcome, _) = run_expecting("flood_stdout", &limits, Ending::Exited(0), QUICK);
    assert_eq!(outcome.stdout_tail.len(), 64 << 10);
    assert!(
        outcome
            .stdout_tail
            .ends_with(b"000000000655358\n000000000655359\n")
    );
}

#[test]
fn one_endless_file_is_stopped_at_the_file_size_limit() {
    let limits = small_limits();
    let sigxfsz = signalled(libc::SIGXFSZ, "SIGXFSZ");
    let (_, workspace) = run_expecting("endless_file", &limits, sigxfsz, QUICK);
    let size = std::fs::metadata(workspace.path().join("big")).map(|m| m.len());
    assert_eq!(size.ok(), Some(limits.file_size));
}

#[test]
fn many_files_are_stopped_at_the_disk_limit() {
    let limits = small_limits();
    let (_, workspace) = run_expecting("many_files", &limits, Ending::TooMuchDisk, QUICK);
    let written: u64 = std::fs::read_dir(workspace.path())
        .expect("read the workspace")
        .flatten()
        .filter_map(|entry| entry.metadata().ok())
        .map(|meta| meta.len())
        .sum();
    eprintln!(
        "many_files wrote {} MiB against a limit of 16",
        written >> 20
    );
    assert!(written > limits.disk, "it was stopped for a reason");
    // Stopped within a tick or so (at about 2 GB/s, 20 ms is 40 MB).
    assert!(
        written < limits.disk + (128 << 20),
        "{written} bytes: checked too late"
    );
}

#[test]
fn endless_allocation_fails_inside_the_program_not_the_grader() {
    // Touching 256 MiB page by page takes a tenth of a second on an idle machine and more than
    // the usual second on a loaded one (CI beside a build): time is not what this is about.
    let limits = Limits {
        time: Duration::from_secs(20),
        ..small_limits()
    };
    let (outcome, _) = run_expecting("allocate", &limits, Ending::Exited(4), limits.time);
    let stderr = String::from_utf8_lossy(&outcome.stderr_tail);
    assert!(stderr.starts_with("out of memory after "), "{stderr}");
    // The limit was set in the child only.
    let mut own = libc::rlimit {
        rlim_cur: 0,
        rlim_max: 0,
    };
    // SAFETY: `own` is a live local the kernel fills in.
    assert_eq!(unsafe { libc::getrlimit(libc::RLIMIT_AS, &mut own) }, 0);
    assert_eq!(own.rlim_cur, libc::RLIM_INFINITY);
}

#[test]
fn a_missing_program_could_not_start() {
    let workspace = close2gl_runner::Workspace::new().expect("make a workspace");
    let words = vec!["/no/such/student-program".to_string()];
    let outcome = close2gl_runner::run(&words, workspace.path(), &small_limits(), &Sandbox::Off);
    let expected = "no such program `/no/such/student-program`".to_string();
    assert_eq!(outcome.ended, Ending::CouldNotStart(expected));
    let outcome = close2gl_runner::run(&[], workspace.path(), &small_limits(), &Sandbox::Off);
    assert!(matches!(outcome.ended, Ending::CouldNotStart(_)));
}

//! Programs whose children try to outlive them: leaving the session with `setsid`, orphaned or
//! not, fifty at once, and several such programs in parallel. After `run` none is left
//! (`run_expecting` checks every pid they wrote).

mod common;

use std::time::Duration;

use close2gl_runner::{Ending, Limits};
use common::{pids_written, run_expecting, signalled, small_limits};

/// The program ends at once, its children do not: `run` must not wait for them (they hold its
/// stdout open).
const AT_ONCE: Duration = Duration::from_millis(500);
/// A one-second time limit, and one more second for everything else.
const LIMIT_AND_A_SECOND: Duration = Duration::from_secs(2);

fn pids_checked(name: &str, ending: Ending, within: Duration, limits: &Limits) -> usize {
    let (_, workspace) = run_expecting(name, limits, ending, within);
    pids_written(workspace.path()).len()
}

#[test]
fn an_orphan_that_left_the_session_is_killed_when_its_parent_exits() {
    let checked = pids_checked("orphan_setsid", Ending::Exited(0), AT_ONCE, &small_limits());
    assert_eq!(checked, 1);
}

#[test]
fn a_setsid_child_of_a_hanging_parent_is_killed_with_it() {
    let limits = small_limits();
    let checked = pids_checked(
        "orphan_and_hang",
        Ending::TimedOut,
        LIMIT_AND_A_SECOND,
        &limits,
    );
    assert_eq!(checked, 2);
}

#[test]
fn a_setsid_grandchild_whose_parent_lives_is_killed() {
    let limits = small_limits();
    let checked = pids_checked("grandchild_setsid", Ending::Exited(0), AT_ONCE, &limits);
    assert_eq!(checked, 2);
}

#[test]
fn fifty_sleepers_half_of_them_in_new_sessions_are_all_killed() {
    let limits = Limits {
        time: Duration::from_secs(2),
        ..small_limits()
    };
    let within = Duration::from_secs(3);
    let checked = pids_checked("fifty_sleepers", Ending::TimedOut, within, &limits);
    assert_eq!(checked, 51);
}

#[test]
fn hostile_programs_in_parallel_each_get_their_own_ending() {
    let cases = [
        ("sleep_forever", Ending::TimedOut, 1),
        ("orphan_and_hang", Ending::TimedOut, 2),
        ("grandchild_setsid", Ending::Exited(0), 2),
        ("orphan_setsid", Ending::Exited(0), 1),
        ("exit3", Ending::Exited(3), 0),
        ("segfault", signalled(libc::SIGSEGV, "SIGSEGV"), 0),
    ];
    // Compile first, so that the runs start together.
    for (name, _, _) in &cases {
        common::program(name);
    }
    let started = std::time::Instant::now();
    std::thread::scope(|scope| {
        let runs: Vec<_> = cases
            .into_iter()
            .map(|(name, ending, pids)| {
                scope.spawn(move || {
                    let limits = small_limits();
                    let checked = pids_checked(name, ending, LIMIT_AND_A_SECOND, &limits);
                    assert_eq!(checked, pids, "{name}");
                })
            })
            .collect();
        for run in runs {
            run.join().expect("a parallel run failed");
        }
    });
    let took = started.elapsed();
    assert!(took < LIMIT_AND_A_SECOND, "the parallel runs took {took:?}");
}

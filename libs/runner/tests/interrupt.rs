//! Ctrl+C while a program runs. Alone in its test binary: the interrupt flag is the process's,
//! and stays set, so any other test running beside it would be interrupted too.

mod common;

use std::time::{Duration, Instant};

use close2gl_runner::{
    Ending, Limits, Sandbox, Workspace, install_interrupt_handler, interrupted, reap_everything,
    run,
};
use common::{gone, pids_written, program};

#[test]
fn sigint_stops_the_running_program_and_reap_everything_removes_the_workspaces() {
    install_interrupt_handler();
    let words = vec![program("fifty_sleepers")];
    let limits = Limits {
        time: Duration::from_secs(30),
        ..common::small_limits()
    };
    let workspace = Workspace::new().expect("make a workspace");
    let path = workspace.path().to_path_buf();
    let (outcome, took) = std::thread::scope(|scope| {
        let running = scope.spawn(|| run(&words, &path, &limits, &Sandbox::Off));
        // Wait until the program and its fifty children are all running.
        let ready = Instant::now();
        while !path.join("pid").exists() {
            assert!(
                ready.elapsed() < Duration::from_secs(10),
                "the program did not start"
            );
            std::thread::sleep(Duration::from_millis(10));
        }
        let sent = Instant::now();
        // SAFETY: the handler above catches SIGINT: it only sets the flag.
        unsafe { libc::kill(libc::getpid(), libc::SIGINT) };
        let outcome = running.join().expect("the run panicked");
        (outcome, sent.elapsed())
    });
    assert!(interrupted());
    assert_eq!(outcome.ended, Ending::Interrupted);
    assert!(
        took < Duration::from_millis(500),
        "it took {took:?} to stop"
    );
    let pids = pids_written(&path);
    assert_eq!(pids.len(), 51);
    assert!(pids.iter().all(|pid| gone(*pid)), "left running: {pids:?}");

    // A run asked for after the interrupt does not start.
    let again = run(&words, &path, &limits, &Sandbox::Off);
    assert_eq!(again.ended, Ending::Interrupted);
    assert_eq!(again.elapsed, Duration::ZERO);

    // The caller exits without dropping its workspace: reap_everything removes it.
    std::mem::forget(workspace);
    reap_everything();
    assert!(!path.exists(), "{} is still there", path.display());
}

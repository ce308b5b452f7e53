//! One run of one program: start it, watch it, stop it, clean up after it. The watcher is the
//! calling thread itself, ticking every [`TICK`]: it reads the output, and checks for the
//! program's exit, the time limit, the disk limit, the process limit and an interrupt. Runs on
//! several threads at once share nothing but the reaper's list of running programs.

use std::os::unix::process::ExitStatusExt;
use std::path::Path;
use std::process::{Child, ExitStatus};
use std::time::{Duration, Instant};

use crate::interrupt::interrupted;
use crate::outcome::{Ending, Outcome};
use crate::output_tail::Output;
use crate::reap::Registration;
use crate::resource_limits::Limits;
use crate::sandbox::Sandbox;
use crate::signals::signal_name;
use crate::{disk, proc_table, spawn};

/// How often the watcher checks: small next to any time limit, rare enough to cost nothing.
const TICK: Duration = Duration::from_millis(20);

/// Runs `words` (a program and its arguments) in `dir` under `limits` and in `sandbox`, and
/// returns once it has ended and every process it started is dead and reaped. Nothing is
/// started once grading was interrupted. Safe to call from several threads at once.
pub fn run(words: &[String], dir: &Path, limits: &Limits, sandbox: &Sandbox) -> Outcome {
    let not_run = |ended| Outcome {
        ended,
        elapsed: Duration::ZERO,
        stdout_tail: Vec::new(),
        stderr_tail: Vec::new(),
        denied: None,
    };
    if interrupted() {
        return not_run(Ending::Interrupted);
    }
    let started = Instant::now();
    let (mut child, registration, sandboxed) = match spawn::start(words, dir, limits, sandbox) {
        Ok(running) => running,
        Err(e) => return not_run(Ending::CouldNotStart(start_error(words, dir, &e))),
    };
    let mut output = Output::new(child.stdout.take(), child.stderr.take(), limits.output);
    let watched = Watched {
        dir,
        limits,
        // The relay and the init above a program in its own PID namespace are the run's too.
        processes: limits.processes as usize + sandboxed.waiting_processes(),
    };
    let (ended, elapsed) = watch(&mut child, &registration, &mut output, &watched, started);
    // Only once the program is reaped may the reaper take the orphans it left.
    drop(registration);
    let (stdout_tail, stderr_tail) = output.finish();
    // A program that ended well was not stopped by whatever it was denied.
    let denied = (ended != Ending::Exited(0))
        .then(|| sandboxed.denial(&stderr_tail))
        .flatten();
    Outcome {
        ended,
        elapsed,
        stdout_tail,
        stderr_tail,
        denied,
    }
}

/// What the watcher holds a run to: its directory's size, its time, its processes.
struct Watched<'a> {
    dir: &'a Path,
    limits: &'a Limits,
    /// The processes the run may have at once, counting those the sandbox puts above it.
    processes: usize,
}

/// Ticks until the program exits or must be stopped; returns how it ended and when. On return
/// the program is reaped.
fn watch(
    child: &mut Child,
    registration: &Registration,
    output: &mut Output,
    watched: &Watched,
    started: Instant,
) -> (Ending, Duration) {
    let (dir, limits) = (watched.dir, watched.limits);
    let mut checked = Instant::now() - TICK;
    let too_many_processes = || {
        let size = proc_table::tree_size(registration.pid(), watched.processes);
        (size > watched.processes).then_some(Ending::TooManyProcesses(limits.processes))
    };
    let mut over_a_limit = || {
        // A chatty program wakes the watcher often: the directory and the process tree are
        // walked once a tick.
        if checked.elapsed() < TICK {
            return None;
        }
        checked = Instant::now();
        too_many_processes()
            .or_else(|| disk::exceeds(dir, limits.disk).then_some(Ending::TooMuchDisk))
    };
    loop {
        output.pump(TICK);
        let elapsed = started.elapsed();
        let stop = match child.try_wait() {
            Ok(Some(status)) => {
                // A program that filled its directory and exited before the check still did.
                let ended = if disk::exceeds(dir, limits.disk) {
                    Ending::TooMuchDisk
                } else {
                    ending(status)
                };
                return (ended, elapsed);
            }
            Ok(None) if interrupted() => Ending::Interrupted,
            // A fork bomb held at the kernel's limit starves the watcher on a small machine:
            // it may first be seen when its time is up, and that is still why it failed.
            Ok(None) if elapsed >= limits.time => too_many_processes().unwrap_or(Ending::TimedOut),
            Ok(None) => match over_a_limit() {
                Some(ending) => ending,
                None => continue,
            },
            Err(e) => Ending::CouldNotStart(format!("could not wait for it: {e}")),
        };
        registration.kill_tree();
        // After SIGKILL this returns at once; its status says nothing more than `stop` does.
        let _ = child.wait();
        return (stop, elapsed);
    }
}

fn ending(status: ExitStatus) -> Ending {
    match (status.code(), status.signal()) {
        (Some(code), _) => Ending::Exited(code),
        (None, Some(signal)) => Ending::Signalled {
            signal,
            name: signal_name(signal),
        },
        (None, None) => Ending::CouldNotStart(format!("it ended in an unknown way: {status}")),
    }
}

/// "no such program `stundent`" reads better than "No such file or directory (os error 2)".
fn start_error(words: &[String], dir: &Path, error: &std::io::Error) -> String {
    let program = words.first().map_or("", String::as_str);
    if !dir.is_dir() {
        return format!("its directory {} does not exist", dir.display());
    }
    match error.kind() {
        std::io::ErrorKind::NotFound => format!("no such program `{program}`"),
        std::io::ErrorKind::PermissionDenied => {
            format!("`{program}` is not executable, or the sandbox denied running it")
        }
        _ => format!("`{program}`: {error}"),
    }
}

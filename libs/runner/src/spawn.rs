//! Starting the program: its directory, its environment, closed stdin, piped output, and what
//! must be set in the child between `fork` and `exec` (a session of its own, resource limits,
//! death with its parent, the sandbox). Between fork and exec only async-signal-safe calls are
//! allowed, so that code makes raw system calls and nothing else; the sandbox's rules are made
//! before the fork.

use std::io;
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::Duration;

use crate::reap::{self, Registration};
use crate::resource_limits::{Limits, lower};
use crate::sandbox::{self, InChild, Prepared, Sandbox};

/// The kernel-enforced limits, computed before the fork (the child must not allocate).
#[derive(Clone, Copy)]
struct ChildLimits {
    address_space: u64,
    file_size: u64,
    cpu_seconds: u64,
}

/// Starts `words` in `dir` with `limits` and registers it with the reaper. The environment is
/// `PATH` and `LANG` from ours (defaults `/usr/bin:/bin`, `C.UTF-8`) and `HOME` = `dir`: nothing
/// of the teacher's environment (tokens, proxies) reaches a student's program. A program named
/// without a slash is looked up in that `PATH`; one with a slash but not absolute is resolved
/// from `dir`, so callers give absolute paths. Returns the run's sandbox too, to read its
/// stderr by.
pub(crate) fn start(
    words: &[String],
    dir: &Path,
    limits: &Limits,
    sandbox: &Sandbox,
) -> io::Result<(Child, Registration, Prepared)> {
    let Some((program, args)) = words.split_first() else {
        return Err(io::Error::other("the command is empty"));
    };
    let home = std::path::absolute(dir)?;
    let path = std::env::var_os("PATH").unwrap_or_else(|| "/usr/bin:/bin".into());
    // Found here, as the child would: in the sandbox it could not look in every folder of
    // PATH, and might find another program of the same name further on.
    let found = sandbox::find_program(program, &path).unwrap_or_else(|| program.into());
    let prepared = Prepared::new(sandbox, words, &home, &path, limits.processes)?;
    let in_sandbox = prepared.in_child();
    let lang = std::env::var_os("LANG").unwrap_or_else(|| "C.UTF-8".into());
    let child_limits = ChildLimits {
        address_space: limits.address_space,
        file_size: limits.file_size,
        cpu_seconds: cpu_seconds(limits.time),
    };
    // SAFETY: getpid has no preconditions.
    let grader = unsafe { libc::getpid() };
    let mut command = Command::new(found);
    // The program still sees the name it was called by.
    std::os::unix::process::CommandExt::arg0(&mut command, program);
    command
        .args(args)
        .current_dir(&home)
        .env_clear()
        .env("PATH", path)
        .env("HOME", &home)
        .env("LANG", lang)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    // SAFETY: the hook runs in the forked child before exec and only makes async-signal-safe
    // system calls (setsid, getrlimit, setrlimit, prctl, getppid, unshare, fork, waitpid,
    // pipe2, read, write, dup2, close, kill, landlock_restrict_self) on copied plain values.
    unsafe {
        std::os::unix::process::CommandExt::pre_exec(&mut command, move || {
            in_child(child_limits, grader, in_sandbox)
        });
    }
    let (child, registration) = reap::spawn(&mut command)?;
    Ok((child, registration, prepared))
}

/// CPU time: the wall-clock limit rounded up, plus a second, so that the grader's own timeout
/// normally comes first; this one still works if the grader dies.
fn cpu_seconds(time: Duration) -> u64 {
    time.as_secs() + u64::from(time.subsec_nanos() > 0) + 1
}

/// Runs in the child between fork and exec; the sandbox last, once nothing else needs a file.
fn in_child(limits: ChildLimits, grader: libc::pid_t, in_sandbox: InChild) -> io::Result<()> {
    // SAFETY: these are plain system calls without pointers into shared state; setsid makes
    // the child a session and process-group leader, which the reaper relies on.
    unsafe {
        if libc::setsid() == -1 {
            return Err(io::Error::last_os_error());
        }
        // If the grader is killed outright, the program is killed too (its own descendants are
        // not: nothing can do that once the grader is gone).
        if libc::prctl(libc::PR_SET_PDEATHSIG, libc::SIGKILL, 0, 0, 0) == -1 {
            return Err(io::Error::last_os_error());
        }
        // The grader may have died before the line above: then no signal would come. (An
        // error from a raw code: allocating here could deadlock on a lock another thread held.)
        if libc::getppid() != grader {
            return Err(io::Error::from_raw_os_error(libc::ESRCH));
        }
    }
    lower(libc::RLIMIT_AS, limits.address_space, limits.address_space)?;
    lower(libc::RLIMIT_FSIZE, limits.file_size, limits.file_size)?;
    lower(libc::RLIMIT_CORE, 0, 0)?;
    // The soft limit sends SIGXCPU, the hard one a second later SIGKILL (if SIGXCPU is caught).
    lower(libc::RLIMIT_CPU, limits.cpu_seconds, limits.cpu_seconds + 1)?;
    sandbox::enter(in_sandbox)
}

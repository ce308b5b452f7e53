//! The sandbox each program runs in, so that a hostile program cannot read or change what is
//! not its own, reach the network or disturb the grader and the other runs. It is Landlock (a
//! Linux security module any process may apply to itself and its children, no root needed),
//! applied in the child between fork and exec, and where unprivileged namespaces are allowed, a
//! user, network and PID namespace of the program's own, with its process count limited there.
//!
//! The files: `kernel` (what this kernel can enforce, probed once), `program_folders` (what a
//! command needs to read: its program, the interpreter, a virtual environment's prefix),
//! `ruleset` (the Landlock rules of one run, made before the fork), `namespaces` (the child's
//! own namespaces), `pid_namespace` (the two forks that make the program the second process of
//! its PID namespace), `denial` (spotting a program the sandbox stopped, from its stderr).

mod denial;
mod kernel;
mod namespaces;
mod pid_namespace;
mod program_folders;
mod ruleset;

use std::ffi::OsStr;
use std::io;
use std::os::fd::{AsRawFd, OwnedFd, RawFd};
use std::path::{Path, PathBuf};

use crate::resource_limits::lower;

pub use kernel::{Protection, Protections};
pub use program_folders::{
    SYSTEM_DEVICES, SYSTEM_FILES, SYSTEM_FOLDERS, command_folders, find_program,
};

/// How a run is confined, beyond its limits.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Sandbox {
    /// Not at all: the program can do anything the user can (`grade --unsandboxed`).
    Off,
    /// Landlock, and a user, network and PID namespace where the kernel allows them. The
    /// program reads and executes the system's folders ([`SYSTEM_FOLDERS`]), the folders its
    /// command names ([`command_folders`]) and `readable`; it reads and writes only its run's
    /// directory.
    On { readable: Vec<PathBuf> },
}

/// One run's sandbox, made before the fork: what the child applies to itself, and what the
/// program was allowed (to tell a denial from another error).
pub(crate) struct Prepared {
    ruleset: Option<OwnedFd>,
    namespaces: bool,
    process_limit: Option<u64>,
    counted_as_nobody: bool,
    allowed: Vec<PathBuf>,
    dir: PathBuf,
}

/// What the child needs between fork and exec: plain values only (it must not allocate).
#[derive(Clone, Copy)]
pub(crate) struct InChild {
    ruleset: Option<RawFd>,
    namespaces: bool,
    /// `RLIMIT_NPROC` for the run's user namespace, where the kernel counts per namespace.
    process_limit: Option<u64>,
    /// Whether the grader is root, whom the kernel never holds to `RLIMIT_NPROC`: the run's
    /// processes are then counted as "nobody"'s (their real uid), still acting as root's.
    counted_as_nobody: bool,
}

impl Prepared {
    /// The sandbox of `words` (the program already resolved to its path) run in `dir`, with at
    /// most `processes` at once. An error when the sandbox is on but the kernel cannot
    /// enforce it.
    pub(crate) fn new(
        sandbox: &Sandbox,
        words: &[String],
        dir: &Path,
        path_var: &OsStr,
        processes: u32,
    ) -> io::Result<Self> {
        let Sandbox::On { readable } = sandbox else {
            return Ok(Self {
                ruleset: None,
                namespaces: false,
                process_limit: None,
                counted_as_nobody: false,
                allowed: Vec::new(),
                dir: dir.to_path_buf(),
            });
        };
        let protections = Protections::current();
        if let Some(why) = protections.unavailable() {
            return Err(io::Error::other(format!("no sandbox: {why}")));
        }
        let mut read = command_folders(words, path_var);
        read.extend(readable.iter().cloned());
        let ruleset = ruleset::make(&read, dir)?;
        let mut allowed = read;
        allowed.push(dir.to_path_buf());
        // The relay and the init above the program count in its namespace too, and so does a
        // process until it is reaped; a few more, so that a bomb held by the kernel is always
        // seen past the limit by the watcher (`supervise`).
        let process_limit = protections
            .process_count_per_namespace()
            .then_some(u64::from(processes) + 8);
        // SAFETY: getuid has no preconditions.
        let root = unsafe { libc::getuid() } == 0;
        Ok(Self {
            ruleset: Some(ruleset),
            namespaces: protections.namespaces.is_ok(),
            process_limit,
            counted_as_nobody: root && process_limit.is_some(),
            allowed,
            dir: dir.to_path_buf(),
        })
    }

    pub(crate) fn in_child(&self) -> InChild {
        InChild {
            ruleset: self.ruleset.as_ref().map(AsRawFd::as_raw_fd),
            namespaces: self.namespaces,
            process_limit: self.process_limit,
            counted_as_nobody: self.counted_as_nobody,
        }
    }

    /// The processes the sandbox puts above the program, which the run counts too: the relay
    /// and the init of its PID namespace.
    pub(crate) fn waiting_processes(&self) -> usize {
        if self.namespaces { 2 } else { 0 }
    }

    /// What the sandbox denied the program, as its stderr shows it; none when it was off.
    pub(crate) fn denial(&self, stderr: &[u8]) -> Option<String> {
        self.ruleset.as_ref()?;
        denial::spot(stderr, &self.allowed, &self.dir)
    }
}

/// The overflow user, "nobody".
const NOBODY: libc::uid_t = 65534;

/// Makes "nobody" the real user of this process and all it starts, keeping root as the
/// effective and saved one: files are still opened as root's (the run's directory, the
/// submission's folder), but the kernel counts the processes against nobody's `RLIMIT_NPROC`,
/// from which only root is exempt. (It also makes the exec a secure one: the C library then
/// ignores `LD_PRELOAD`-like variables, none of which a run's environment holds.) The raw
/// system call: the C library's wrapper would signal threads the child does not have.
fn count_as_nobody() -> io::Result<()> {
    let unchanged = libc::uid_t::MAX;
    // SAFETY: setresuid takes three integers and touches no memory of ours.
    if unsafe { libc::syscall(libc::SYS_setresuid, NOBODY, unchanged, unchanged) } == -1 {
        return Err(io::Error::last_os_error());
    }
    Ok(())
}

/// Runs in the child between fork and exec: its own namespaces (if allowed), the process
/// limit counted in them, then the Landlock rules, which also hold for everything it starts.
/// Only system calls.
pub(crate) fn enter(child: InChild) -> io::Result<()> {
    if child.counted_as_nobody {
        count_as_nobody()?;
    }
    if child.namespaces {
        namespaces::enter()?;
    }
    // Only once in its own user namespace: before, the limit would count every process of
    // the user's, the teacher's desktop included.
    if let Some(limit) = child.process_limit {
        lower(libc::RLIMIT_NPROC, limit, limit)?;
    }
    if let Some(fd) = child.ruleset {
        ruleset::restrict_self(fd)?;
    }
    Ok(())
}

//! The sandbox each program runs in, so that a hostile program cannot read or change what is
//! not its own, reach the network or disturb the grader and the other runs. It is Landlock (a
//! Linux security module any process may apply to itself and its children, no root needed),
//! applied in the child between fork and exec, and where unprivileged namespaces are allowed, a
//! user and network namespace of the program's own.
//!
//! The files: `kernel` (what this kernel can enforce, probed once), `program_folders` (what a
//! command needs to read: its program, the interpreter, a virtual environment's prefix),
//! `ruleset` (the Landlock rules of one run, made before the fork), `namespaces` (the child's
//! own network namespace), `denial` (spotting a program the sandbox stopped, from its stderr).

mod denial;
mod kernel;
mod namespaces;
mod program_folders;
mod ruleset;

use std::ffi::OsStr;
use std::io;
use std::os::fd::{AsRawFd, OwnedFd, RawFd};
use std::path::{Path, PathBuf};

pub use kernel::{Protection, Protections};
pub use program_folders::{
    SYSTEM_DEVICES, SYSTEM_FILES, SYSTEM_FOLDERS, command_folders, find_program,
};

/// How a run is confined, beyond its limits.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Sandbox {
    /// Not at all: the program can do anything the user can (`grade --unsandboxed`).
    Off,
    /// Landlock, and a network namespace where the kernel allows one. The program reads and
    /// executes the system's folders ([`SYSTEM_FOLDERS`]), the folders its command names
    /// ([`command_folders`]) and `readable`; it reads and writes only its run's directory.
    On { readable: Vec<PathBuf> },
}

/// One run's sandbox, made before the fork: what the child applies to itself, and what the
/// program was allowed (to tell a denial from another error).
pub(crate) struct Prepared {
    ruleset: Option<OwnedFd>,
    namespaces: bool,
    allowed: Vec<PathBuf>,
    dir: PathBuf,
}

/// What the child needs between fork and exec: plain values only (it must not allocate).
#[derive(Clone, Copy)]
pub(crate) struct InChild {
    ruleset: Option<RawFd>,
    namespaces: bool,
}

impl Prepared {
    /// The sandbox of `words` (the program already resolved to its path) run in `dir`. An
    /// error when the sandbox is on but the kernel cannot enforce it.
    pub(crate) fn new(
        sandbox: &Sandbox,
        words: &[String],
        dir: &Path,
        path_var: &OsStr,
    ) -> io::Result<Self> {
        let Sandbox::On { readable } = sandbox else {
            return Ok(Self {
                ruleset: None,
                namespaces: false,
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
        Ok(Self {
            ruleset: Some(ruleset),
            namespaces: protections.namespaces.is_ok(),
            allowed,
            dir: dir.to_path_buf(),
        })
    }

    pub(crate) fn in_child(&self) -> InChild {
        InChild {
            ruleset: self.ruleset.as_ref().map(AsRawFd::as_raw_fd),
            namespaces: self.namespaces,
        }
    }

    /// What the sandbox denied the program, as its stderr shows it; none when it was off.
    pub(crate) fn denial(&self, stderr: &[u8]) -> Option<String> {
        self.ruleset.as_ref()?;
        denial::spot(stderr, &self.allowed, &self.dir)
    }
}

/// Runs in the child between fork and exec: its own user and network namespace (if allowed),
/// then the Landlock rules, which also hold for everything it starts. Only system calls.
pub(crate) fn enter(child: InChild) -> io::Result<()> {
    if child.namespaces {
        namespaces::unshare_network()?;
    }
    if let Some(fd) = child.ruleset {
        ruleset::restrict_self(fd)?;
    }
    Ok(())
}

//! What a program may use. The defaults suit a student's geometry pipeline run on one scene: it
//! should take well under a second, a few hundred megabytes and write one trace file.

use std::io;
use std::time::Duration;

/// The limits of one [`run`](crate::run()).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Limits {
    /// Wall-clock time before the program and everything it started are killed (default 10 s).
    /// Its CPU time is limited to this plus one second too (`RLIMIT_CPU`), a backstop that
    /// works even if the grader itself is killed; a program busy on two cores meets it first.
    pub time: Duration,
    /// Address space of each process (`RLIMIT_AS`, default 2 GiB): an allocation beyond it
    /// fails inside the program instead of swapping the machine.
    pub address_space: u64,
    /// Size of any one file the program writes (`RLIMIT_FSIZE`, default 64 MiB): writing past it
    /// kills the program with `SIGXFSZ`.
    pub file_size: u64,
    /// What the whole run directory may hold (default 256 MiB), checked while it runs: a
    /// program writing many files is stopped with [`Ending::TooMuchDisk`](crate::Ending).
    pub disk: u64,
    /// Bytes kept of each of stdout and stderr: the last ones (default 64 KiB).
    pub output: usize,
    /// Processes the run may have at once, the program's own included (default 256): one
    /// more, and the whole run is killed with [`Ending::TooManyProcesses`](crate::Ending).
    /// In a PID namespace of its own on Linux 5.14 or later the kernel enforces it too
    /// (`RLIMIT_NPROC`, counted in the run's user namespace), so a fork bomb's forks fail.
    pub processes: u32,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            time: Duration::from_secs(10),
            address_space: 2 << 30,
            file_size: 64 << 20,
            disk: 256 << 20,
            output: 64 << 10,
            processes: 256,
        }
    }
}

/// Lowers a resource limit to `soft`/`hard`, never above the current hard limit (raising it
/// needs privileges the grader may not have). Between fork and exec: only system calls.
pub(crate) fn lower(resource: libc::__rlimit_resource_t, soft: u64, hard: u64) -> io::Result<()> {
    let mut current = libc::rlimit {
        rlim_cur: 0,
        rlim_max: 0,
    };
    // SAFETY: `current` is a live local rlimit the kernel fills in.
    if unsafe { libc::getrlimit(resource, &mut current) } == -1 {
        return Err(io::Error::last_os_error());
    }
    let wanted = libc::rlimit {
        rlim_cur: soft.min(current.rlim_max),
        rlim_max: hard.min(current.rlim_max),
    };
    // SAFETY: `wanted` is a live local rlimit the kernel only reads.
    if unsafe { libc::setrlimit(resource, &wanted) } == -1 {
        return Err(io::Error::last_os_error());
    }
    Ok(())
}

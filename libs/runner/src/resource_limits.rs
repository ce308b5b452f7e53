//! What a program may use. The defaults suit a student's geometry pipeline run on one scene: it
//! should take well under a second, a few hundred megabytes and write one trace file.

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
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            time: Duration::from_secs(10),
            address_space: 2 << 30,
            file_size: 64 << 20,
            disk: 256 << 20,
            output: 64 << 10,
        }
    }
}

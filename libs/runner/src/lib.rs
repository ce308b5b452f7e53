//! Runs a program the user did not write (a student's pipeline, for `close2gl grade`) under
//! limits, and leaves nothing behind. The command line is split into words as a POSIX shell would
//! ([`split_words`]) but never run through a shell; [`substitute`] fills in `{scene}`-style
//! placeholders. Each run happens in a fresh [`Workspace`] (a temporary directory, removed on
//! drop and after an interrupt) with a wall-clock time limit, an address-space limit, a per-file
//! size limit, a limit on what the whole directory holds, a limit on its processes at once,
//! stdin closed, only the last bytes of stdout and stderr kept, and an environment of `PATH`,
//! `HOME` and `LANG` only. What it wrote is read back only as its own ([`Workspace::read_own`]:
//! never through a link, a FIFO or a device it made). When [`run()`]
//! returns, the program and every process it started are gone (including those that left its
//! session), and its [`Outcome`] says how it ended in words a report can show. Ctrl+C
//! ([`install_interrupt_handler`]) stops every running program and lets the caller clean up.
//!
//! Each run is also **sandboxed** ([`Sandbox::On`], `sandbox/`): Landlock rules applied in the
//! child between fork and exec let the program and everything it starts read and execute only
//! the system's folders, the folders its command names (its program, a script's interpreter and
//! prefix, a virtual environment's base Python) and those the caller adds; read and write only
//! its directory; make no TCP connection; signal nothing and reach no abstract socket outside its
//! run; and, where the kernel allows unprivileged namespaces, it gets a user, network and PID
//! namespace of its own (no network at all; nothing it starts outlives it). [`Protections`] says what this kernel enforces; a run's
//! [`Outcome`] says what the sandbox denied it, as its stderr shows. It does not hide
//! world-readable system files, nor time as a side channel. Linux only.
//!
//! The files follow one run: `words` (the command line) → `workspace` (the directory, with
//! `disk` measuring it and `own_file` reading what the program wrote, both through `beneath`,
//! which follows no link) → `spawn` (the child's limits, session and environment, set between fork
//! and exec) → `run` (watching it: exit, time, disk, processes, interrupt, with `output` keeping the tails)
//! → `reap` (killing the program's whole tree, found through `proc_table`) → `outcome` (how it
//! ended, with `signals`' names). `interrupt` is the Ctrl+C flag every run watches; `sandbox`
//! makes each run's rules before the fork, and the child applies them.

#![cfg(target_os = "linux")]

mod beneath;
mod command_words;
mod disk;
mod interrupt;
mod outcome;
mod output_tail;
mod own_file;
mod proc_table;
mod reap;
mod resource_limits;
mod sandbox;
mod signals;
mod spawn;
mod supervise;
mod workspace;

pub use command_words::{split_words, substitute};
pub use interrupt::{install_interrupt_handler, interrupted, request_interrupt};
pub use outcome::{Ending, Outcome};
pub use own_file::NotItsOwn;
pub use reap::reap_everything;
pub use resource_limits::Limits;
pub use sandbox::{
    Protection, Protections, SYSTEM_DEVICES, SYSTEM_FILES, SYSTEM_FOLDERS, Sandbox, command_folders,
};
pub use supervise::run;
pub use workspace::Workspace;

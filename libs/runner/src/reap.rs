//! Killing a program and everything it started, so that nothing is left running when `grade`
//! returns. Killing its process group is not enough: a child that calls `setsid` leaves it. So:
//!
//! - Every program starts a session of its own (`setsid`, in `spawn`), and the grader is a
//!   *child subreaper*: an orphan of a program (a process whose parent died) is re-parented to
//!   the grader instead of init. The grader's children outside its own session are therefore
//!   programs (registered here while they run) or their orphans; children the grader starts by
//!   other means (a compiler, say) share its session and are never touched.
//! - To kill a program that is still running, its descendants are found by their parent pids
//!   in `/proc` and killed along with its process group, round after round until none is left
//!   (one may fork between the reading and the killing; its child is then an orphan of ours).
//! - Once a program has ended, its orphans and their descendants are killed and reaped (each
//!   by its own pid: `waitpid(-1)` would steal the status of a child another thread waits for).
//!
//! An orphan is the ending program's when it is still in the program's session; one that
//! called `setsid` cannot be told apart, so it is taken by whichever run ends first. The
//! trade-off: with parallel jobs, a program's `setsid` orphan may be killed before its own run
//! ends. Only programs that mean to escape do that; they lose their escapee either way.
//!
//! Pids are read from `/proc` and then signalled, so a process that died in between and whose
//! pid was reused at once could be signalled by mistake; the grader's own children (programs and
//! orphans) keep their pids until reaped, so only deeper descendants carry that (tiny) risk.

use std::io;
use std::process::{Child, Command};
use std::sync::{Mutex, MutexGuard, Once, PoisonError};
use std::time::{Duration, Instant};

use crate::proc_table::ProcTable;
use crate::workspace::remove_live_workspaces;

/// How long a sweep keeps killing before it gives up on a process that does not die (one stuck
/// in the kernel, say): grading goes on rather than hang.
const SWEEP_PATIENCE: Duration = Duration::from_secs(10);

/// The programs now running, by the id of their run; every sweep happens under this lock, and
/// so does every spawn, so that no sweep sees a program before it is registered.
static RUNNING: Mutex<Running> = Mutex::new(Running {
    programs: Vec::new(),
    next_id: 0,
});

struct Running {
    programs: Vec<(u64, i32)>,
    next_id: u64,
}

impl Running {
    fn pids(&self) -> Vec<i32> {
        self.programs.iter().map(|(_, pid)| *pid).collect()
    }
}

fn running() -> MutexGuard<'static, Running> {
    // The list stays consistent through a panic (push and retain only): keep using it.
    RUNNING.lock().unwrap_or_else(PoisonError::into_inner)
}

/// A running program, registered so that sweeps leave it (and, while it runs, the orphans in
/// its session) alone. Dropping it, once the program has been reaped, kills and reaps the
/// orphans it left.
pub(crate) struct Registration {
    id: u64,
    pid: i32,
}

/// Starts `command` (whose pre-exec hook must call `setsid`) and registers it.
pub(crate) fn spawn(command: &mut Command) -> io::Result<(Child, Registration)> {
    become_subreaper();
    let mut running = running();
    let child = command.spawn()?;
    let pid = i32::try_from(child.id()).map_err(io::Error::other)?;
    let id = running.next_id;
    running.next_id += 1;
    running.programs.push((id, pid));
    Ok((child, Registration { id, pid }))
}

/// Makes orphans of the whole process come to the grader instead of init; once per process.
fn become_subreaper() {
    static ONCE: Once = Once::new();
    // SAFETY: PR_SET_CHILD_SUBREAPER takes an integer flag and touches no memory of ours.
    ONCE.call_once(|| unsafe {
        libc::prctl(libc::PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0);
    });
}

impl Registration {
    /// The program's pid (with a PID namespace, the relay's: the process the grader started).
    pub(crate) fn pid(&self) -> i32 {
        self.pid
    }

    /// Kills the still running program, its process group and all its descendants, and the
    /// orphans of its session. The program itself is left to be reaped by its `Child`.
    pub(crate) fn kill_tree(&self) {
        let running = running();
        sweep(&running, Some(self.pid), Orphans::OfSession(self.pid));
    }
}

impl Drop for Registration {
    fn drop(&mut self) {
        let mut running = running();
        running.programs.retain(|(id, _)| *id != self.id);
        sweep(&running, None, Orphans::OfSession(self.pid));
    }
}

/// Kills and reaps every process left by the programs (every descendant of the grader outside
/// its session, except programs still running), and removes every workspace not yet dropped.
/// Call it when grading is over, also after an interrupt, and then exit.
pub fn reap_everything() {
    let running = running();
    sweep(&running, None, Orphans::All);
    drop(running);
    remove_live_workspaces();
}

/// Which of the grader's orphans a sweep takes.
#[derive(Clone, Copy)]
enum Orphans {
    /// Those in this program's session, and those in no running program's session.
    OfSession(i32),
    All,
}

/// Kills `root`'s tree if given, and the chosen orphans with theirs; reaps the orphans; again
/// until nothing chosen is alive or unreaped (or [`SWEEP_PATIENCE`] runs out).
fn sweep(running: &Running, root: Option<i32>, orphans: Orphans) {
    let running = running.pids();
    // SAFETY: getpid and getsid(0) have no preconditions.
    let (me, my_session) = unsafe { (libc::getpid(), libc::getsid(0)) };
    let chosen = |session: i32| match orphans {
        Orphans::OfSession(own) => session == own || !running.contains(&session),
        Orphans::All => true,
    };
    let started = Instant::now();
    let mut pause = Duration::from_millis(1);
    while started.elapsed() < SWEEP_PATIENCE {
        let table = ProcTable::read();
        let mut left = 0;
        if let Some(root) = root {
            kill(-root);
            let root_alive = table
                .children_of(me)
                .iter()
                .any(|p| p.pid == root && !p.zombie);
            left += usize::from(root_alive) + kill_all(table.descendants(root));
            kill(root);
        }
        let taken = table
            .children_of(me)
            .iter()
            .filter(|p| p.session != my_session && !running.contains(&p.pid) && chosen(p.session));
        for orphan in taken {
            left += kill_all(vec![*orphan]) + kill_all(table.descendants(orphan.pid));
            left += usize::from(!reap(orphan.pid));
        }
        if left == 0 {
            return;
        }
        std::thread::sleep(pause);
        pause = (pause * 2).min(Duration::from_millis(20));
    }
}

/// Sends SIGKILL to each living process of `processes`; returns how many were alive.
fn kill_all(processes: Vec<crate::proc_table::Process>) -> usize {
    let alive: Vec<_> = processes.into_iter().filter(|p| !p.zombie).collect();
    for process in &alive {
        kill(process.pid);
    }
    alive.len()
}

/// SIGKILL to a pid, or to a process group when negative.
fn kill(pid: i32) {
    // SAFETY: kill only sends a signal; a pid that no longer exists gives ESRCH, ignored.
    unsafe { libc::kill(pid, libc::SIGKILL) };
}

/// Reaps our child `pid` if it has ended; true when it is gone (reaped now or before).
fn reap(pid: i32) -> bool {
    let mut status = 0;
    // SAFETY: `status` is a live local; WNOHANG makes the call return at once. `pid` is a child
    // of ours that no `Child` owns (registered programs are never passed here).
    let result = unsafe { libc::waitpid(pid, &mut status, libc::WNOHANG) };
    result != 0
}

//! The run's own PID namespace, so that no process of a run outlives it: when a namespace's
//! first process (its init) ends, the kernel kills every process left in it, however it hid
//! (a daemon, a `setsid` escapee, a fork bomb's thousands).
//!
//! `unshare(CLONE_NEWPID)` moves only the caller's *children* into the new namespace, and the
//! first of them becomes its init. The program should not be that init: an init ignores every
//! signal it has no handler for, its own `abort()` and `SIGXFSZ` among them. So the child forks
//! twice. The first fork is the namespace's init: it forks the program (the namespace's second
//! process) and waits for it. The caller (the process the grader started and watches) waits for
//! the init and then ends as the program ended, with its exit status or by its signal, so that
//! the grader reads the program's own ending. Only system calls, between fork and exec.

use std::io;

/// The file descriptor each waiting process keeps: the pipe that carries the program's status.
const STATUS_FD: libc::c_int = 3;

/// In the child, right after `unshare(CLONE_NEWPID)`: returns only in the program's process
/// (then exec follows); the two processes above it wait, and never return.
pub(super) fn fork_program() -> io::Result<()> {
    let mut pipe = [0; 2];
    // SAFETY: pipe2 writes two descriptors into the live local array.
    if unsafe { libc::pipe2(pipe.as_mut_ptr(), libc::O_CLOEXEC) } == -1 {
        return Err(io::Error::last_os_error());
    }
    let [status_in, status_out] = pipe;
    // SAFETY: fork in the single-threaded child; each side closes the other's end of the pipe.
    match unsafe { libc::fork() } {
        -1 => Err(io::Error::last_os_error()),
        0 => {
            // SAFETY: closes our own end of the pipe.
            unsafe { libc::close(status_in) };
            init(status_out)
        }
        init => {
            // SAFETY: closes our own end of the pipe.
            unsafe { libc::close(status_out) };
            relay(init, status_in)
        }
    }
}

/// The namespace's init: it forks the program, waits for it and writes its status to the
/// pipe. It dies with the relay above it, and the kernel then kills the whole namespace.
fn init(status_out: libc::c_int) -> io::Result<()> {
    die_with_parent()?;
    // SAFETY: fork in a single-threaded process.
    match unsafe { libc::fork() } {
        -1 => Err(io::Error::last_os_error()),
        0 => {
            // SAFETY: the program has no use for the pipe.
            unsafe { libc::close(status_out) };
            die_with_parent()
        }
        program => {
            keep_only(status_out);
            let status = wait_for(program);
            // SAFETY: writes four bytes from a live local; _exit ends the process at once.
            unsafe {
                libc::write(STATUS_FD, (&raw const status).cast(), 4);
                libc::_exit(0)
            }
        }
    }
}

/// The process the grader started: it ends as the program did (the init's own ending when the
/// init was killed before it could tell).
fn relay(init: libc::pid_t, status_in: libc::c_int) -> ! {
    keep_only(status_in);
    let init_status = wait_for(init);
    let mut status: libc::c_int = 0;
    // SAFETY: reads at most four bytes into a live local.
    let read = unsafe { libc::read(STATUS_FD, (&raw mut status).cast(), 4) };
    end_as(if read == 4 { status } else { init_status })
}

/// Keeps `fd` (as [`STATUS_FD`]) and standard input, output and error; closes every other
/// descriptor, among them the one the standard library watches to learn that exec happened:
/// the waiting processes never exec, and must not hold it open.
fn keep_only(fd: libc::c_int) {
    // SAFETY: dup2 and close only change this process's descriptor table.
    unsafe {
        if fd != STATUS_FD {
            libc::dup2(fd, STATUS_FD);
        }
        let first = (STATUS_FD + 1) as libc::c_uint;
        if libc::syscall(libc::SYS_close_range, first, libc::c_uint::MAX, 0) == -1 {
            // Before Linux 5.9: the descriptors a child of the grader holds are few and low.
            for fd in first..1024 {
                libc::close(fd as libc::c_int);
            }
        }
    }
}

/// Waits for our child `pid`; its wait status.
fn wait_for(pid: libc::pid_t) -> libc::c_int {
    let mut status = 0;
    // SAFETY: `status` is a live local the kernel fills in.
    while unsafe { libc::waitpid(pid, &mut status, 0) } == -1 {
        if io::Error::last_os_error().raw_os_error() != Some(libc::EINTR) {
            // W_EXITCODE(127, 0): as a shell reports a program it could not run.
            return 127 << 8;
        }
    }
    status
}

/// Ends this process as `status` says: by the same signal (its default action, unblocked),
/// or with the same exit status.
fn end_as(status: libc::c_int) -> ! {
    // SAFETY: signal, sigprocmask, kill and _exit are async-signal-safe system calls on plain
    // values and live locals.
    unsafe {
        if libc::WIFSIGNALED(status) {
            let signal = libc::WTERMSIG(status);
            libc::signal(signal, libc::SIG_DFL);
            let mut set: libc::sigset_t = std::mem::zeroed();
            libc::sigemptyset(&mut set);
            libc::sigaddset(&mut set, signal);
            libc::sigprocmask(libc::SIG_UNBLOCK, &set, std::ptr::null_mut());
            libc::kill(libc::getpid(), signal);
            libc::_exit(128 + signal)
        }
        libc::_exit(libc::WEXITSTATUS(status))
    }
}

/// SIGKILL when the parent ends, so that killing the process the grader started kills the
/// init, and killing the init kills the namespace.
fn die_with_parent() -> io::Result<()> {
    // SAFETY: prctl takes integers and touches no memory of ours.
    if unsafe { libc::prctl(libc::PR_SET_PDEATHSIG, libc::SIGKILL, 0, 0, 0) } == -1 {
        return Err(io::Error::last_os_error());
    }
    Ok(())
}

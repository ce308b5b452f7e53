//! Namespaces of the program's own: a user namespace (which lets an unprivileged process make
//! the others), a network namespace whose only device is a loopback that is down, so nothing
//! leaves it (UDP and DNS included, which Landlock does not cover), and a PID namespace, so
//! that every process the run starts ends with it (`pid_namespace`). Made with `unshare` in the
//! child; no uid map is written, so the program runs as the overflow user ("nobody") inside,
//! holding no capability once it executes, while the kernel still checks its file accesses as
//! the user's.

use std::io;

use super::pid_namespace;

const FLAGS: libc::c_int = libc::CLONE_NEWUSER | libc::CLONE_NEWNET | libc::CLONE_NEWPID;

/// In the child, between fork and exec: only system calls. Returns in the program's process,
/// the second of its PID namespace.
pub(super) fn enter() -> io::Result<()> {
    // SAFETY: unshare takes flags and touches no memory of ours.
    if unsafe { libc::unshare(FLAGS) } == -1 {
        return Err(io::Error::last_os_error());
    }
    pid_namespace::fork_program()
}

/// Whether an unprivileged `unshare` works here (distributions may forbid it): tried in a
/// forked child, which exits at once.
pub(super) fn probe() -> Result<(), String> {
    // SAFETY: the child makes only async-signal-safe system calls (unshare, _exit); the parent
    // waits for it with a live local status.
    let status = unsafe {
        match libc::fork() {
            -1 => return Err(format!("cannot fork: {}", io::Error::last_os_error())),
            0 => libc::_exit(if libc::unshare(FLAGS) == 0 { 0 } else { 1 }),
            child => {
                let mut status = 0;
                while libc::waitpid(child, &mut status, 0) == -1 {
                    if io::Error::last_os_error().kind() != io::ErrorKind::Interrupted {
                        return Err("cannot wait for the probe".into());
                    }
                }
                status
            }
        }
    };
    match libc::WIFEXITED(status) && libc::WEXITSTATUS(status) == 0 {
        true => Ok(()),
        false => Err("this system does not let unprivileged users make them".into()),
    }
}

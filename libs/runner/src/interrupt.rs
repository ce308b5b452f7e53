//! Ctrl+C while grading. A signal handler may do almost nothing safely, so it only sets a flag;
//! every [`run`](crate::run()) polls the flag, kills its program's tree and returns
//! [`Ending::Interrupted`](crate::Ending), and the caller then drops its workspaces, calls
//! [`reap_everything`](crate::reap_everything) and exits with status 130.

use std::sync::atomic::{AtomicBool, Ordering};

static INTERRUPTED: AtomicBool = AtomicBool::new(false);

/// The signals that mean "stop grading": Ctrl+C, `kill`, and the terminal closing.
const STOP_SIGNALS: [libc::c_int; 3] = [libc::SIGINT, libc::SIGTERM, libc::SIGHUP];

/// Catches SIGINT, SIGTERM and SIGHUP: the first one sets the flag [`interrupted`] reads. The
/// handler then resets itself, so a second Ctrl+C kills the grader at once (for a grader that
/// does not stop); programs it was running may then be left over.
pub fn install_interrupt_handler() {
    for signal in STOP_SIGNALS {
        // SAFETY: `action` is zero-initialised (a valid `sigaction`: empty mask, no flags)
        // before its fields are set; `on_stop_signal` only stores to an atomic, which is
        // async-signal-safe; `sigaction` is given valid pointers to a live local.
        unsafe {
            let mut action: libc::sigaction = std::mem::zeroed();
            action.sa_sigaction = on_stop_signal as extern "C" fn(libc::c_int) as usize;
            action.sa_flags = libc::SA_RESTART | libc::SA_RESETHAND;
            libc::sigemptyset(&mut action.sa_mask);
            libc::sigaction(signal, &action, std::ptr::null_mut());
        }
    }
}

extern "C" fn on_stop_signal(_signal: libc::c_int) {
    INTERRUPTED.store(true, Ordering::SeqCst);
}

/// Whether grading was interrupted: a stop signal arrived or [`request_interrupt`] was called.
/// It stays set for the rest of the process: every later `run` returns `Interrupted` at once.
pub fn interrupted() -> bool {
    INTERRUPTED.load(Ordering::SeqCst)
}

/// Does what Ctrl+C does, without a signal: for a caller that stops grading early, and for
/// tests (a signal sent to a test process would reach the test harness too).
pub fn request_interrupt() {
    INTERRUPTED.store(true, Ordering::SeqCst);
}

//! One run's Landlock rules, made in the grader before the fork (opening paths allocates, the
//! child must not) and applied by the child to itself with two system calls. Every access right
//! this crate knows of is handled, so whatever a newer kernel adds is denied too; on an older
//! kernel the crate drops what it cannot enforce (best effort) and `kernel` reports it missing.

use std::io;
use std::os::fd::{OwnedFd, RawFd};
use std::path::{Path, PathBuf};

use landlock::{
    ABI, Access, AccessFs, AccessNet, Ruleset, RulesetAttr, RulesetCreatedAttr, RulesetError,
    Scope, path_beneath_rules,
};

use super::program_folders::{SYSTEM_DEVICES, SYSTEM_FILES, SYSTEM_FOLDERS};

/// The newest ABI this crate knows: what the rules ask for before the kernel's best effort.
const NEWEST: ABI = ABI::V10;

/// The rules: read and execute the system's folders and files and `read`; read and write the
/// devices everyone may (`/dev/null`, ...); everything in `dir`; no TCP; signals and abstract
/// sockets scoped to the run. Paths that do not exist are left out.
pub(super) fn make(read: &[PathBuf], dir: &Path) -> io::Result<OwnedFd> {
    match make_rules(read, dir) {
        Ok(Some(fd)) => Ok(fd),
        Ok(None) => Err(io::Error::other("the kernel made no Landlock ruleset")),
        Err(e) => Err(io::Error::other(format!("the sandbox's rules: {e}"))),
    }
}

fn make_rules(read: &[PathBuf], dir: &Path) -> Result<Option<OwnedFd>, RulesetError> {
    let read_only = AccessFs::from_read(NEWEST);
    let everything = AccessFs::from_all(NEWEST);
    let system = SYSTEM_FOLDERS.iter().chain(SYSTEM_FILES).map(Path::new);
    let devices = SYSTEM_DEVICES.iter().map(Path::new);
    let device_access = AccessFs::ReadFile | AccessFs::WriteFile;
    let created = Ruleset::default()
        .handle_access(everything)?
        .handle_access(AccessNet::from_all(NEWEST))?
        .scope(Scope::from_all(NEWEST))?
        .create()?
        .add_rules(path_beneath_rules(system, read_only))?
        .add_rules(path_beneath_rules(read, read_only))?
        .add_rules(path_beneath_rules(devices, device_access))?
        .add_rules(path_beneath_rules([dir], everything))?;
    Ok(created.into())
}

/// In the child, between fork and exec: no new privileges (Landlock requires it of an
/// unprivileged process, and it keeps set-uid programs from running as someone else), then
/// the ruleset. Only system calls.
pub(super) fn restrict_self(fd: RawFd) -> io::Result<()> {
    // SAFETY: prctl and landlock_restrict_self take integers and touch no memory of ours; `fd`
    // is the ruleset the parent opened, still open in the child until exec.
    unsafe {
        if libc::prctl(libc::PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == -1 {
            return Err(io::Error::last_os_error());
        }
        if libc::syscall(libc::SYS_landlock_restrict_self, fd, 0) == -1 {
            return Err(io::Error::last_os_error());
        }
    }
    Ok(())
}

//! What this kernel can enforce, probed once per process: the Landlock ABI (each version adds
//! protections), whether an unprivileged process may make a user, network and PID namespace,
//! and whether the kernel counts processes per user namespace (Linux 5.14).
//! The same words go to the start of grading and to every report.

use std::sync::OnceLock;

use super::namespaces;

/// `landlock_create_ruleset`'s flag asking for the ABI version instead of a ruleset.
const LANDLOCK_CREATE_RULESET_VERSION: libc::c_uint = 1;

/// What Landlock protects from which ABI (and Linux version) on: name, ABI, Linux, what.
const LANDLOCK_PROTECTIONS: [(&str, i32, &str, &str); 4] = [
    (
        "filesystem",
        1,
        "5.13",
        "reads only the system's folders and its program's, writes only its run's directory",
    ),
    ("network", 4, "6.7", "no TCP connect or bind"),
    (
        "signals",
        6,
        "6.12",
        "signals and abstract Unix sockets only within its own run",
    ),
    (
        "unix sockets",
        9,
        "7.1",
        "no connecting to a Unix socket by its path",
    ),
];

/// What the sandbox can do on this kernel.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Protections {
    /// The Landlock ABI version, or why there is none.
    pub landlock_abi: Result<i32, String>,
    /// Whether a run can have a user, network and PID namespace of its own, or why not.
    pub namespaces: Result<(), String>,
    /// The kernel's version, `(major, minor)`, as `uname` gives it; none when unreadable.
    pub linux: Option<(u32, u32)>,
}

/// One protection, enforced or missing, in words a report shows.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Protection {
    pub name: &'static str,
    pub enforced: bool,
    pub detail: String,
}

impl Protections {
    /// This kernel's, probed on first use.
    pub fn current() -> &'static Protections {
        static PROBED: OnceLock<Protections> = OnceLock::new();
        PROBED.get_or_init(|| Protections {
            landlock_abi: landlock_abi(),
            namespaces: namespaces::probe(),
            linux: linux_version(),
        })
    }

    /// Whether `RLIMIT_NPROC` counts a run's processes alone: in its own user namespace, from
    /// Linux 5.14 (before, it counts every process of the user's, across namespaces). The
    /// kernel exempts root from it: a grader run as root relies on the watcher alone.
    pub fn process_count_per_namespace(&self) -> bool {
        self.namespaces.is_ok() && self.linux.is_some_and(|v| v >= (5, 14))
    }

    /// Why nothing can be sandboxed here (no Landlock), in one line; none when it can.
    pub fn unavailable(&self) -> Option<String> {
        self.landlock_abi.as_ref().err().cloned()
    }

    /// Each protection, enforced or missing, in a fixed order.
    pub fn list(&self) -> Vec<Protection> {
        let abi = *self.landlock_abi.as_ref().unwrap_or(&0);
        let landlock = Protection {
            name: "landlock",
            enforced: abi > 0,
            detail: match &self.landlock_abi {
                Ok(v) => format!("ABI {v}"),
                Err(why) => why.clone(),
            },
        };
        let namespace = Protection {
            name: "namespaces",
            enforced: self.namespaces.is_ok(),
            detail: match &self.namespaces {
                Ok(()) => "a user and network namespace of its own: no network at all, \
                           UDP and DNS included"
                    .into(),
                Err(why) => format!("no network namespace ({why}): UDP and DNS are not blocked"),
            },
        };
        let processes = Protection {
            name: "processes",
            enforced: self.namespaces.is_ok(),
            detail: match (&self.namespaces, self.process_count_per_namespace()) {
                (Ok(()), true) => "a PID namespace of its own: nothing it starts outlives it; \
                                   its process count limited by the kernel"
                    .into(),
                (Ok(()), false) => "a PID namespace of its own: nothing it starts outlives it; \
                                    its process count only watched (the kernel's count per \
                                    namespace needs Linux 5.14)"
                    .into(),
                (Err(why), _) => format!(
                    "no PID namespace ({why}): what it starts is found and killed through \
                     /proc, and its process count is only watched"
                ),
            },
        };
        let mut list = vec![landlock];
        list.extend(
            LANDLOCK_PROTECTIONS
                .iter()
                .map(|&(name, version, linux, what)| Protection {
                    name,
                    enforced: abi >= version,
                    detail: match abi >= version {
                        true => what.to_string(),
                        false => format!("{what}: needs Landlock ABI {version} (Linux {linux})"),
                    },
                }),
        );
        list.push(namespace);
        list.push(processes);
        list
    }

    /// One line for the start of grading and the text report: what is enforced, what is not.
    pub fn summary(&self) -> String {
        if let Some(why) = self.unavailable() {
            return format!("sandbox: none ({why})");
        }
        let list = self.list();
        let (on, off): (Vec<_>, Vec<_>) = list[1..].iter().partition(|p| p.enforced);
        let names = |ps: &[&Protection]| ps.iter().map(|p| p.name).collect::<Vec<_>>().join(", ");
        let mut line = format!(
            "sandbox: Landlock {}; enforced: {}",
            list[0].detail,
            names(&on)
        );
        if !off.is_empty() {
            line.push_str(&format!("; missing: {}", names(&off)));
        }
        line
    }
}

/// `(major, minor)` of the running kernel's release ("6.18.44-generic" gives (6, 18)).
fn linux_version() -> Option<(u32, u32)> {
    // SAFETY: utsname is plain bytes; uname fills the live local in.
    let mut names: libc::utsname = unsafe { std::mem::zeroed() };
    if unsafe { libc::uname(&mut names) } == -1 {
        return None;
    }
    let release: Vec<u8> = names.release.iter().map(|&c| c as u8).collect();
    let release = String::from_utf8_lossy(&release);
    let mut numbers = release
        .split(|c: char| !c.is_ascii_digit())
        .map(|n| n.parse().ok());
    Some((numbers.next()??, numbers.next()??))
}

/// The kernel's Landlock ABI, or why there is none (as `landlock_create_ruleset` says).
fn landlock_abi() -> Result<i32, String> {
    // SAFETY: with a null attribute, size 0 and the VERSION flag the call only returns a
    // number; it reads and writes no memory.
    let version = unsafe {
        libc::syscall(
            libc::SYS_landlock_create_ruleset,
            std::ptr::null::<u8>(),
            0usize,
            LANDLOCK_CREATE_RULESET_VERSION,
        )
    };
    if version > 0 {
        return Ok(version as i32);
    }
    Err(match std::io::Error::last_os_error().raw_os_error() {
        Some(libc::EOPNOTSUPP) => "Landlock is built into this kernel but disabled at boot \
                                   (add landlock to the lsm= boot parameter)"
            .into(),
        _ => "this kernel has no Landlock (it needs Linux 5.13 or later built with it)".into(),
    })
}

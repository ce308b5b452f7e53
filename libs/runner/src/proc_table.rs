//! A snapshot of the machine's processes from `/proc`: who is whose parent, and in which
//! session. A process group cannot find a child that called `setsid`, its parent's pid can.

use std::collections::{HashMap, HashSet};
use std::fs;
use std::path::Path;
use std::sync::OnceLock;

/// One process, as `/proc/<pid>/stat` describes it.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Process {
    pub(crate) pid: i32,
    pub(crate) ppid: i32,
    pub(crate) session: i32,
    /// Dead but not yet reaped by its parent: it runs nothing, but holds its pid.
    pub(crate) zombie: bool,
}

/// Every process visible in `/proc` at one moment, by parent.
pub(crate) struct ProcTable {
    children: HashMap<i32, Vec<Process>>,
}

impl ProcTable {
    /// Reads `/proc`. A process that exits while it is read is simply missing.
    pub(crate) fn read() -> Self {
        let mut children: HashMap<i32, Vec<Process>> = HashMap::new();
        let entries = fs::read_dir("/proc").into_iter().flatten().flatten();
        for entry in entries {
            let Some(pid) = entry
                .file_name()
                .to_str()
                .and_then(|name| name.parse().ok())
            else {
                continue;
            };
            let stat = fs::read_to_string(entry.path().join("stat")).unwrap_or_default();
            if let Some(process) = parse_stat(pid, &stat) {
                children.entry(process.ppid).or_default().push(process);
            }
        }
        Self { children }
    }

    /// The processes whose parent is `pid`.
    pub(crate) fn children_of(&self, pid: i32) -> &[Process] {
        self.children.get(&pid).map_or(&[], Vec::as_slice)
    }

    /// Every process below `pid`, parents before their children. The files are read one after
    /// another, so with pids reused meanwhile the snapshot could hold a cycle: each pid is
    /// visited once.
    pub(crate) fn descendants(&self, pid: i32) -> Vec<Process> {
        let mut seen = HashSet::from([pid]);
        let mut below: Vec<Process> = Vec::new();
        let mut parent = pid;
        let mut next = 0;
        loop {
            let new = self
                .children_of(parent)
                .iter()
                .filter(|p| seen.insert(p.pid));
            below.extend(new);
            let Some(process) = below.get(next) else {
                break;
            };
            parent = process.pid;
            next += 1;
        }
        below
    }
}

/// How many processes `pid`'s tree holds (itself included), counted up to `enough` and a
/// little past: each process's children as its threads list them (`/proc/PID/task/TID/children`),
/// so that only the tree is read, not every process of the machine. A kernel built without
/// those files is read whole instead.
pub(crate) fn tree_size(pid: i32, enough: usize) -> usize {
    // Looked up once: the watcher asks every tick.
    static HAS_CHILDREN_FILES: OnceLock<bool> = OnceLock::new();
    let has_children_files = HAS_CHILDREN_FILES.get_or_init(|| {
        let me = std::process::id().to_string();
        Path::new("/proc/self/task")
            .join(me)
            .join("children")
            .exists()
    });
    if !has_children_files {
        return 1 + ProcTable::read().descendants(pid).len();
    }
    let mut count = 0;
    let mut pending = vec![pid];
    while let Some(pid) = pending.pop() {
        count += 1;
        if count > enough {
            break;
        }
        let tasks = fs::read_dir(format!("/proc/{pid}/task"))
            .into_iter()
            .flatten();
        for task in tasks.flatten() {
            let children = fs::read_to_string(task.path().join("children")).unwrap_or_default();
            pending.extend(
                children
                    .split_whitespace()
                    .filter_map(|c| c.parse::<i32>().ok()),
            );
        }
    }
    count
}

/// `pid (comm) state ppid pgrp session ...`: the command name may hold spaces and parentheses,
/// so the fields are read after its last `)`.
fn parse_stat(pid: i32, stat: &str) -> Option<Process> {
    let after_name = &stat[stat.rfind(')')? + 1..];
    let mut fields = after_name.split_whitespace();
    let state = fields.next()?;
    let ppid = fields.next()?.parse().ok()?;
    let _pgrp = fields.next()?;
    let session = fields.next()?.parse().ok()?;
    Some(Process {
        pid,
        ppid,
        session,
        zombie: state == "Z",
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_command_name_with_spaces_and_parentheses_is_skipped() {
        let stat = "4242 (evil) Z 7 (x) R 1 99 4242 0 -1";
        let process = parse_stat(4242, stat);
        assert!(process.is_some_and(|p| p.ppid == 1 && p.session == 4242 && !p.zombie));
        let zombie = parse_stat(5, "5 (a b) Z 3 5 6 0");
        assert!(zombie.is_some_and(|p| p.ppid == 3 && p.session == 6 && p.zombie));
    }

    #[test]
    fn a_cycle_from_reused_pids_is_walked_once() {
        let process = |pid, ppid| Process {
            pid,
            ppid,
            session: 1,
            zombie: false,
        };
        let table = ProcTable {
            children: HashMap::from([
                (1, vec![process(2, 1)]),
                (2, vec![process(3, 2)]),
                (3, vec![process(2, 3), process(4, 3)]),
            ]),
        };
        let below: Vec<i32> = table.descendants(1).iter().map(|p| p.pid).collect();
        assert_eq!(below, [2, 3, 4]);
    }

    #[test]
    fn a_tree_counts_its_children() {
        let mut children: Vec<_> = (0..3)
            .map(|_| {
                std::process::Command::new("sleep")
                    .arg("5")
                    .spawn()
                    .expect("sleep")
            })
            .collect();
        let me = std::process::id() as i32;
        let counted = tree_size(me, 100);
        for child in &mut children {
            let _ = child.kill();
            let _ = child.wait();
        }
        assert!(counted >= 4, "{counted}");
    }

    #[test]
    fn this_process_is_in_the_table_under_its_parent() {
        let me = std::process::id() as i32;
        // SAFETY: getppid has no preconditions.
        let parent = unsafe { libc::getppid() };
        let table = ProcTable::read();
        assert!(table.children_of(parent).iter().any(|p| p.pid == me));
    }
}

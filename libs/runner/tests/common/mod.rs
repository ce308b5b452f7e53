//! Hostile programs, written in C and compiled with the system's `cc` on first use (CI installs
//! it; without it these tests fail, they never skip), and what the tests check after a run.

#![allow(dead_code)] // each test binary uses some of the helpers

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Mutex;
use std::time::{Duration, Instant};

use close2gl_runner::{Ending, Limits, Outcome, Sandbox, Workspace, run};

/// Helpers every program may use: `write_pid` (atomically, so a reader never sees half a
/// number) and `wait_for` (a file another process writes).
const PRELUDE: &str = r#"
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <sys/stat.h>
static void write_pid(const char *name) {
    char tmp[256];
    snprintf(tmp, sizeof tmp, "%s.tmp", name);
    FILE *f = fopen(tmp, "w");
    if (!f) _exit(90);
    fprintf(f, "%d\n", (int)getpid());
    fclose(f);
    rename(tmp, name);
}
static void wait_for(const char *name) {
    struct stat st;
    while (stat(name, &st) != 0) usleep(1000);
}
static void sleep_forever(void) { for (;;) pause(); }
"#;

/// The hostile programs, by name.
const PROGRAMS: &[(&str, &str)] = &[
    (
        "sleep_forever",
        r#"int main(void) { write_pid("pid"); sleep_forever(); }"#,
    ),
    (
        "spin",
        r#"int main(void) { write_pid("pid"); for (;;) {} }"#,
    ),
    ("abort", r#"int main(void) { abort(); }"#),
    (
        "segfault",
        r#"int main(void) { *(volatile int *)0 = 1; return 0; }"#,
    ),
    (
        "exit3",
        r#"int main(void) {
            for (int i = 1; i <= 8; i++) fprintf(stderr, "line %d\n", i);
            puts("to stdout");
            return 3;
        }"#,
    ),
    (
        "flood_stdout",
        r#"int main(void) {
            for (int i = 0; i < 655360; i++) printf("%015d\n", i);
            return 0;
        }"#,
    ),
    (
        "endless_file",
        r#"int main(void) {
            static char block[1 << 16];
            FILE *f = fopen("big", "w");
            for (;;) fwrite(block, 1, sizeof block, f);
        }"#,
    ),
    (
        "many_files",
        r#"int main(void) {
            static char block[1 << 20];
            memset(block, 'x', sizeof block);
            for (int i = 0;; i++) {
                char name[32];
                snprintf(name, sizeof name, "f%d", i);
                FILE *f = fopen(name, "w");
                fwrite(block, 1, sizeof block, f);
                fclose(f);
            }
        }"#,
    ),
    (
        "allocate",
        r#"int main(void) {
            for (int mib = 0;; mib++) {
                char *p = malloc(1 << 20);
                if (!p) { fprintf(stderr, "out of memory after %d MiB\n", mib); return 4; }
                memset(p, 1, 1 << 20);
            }
        }"#,
    ),
    (
        "orphan_setsid",
        r#"int main(void) {
            if (fork() == 0) { setsid(); write_pid("child"); sleep_forever(); }
            wait_for("child");
            return 0;
        }"#,
    ),
    (
        "orphan_and_hang",
        r#"int main(void) {
            if (fork() == 0) { setsid(); write_pid("child"); sleep_forever(); }
            write_pid("parent");
            sleep_forever();
        }"#,
    ),
    (
        "grandchild_setsid",
        r#"int main(void) {
            if (fork() == 0) {
                if (fork() == 0) { setsid(); write_pid("b"); sleep_forever(); }
                write_pid("a");
                sleep_forever();
            }
            wait_for("a");
            wait_for("b");
            return 0;
        }"#,
    ),
    (
        "fifty_sleepers",
        r#"int main(void) {
            char name[32];
            for (int i = 0; i < 50; i++) {
                snprintf(name, sizeof name, "sleeper-%d", i);
                if (fork() == 0) { if (i % 2) setsid(); write_pid(name); sleep_forever(); }
            }
            for (int i = 0; i < 50; i++) { snprintf(name, sizeof name, "sleeper-%d", i); wait_for(name); }
            write_pid("pid");
            sleep_forever();
        }"#,
    ),
    (
        "print_env",
        r#"extern char **environ;
        int main(void) { for (char **e = environ; *e; e++) puts(*e); return 0; }"#,
    ),
    (
        "read_stdin",
        r#"int main(void) { char b[16]; printf("%zd\n", read(0, b, sizeof b)); return 0; }"#,
    ),
    (
        "cat_first_argument",
        r#"int main(int argc, char **argv) {
            FILE *f = fopen(argv[1], "r");
            if (!f) { perror(argv[1]); return 1; }
            int c;
            while ((c = fgetc(f)) != EOF) putchar(c);
            return 0;
        }"#,
    ),
    (
        "write_first_argument",
        r#"int main(int argc, char **argv) {
            FILE *f = fopen(argv[1], "w");
            if (!f) { perror(argv[1]); return 1; }
            return fclose(f) != 0;
        }"#,
    ),
    (
        "print_cwd",
        r#"int main(void) { char b[4096]; puts(getcwd(b, sizeof b)); return 0; }"#,
    ),
    (
        "fork_twenty",
        r#"int main(void) {
            for (int i = 0; i < 20; i++) {
                pid_t child = fork();
                if (child == 0) sleep_forever();
                if (child < 0) { fprintf(stderr, "fork failed after %d\n", i); break; }
            }
            sleep_forever();
        }"#,
    ),
    (
        "fork_bomb",
        r#"int main(void) { write_pid("pid"); for (;;) fork(); }"#,
    ),
    (
        "daemon_then_exit",
        r#"int main(void) {
            if (fork() == 0) {
                setsid();
                if (fork() == 0) { write_pid("daemon"); sleep_forever(); }
                _exit(0);
            }
            wait_for("daemon");
            return 0;
        }"#,
    ),
    (
        "links_its_trace",
        r#"int main(int argc, char **argv) { return symlink(argv[1], "trace.txt") != 0; }"#,
    ),
];

/// The compiled program `name`, compiled once per test binary.
pub fn program(name: &str) -> String {
    static COMPILED: Mutex<Option<HashMap<String, PathBuf>>> = Mutex::new(None);
    let mut compiled = COMPILED.lock().expect("an earlier compile panicked");
    let compiled = compiled.get_or_insert_with(HashMap::new);
    if let Some(path) = compiled.get(name) {
        return path.display().to_string();
    }
    let source = PROGRAMS
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, source)| format!("{PRELUDE}\n{source}\n"))
        .unwrap_or_else(|| panic!("no test program {name}"));
    let dir = Path::new(env!("CARGO_TARGET_TMPDIR")).join("runner-programs");
    std::fs::create_dir_all(&dir).expect("make the programs' directory");
    let c_file = dir.join(format!("{name}.c"));
    let binary = dir.join(name);
    std::fs::write(&c_file, source).expect("write the C source");
    let status = Command::new("cc")
        .args(["-O1", "-w", "-o"])
        .arg(&binary)
        .arg(&c_file)
        .status()
        .expect("these tests need a C compiler `cc` on PATH (CI installs one)");
    assert!(status.success(), "cc failed on {name}");
    compiled.insert(name.to_string(), binary.clone());
    binary.display().to_string()
}

/// Small limits so that the tests are quick: 1 s, 256 MiB of address space, 4 MiB files,
/// 16 MiB of disk, the default 64 KiB of output.
pub fn small_limits() -> Limits {
    Limits {
        time: Duration::from_secs(1),
        address_space: 256 << 20,
        file_size: 4 << 20,
        disk: 16 << 20,
        ..Limits::default()
    }
}

/// Runs the program `name` in a fresh workspace; returns the outcome, the workspace (to look
/// in) and how long `run` took.
pub fn run_program(name: &str, limits: &Limits) -> (Outcome, Workspace, Duration) {
    let words = vec![program(name)];
    let workspace = Workspace::new().expect("make a workspace");
    let started = Instant::now();
    let outcome = run(&words, workspace.path(), limits, &Sandbox::Off);
    let took = started.elapsed();
    eprintln!("{name}: {:?} in {took:.2?}", outcome.ended);
    (outcome, workspace, took)
}

/// Runs the program `name`, asserts that it ended as `expected`, that `run` returned within
/// `within`, and that nothing it started is left ([`assert_nothing_left`]).
pub fn run_expecting(
    name: &str,
    limits: &Limits,
    expected: Ending,
    within: Duration,
) -> (Outcome, Workspace) {
    let (outcome, workspace, took) = run_program(name, limits);
    assert_eq!(outcome.ended, expected, "{name}");
    assert!(took < within, "{name}: run took {took:?}");
    assert_nothing_left(workspace.path());
    (outcome, workspace)
}

/// The ending of a program killed by `signal`.
pub fn signalled(signal: i32, name: &'static str) -> Ending {
    Ending::Signalled { signal, name }
}

/// The pids a program wrote to files in `dir` (`pid`, `child`, `sleeper-7`, ...).
pub fn pids_written(dir: &Path) -> Vec<i32> {
    let entries = std::fs::read_dir(dir).expect("read the workspace");
    entries
        .flatten()
        .filter(|entry| !entry.file_name().to_string_lossy().ends_with(".tmp"))
        .filter_map(|entry| std::fs::read_to_string(entry.path()).ok())
        .filter_map(|text| text.trim().parse().ok())
        .collect()
}

/// Whether process `pid` is gone: not running, and not a zombie either (it was reaped).
pub fn gone(pid: i32) -> bool {
    !Path::new(&format!("/proc/{pid}")).exists()
}

/// The processes whose working directory is `dir` (every program's, unless it moved).
pub fn processes_in(dir: &Path) -> Vec<i32> {
    let entries = std::fs::read_dir("/proc").expect("read /proc");
    entries
        .flatten()
        .filter_map(|entry| {
            let pid: i32 = entry.file_name().to_str()?.parse().ok()?;
            let cwd = std::fs::read_link(entry.path().join("cwd")).ok()?;
            (cwd == dir).then_some(pid)
        })
        .collect()
}

/// Asserts that every pid the program wrote is gone and that no process still works in `dir`;
/// returns how many pids were checked.
pub fn assert_nothing_left(dir: &Path) -> usize {
    let pids = pids_written(dir);
    let left: Vec<i32> = pids.iter().copied().filter(|pid| !gone(*pid)).collect();
    assert!(
        left.is_empty(),
        "still there after run: {left:?} of {pids:?}"
    );
    assert_eq!(
        processes_in(dir),
        Vec::<i32>::new(),
        "processes in {}",
        dir.display()
    );
    pids.len()
}

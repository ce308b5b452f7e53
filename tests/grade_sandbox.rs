//! `close2gl grade` against hostile students: a class graded with `--submissions`, one
//! submission hostile, the others the correct C program. The hostile one tries to read a file
//! in the teacher's (temporary) HOME and a sibling's folder, to leak it by writing outside its
//! directory and to a TCP listener the test opened, to rewrite a sibling's program, to signal
//! the grader, to talk over an abstract Unix socket, and through children that outlive it.
//! Every attempt must fail, nothing may leak, and the others still score 200/200. A correct
//! Python program with numpy from a virtual environment scores 200/200 in the sandbox too.
//!
//! These tests skip, saying why, only on a kernel without Landlock.

use std::io::ErrorKind;
use std::net::TcpListener;
use std::os::linux::net::SocketAddrExt;
use std::os::unix::net::UnixListener;
use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use close2gl_testkit::TempDir;
use close2gl_testkit::student::{asset, compile_c, compile_pipeline, repository};

/// Whether this kernel can sandbox; says why not when it cannot.
fn sandbox_available() -> bool {
    match close2gl_runner::Protections::current().unavailable() {
        None => true,
        Some(why) => {
            eprintln!("skipped: {why}");
            false
        }
    }
}

/// A class: `good` and `other` (the correct program, as `prog`), `hostile` (a C program, as
/// `prog`, given by [`Class::hostile`]), a secret in a temporary HOME and one in `good`'s
/// folder.
struct Class {
    dir: TempDir,
    class: PathBuf,
    home: PathBuf,
}

impl Class {
    fn new(name: &str) -> Self {
        let dir = TempDir::new(name);
        let class = dir.join("class");
        let home = dir.join("home");
        for folder in ["good", "other", "hostile"] {
            std::fs::create_dir_all(class.join(folder)).expect("a submission's folder");
        }
        std::fs::create_dir_all(&home).expect("HOME");
        std::fs::write(home.join("answer-key.txt"), "SECRET-KEY\n").expect("the key");
        std::fs::write(class.join("good/notes.txt"), "SECRET-NOTES\n").expect("notes");
        for good in ["good", "other"] {
            let program = compile_pipeline(&class.join(good), "pipeline", &[]);
            std::fs::rename(program, class.join(good).join("prog")).expect("rename");
        }
        Self { dir, class, home }
    }

    /// Compiles `body` (C, with the usual headers) as the hostile submission's program.
    fn hostile(&self, body: &str) {
        let source = self.dir.join("hostile.c");
        let prelude = "#define _GNU_SOURCE\n#include <errno.h>\n#include <signal.h>\n\
                       #include <stdio.h>\n#include <stdlib.h>\n#include <string.h>\n\
                       #include <dirent.h>\n#include <stddef.h>\n#include <unistd.h>\n#include <sys/socket.h>\n#include <sys/un.h>\n\
                       #include <netinet/in.h>\n#include <arpa/inet.h>\n";
        std::fs::write(&source, format!("{prelude}{body}\n")).expect("the hostile source");
        let flags = ["-Wno-unused-parameter", "-Wno-unused-result"];
        compile_c(&source, &self.class.join("hostile/prog"), &flags);
    }

    /// Grades the class on the cube with HOME set to the temporary one; the CSV's rows.
    fn grade(&self) -> (Output, String) {
        let tmp = self.dir.join("tmp");
        std::fs::create_dir_all(&tmp).expect("TMPDIR");
        let cube = asset("cube.in").display().to_string();
        let output = Command::new(env!("CARGO_BIN_EXE_close2gl"))
            .args(["grade", "--submissions"])
            .arg(&self.class)
            .args(["--run", "{dir}/prog {scene} {trace}", "--model", &cube])
            .args(["--jobs", "2", "--time-limit", "2"])
            .env("TMPDIR", &tmp)
            .env("HOME", &self.home)
            .output()
            .expect("run close2gl grade");
        let stderr = String::from_utf8_lossy(&output.stderr);
        assert!(output.status.success(), "grade failed: {stderr}");
        let csv = std::fs::read_to_string(self.class.join("grades.csv")).expect("grades.csv");
        (output, csv)
    }

    /// Asserts both good submissions scored 200, the hostile one 0, and returns its page.
    fn assert_graded(&self, csv: &str) -> String {
        let total = |name: &str| {
            let row = csv.lines().find(|l| l.starts_with(&format!("{name},")));
            row.and_then(|r| r.rsplit(',').next()).map(str::to_string)
        };
        assert_eq!(total("good").as_deref(), Some("200"), "{csv}");
        assert_eq!(total("other").as_deref(), Some("200"), "{csv}");
        assert_eq!(total("hostile").as_deref(), Some("0"), "{csv}");
        std::fs::read_to_string(self.class.join("hostile.html")).expect("hostile.html")
    }

    fn path(&self, relative: &str) -> String {
        self.dir.join(relative).display().to_string()
    }
}

/// A TCP listener on 127.0.0.1 that must receive nothing.
fn listener() -> (TcpListener, u16) {
    let listener = TcpListener::bind("127.0.0.1:0").expect("a TCP listener");
    listener.set_nonblocking(true).expect("non-blocking");
    let port = listener.local_addr().expect("its address").port();
    (listener, port)
}

fn assert_nothing_received(listener: &TcpListener) {
    match listener.accept() {
        Err(e) if e.kind() == ErrorKind::WouldBlock => {}
        Ok((_, from)) => panic!("a program connected to the listener from {from}"),
        Err(e) => panic!("accept: {e}"),
    }
}

/// C that reads `secret`, then tries to leak it: to `leak` (outside its directory) and to
/// 127.0.0.1:`port`; prints each error on stderr and exits 3.
fn leak_attempts(secret: &str, leak: &str, port: u16) -> String {
    format!(
        r#"static void try_leak(void) {{
            char buf[64] = "nothing read";
            FILE *in = fopen("{secret}", "r");
            if (in) {{ fgets(buf, sizeof buf, in); fclose(in); }} else perror("{secret}");
            FILE *out = fopen("{leak}", "w");
            if (out) {{ fputs(buf, out); fclose(out); }} else perror("{leak}");
            int s = socket(AF_INET, SOCK_STREAM, 0);
            struct sockaddr_in a = {{ .sin_family = AF_INET, .sin_port = htons({port}) }};
            a.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
            if (connect(s, (struct sockaddr *)&a, sizeof a) == 0) write(s, buf, strlen(buf));
            else perror("connect 127.0.0.1");
        }}"#
    )
}

#[test]
fn a_program_cannot_read_the_teachers_home_nor_leak_it() {
    if !sandbox_available() {
        return;
    }
    leaks_nothing(
        "leak",
        "home/answer-key.txt",
        "leak.txt",
        "tried to open ~/answer-key.txt",
    );
}

#[test]
fn a_program_cannot_read_a_sibling_submission() {
    if !sandbox_available() {
        return;
    }
    // Its own submission's folder is read-only to it: the leak has nowhere to go there either.
    let notes = "class/good/notes.txt";
    leaks_nothing("sibling", notes, "class/hostile/leak.txt", notes);
}

/// A class whose hostile program reads `secret` and tries to leak it to `leak` and a TCP
/// listener (both paths in the test's folder): the page says `says` was denied, no file
/// appears and the listener receives nothing.
fn leaks_nothing(name: &str, secret: &str, leak: &str, says: &str) {
    let (tcp, port) = listener();
    let class = Class::new(&format!("grade_sandbox_{name}"));
    let (secret, leak) = (class.path(secret), class.path(leak));
    class.hostile(&format!(
        "{}\nint main(void) {{ try_leak(); return 3; }}",
        leak_attempts(&secret, &leak, port)
    ));
    let (_, csv) = class.grade();
    let page = class.assert_graded(&csv);
    let denied = "the sandbox stopped it: tried to open ";
    assert!(page.contains(denied), "{page}");
    assert!(page.contains(&format!("{says}: denied")), "{page}");
    assert!(
        !Path::new(&leak).exists(),
        "a file appeared outside the run"
    );
    assert_nothing_received(&tcp);
}

#[test]
fn a_program_cannot_rewrite_a_siblings_program() {
    if !sandbox_available() {
        return;
    }
    let class = Class::new("grade_sandbox_rewrite");
    let other = class.path("class/other/prog");
    class.hostile(&format!(
        r##"int main(void) {{
            FILE *f = fopen("{other}", "w");
            if (f) {{ fputs("#!/bin/sh\nexit 1\n", f); fclose(f); }} else perror("{other}");
            if (unlink("{other}") != 0) perror("unlink {other}");
            return 3;
        }}"##
    ));
    let before = std::fs::read(class.class.join("other/prog")).expect("other's program");
    let (_, csv) = class.grade();
    let page = class.assert_graded(&csv);
    assert!(page.contains("the sandbox stopped it"), "{page}");
    let after = std::fs::read(class.class.join("other/prog")).expect("other's program");
    assert!(before == after, "the sibling's program changed");
}

#[test]
fn a_program_cannot_signal_the_grader() {
    if !sandbox_available() {
        return;
    }
    // Its parent (the grader), every process it may signal, and the grader found by name.
    let body = r#"int main(void) {
        if (kill(getppid(), SIGTERM) != 0) perror("kill grader");
        if (kill(-1, SIGTERM) != 0) perror("kill -1");
        DIR *proc = opendir("/proc");
        if (!proc) perror("/proc");
        for (struct dirent *e; proc && (e = readdir(proc));) {
            char path[300], name[64] = "";
            snprintf(path, sizeof path, "/proc/%s/comm", e->d_name);
            FILE *f = fopen(path, "r");
            if (!f) continue;
            fgets(name, sizeof name, f);
            fclose(f);
            if (!strncmp(name, "close2gl", 8) && kill(atoi(e->d_name), SIGTERM) != 0)
                perror("kill close2gl");
        }
        return 3;
    }"#;
    let class = Class::new("grade_sandbox_signal");
    class.hostile(body);
    let (output, csv) = class.grade();
    let page = class.assert_graded(&csv);
    assert!(page.contains("Operation not permitted"), "{page}");
    let stdout = String::from_utf8_lossy(&output.stdout);
    assert!(stdout.contains("hostile: 0/200"), "{stdout}");
}

#[test]
fn a_program_cannot_talk_over_an_abstract_unix_socket() {
    if !sandbox_available() {
        return;
    }
    // The test's own abstract socket, and one the runs make to find each other.
    let name = format!("close2gl-test-{}", std::process::id());
    let address =
        <std::os::unix::net::SocketAddr as SocketAddrExt>::from_abstract_name(name.as_bytes())
            .expect("an abstract address");
    let ours = UnixListener::bind_addr(&address).expect("an abstract socket");
    ours.set_nonblocking(true).expect("non-blocking");
    let body = format!(
        r#"static int talk(const char *name) {{
            struct sockaddr_un a = {{ .sun_family = AF_UNIX }};
            strcpy(a.sun_path + 1, name);
            socklen_t len = offsetof(struct sockaddr_un, sun_path) + 1 + strlen(name);
            int s = socket(AF_UNIX, SOCK_STREAM, 0);
            if (connect(s, (struct sockaddr *)&a, len) == 0) return write(s, "hi", 2) == 2;
            perror(name);
            int l = socket(AF_UNIX, SOCK_STREAM, 0);
            if (bind(l, (struct sockaddr *)&a, len) == 0 && listen(l, 1) == 0) {{
                usleep(300000);   /* another run may connect meanwhile */
                return 0;
            }}
            return 0;
        }}
        int main(void) {{
            int talked = talk("{name}") + talk("close2gl-runs");
            return talked ? 42 : 3;
        }}"#
    );
    let class = Class::new("grade_sandbox_abstract");
    class.hostile(&body);
    let (_, csv) = class.grade();
    let page = class.assert_graded(&csv);
    assert!(
        !page.contains("status 42"),
        "a run talked to another: {page}"
    );
    match ours.accept() {
        Err(e) if e.kind() == ErrorKind::WouldBlock => {}
        other => panic!("a program reached the test's abstract socket: {other:?}"),
    }
}

#[test]
fn children_that_outlive_their_parent_are_sandboxed_too() {
    if !sandbox_available() {
        return;
    }
    let (tcp, port) = listener();
    let class = Class::new("grade_sandbox_children");
    let (secret, leak) = (class.path("home/answer-key.txt"), class.path("leak.txt"));
    class.hostile(&format!(
        r#"{}
        int main(void) {{
            pid_t parent = getpid();
            for (int i = 0; i < 4; i++)
                if (fork() == 0) {{
                    if (i % 2) setsid();
                    while (getppid() == parent) usleep(1000);   /* until the parent is gone */
                    try_leak();
                    kill(getppid(), SIGTERM);
                    _exit(0);
                }}
            return 3;
        }}"#,
        leak_attempts(&secret, &leak, port)
    ));
    let (_, csv) = class.grade();
    class.assert_graded(&csv);
    assert!(!Path::new(&leak).exists(), "a child leaked");
    assert_nothing_received(&tcp);
}

/// A virtual environment with numpy, made once per build in the test target's folder.
fn venv_with_numpy() -> PathBuf {
    let venv = Path::new(env!("CARGO_TARGET_TMPDIR")).join("venv-numpy");
    let python = venv.join("bin/python");
    let has_numpy = |python: &Path| {
        Command::new(python)
            .args(["-c", "import numpy"])
            .status()
            .is_ok_and(|s| s.success())
    };
    if !has_numpy(&python) {
        let made = Command::new("python3")
            .arg("-m")
            .arg("venv")
            .arg(&venv)
            .status();
        assert!(
            made.is_ok_and(|s| s.success()),
            "python3 -m venv failed (CI installs python3-venv)"
        );
        let pip = Command::new(venv.join("bin/pip"))
            .args(["install", "--quiet", "numpy"])
            .status();
        assert!(pip.is_ok_and(|s| s.success()), "pip install numpy failed");
    }
    assert!(has_numpy(&python), "numpy is not in {}", venv.display());
    python
}

#[test]
fn a_python_program_with_numpy_from_a_virtual_environment_scores_200() {
    if !sandbox_available() {
        return;
    }
    let python = venv_with_numpy();
    let script = repository().join("examples/trace/pipeline.py");
    let dir = TempDir::new("grade_sandbox_python");
    let tmp = dir.join("tmp");
    std::fs::create_dir_all(&tmp).expect("TMPDIR");
    let command = format!(
        "'{}' '{}' {{scene}} {{trace}}",
        python.display(),
        script.display()
    );
    let output = Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .args(["grade", "--run", &command, "--jobs", "2", "--json"])
        .env("TMPDIR", &tmp)
        .output()
        .expect("run close2gl grade");
    let stderr = String::from_utf8_lossy(&output.stderr);
    assert!(output.status.success(), "{stderr}");
    let grade: serde_json::Value = serde_json::from_slice(&output.stdout).expect("JSON");
    assert_eq!(grade["sandbox"]["enforced"], true, "{stderr}");
    assert_eq!(grade["total"], 200, "{:#}", grade["lines"]);
}

#[test]
fn the_report_says_what_the_sandbox_enforces() {
    if !sandbox_available() {
        return;
    }
    let dir = TempDir::new("grade_sandbox_report");
    let program = compile_pipeline(&dir, "pipeline", &[]);
    let tmp = dir.join("tmp");
    std::fs::create_dir_all(&tmp).expect("TMPDIR");
    let command = format!("'{}' {{scene}} {{trace}}", program.display());
    let cube = asset("cube.in").display().to_string();
    let html = dir.join("report.html");
    let run = |extra: &[&str]| {
        let output = Command::new(env!("CARGO_BIN_EXE_close2gl"))
            .args(["grade", "--run", &command, "--model", &cube, "--jobs", "2"])
            .args(extra)
            .env("TMPDIR", &tmp)
            .output()
            .expect("run close2gl grade");
        assert!(output.status.success());
        output
    };
    let table = run(&["--html", html.to_str().unwrap_or_default()]);
    let (stdout, stderr) = (
        String::from_utf8_lossy(&table.stdout),
        String::from_utf8_lossy(&table.stderr),
    );
    let abi = close2gl_runner::Protections::current().landlock_abi.clone();
    let landlock = format!("sandbox: Landlock ABI {}", abi.unwrap_or(0));
    assert!(stderr.starts_with(&landlock), "{stderr}");
    assert!(stdout.contains(&landlock), "{stdout}");
    assert!(stdout.contains("total                                    200/200"));
    let page = std::fs::read_to_string(&html).expect("the page");
    assert!(page.contains("<b>filesystem</b> (enforced)"), "{page}");
    let json = run(&["--json"]);
    let grade: serde_json::Value = serde_json::from_slice(&json.stdout).expect("JSON");
    let names: Vec<&str> = grade["sandbox"]["protections"]
        .as_array()
        .map(|p| p.iter().filter_map(|p| p["name"].as_str()).collect())
        .unwrap_or_default();
    assert_eq!(
        names,
        [
            "landlock",
            "filesystem",
            "network",
            "signals",
            "unix sockets",
            "namespaces",
            "processes"
        ]
    );
    let unsandboxed = run(&["--unsandboxed"]);
    let stdout = String::from_utf8_lossy(&unsandboxed.stdout);
    assert!(stdout.contains("sandbox: none (--unsandboxed)"), "{stdout}");
}

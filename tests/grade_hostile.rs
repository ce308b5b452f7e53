//! `close2gl grade` reads only what a program wrote, and one program cannot stall the class.
//! A class of the correct C program and hostile ones, graded together on the cube with
//! `--time-limit 3 --jobs 2`: traces that are links (to `/proc/self/environ`, a classmate's
//! source, a file in the teacher's HOME, `/dev/zero`), a FIFO, a directory, a hard link to a
//! classmate's file, a fork bomb, a disk filler, and a program that locks its directory and
//! links a subdirectory to the teacher's HOME. Three secrets are planted (a variable in
//! grade's environment, a line in the classmate's source, a file in HOME): none may appear in
//! anything grade printed or wrote; each hostile program's report says what it did; the correct
//! program scores 200/200; no process of any run is left a second after grade exits; nothing
//! outside the runs changed; and the class takes no longer than the bomb's time-outs would
//! plus 30 s.

use std::os::unix::fs::PermissionsExt;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::time::{Duration, Instant};

use close2gl_testkit::TempDir;
use close2gl_testkit::student::{asset, compile_c, compile_pipeline};

const TOKEN: &str = "ghp_PLANTED-GRADER-TOKEN";
const CLASSMATE: &str = "PLANTED-CLASSMATE-LINE";
const HOME_SECRET: &str = "PLANTED-HOME-SECRET";

/// A hostile submission: its folder's name, its C `main`, and what its report must say.
struct Hostile {
    name: &'static str,
    main: String,
    says: &'static str,
}

/// The hostile programs; `classmate` and `home` are the planted files' absolute paths.
fn hostiles(classmate: &str, home: &Path, bomb: bool) -> Vec<Hostile> {
    let link = |target: &str| {
        format!("int main(int c, char **v) {{ return symlink(\"{target}\", v[2]) != 0; }}")
    };
    let home_dir = home.display();
    let mut all = vec![
        Hostile {
            name: "environ",
            main: link("/proc/self/environ"),
            says: "its trace is a link to /proc/self/environ, not a file it wrote",
        },
        Hostile {
            name: "classmate",
            main: link(classmate),
            says: "its trace is a link to ",
        },
        Hostile {
            name: "home",
            main: link(&format!("{home_dir}/answer-key.txt")),
            says: "its trace is a link to ",
        },
        Hostile {
            name: "zero",
            main: link("/dev/zero"),
            says: "its trace is a link to /dev/zero, not a file it wrote",
        },
        Hostile {
            name: "fifo",
            main: "int main(int c, char **v) { return mkfifo(v[2], 0600) != 0; }".into(),
            says: "its trace is a FIFO, not a file it wrote",
        },
        Hostile {
            name: "directory",
            main: "int main(int c, char **v) { return mkdir(v[2], 0700) != 0; }".into(),
            says: "its trace is a directory, not a file it wrote",
        },
        Hostile {
            name: "hardlink",
            main: format!(
                "int main(int c, char **v) {{ if (link(\"{classmate}\", v[2])) perror(\"link\"); \
                 return 0; }}"
            ),
            says: "it wrote no trace",
        },
        Hostile {
            name: "disk",
            // Sparse files: the disk limit counts a file's length, and nothing is written.
            main: "int main(void) { char n[16]; for (int i = 0; ; i++) { \
                   snprintf(n, sizeof n, \"f%d\", i); int fd = creat(n, 0600); \
                   if (fd < 0 || ftruncate(fd, 60 << 20)) return 1; close(fd); usleep(2000); } }"
                .into(),
            says: "its directory grew past the disk limit",
        },
        Hostile {
            name: "locked",
            main: format!(
                "int main(void) {{ mkdir(\"d\", 0700); symlink(\"{home_dir}\", \"d/home\"); \
                 symlink(\"{home_dir}\", \"home\"); chmod(\"d\", 0); chmod(\".\", 0); return 0; }}"
            ),
            says: "it wrote no trace",
        },
    ];
    if bomb {
        all.push(Hostile {
            name: "bomb",
            main: "int main(void) { for (;;) fork(); }".into(),
            says: "it made more than 256 processes at once",
        });
    }
    all
}

/// Compiles `main` (C, with the usual headers) to `out`.
fn compile(dir: &Path, name: &str, main: &str, out: &Path) {
    let source = dir.join(format!("{name}.c"));
    let prelude = "#define _GNU_SOURCE\n#include <fcntl.h>\n#include <stdio.h>\n\
                   #include <stdlib.h>\n#include <sys/stat.h>\n#include <unistd.h>\n";
    std::fs::write(&source, format!("{prelude}{main}\n")).expect("a hostile source");
    let flags = ["-Wno-unused-parameter", "-Wno-unused-result"];
    compile_c(&source, out, &flags);
}

/// The pids of processes whose command line starts with one of `programs`.
fn running(programs: &[PathBuf]) -> Vec<i32> {
    let entries = std::fs::read_dir("/proc").expect("/proc");
    entries
        .flatten()
        .filter_map(|entry| {
            let pid: i32 = entry.file_name().to_str()?.parse().ok()?;
            let cmdline = std::fs::read(entry.path().join("cmdline")).ok()?;
            let first = cmdline.split(|&b| b == 0).next()?;
            programs
                .iter()
                .any(|p| p.as_os_str().as_encoded_bytes() == first)
                .then_some(pid)
        })
        .collect()
}

/// Every file grade wrote into the class folder (the CSV, the reports), as text.
fn written(class: &Path) -> Vec<(PathBuf, String)> {
    std::fs::read_dir(class)
        .expect("the class folder")
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.is_file())
        .map(|p| {
            let text = String::from_utf8_lossy(&std::fs::read(&p).expect("a report")).into();
            (p, text)
        })
        .collect()
}

#[test]
fn a_hostile_class_leaks_nothing_leaves_nothing_and_does_not_stall() {
    let protections = close2gl_runner::Protections::current();
    if let Some(why) = protections.unavailable() {
        eprintln!("skipped: {why}");
        return;
    }
    // A fork bomb is only safe to try where the kernel holds a run to its process count.
    let bomb = protections.process_count_per_namespace();
    if !bomb {
        eprintln!("the fork bomb is left out: the kernel does not count processes per namespace");
    }
    let dir = TempDir::new("grade_hostile_class");
    let (class, home, tmp) = (dir.join("class"), dir.join("home"), dir.join("tmp"));
    for folder in [&class, &home, &tmp] {
        std::fs::create_dir_all(folder).expect("a folder");
    }
    std::fs::write(home.join("answer-key.txt"), format!("{HOME_SECRET}\n")).expect("HOME");
    std::fs::set_permissions(&home, std::fs::Permissions::from_mode(0o751)).expect("chmod");
    let good = class.join("good");
    std::fs::create_dir_all(&good).expect("good's folder");
    let program = compile_pipeline(&good, "pipeline", &[]);
    std::fs::rename(program, good.join("prog")).expect("rename");
    let classmate = good.join("pipeline.c");
    std::fs::write(&classmate, format!("/* {CLASSMATE} */\n")).expect("the classmate's source");
    let hostiles = hostiles(&classmate.display().to_string(), &home, bomb);
    let mut programs = vec![good.join("prog")];
    for hostile in &hostiles {
        let folder = class.join(hostile.name);
        std::fs::create_dir_all(&folder).expect("a submission's folder");
        compile(&dir, hostile.name, &hostile.main, &folder.join("prog"));
        programs.push(folder.join("prog"));
    }

    let started = Instant::now();
    let output = Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .args(["grade", "--submissions"])
        .arg(&class)
        .args(["--run", "{dir}/prog {scene} {trace}"])
        .args(["--model", &asset("cube.in").display().to_string()])
        .args(["--jobs", "2", "--time-limit", "3"])
        .env("TMPDIR", &tmp)
        .env("HOME", &home)
        .env("GRADER_TOKEN", TOKEN)
        .output()
        .expect("run close2gl grade");
    let took = started.elapsed();
    std::thread::sleep(Duration::from_secs(1));
    assert_eq!(running(&programs), Vec::<i32>::new(), "processes left");
    let (stdout, stderr) = (
        String::from_utf8_lossy(&output.stdout),
        String::from_utf8_lossy(&output.stderr),
    );
    assert!(output.status.success(), "{stderr}");

    let mut everything = vec![("stdout".into(), stdout.to_string())];
    everything.push(("stderr".into(), stderr.to_string()));
    everything.extend(written(&class));
    for (file, text) in &everything {
        for secret in [TOKEN, CLASSMATE, HOME_SECRET, "GRADER_TOKEN"] {
            assert!(!text.contains(secret), "{} quotes {secret}", file.display());
        }
    }
    let csv = std::fs::read_to_string(class.join("grades.csv")).expect("grades.csv");
    let total = |name: &str| {
        let row = csv.lines().find(|l| l.starts_with(&format!("{name},")));
        row.and_then(|r| r.rsplit(',').next()).map(str::to_string)
    };
    assert_eq!(total("good").as_deref(), Some("200"), "{csv}");
    for hostile in &hostiles {
        assert_eq!(total(hostile.name).as_deref(), Some("0"), "{csv}");
        let page = std::fs::read_to_string(class.join(format!("{}.html", hostile.name)))
            .expect("a hostile's report");
        assert!(
            page.contains(hostile.says),
            "{}: {}",
            hostile.name,
            hostile.says
        );
        // Every scene failed the same way: one bug to fix, not one per line.
        assert!(
            page.contains("to fix (1):"),
            "{}: more than one bug",
            hostile.name
        );
    }
    // One program alone, as JSON: the same words, nothing of the target.
    let environ = class.join("environ/prog");
    let json = Command::new(env!("CARGO_BIN_EXE_close2gl"))
        .args(["grade", "--json", "--jobs", "2", "--time-limit", "3"])
        .args(["--model", &asset("cube.in").display().to_string()])
        .arg("--run")
        .arg(format!("'{}' {{scene}} {{trace}}", environ.display()))
        .env("TMPDIR", &tmp)
        .env("GRADER_TOKEN", TOKEN)
        .output()
        .expect("grade --json");
    let json = String::from_utf8_lossy(&json.stdout);
    assert!(
        json.contains("its trace is a link to /proc/self/environ"),
        "{json}"
    );
    assert!(
        !json.contains(TOKEN) && !json.contains("GRADER_TOKEN"),
        "{json}"
    );
    assert!(
        home.join("answer-key.txt").exists(),
        "a file behind a link was removed"
    );
    let mode = std::fs::metadata(&home).expect("HOME").permissions().mode();
    assert_eq!(mode & 0o777, 0o751, "HOME's permissions changed");
    assert_eq!(
        std::fs::read_dir(&tmp).map(Iterator::count).ok(),
        Some(0),
        "a run's directory is left"
    );
    // The bomb's own time-outs: each of the cube's scenes timing out at 3 s, two at a time.
    let cube = close2gl_core::ModelSource::File(asset("cube.in"));
    let mesh = close2gl_model::load(&cube, &Default::default())
        .expect("the cube")
        .mesh;
    let scenes = close2gl_check::rubric::scenes("cube", "cube.in", &mesh).len();
    let bound = Duration::from_secs_f64(scenes as f64 * 3.0 / 2.0 + 30.0);
    eprintln!(
        "{} submissions in {took:?} (bound {bound:?})",
        hostiles.len() + 1
    );
    assert!(took < bound, "{took:?}");
}

//! How a run ended, in the words a grading report shows a student: what stopped the program,
//! when, and the last lines it wrote to stderr (usually the error message that explains it).

use std::time::Duration;

/// Lines of stderr [`Outcome::reason`] quotes.
const STDERR_LINES: usize = 5;
/// Characters kept of each quoted line: one line of a binary dump could be 64 KiB.
const LINE_CHARS: usize = 200;

/// What happened to one program.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Outcome {
    pub ended: Ending,
    /// From the start to the end of the program (or to the moment it was stopped).
    pub elapsed: Duration,
    /// The last [`Limits::output`](crate::Limits) bytes of stdout.
    pub stdout_tail: Vec<u8>,
    /// The last [`Limits::output`](crate::Limits) bytes of stderr.
    pub stderr_tail: Vec<u8>,
    /// What the sandbox denied it, as its stderr shows ("tried to open ~/key: denied"), when
    /// it did not end well.
    pub denied: Option<String>,
}

/// Why the program stopped.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Ending {
    /// It exited by itself with this status (0 is success).
    Exited(i32),
    /// A signal killed it: its own crash (`SIGSEGV`, `SIGABRT`), or a limit the kernel enforces
    /// (`SIGXFSZ` for the file size, `SIGXCPU` for CPU time).
    Signalled { signal: i32, name: &'static str },
    /// It ran past the time limit and was killed.
    TimedOut,
    /// Its directory grew past the disk limit; it was killed.
    TooMuchDisk,
    /// It had more processes at once than the limit (a fork bomb); it was killed, all of them.
    TooManyProcesses(u32),
    /// Grading was interrupted (Ctrl+C); it was killed, or not started.
    Interrupted,
    /// It could not be started (no such program, not executable, empty command).
    CouldNotStart(String),
}

impl Outcome {
    /// One line saying how the program ended ("killed by SIGSEGV after 0.12 s", "timed out
    /// after 10 s", "exited with status 3"), then the last lines of its stderr, one per line,
    /// with control characters escaped so a program cannot drive the teacher's terminal.
    pub fn reason(&self) -> String {
        let after = seconds(self.elapsed);
        let mut reason = match &self.ended {
            Ending::Exited(status) => format!("exited with status {status}"),
            Ending::Signalled { name, .. } => format!("killed by {name} after {after} s"),
            Ending::TimedOut => format!("timed out after {after} s"),
            Ending::TooMuchDisk => {
                format!("killed after {after} s: its directory grew past the disk limit")
            }
            Ending::TooManyProcesses(limit) => {
                format!("killed after {after} s: it made more than {limit} processes at once")
            }
            Ending::Interrupted => format!("stopped after {after} s: grading was interrupted"),
            Ending::CouldNotStart(why) => format!("could not start: {why}"),
        };
        if let Some(denied) = &self.denied {
            reason.push_str("\nthe sandbox stopped it: ");
            reason.push_str(&printable(denied));
        }
        for line in last_lines(&self.stderr_tail, STDERR_LINES) {
            reason.push('\n');
            reason.push_str(&line);
        }
        reason
    }

    /// How it ended without the times and its stderr ("timed out", "killed by SIGSEGV", with
    /// what the sandbox denied it): the same words for every run that failed the same way, so
    /// that a report can say it once.
    pub fn in_brief(&self) -> String {
        let brief = match &self.ended {
            Ending::Exited(status) => format!("exited with status {status}"),
            Ending::Signalled { name, .. } => format!("killed by {name}"),
            Ending::TimedOut => "timed out".into(),
            Ending::TooMuchDisk => "its directory grew past the disk limit".into(),
            Ending::TooManyProcesses(limit) => {
                format!("it made more than {limit} processes at once")
            }
            Ending::Interrupted => "grading was interrupted".into(),
            Ending::CouldNotStart(why) => format!("could not start: {why}"),
        };
        match &self.denied {
            Some(denied) => format!("{brief}; the sandbox stopped it: {}", printable(denied)),
            None => brief,
        }
    }
}

/// Seconds for a report: two decimals under a second ("0.12"), otherwise one, without a
/// trailing ".0" ("10", "1.5"): a timeout detected 20 ms late still reads "10 s".
fn seconds(duration: Duration) -> String {
    let secs = duration.as_secs_f64();
    let text = if secs < 1.0 {
        format!("{secs:.2}")
    } else {
        format!("{secs:.1}")
    };
    match text.strip_suffix(".0") {
        Some(whole) => whole.to_string(),
        None => text,
    }
}

/// The last `count` non-blank lines of `bytes` (lossy UTF-8), each cut to [`LINE_CHARS`]
/// characters, control characters escaped.
fn last_lines(bytes: &[u8], count: usize) -> Vec<String> {
    let text = String::from_utf8_lossy(bytes);
    let mut lines: Vec<String> = text
        .lines()
        .rev()
        .filter(|line| !line.trim().is_empty())
        .take(count)
        .map(printable)
        .collect();
    lines.reverse();
    lines
}

fn printable(line: &str) -> String {
    let mut out = String::new();
    for c in line.trim_end().chars().take(LINE_CHARS) {
        if c.is_control() && c != '\t' {
            out.extend(c.escape_default());
        } else {
            out.push(c);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn outcome(ended: Ending, millis: u64, stderr: &[u8]) -> Outcome {
        Outcome {
            ended,
            elapsed: Duration::from_millis(millis),
            stdout_tail: Vec::new(),
            stderr_tail: stderr.to_vec(),
            denied: None,
        }
    }

    #[test]
    fn reasons_read_as_the_issue_words_them() {
        let segv = Ending::Signalled {
            signal: 11,
            name: "SIGSEGV",
        };
        assert_eq!(
            outcome(segv, 120, b"").reason(),
            "killed by SIGSEGV after 0.12 s"
        );
        assert_eq!(
            outcome(Ending::TimedOut, 10_020, b"").reason(),
            "timed out after 10 s"
        );
        assert_eq!(
            outcome(Ending::TimedOut, 1_500, b"").reason(),
            "timed out after 1.5 s"
        );
        assert_eq!(
            outcome(Ending::Exited(3), 5, b"").reason(),
            "exited with status 3"
        );
    }

    #[test]
    fn in_brief_leaves_out_the_times_and_stderr() {
        let late = outcome(Ending::TimedOut, 3_020, b"waiting\n");
        let later = outcome(Ending::TimedOut, 3_100, b"still waiting\n");
        assert_eq!(late.in_brief(), "timed out");
        assert_eq!(late.in_brief(), later.in_brief());
        let bomb = outcome(Ending::TooManyProcesses(256), 50, b"");
        assert_eq!(bomb.in_brief(), "it made more than 256 processes at once");
        assert_eq!(
            bomb.reason(),
            "killed after 0.05 s: it made more than 256 processes at once"
        );
    }

    #[test]
    fn reason_quotes_the_last_five_lines_of_stderr_escaped() {
        let stderr = b"one\ntwo\nthree\n\nfour\nfive\nsix \x1b[2J\n\n";
        let reason = outcome(Ending::Exited(1), 5, stderr).reason();
        assert_eq!(
            reason,
            "exited with status 1\ntwo\nthree\nfour\nfive\nsix \\u{1b}[2J"
        );
    }

    #[test]
    fn a_long_line_is_cut() {
        let stderr = vec![b'x'; 10_000];
        let reason = outcome(Ending::Exited(1), 5, &stderr).reason();
        assert_eq!(reason.lines().nth(1).map(str::len), Some(LINE_CHARS));
    }
}

//! A big model's loading progress on the terminal, for the headless commands and the viewer's
//! start-up: on stderr, so that a command's output (stats' JSON) stays clean.

use std::io::{IsTerminal, Write};

use close2gl_core::ModelSource;

/// One updating line on a terminal; a line per tenth done otherwise (a log, a test), which
/// stays readable where `\r` does not work.
pub struct TerminalProgress {
    /// What is under way: "loading knot.obj".
    label: String,
    terminal: bool,
    /// The last percent shown on a terminal, or tenth written to a log.
    shown: Option<u32>,
}

impl TerminalProgress {
    pub fn new(source: &ModelSource) -> Self {
        let name = match source {
            ModelSource::File(path) => path.display().to_string(),
            ModelSource::Primitive(kind) => kind.name().to_string(),
        };
        Self::labelled(format!("loading {name}"))
    }

    /// Progress of anything else: `label` says what ("grading 30 submissions").
    pub fn labelled(label: String) -> Self {
        Self {
            label,
            terminal: std::io::stderr().is_terminal(),
            shown: None,
        }
    }

    pub fn show(&mut self, fraction: f32) {
        let percent = (fraction.clamp(0.0, 1.0) * 100.0) as u32;
        let step = if self.terminal { percent } else { percent / 10 };
        // In a log, the first tenth is not news: a load that fails at once prints only its error.
        if self.shown == Some(step) || (!self.terminal && step == 0) {
            return;
        }
        self.shown = Some(step);
        let mut stderr = std::io::stderr().lock();
        // A failed write to stderr has nowhere to be reported; the load goes on.
        let _ = if self.terminal {
            write!(stderr, "\r{}: {percent:3}%", self.label)
        } else {
            writeln!(stderr, "{}: {percent}%", self.label)
        };
        let _ = stderr.flush();
    }

    /// Ends the line: at 100 % when the model `loaded`, where it stopped when not (the error
    /// follows on its own line).
    pub fn finish(mut self, loaded: bool) {
        if loaded {
            self.show(1.0);
        }
        if self.terminal {
            let _ = writeln!(std::io::stderr());
        }
    }
}

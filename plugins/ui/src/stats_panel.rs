use std::collections::VecDeque;
use web_time::{Duration, Instant};

use bevy_ecs::prelude::*;
use close2gl_core::{Close2glFrame, PipelineSettings, Rasterizer, SoftwareFrame};

/// What the viewer measured, for the Stats section: one timer per view, the adapter, and what
/// the adapter cannot do.
#[derive(Resource, Debug, Default)]
pub struct ViewStats {
    pub adapter: String,
    pub limitations: Option<String>,
    pub reference: FrameTimer,
    pub close2gl: FrameTimer,
    /// During `--replay`: the frame being replayed and how many there are. Times are not
    /// shown then: a replay must draw the same window on every run, and times never repeat.
    pub replay: Option<(u32, u32)>,
    /// The two views' coverage agreement when they were last compared (the screenshot key,
    /// `ToolRequests::compare_views`), as `close2gl render` computes it.
    pub coverage_agreement: Option<f64>,
}

/// The frames of the last second: when each started and how long it took.
#[derive(Debug, Default)]
pub struct FrameTimer {
    frames: VecDeque<(Instant, Duration)>,
}

impl FrameTimer {
    const WINDOW: Duration = Duration::from_secs(1);

    pub fn record(&mut self, start: Instant, took: Duration) {
        self.frames.push_back((start, took));
        while self
            .frames
            .front()
            .is_some_and(|(t, _)| start.duration_since(*t) > Self::WINDOW)
        {
            self.frames.pop_front();
        }
    }

    /// Frames per second over the last second's frames; `None` below two frames (the viewer
    /// draws on demand, so an idle second has no rate).
    pub fn fps(&self) -> Option<f64> {
        let (first, _) = self.frames.front()?;
        let (last, _) = self.frames.back()?;
        let span = last.duration_since(*first).as_secs_f64();
        (self.frames.len() >= 2 && span > 0.0).then(|| (self.frames.len() - 1) as f64 / span)
    }

    /// Mean time a frame of this view took, milliseconds.
    pub fn mean_ms(&self) -> Option<f64> {
        let total: Duration = self.frames.iter().map(|(_, took)| *took).sum();
        (!self.frames.is_empty()).then(|| total.as_secs_f64() * 1e3 / self.frames.len() as f64)
    }
}

/// FPS and frame time of each view, the Close2GL stage counts and time, the adapter.
pub fn section(
    InMut(ui): InMut<egui::Ui>,
    stats: Res<ViewStats>,
    frame: Option<Res<Close2glFrame>>,
    settings: Option<Res<PipelineSettings>>,
    software: Option<Res<SoftwareFrame>>,
) {
    let timed = stats.replay.is_none();
    if let Some((frame, frames)) = stats.replay {
        ui.label(format!("Replaying frame {} of {frames}", frame + 1));
    }
    frame_rates(ui, &stats, timed);
    if let Some(frame) = frame {
        let drawn_in_software = settings.is_some_and(|s| s.close2gl_raster == Rasterizer::Software);
        let raster_ms = software
            .filter(|_| timed && drawn_in_software)
            .map(|image| image.raster_ms);
        counts(ui, &frame, timed.then_some(frame.geometry_ms), raster_ms);
    }
    ui.label(format!("Adapter: {}", stats.adapter));
    if let Some(limits) = &stats.limitations {
        ui.colored_label(ui.visuals().warn_fg_color, limits);
    }
}

/// Each view's frames a second and frame time (none while replaying: a replay's pace is not
/// the app's).
fn frame_rates(ui: &mut egui::Ui, stats: &ViewStats, timed: bool) {
    egui::Grid::new("stats_grid").num_columns(3).show(ui, |ui| {
        ui.label("");
        ui.label("FPS");
        ui.label("frame ms")
            .on_hover_text("Recording plus the GPU's work for the view, waited on.");
        ui.end_row();
        let timers = [
            ("Reference", &stats.reference),
            ("Close2GL", &stats.close2gl),
        ];
        for (name, timer) in timers.into_iter().filter(|_| timed) {
            ui.label(name);
            ui.monospace(number(timer.fps(), 1));
            ui.monospace(number(timer.mean_ms(), 2));
            ui.end_row();
        }
    });
}

/// The Close2GL stage's counts, and its times when given: the geometry's, and the software
/// rasterizer's when it draws.
fn counts(
    ui: &mut egui::Ui,
    frame: &Close2glFrame,
    geometry_ms: Option<f64>,
    raster_ms: Option<f64>,
) {
    let c = frame.counts;
    egui::Grid::new("counts_grid")
        .num_columns(4)
        .show(ui, |ui| {
            let rows = [
                [("Triangles in", c.triangles_in), ("Clipped", c.clipped)],
                [("Culled", c.culled), ("Drawn", c.drawn)],
            ];
            for row in rows {
                for (name, value) in row {
                    ui.label(name);
                    ui.monospace(value.to_string());
                }
                ui.end_row();
            }
            ui.label("2D primitives");
            ui.monospace(c.output_primitives.to_string());
            if let Some(ms) = geometry_ms {
                ui.label("Geometry");
                ui.monospace(format!("{ms:.2} ms"));
            }
            ui.end_row();
            if let Some(ms) = raster_ms {
                ui.label("Raster");
                ui.monospace(format!("{ms:.2} ms"));
                ui.end_row();
            }
        });
}

fn number(value: Option<f64>, decimals: usize) -> String {
    value.map_or_else(|| "–".to_string(), |v| format!("{v:.decimals$}"))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `t` plus `d`, checked: no arithmetic on an Instant can overflow, in tests either.
    fn after(t: Instant, d: Duration) -> Instant {
        t.checked_add(d)
            .expect("an instant seconds after the clock's reading")
    }

    #[test]
    fn fps_counts_the_frames_of_the_last_second() {
        let mut timer = FrameTimer::default();
        let t0 = Instant::now();
        assert_eq!(timer.fps(), None);
        for i in 0..=20 {
            timer.record(
                after(t0, Duration::from_millis(50 * i)),
                Duration::from_millis(4),
            );
        }
        // 21 frames 50 ms apart, the oldest ones past one second dropped: 20 fps.
        let fps = timer.fps().unwrap_or_default();
        assert!((fps - 20.0).abs() < 1e-6, "fps {fps}");
        assert!((timer.mean_ms().unwrap_or_default() - 4.0).abs() < 1e-9);
        timer.record(after(t0, Duration::from_secs(10)), Duration::from_millis(8));
        assert_eq!(timer.fps(), None, "a lone frame after a pause has no rate");
        assert_eq!(timer.mean_ms(), Some(8.0));
    }
}

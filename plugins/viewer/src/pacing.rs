//! When to draw: on demand (input, held keys, the panel's own animations), so that an idle
//! viewer sleeps, and with frame times that do not fling the camera after a pause.

use web_time::{Duration, Instant};

use winit::event_loop::ControlFlow;

/// How long to wait before drawing again a frame that a window could not present.
const RETRY_MISSED_FRAME: Duration = Duration::from_millis(50);

/// The time a frame covers when nothing was moving before it: one nominal frame.
const NOMINAL_FRAME: f32 = 1.0 / 60.0;

#[derive(Debug)]
pub struct Pacing {
    last_frame: Instant,
    /// Keys were held last frame: the camera is moving, so keep drawing.
    moving: bool,
    /// When the next frame is due by itself (the panel's animation, a missed frame).
    repaint_at: Option<Instant>,
}

impl Pacing {
    pub fn new(now: Instant) -> Self {
        Self {
            last_frame: now,
            moving: false,
            repaint_at: None,
        }
    }

    /// The seconds the frame starting `now` covers. The first frame of a hold has no previous
    /// moving frame to measure from: it counts as one nominal frame, so that a quick tap still
    /// moves the camera a little.
    pub fn frame_dt(&mut self, now: Instant) -> f32 {
        let dt = if self.moving {
            now.duration_since(self.last_frame).as_secs_f32()
        } else {
            NOMINAL_FRAME
        };
        self.last_frame = now;
        dt
    }

    /// After the frame that started `now`: whether to draw again at once. `held`: keys are down;
    /// `missed`: a window could not present, so it is drawn again shortly (otherwise the last
    /// camera move before an idle stretch could stay unseen); `continuous`: draw every frame;
    /// `repaint_delay`: when the panel wants to be drawn again.
    pub fn after_frame(
        &mut self,
        now: Instant,
        held: bool,
        missed: bool,
        continuous: bool,
        repaint_delay: Duration,
    ) -> bool {
        let was_moving = std::mem::replace(&mut self.moving, held);
        if missed {
            self.repaint_at = now.checked_add(RETRY_MISSED_FRAME);
            return false;
        }
        // One more frame after the camera stops, so the panel shows where it stopped.
        let again = held || was_moving || continuous || repaint_delay.is_zero();
        self.repaint_at = now.checked_add(repaint_delay).filter(|_| !again);
        again
    }

    /// Before the event loop sleeps: how long it may, and whether a frame is due now.
    pub fn wait(&mut self, now: Instant) -> (ControlFlow, bool) {
        match self.repaint_at {
            Some(at) if at <= now => {
                self.repaint_at = None;
                (ControlFlow::Wait, true)
            }
            Some(at) => (ControlFlow::WaitUntil(at), false),
            None => (ControlFlow::Wait, false),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `t` plus `d`, checked: no arithmetic on an Instant can overflow, in tests either.
    fn after(t: Instant, d: Duration) -> Instant {
        t.checked_add(d)
            .expect("an instant seconds after the clock's reading")
    }

    const IDLE: Duration = Duration::MAX;

    #[test]
    fn a_hold_is_timed_from_its_previous_frame_and_its_first_frame_is_nominal() {
        let t0 = Instant::now();
        let mut pacing = Pacing::new(t0);
        assert_eq!(
            pacing.frame_dt(after(t0, Duration::from_secs(5))),
            NOMINAL_FRAME
        );
        assert!(pacing.after_frame(t0, true, false, false, IDLE));
        let dt = pacing.frame_dt(after(t0, Duration::from_millis(5020)));
        assert!((dt - 0.02).abs() < 1e-6, "dt {dt}");
    }

    #[test]
    fn one_more_frame_after_the_keys_are_released_then_sleep() {
        let now = Instant::now();
        let mut pacing = Pacing::new(now);
        assert!(pacing.after_frame(now, true, false, false, IDLE));
        assert!(pacing.after_frame(now, false, false, false, IDLE));
        assert!(!pacing.after_frame(now, false, false, false, IDLE));
        assert_eq!(pacing.wait(now), (ControlFlow::Wait, false));
    }

    #[test]
    fn a_missed_frame_and_the_panels_animation_wake_the_loop_later() {
        let now = Instant::now();
        let mut pacing = Pacing::new(now);
        assert!(!pacing.after_frame(now, false, true, false, IDLE));
        let due = after(now, RETRY_MISSED_FRAME);
        assert_eq!(pacing.wait(now), (ControlFlow::WaitUntil(due), false));
        assert_eq!(pacing.wait(due), (ControlFlow::Wait, true));

        let blink = Duration::from_millis(500);
        assert!(!pacing.after_frame(now, false, false, false, blink));
        assert_eq!(
            pacing.wait(now),
            (ControlFlow::WaitUntil(after(now, blink)), false)
        );
    }

    #[test]
    fn a_pacing_started_at_the_clocks_first_reading_never_overflows() {
        // A page's clock starts at zero: nothing may be subtracted from its first reading, and
        // an idle panel's "never" (Duration::MAX) is no deadline rather than an overflow.
        let zero = Instant::now();
        let mut pacing = Pacing::new(zero);
        assert_eq!(pacing.frame_dt(zero), NOMINAL_FRAME);
        assert!(pacing.after_frame(zero, true, false, false, IDLE));
        assert_eq!(pacing.frame_dt(zero), 0.0);
        assert!(pacing.after_frame(zero, false, false, false, IDLE));
        assert!(!pacing.after_frame(zero, false, false, false, IDLE));
        assert_eq!(pacing.wait(zero), (ControlFlow::Wait, false));
        assert!(!pacing.after_frame(zero, false, true, false, IDLE));
        let retry = ControlFlow::WaitUntil(after(zero, RETRY_MISSED_FRAME));
        assert_eq!(pacing.wait(zero), (retry, false));
    }
}

//! How long the page's link must wait before it changes again. No arithmetic on an `Instant`:
//! in a browser `web_time::Instant` counts from the page's start, so "the last write was one
//! period ago" cannot be written as `now - period` in a page younger than the period (it
//! underflowed and panicked in a page started within 250 ms). "Never written" is `None`.

use web_time::{Duration, Instant};

/// When the link last changed, if it ever did.
#[derive(Debug, Default)]
pub struct LinkThrottle {
    last: Option<Instant>,
}

impl LinkThrottle {
    /// How often the link may change while the camera moves: often enough to be current when
    /// copied, rarely enough that the browser is not asked on every frame of a drag.
    pub const PERIOD: Duration = Duration::from_millis(250);

    /// How long a change at `now` must wait (zero: write it now).
    pub fn wait(&self, now: Instant) -> Duration {
        self.last.map_or(Duration::ZERO, |last| {
            Self::PERIOD.saturating_sub(now.saturating_duration_since(last))
        })
    }

    /// The link changed at `now`.
    pub fn wrote(&mut self, now: Instant) {
        self.last = Some(now);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn later(at: Instant, millis: u64) -> Instant {
        at.checked_add(Duration::from_millis(millis))
            .expect("a test instant a few milliseconds on")
    }

    #[test]
    fn a_link_never_written_is_written_at_once_whenever_the_clock_starts() {
        // The earliest instant the clock gives this process: a page's time zero, where the
        // old `now - PERIOD` panicked.
        let zero = Instant::now();
        assert_eq!(LinkThrottle::default().wait(zero), Duration::ZERO);
    }

    #[test]
    fn a_write_holds_the_next_for_one_period_from_time_zero() {
        let zero = Instant::now();
        let mut throttle = LinkThrottle::default();
        throttle.wrote(zero);
        assert_eq!(throttle.wait(zero), LinkThrottle::PERIOD);
        assert_eq!(throttle.wait(later(zero, 100)), Duration::from_millis(150));
        assert_eq!(throttle.wait(later(zero, 250)), Duration::ZERO);
        assert_eq!(throttle.wait(later(zero, 10_000)), Duration::ZERO);
    }

    #[test]
    fn a_clock_read_before_the_last_write_waits_one_period_without_panicking() {
        let zero = Instant::now();
        let mut throttle = LinkThrottle::default();
        throttle.wrote(later(zero, 40));
        assert_eq!(throttle.wait(zero), LinkThrottle::PERIOD);
    }
}

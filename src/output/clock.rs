//! When an output acts: sample times on a regular grid and listed snapshot times. Outputs never move
//! the clock: a sample or snapshot is taken at the first time level at or after its time and records the
//! level's actual time. Only events land the clock on their times ([`crate::run`]).

/// Levels closer than this fraction of the nominal step to a requested time count as reaching it.
pub const LANDING: f64 = 1.0e-9;

/// A regular grid of sample times `k h`, `k = 0, 1, ...`.
#[derive(Clone, Debug)]
pub struct SampleClock {
    interval_s: f64,
    /// the next sample time [s]: `k h` for the next grid index `k`, or just above the last sample's time
    /// when the grid is finer than the resolution of `t`
    next_s: f64,
}

impl SampleClock {
    /// Samples every `interval_s` [s] (> 0), starting at `t = 0`.
    pub fn new(interval_s: f64) -> Self {
        SampleClock { interval_s, next_s: 0.0 }
    }

    /// Whether the level at `t_s` takes a sample (then the next one is the first grid time after it).
    /// Constant work per call, however small the interval.
    ///
    /// The next sample time is always strictly after `t_s + tol_s`: when the grid is finer than the
    /// resolution of `t` (an interval of 1e-300 s: `floor((t + tol) / h) + 1` rounds back to
    /// `(t + tol) / h`, or overflows to infinity), the next sample is due at the next representable time
    /// after `t_s + tol_s`, i.e. at the next level. So the clock never samples twice at one time and never
    /// stops sampling.
    pub fn due(&mut self, t_s: f64, tol_s: f64) -> bool {
        if t_s < self.quiet_until_s(tol_s) {
            return false;
        }
        let reached = t_s + tol_s;
        let next_k = (reached / self.interval_s).floor() + 1.0;
        let next_s = next_k * self.interval_s;
        // Not `next_s <= reached`: a NaN or infinite grid time must fall back too.
        self.next_s = if next_s > reached && next_s.is_finite() { next_s } else { reached.next_up() };
        true
    }

    /// The next sample time [s] (strictly after the last sample's time plus the tolerance).
    pub fn next_s(&self) -> f64 {
        self.next_s
    }

    /// The level time [s] below which [`SampleClock::due`] with the tolerance `tol_s` [s] is false: its
    /// own test, `t_s < next - tol_s`.
    #[inline(always)]
    pub fn quiet_until_s(&self, tol_s: f64) -> f64 {
        self.next_s - tol_s
    }
}

/// Listed times (sorted), each taken once at the first level at or after it.
#[derive(Clone, Debug)]
pub struct ListClock {
    times_s: Vec<f64>,
    next: usize,
}

impl ListClock {
    /// The times, sorted here (a NaN, which no level reaches, is dropped: it would hold back the times
    /// after it).
    pub fn new(mut times_s: Vec<f64>) -> Self {
        times_s.retain(|t| !t.is_nan());
        times_s.sort_by(f64::total_cmp);
        ListClock { times_s, next: 0 }
    }

    /// A level time below which [`ListClock::due`] with the tolerance `tol_s >= 0` [s] is false for every
    /// level time `t >= 0` [s] (`+inf` once every listed time was taken): `T - 2 tol - 8 eps T` for the next
    /// listed time `T >= 0`. Below it (computed with two roundings of at most `eps T / 2` each), `t + tol <
    /// T - tol - 7 eps T`, and `t + tol` rounds to less than `T`: the test `T <= t + tol` fails.
    pub fn quiet_until_s(&self, tol_s: f64) -> f64 {
        match self.times_s.get(self.next) {
            Some(&t) => t - 2.0 * tol_s - 8.0 * f64::EPSILON * t.abs(),
            None => f64::INFINITY,
        }
    }

    /// Whether one or more listed times were reached at `t_s` (all of them are then consumed: one level,
    /// one snapshot).
    pub fn due(&mut self, t_s: f64, tol_s: f64) -> bool {
        let before = self.next;
        while self.next < self.times_s.len() && self.times_s[self.next] <= t_s + tol_s {
            self.next += 1;
        }
        self.next > before
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Below [`ListClock::quiet_until_s`] no level is due, just below the time it gives and far below;
    /// and it lies within a few roundings of `T - tol` (so a sampled output is skipped at nearly every
    /// level before its time, and at none where it is due).
    #[test]
    fn no_listed_time_is_due_below_the_quiet_time() {
        for t_next in [0.0, 5e-324, 1e-3, 0.1, 1.0, 2.0, 3.000_000_1, 17.25, 1e5, 2.0_f64.powi(40)] {
            for tol in [0.0, 1e-300, 1e-15, 4e-13, 1e-9, 0.25] {
                let q = ListClock::new(vec![t_next]).quiet_until_s(tol);
                assert!(q >= t_next - 3.0 * tol - 16.0 * f64::EPSILON * t_next, "{t_next} {tol}: {q}");
                let mut t = q.next_down();
                for _ in 0..40 {
                    if t < 0.0 {
                        break;
                    }
                    assert!(!ListClock::new(vec![t_next]).due(t, tol), "{t_next} {tol}: due at {t} < {q}");
                    t = if t > 1e-300 { t - (q - t).max(t * 1e-15) } else { t.next_down() };
                }
            }
        }
        assert_eq!(ListClock::new(vec![]).quiet_until_s(1e-9), f64::INFINITY);
    }

    /// Levels `t_k = k dt` from `t0`; every call must take a sample when the interval is below `dt`.
    fn levels(interval: f64, t0: f64, dt: f64, count: usize) {
        let mut c = SampleClock::new(interval);
        let tol = LANDING * dt;
        let mut taken = 0;
        for k in 0..count {
            let t = t0 + k as f64 * dt;
            if c.due(t, tol) {
                taken += 1;
            }
            assert!(c.next_s() > t + tol, "interval {interval}, t = {t}: next {} not after t", c.next_s());
            // The same level again takes no second sample.
            assert!(!c.due(t, tol), "interval {interval}: sampled twice at t = {t}");
        }
        if interval < dt {
            assert_eq!(taken, count, "interval {interval} below dt = {dt}: every level samples");
        }
    }

    #[test]
    fn sample_clock_always_advances_past_t() {
        for interval in [1e-300, 1e-310, 1e-12, 1e-3, 0.05, 7.0] {
            for (t0, dt) in [(0.0, 1e-4), (1.0, 1e-9), (1e6, 1e-3), (1e6, 1e-9), (3e5, 0.1)] {
                levels(interval, t0, dt, 200);
            }
        }
        // A level exactly on t = 0 with no tolerance, then one a single ulp later.
        let mut c = SampleClock::new(1e-300);
        assert!(c.due(0.0, 0.0));
        assert!(c.next_s() > 0.0);
        assert!(!c.due(0.0, 0.0));
        assert!(c.due(1e-300, 0.0));
        let mut c = SampleClock::new(1e-300);
        assert!(c.due(1e6, 0.0));
        assert!(!c.due(1e6, 0.0));
        assert!(c.due(1e6_f64.next_up(), 0.0));
    }

    #[test]
    fn sample_clock_keeps_its_grid() {
        // Interval 0.05 s, steps of 0.012 s: samples at the first level at or after each k * 0.05.
        let mut c = SampleClock::new(0.05);
        let taken: Vec<usize> = (0..30).filter(|&k| c.due(k as f64 * 0.012, 1e-12)).collect();
        assert_eq!(taken, vec![0, 5, 9, 13, 17, 21, 25]);
    }

    #[test]
    fn list_clock_consumes_each_time_once() {
        let mut c = ListClock::new(vec![0.3, f64::NAN, 0.1, 0.1, -f64::NAN, 1e300]);
        assert!(!c.due(0.05, 0.0));
        assert!(c.due(0.1, 0.0));
        assert!(!c.due(0.1, 0.0));
        assert!(c.due(0.5, 0.0));
        assert!(!c.due(1e6, 0.0));
        assert!(c.due(f64::INFINITY, 0.0));
        assert!(!c.due(f64::INFINITY, 0.0));
    }
}

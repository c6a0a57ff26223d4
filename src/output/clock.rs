//! When an output acts: sample times on a regular grid and listed snapshot times. Outputs never move
//! the clock: a sample or snapshot is taken at the first time level at or after its time and records the
//! level's actual time. Only events land the clock on their times ([`crate::run`]).

/// Levels closer than this fraction of the nominal step to a requested time count as reaching it.
pub const LANDING: f64 = 1.0e-9;

/// A regular grid of sample times `k h`, `k = 0, 1, ...`.
#[derive(Clone, Debug)]
pub struct SampleClock {
    interval_s: f64,
    next_k: f64,
}

impl SampleClock {
    /// Samples every `interval_s` [s] (> 0), starting at `t = 0`.
    pub fn new(interval_s: f64) -> Self {
        SampleClock { interval_s, next_k: 0.0 }
    }

    /// Whether the level at `t_s` takes a sample (then the next one is the first grid time after it).
    /// Constant work per call, however small the interval.
    pub fn due(&mut self, t_s: f64, tol_s: f64) -> bool {
        if t_s < self.next_k * self.interval_s - tol_s {
            return false;
        }
        self.next_k = ((t_s + tol_s) / self.interval_s).floor() + 1.0;
        true
    }
}

/// Listed times (sorted), each taken once at the first level at or after it.
#[derive(Clone, Debug)]
pub struct ListClock {
    times_s: Vec<f64>,
    next: usize,
}

impl ListClock {
    /// The times, sorted here.
    pub fn new(mut times_s: Vec<f64>) -> Self {
        times_s.sort_by(f64::total_cmp);
        ListClock { times_s, next: 0 }
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

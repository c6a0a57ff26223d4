//! The conductor's temperature from its current and the weather during a run (`[thermal]`,
//! [`crate::scenario::thermal`]): a temperature history computed before the run, interpolated linearly at
//! every time level and set on every segment, whose stress-free lengths follow by (5.5)
//! ([`Wire::update_rest_lengths`]).

use crate::wire::Wire;

/// A temperature history being played onto the wire.
#[derive(Clone, Debug)]
pub struct Heating {
    /// `(t [s], T [K])`, times increasing
    samples: Vec<(f64, f64)>,
    /// index of the sample at or before the last time asked for
    cursor: usize,
}

impl Heating {
    /// Play `samples` (`(t [s], T [K])`, times increasing, at least one).
    pub fn new(samples: Vec<(f64, f64)>) -> Self {
        assert!(!samples.is_empty(), "a temperature history needs a sample");
        Heating { samples, cursor: 0 }
    }

    /// The temperature at `t` [K]: linear between the samples around `t`, the first or last outside them.
    pub fn temperature_at(&mut self, t: f64) -> f64 {
        let s = &self.samples;
        if t <= s[0].0 {
            return s[0].1;
        }
        if t < s[self.cursor].0 {
            self.cursor = 0;
        }
        while self.cursor + 1 < s.len() && s[self.cursor + 1].0 <= t {
            self.cursor += 1;
        }
        let k = self.cursor;
        if k + 1 == s.len() {
            return s[k].1;
        }
        let ((t0, a), (t1, b)) = (s[k], s[k + 1]);
        if t1 == t0 { b } else { a + (b - a) * (t - t0) / (t1 - t0) }
    }

    /// Set the temperature at `t` [s] on every segment of `wire` and rescale the stress-free lengths.
    pub fn apply(&mut self, wire: &mut Wire, t: f64) {
        let temp = self.temperature_at(t);
        wire.temperature_k.fill(temp);
        wire.update_rest_lengths();
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolates_and_holds_the_ends() {
        let mut h = Heating::new(vec![(0.0, 300.0), (10.0, 310.0), (10.0, 320.0), (20.0, 320.0)]);
        assert_eq!(h.temperature_at(-1.0), 300.0);
        assert_eq!(h.temperature_at(5.0), 305.0);
        assert_eq!(h.temperature_at(10.0), 320.0);
        assert_eq!(h.temperature_at(15.0), 320.0);
        assert_eq!(h.temperature_at(2.5), 302.5, "going back in time restarts the search");
        assert_eq!(h.temperature_at(99.0), 320.0);
    }
}

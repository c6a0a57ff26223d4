//! The conductor's temperature from its current and the weather during a run (`[thermal]`,
//! [`crate::scenario::thermal`]): a temperature history computed before the run, interpolated linearly at
//! every time level and set on every segment, whose stress-free lengths follow by (5.5)
//! ([`crate::wire::Wire::update_rest_lengths`]).

use crate::scheme::Explicit;

/// A temperature history being played onto the wire.
#[derive(Clone, Debug)]
pub struct Heating {
    /// `(t [s], T [K])`, times increasing
    samples: Vec<(f64, f64)>,
    /// index of the sample at or before the last time asked for
    cursor: usize,
    /// the bits of the temperature last set and the solver's wire stamp after setting it
    held: Option<(u64, u64)>,
}

impl Heating {
    /// Play `samples` (`(t [s], T [K])`, times increasing, at least one).
    pub fn new(samples: Vec<(f64, f64)>) -> Self {
        assert!(!samples.is_empty(), "a temperature history needs a sample");
        Heating { samples, cursor: 0, held: None }
    }

    /// The temperature at `t` [K]: linear between the samples around `t`, the first or last outside them.
    #[inline]
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

    /// Set the temperature at `t` [s] on every segment of the solver's wire and rescale the stress-free
    /// lengths. Where this history set the same temperature (bit for bit) last and nothing changed the
    /// wire since (its [`Explicit::wire_stamp`] is the one read after that setting: a history that stays
    /// at one temperature, such as the melting ice's 0 C for most of case d), setting it again would write
    /// the bits already there: nothing is written and the wire is not taken mutably, so the solver keeps
    /// what it derives from the wire (`1 / l0` per segment, whether any segment is viscous) instead of
    /// recomputing it from the same bits. The forces of the level are evaluated after this in any case.
    pub fn apply(&mut self, solver: &mut Explicit, t: f64) {
        let temp = self.temperature_at(t);
        if self.held == Some((temp.to_bits(), solver.wire_stamp())) {
            return;
        }
        // The bits of filling the temperatures and `Wire::update_rest_lengths` through `wire_mut`, with the
        // thermal factor formed once and the solver's viscous flag kept (`Explicit::set_uniform_temperature`).
        solver.set_uniform_temperature(temp);
        self.held = Some((temp.to_bits(), solver.wire_stamp()));
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

    /// A history that warms, holds, warms and holds again: the run that skips the levels where the wire
    /// holds the temperature already (set last by the history, the wire not changed since) is bit for
    /// bit the run that sets it every step.
    #[test]
    fn holding_a_temperature_skips_nothing_that_counts() {
        use crate::scheme::configs::Config;
        let mut skip = Config::Wind3d.solver(40);
        skip.wire_mut().thermal_expansion_per_k = 1.9e-5;
        let mut every = skip.clone();
        let dt = skip.params().dt_s;
        let samples = vec![(0.0, 288.15), (50.0 * dt, 300.0), (150.0 * dt, 300.0), (200.0 * dt, 310.0)];
        let (mut a, mut b) = (Heating::new(samples.clone()), Heating::new(samples));
        let mut held = 0;
        for n in 0..300 {
            let t = skip.time_s();
            let stamp = skip.wire_stamp();
            if n == 120 {
                // Another change of the wire (here none of its values) between two levels at 300 K.
                skip.wire_mut();
                every.wire_mut();
            }
            a.apply(&mut skip, t);
            held += usize::from(skip.wire_stamp() == stamp);
            let temp = b.temperature_at(t);
            // The reference sets every level the way `set` did before the factor was hoisted.
            let w = every.wire_mut();
            w.temperature_k.fill(temp);
            w.update_rest_lengths();
            for s in [&mut skip, &mut every] {
                s.evaluate_forces();
                s.step(dt).unwrap();
            }
        }
        assert!(held > 150, "only {held} levels held the temperature");
        for k in 0..3 {
            for (p, q) in skip.wire().x[k].iter().zip(&every.wire().x[k]) {
                assert_eq!(p.to_bits(), q.to_bits());
            }
            for (p, q) in skip.wire().v[k].iter().zip(&every.wire().v[k]) {
                assert_eq!(p.to_bits(), q.to_bits());
            }
        }
        for (p, q) in skip.wire().rest_length.iter().zip(&every.wire().rest_length) {
            assert_eq!(p.to_bits(), q.to_bits());
        }
    }
}

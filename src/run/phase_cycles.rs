//! Where a run's time goes: the time-stamp-counter cycles per step of each phase of a run loop, printed
//! to standard error when the loop ends. [`super::run_loop`] (a conductor or a section) counts the forces
//! of a level ([`crate::scheme::Explicit::evaluate_forces`]: the segment pass and the strings), the step
//! ([`crate::scheme::Explicit::step`]: the node pass and the ground contact) and each observer by its type;
//! [`super::line::run_line_observed`] (a line) counts the line's forces (with the links and the
//! short-circuit pair forces), the short-circuit observer, the conductors' outputs, the clearances
//! between conductors, the links' and towers' peaks with the line's samples, and the step. What no phase
//! holds (events, the step length, the readings themselves) is printed as the rest of the loop.
//! `app/benches/phase_table.sh` tabulates them for every case and example.
//!
//! Compiled only with the cargo feature `phase-timing` (`cargo build --release -p ohl-app --features
//! ohl/phase-timing`); without it [`PhaseClock`] is an empty type whose methods do nothing (the phases'
//! names are not even formed), so a normal build's loop carries no trace of it: the instructions of a run
//! are those of a build without the counters (callgrind, the IEC ice-and-wind example's whole run:
//! 3,118,992,808 before the counters were written, 3,118,998,082 after, none of the difference per step).
//! A reading is one `rdtsc` on x86-64 (some tens of cycles; it does not wait for the
//! instructions before it, so a phase of a few hundred cycles is read to within some tens), elsewhere the
//! monotonic clock in nanoseconds. The counter runs at a fixed rate (the nominal clock, not the boosted
//! one): the phases' shares are what it is for, and the readings add a few percent to the loop. Counting
//! never changes the trajectory: it reads a counter and nothing else.

#[cfg(feature = "phase-timing")]
mod on {
    /// The counters of one run loop: one per phase.
    pub struct PhaseClock {
        start: u64,
        started: std::time::Instant,
        phases: Vec<(String, u64)>,
        steps: u64,
    }

    impl PhaseClock {
        /// Counters for the phases `names` (indexed in that order by [`PhaseClock::add`]), started now.
        pub fn new(names: impl Iterator<Item = String>) -> Self {
            let mut clock = PhaseClock {
                start: 0,
                started: std::time::Instant::now(),
                phases: names.map(|n| (n, 0)).collect(),
                steps: 0,
            };
            clock.start = clock.mark();
            clock
        }

        /// A reading, to pass to [`PhaseClock::add`] after the phase: `rdtsc` on x86-64, elsewhere the
        /// nanoseconds since the clock started.
        #[inline(always)]
        pub fn mark(&self) -> u64 {
            #[cfg(target_arch = "x86_64")]
            {
                // SAFETY: `rdtsc` exists on every x86-64 processor and has no memory effects.
                unsafe { core::arch::x86_64::_rdtsc() }
            }
            #[cfg(not(target_arch = "x86_64"))]
            {
                self.started.elapsed().as_nanos() as u64
            }
        }

        /// Phase `k` took the time since `from`.
        #[inline(always)]
        pub fn add(&mut self, k: usize, from: u64) {
            self.phases[k].1 += self.mark() - from;
        }

        /// One more step (the divisor of the report).
        #[inline(always)]
        pub fn count_step(&mut self) {
            self.steps += 1;
        }

        /// Print the counters per step, each with its share of the loop, to standard error.
        pub fn report(&self) {
            let total = self.mark() - self.start;
            let seconds = self.started.elapsed().as_secs_f64();
            let steps = self.steps.max(1) as f64;
            let share = |c: u64| 100.0 * c as f64 / total.max(1) as f64;
            let line = |what: &str, c: u64| eprintln!("  {:>10.1} ({:5.1} %)  {what}", c as f64 / steps, share(c));
            eprintln!(
                "phase cycles per step ({} steps; time-stamp counter, {:.4} GHz over the loop's wall time):",
                self.steps,
                total as f64 / seconds.max(1e-9) / 1e9
            );
            let mut rest = total as i128;
            for (name, c) in &self.phases {
                rest -= *c as i128;
                line(name, *c);
            }
            line("rest of the loop (events, step length, readings)", rest.max(0) as u64);
            line("whole loop", total);
        }
    }
}

#[cfg(not(feature = "phase-timing"))]
mod off {
    /// Without the feature `phase-timing`: nothing is counted (the phases' names are not even formed).
    pub struct PhaseClock;

    impl PhaseClock {
        #[inline(always)]
        pub fn new(_names: impl Iterator<Item = String>) -> Self {
            PhaseClock
        }
        #[inline(always)]
        pub fn mark(&self) -> u64 {
            0
        }
        #[inline(always)]
        pub fn add(&mut self, _k: usize, _from: u64) {}
        #[inline(always)]
        pub fn count_step(&mut self) {}
        #[inline(always)]
        pub fn report(&self) {}
    }
}

#[cfg(not(feature = "phase-timing"))]
pub(crate) use off::PhaseClock;
#[cfg(feature = "phase-timing")]
pub(crate) use on::PhaseClock;

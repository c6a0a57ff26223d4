//! What a run tells the outputs: every time level, every event, and the end.
//!
//! The loop ([`crate::run::run_loop`]) notifies each [`Observer`] once per time level, after the events due
//! at that level were applied and the segment forces of the level evaluated
//! ([`Explicit::evaluate_forces`]), so that an observer reads the state (positions, velocities at
//! `n - 1/2`, the largest tension, the support forces) at no extra cost and cannot change it: it gets a
//! shared reference. Asking for more output therefore never changes the trajectory. An observer decides
//! by itself whether a level concerns it (a sample time has been reached, a snapshot is due), and may
//! tell the loop until when none will ([`Control::QuietUntil`]); peaks and settling are tracked at every
//! level.

use crate::scheme::{Explicit, Instability};

/// One time level as the observers see it.
#[derive(Clone, Copy)]
pub struct Level<'a> {
    /// the solver at time `t_n`, forces evaluated
    pub solver: &'a Explicit,
    /// time `t_n` [s]
    pub t_s: f64,
    /// dimensionless time per second, `U / l` [1/s] (`tau = t U / l`, section 2)
    pub tau_per_s: f64,
}

impl Level<'_> {
    /// Dimensionless time `tau = t U / l` of this level [-].
    pub fn tau(&self) -> f64 {
        self.t_s * self.tau_per_s
    }
}

/// What an observer asks of the loop after a level.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Control {
    /// go on
    Continue,
    /// go on, and skip this observer at the levels before this time [s] (`t_n < t`): its
    /// [`Observer::observe`] would do nothing there and answer [`Control::QuietUntil`] with the same time
    /// (a sampled output before its next sample time, by its own clock's test; the time step does not
    /// change during a run). A loop may call it at those levels all the same.
    QuietUntil(f64),
    /// the wire has settled: the run may stop here once no event is pending
    Settled,
}

/// How a run ended.
#[derive(Clone, Debug, PartialEq)]
pub enum Ending {
    /// the end time was reached
    Completed,
    /// the wire settled after the last event
    Settled,
    /// the time cap of a run until settled was reached first
    NotSettled,
    /// the scheme went unstable; the state is that of the failed step
    Unstable(Instability),
}

impl Ending {
    /// The status word of `summary.json`.
    pub fn status(&self) -> &'static str {
        match self {
            Ending::Completed => "completed",
            Ending::Settled => "settled",
            Ending::NotSettled => "not_settled",
            Ending::Unstable(_) => "unstable",
        }
    }
}

/// An output that failed to be written.
#[derive(Debug, thiserror::Error)]
#[error("cannot write {path}: {source}")]
pub struct OutputError {
    /// the file
    pub path: String,
    /// the I/O error
    pub source: std::io::Error,
}

impl OutputError {
    /// The error of writing `path`.
    pub fn at(path: &std::path::Path) -> impl FnOnce(std::io::Error) -> OutputError + '_ {
        move |source| OutputError { path: path.display().to_string(), source }
    }
}

/// An output, a tracker or a stop criterion of a run. A new output is one type implementing this and
/// one line adding it to the run's list of observers.
pub trait Observer {
    /// Every time level, in order.
    fn observe(&mut self, level: &Level) -> Result<Control, OutputError>;
    /// Events were applied at time `t_s` [s] (called before [`Observer::observe`] of that level).
    fn event(&mut self, _t_s: f64, _what: &str) {}
    /// Once at the end. `level` is the final state (already observed unless the run went unstable).
    fn finish(&mut self, _level: &Level, _ending: &Ending) -> Result<(), OutputError> {
        Ok(())
    }
    /// The observer's type, for diagnostics (the cycles per phase of a run, `phase-timing`).
    fn name(&self) -> &'static str {
        std::any::type_name::<Self>()
    }
}

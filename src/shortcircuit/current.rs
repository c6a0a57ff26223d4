//! The fault current of each phase as a function of time (issue 25): the symmetrical a.c. component and
//! the decaying d.c. component of a short circuit fed through a source impedance `R + jX`, with the fault's
//! kind, its inception angle, its duration and an optional auto-reclose onto the fault.
//!
//! # Equations
//!
//! A sinusoidal source `u(t) = sqrt(2) U sin(w t + g)` switched at `t' = 0` onto a series `R`, `L` circuit
//! (`X = w L`) drives the current (the solution of `L di/dt + R i = u` with `i(0) = 0`; any circuit
//! textbook, e.g. Kasikci, "Short Circuits in Power Systems", 2nd ed., 2018, section 3.1; IEC 60909-1:2002
//! figure 1; Grainger and Stevenson, "Power System Analysis", 1994, section 10.1):
//!
//! ```text
//! i(t) = sqrt(2) I''k [ sin(w t' + g - phi_k) - sin(g - phi_k) exp(-t'/tau) ],   t' = t - t_inception,
//! phi_k = atan(X / R),   tau = X / (w R),   w = 2 pi f.
//! ```
//!
//! `I''k` [A] is the initial symmetrical short-circuit current (r.m.s.) of the fault kind given:
//!
//! - [`FaultKind::ThreePhase`]: `I''k = I''k3`; phase `L` has the voltage angle `g_L`: `g_L1 = gamma`,
//!   `g_L2 = gamma - 120 deg`, `g_L3 = gamma + 120 deg`. The three currents sum to zero at every instant
//!   (their a.c. parts are a symmetrical set, their d.c. parts `sin(g_L - phi_k)` sum to zero).
//! - [`FaultKind::LineToLine`]: `I''k = I''k2` (IEC 60909-0:2016, 8.1: `I''k2 = sqrt(3)/2 I''k3` for equal
//!   positive- and negative-sequence impedances; the caller passes `I''k2` itself) flows out through L1 and
//!   back through L2, driven by the line-to-line voltage `u_L1 - u_L2`, whose angle is `gamma + 30 deg`:
//!   `i_L1 = i`, `i_L2 = -i_L1`, `i_L3 = 0`.
//! - [`FaultKind::LineToEarth`]: `I''k = I''k1` in L1 only, with the angle `gamma` (the return through the
//!   earth is no conductor of the line model), `i_L2 = i_L3 = 0`.
//!
//! Outside the intervals of current flow every current is zero. The breaker interrupts at
//! `t_start + T_k1` exactly, not at a current zero (a real breaker clears at the next zero of each phase,
//! at most half a cycle later): the model keeps the duration the user states, and its Joule integral is
//! that of the interval `[t_start, t_start + T_k1)`. An auto-reclose onto the persisting fault starts the
//! same waveform again at `t_start + T_k1 + dead_time` for its own duration, with the same inception
//! angle `gamma` (the reclosing instant is not synchronised to the voltage: the same angle, worst case by
//! default, is the conservative choice).
//!
//! # The peak factor
//!
//! `kappa = 1.02 + 0.98 exp(-3 R/X)` (IEC 60909-0:2016, equation (55)), the ratio of the peak
//! short-circuit current `i_p` to `sqrt(2) I''k`. The standard's formula is a fit of the largest peak of
//! the waveform above over all inception angles; `tests/fault_current.rs` measures it against that peak
//! (found by scanning the angle): within 0.53 % for `R/X` in `[0.05, 1]`. Its inverse is
//! `R/X = -ln((kappa - 1.02) / 0.98) / 3` for `kappa` in `(1.02, 2]`.
//!
//! # The worst case
//!
//! With no inception angle given, `gamma` is chosen for the full d.c. offset (`g - phi_k = -90 deg`, the
//! d.c. component starts at its largest, `sqrt(2) I''k`). It maximises the d.c. component, which drives
//! the impulse `int i^2 dt` of the first cycles that throws a flexible conductor out (IEC 60865-1 takes
//! the swing-out from the Joule integral, not from the peak), and gives a peak near `kappa sqrt(2) I''k`:
//! the largest peak over all angles is reached slightly off the full offset, and the full-offset peak is
//! below it by 0.06 % at `R/X = 0.05`, 0.7 % at 0.2 and 2.4 % at 0.5 to 1 (`tests/fault_current.rs`).
//! Which phase:
//!
//! - line-to-line: the full offset of the loop current, `gamma + 30 deg = phi_k - 90 deg`: the largest peak
//!   of the current both conductors carry, so the largest force between them (`i^2`);
//! - three-phase: the full offset in the centre phase L2, `gamma - 120 deg = phi_k - 90 deg`: the largest
//!   current peak in the centre conductor of a flat arrangement, the one IEC 60865-1 (clause 5.2 and the
//!   factor 0.75 of equation (19a) for flexible conductors) takes as carrying the largest force;
//! - line-to-earth: the full offset in L1, `gamma = phi_k - 90 deg`.

// Units in brackets, `[N]`, `[m]`, `[A]`, would otherwise be taken for intra-doc links.
#![allow(rustdoc::broken_intra_doc_links)]

/// Which phases carry the fault current.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FaultKind {
    /// a balanced three-phase fault (`I''k3` in L1, L2, L3)
    ThreePhase,
    /// a fault between L1 and L2 (`I''k2` out through L1, back through L2)
    LineToLine,
    /// a fault from L1 to earth (`I''k1` in L1 only)
    LineToEarth,
}

/// An auto-reclose onto the persisting fault.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Reclose {
    /// dead time between the interruption of the first flow and the reclose [s], > 0
    pub dead_time_s: f64,
    /// duration of the second current flow `T_k2` [s], > 0
    pub duration_s: f64,
}

/// The fault as the user gives it (validated by [`FaultCurrent::new`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FaultCurrentSpec {
    /// what kind of fault
    pub kind: FaultKind,
    /// `I''k`, initial symmetrical short-circuit current of this kind of fault, r.m.s. [A], > 0 (`I''k3`,
    /// `I''k2` or `I''k1`: module docs)
    pub initial_current_a: f64,
    /// `f`, system frequency [Hz], > 0
    pub frequency_hz: f64,
    /// `R/X` of the source impedance [-], >= 0 (the d.c. time constant is `X / (w R)`; 0: no decay)
    pub r_over_x: f64,
    /// voltage phase angle `gamma` of L1 at inception [deg]; `None`: the worst case (module docs)
    pub inception_angle_deg: Option<f64>,
    /// fault inception time `t_start` [s], >= 0
    pub start_s: f64,
    /// `T_k1`, duration of the first current flow [s], > 0
    pub duration_s: f64,
    /// an auto-reclose onto the fault, if any
    pub reclose: Option<Reclose>,
}

/// A value of a [`FaultCurrentSpec`] outside its range.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum CurrentError {
    /// a field outside its allowed range
    #[error("{field} = {value} must be {allowed}")]
    Value {
        /// the field, as [`FaultCurrentSpec`] names it (`reclose.dead_time_s` for a reclose's)
        field: &'static str,
        /// the value given
        value: f64,
        /// the allowed range
        allowed: &'static str,
    },
}

/// A validated fault current ([`FaultCurrent::new`]).
#[derive(Clone, Debug, PartialEq)]
pub struct FaultCurrent {
    spec: FaultCurrentSpec,
    /// `w = 2 pi f` [rad/s]
    omega: f64,
    /// `phi_k = atan(X/R)` [rad]
    phi: f64,
    /// `1 / tau = w R/X` [1/s] (0: no decay)
    inv_tau: f64,
    /// `gamma` [rad], resolved
    gamma: f64,
    /// `sin(g_L - phi_k)`, `cos(g_L - phi_k)` per phase (zero for a phase without current)
    offset: [(f64, f64); 3],
    /// current per unit waveform per phase: `sqrt(2) I''k` times +1, -1 or 0
    amplitude: [f64; 3],
    /// the flow intervals `[start, end)` [s]
    intervals: [(f64, f64); 2],
    /// how many of `intervals` are used (1 or 2)
    flows: usize,
}

fn check(field: &'static str, v: f64, ok: bool, allowed: &'static str) -> Result<(), CurrentError> {
    if v.is_finite() && ok { Ok(()) } else { Err(CurrentError::Value { field, value: v, allowed }) }
}

impl FaultCurrent {
    /// Validate the spec and resolve the worst-case angle.
    pub fn new(spec: FaultCurrentSpec) -> Result<Self, CurrentError> {
        let s = &spec;
        check("initial_current_a", s.initial_current_a, s.initial_current_a > 0.0, "a finite number > 0 [A]")?;
        check("frequency_hz", s.frequency_hz, s.frequency_hz > 0.0, "a finite number > 0 [Hz]")?;
        check("r_over_x", s.r_over_x, s.r_over_x >= 0.0, "a finite number >= 0")?;
        if let Some(g) = s.inception_angle_deg {
            check("inception_angle_deg", g, true, "a finite angle [deg]")?;
        }
        check("start_s", s.start_s, s.start_s >= 0.0, "a finite number >= 0 [s]")?;
        check("duration_s", s.duration_s, s.duration_s > 0.0, "a finite number > 0 [s]")?;
        if let Some(r) = &s.reclose {
            check("reclose.dead_time_s", r.dead_time_s, r.dead_time_s > 0.0, "a finite number > 0 [s]")?;
            check("reclose.duration_s", r.duration_s, r.duration_s > 0.0, "a finite number > 0 [s]")?;
        }
        let omega = 2.0 * std::f64::consts::PI * s.frequency_hz;
        // atan(X/R) = atan2(1, R/X): 90 deg for R = 0.
        let phi = 1f64.atan2(s.r_over_x);
        let inv_tau = omega * s.r_over_x;
        let deg = std::f64::consts::PI / 180.0;
        let half_pi = 0.5 * std::f64::consts::PI;
        // The angle of the driving voltage of L1's current relative to gamma, and the phases' shifts.
        let (drive, shifts, signs): (f64, [f64; 3], [f64; 3]) = match s.kind {
            FaultKind::ThreePhase => (0.0, [0.0, -120.0 * deg, 120.0 * deg], [1.0, 1.0, 1.0]),
            FaultKind::LineToLine => (30.0 * deg, [30.0 * deg; 3], [1.0, -1.0, 0.0]),
            FaultKind::LineToEarth => (0.0, [0.0; 3], [1.0, 0.0, 0.0]),
        };
        let gamma = match s.inception_angle_deg {
            Some(g) => g * deg,
            None => match s.kind {
                // full offset in L2: gamma - 120 deg - phi = -90 deg
                FaultKind::ThreePhase => phi - half_pi + 120.0 * deg,
                // full offset of the loop current (angle gamma + 30 deg), or of L1
                FaultKind::LineToLine | FaultKind::LineToEarth => phi - half_pi - drive,
            },
        };
        let amp = std::f64::consts::SQRT_2 * s.initial_current_a;
        let mut offset = [(0.0, 0.0); 3];
        let mut amplitude = [0.0; 3];
        for l in 0..3 {
            if signs[l] != 0.0 {
                let a = gamma + shifts[l] - phi;
                offset[l] = (a.sin(), a.cos());
                amplitude[l] = signs[l] * amp;
            }
        }
        let end1 = s.start_s + s.duration_s;
        let (intervals, flows) = match s.reclose {
            None => ([(s.start_s, end1), (end1, end1)], 1),
            Some(r) => {
                let t2 = end1 + r.dead_time_s;
                ([(s.start_s, end1), (t2, t2 + r.duration_s)], 2)
            }
        };
        Ok(FaultCurrent { spec, omega, phi, inv_tau, gamma, offset, amplitude, intervals, flows })
    }

    /// The spec it was built from (with `inception_angle_deg` as given).
    pub fn spec(&self) -> &FaultCurrentSpec {
        &self.spec
    }

    /// The interval of flow containing `t_s`, as its start [s].
    fn inception(&self, t_s: f64) -> Option<f64> {
        self.intervals[..self.flows].iter().find(|&&(a, b)| t_s >= a && t_s < b).map(|&(a, _)| a)
    }

    /// The currents `i_L1`, `i_L2`, `i_L3` [A] at `t_s` [s] (zero outside the flow intervals).
    pub fn phase_currents_a(&self, t_s: f64) -> [f64; 3] {
        let Some(t0) = self.inception(t_s) else { return [0.0; 3] };
        let tp = t_s - t0;
        let (s, c) = (self.omega * tp).sin_cos();
        let decay = (-tp * self.inv_tau).exp();
        let mut i = [0.0; 3];
        for l in 0..3 {
            let (so, co) = self.offset[l];
            // sin(w t' + a) = sin(w t') cos a + cos(w t') sin a
            i[l] = self.amplitude[l] * (s * co + c * so - so * decay);
        }
        i
    }

    /// Whether any current flows at `t_s` [s] (inside `[t_start, t_start + T_k1)` or the reclose's flow).
    pub fn is_flowing(&self, t_s: f64) -> bool {
        self.inception(t_s).is_some()
    }

    /// The flow intervals `[start, end)` [s], in time order.
    pub fn intervals_s(&self) -> &[(f64, f64)] {
        &self.intervals[..self.flows]
    }

    /// The end of the last flow [s].
    pub fn end_s(&self) -> f64 {
        self.intervals[self.flows - 1].1
    }

    /// `kappa = 1.02 + 0.98 exp(-3 R/X)` (IEC 60909-0:2016, (55)).
    pub fn peak_factor(&self) -> f64 {
        1.02 + 0.98 * (-3.0 * self.spec.r_over_x).exp()
    }

    /// `R/X` from the peak factor `kappa` in `(1.02, 2]`: the inverse of [`FaultCurrent::peak_factor`].
    pub fn r_over_x_from_peak_factor(kappa: f64) -> Result<f64, CurrentError> {
        check("kappa", kappa, kappa > 1.02 && kappa <= 2.0, "in (1.02, 2]")?;
        Ok((-((kappa - 1.02) / 0.98).ln() / 3.0).max(0.0))
    }

    /// The inception angle `gamma` of L1's voltage used [deg] (the worst case resolved).
    pub fn inception_angle_deg(&self) -> f64 {
        self.gamma.to_degrees()
    }

    /// `phi_k = atan(X/R)` [deg].
    pub fn impedance_angle_deg(&self) -> f64 {
        self.phi.to_degrees()
    }

    /// The d.c. time constant `tau = X / (w R)` [s] (infinite for `R = 0`).
    pub fn time_constant_s(&self) -> f64 {
        1.0 / self.inv_tau
    }
}

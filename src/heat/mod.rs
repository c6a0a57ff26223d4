//! Heat conduction along the wire: the dimensionless heat equation (5.1) by the explicit scheme (5.2).
//!
//! # Equation and scheme
//!
//! (5.1) `u_t = u_ss + f` on `0 < s < 1` with insulated ends (zero flux), where `s` is the Lagrangian
//! coordinate divided by the span, `t` the dimensionless time and `f` the density of heat sources. On the
//! nodes `s_i = i h`, `h = 1/N`, `i = 0..N`, the explicit scheme (5.2) is
//! ```text
//! u_i^{j+1} = (1 - 2r) u_i^j + r (u_{i+1}^j + u_{i-1}^j) + tau f_i^j,     r = tau / h^2,
//! ```
//! evaluated as `u_i + r (u_{i+1} - 2 u_i + u_{i-1}) + tau f_i` (the same number, less rounding near a
//! uniform field). It is stable for `r <= 1/2`, the paper's `tau = alpha h^2 / 2`, `0 < alpha <= 1`;
//! [`HeatRod::max_stable_step`] is `h^2 / 2`. The ends are closed by one of the [`HeatBoundary`] options,
//! derived in [`boundary`]: the paper's two options (5.3) and (5.4), re-derived, their literal printed forms,
//! and the conservative [`HeatBoundary::ZeroFlux`], which is the one to use.
//!
//! # Held nodes
//!
//! [`HeatRod::hold`] keeps a range of nodes at a fixed temperature (a heated part of the span, a Dirichlet
//! condition): the held values are imposed on the new level after the interior update and again after the
//! end closure, so a held range that contains an end node overrides the closure there, and a closure that
//! reads the new level (`LagrangeQuadratic`) sees the held values. Heat then flows into the rod from the held
//! range; the mean is no longer conserved. [`HeatRod::release`] removes every hold.
//!
//! # Units
//!
//! Temperatures are in whatever unit the caller uses: kelvin, degrees Celsius, or the paper's
//! `u = T / 273.15 K`. Every consistent closure has coefficients summing to one, so the scheme commutes with
//! an affine change of unit (only the inconsistent literal (5.4) does not). `f` is in the temperature unit
//! per unit dimensionless time.
//!
//! # Time scale
//!
//! Dimensionless time is `t = kappa t_phys / l^2` with the diffusivity `kappa = k / (rho c)` and the span `l`
//! ([`scale`]). For the paper's aluminium (`kappa = 8.6e-5 m^2/s`) and `l = 160 m`, `t = 1` is about
//! 3.0e8 s: conduction alone cannot spread heat along a span in seconds (see `docs/paper_notes.md`), so a run that
//! couples this rod to the wire's motion in a few seconds uses a time scale of its own choosing, which the
//! caller must state.

// Doc comments name units in brackets, `[N]`, `[m^2/s]`, which rustdoc would otherwise try to resolve as
// intra-doc links.
#![allow(rustdoc::broken_intra_doc_links)]

pub mod boundary;
pub mod expansion;
pub mod scale;

pub use boundary::HeatBoundary;

use std::ops::Range;

/// A rod (the wire, along its Lagrangian coordinate) with insulated ends, advanced by the explicit
/// scheme (5.2).
#[derive(Debug, Clone)]
pub struct HeatRod {
    /// Nodal temperatures `u_0 .. u_N` [caller's temperature unit].
    u: Vec<f64>,
    /// Scratch for the new level, same length as `u`.
    next: Vec<f64>,
    /// The closure at both ends.
    boundary: HeatBoundary,
    /// Held node ranges and their temperatures [caller's temperature unit].
    holds: Vec<(Range<usize>, f64)>,
    /// Dimensionless time advanced so far.
    time: f64,
}

impl HeatRod {
    /// A rod with nodal temperatures `u0` (`u_0 .. u_N`, `N = u0.len() - 1` segments of length `h = 1/N`).
    ///
    /// # Panics
    /// If `u0` has fewer than 3 values (`N >= 2` is needed by every closure) or a non-finite value: both are
    /// programming errors; scenario input is validated before it reaches here.
    pub fn new(u0: Vec<f64>, boundary: HeatBoundary) -> Self {
        match HeatRod::try_new(u0, boundary) {
            Ok(rod) => rod,
            Err(why) => panic!("{why}"),
        }
    }

    /// As [`HeatRod::new`], but fewer than 3 values or a non-finite value (e.g. a temperature divided by a
    /// tiny temperature scale, which overflows) is an error that says which, not a panic.
    pub fn try_new(u0: Vec<f64>, boundary: HeatBoundary) -> Result<Self, String> {
        if u0.len() < 3 {
            return Err(format!("HeatRod needs at least 3 nodes (N >= 2 segments), got {}", u0.len()));
        }
        if let Some(i) = u0.iter().position(|u| !u.is_finite()) {
            return Err(format!("HeatRod initial temperature u[{i}] = {} is not finite", u0[i]));
        }
        let next = u0.clone();
        Ok(HeatRod { u: u0, next, boundary, holds: Vec::new(), time: 0.0 })
    }

    /// The paper's test 5.4: `segments` segments, nodes with `s < 1/2` at `u_left`, nodes with `s > 1/2` at
    /// `u_right`, and a node at `s = 1/2` (even `segments`) at the mean `(u_left + u_right) / 2`, so that the
    /// trapezoidal mean is exactly `(u_left + u_right) / 2`.
    ///
    /// # Panics
    /// As [`HeatRod::new`].
    pub fn two_halves(segments: usize, u_left: f64, u_right: f64, boundary: HeatBoundary) -> Self {
        let u0 = (0..=segments)
            .map(|i| match (2 * i).cmp(&segments) {
                std::cmp::Ordering::Less => u_left,
                std::cmp::Ordering::Equal => 0.5 * (u_left + u_right),
                std::cmp::Ordering::Greater => u_right,
            })
            .collect();
        HeatRod::new(u0, boundary)
    }

    /// Number of segments `N`.
    pub fn segments(&self) -> usize {
        self.u.len() - 1
    }

    /// Node spacing `h = 1/N` (dimensionless).
    pub fn spacing(&self) -> f64 {
        1.0 / self.segments() as f64
    }

    /// The end closure.
    pub fn boundary(&self) -> HeatBoundary {
        self.boundary
    }

    /// Largest stable dimensionless step of (5.2), `h^2 / 2` (`r = 1/2`, the paper's `alpha = 1`).
    pub fn max_stable_step(&self) -> f64 {
        0.5 * self.spacing() * self.spacing()
    }

    /// Dimensionless time advanced so far.
    pub fn time(&self) -> f64 {
        self.time
    }

    /// Advances by the dimensionless step `dt` without sources (`f = 0`); `dt = 0` does nothing.
    ///
    /// # Panics
    /// If `dt` is not in `[0, max_stable_step()]` (up to a relative `1e-12`), a programming error.
    pub fn step(&mut self, dt: f64) {
        self.advance(dt, None);
    }

    /// Advances by the dimensionless step `dt` with the nodal source `f` [temperature unit per unit
    /// dimensionless time] (`N + 1` values, at the old level).
    ///
    /// # Panics
    /// As [`HeatRod::step`], or if `f` does not have `N + 1` values.
    pub fn step_with_source(&mut self, dt: f64, f: &[f64]) {
        assert_eq!(f.len(), self.u.len(), "heat source needs one value per node");
        self.advance(dt, Some(f));
    }

    fn advance(&mut self, dt: f64, source: Option<&[f64]>) {
        let limit = self.max_stable_step();
        assert!(
            dt.is_finite() && dt >= 0.0 && dt <= limit * (1.0 + 1e-12),
            "heat step {dt:e} outside [0, h^2/2 = {limit:e}]"
        );
        if dt == 0.0 {
            return;
        }
        let n = self.segments();
        let r = dt * (n * n) as f64;
        let (old, new) = (&self.u, &mut self.next);
        for i in 1..n {
            let f = source.map_or(0.0, |f| f[i]);
            new[i] = old[i] + r * (old[i + 1] - 2.0 * old[i] + old[i - 1]) + dt * f;
        }
        impose(&self.holds, new);
        self.boundary.close(old, new, r, dt, source);
        impose(&self.holds, new);
        std::mem::swap(&mut self.u, &mut self.next);
        self.time += dt;
    }

    /// Keeps the nodes `nodes` at the temperature `value` from now on (sets them at once), until
    /// [`HeatRod::release`]. Holds accumulate; where two overlap, the later one wins.
    ///
    /// # Panics
    /// If the range is empty or reaches past node `N`, or `value` is not finite (programming errors).
    pub fn hold(&mut self, nodes: Range<usize>, value: f64) {
        assert!(
            nodes.start < nodes.end && nodes.end <= self.u.len(),
            "held nodes {nodes:?} not a non-empty range within 0..{}",
            self.u.len()
        );
        assert!(value.is_finite(), "held temperature {value} is not finite");
        self.u[nodes.clone()].fill(value);
        self.holds.push((nodes, value));
    }

    /// Removes every hold; the held nodes keep their current temperature and evolve freely from now on.
    pub fn release(&mut self) {
        self.holds.clear();
    }

    /// Nodal temperatures `u_0 .. u_N` [caller's unit].
    pub fn temperatures(&self) -> &[f64] {
        &self.u
    }

    /// Trapezoidal mean over `s in [0, 1]`: `h (u_0/2 + u_1 + .. + u_{N-1} + u_N/2)` [caller's unit].
    pub fn mean(&self) -> f64 {
        let n = self.segments();
        let inner: f64 = self.u[1..n].iter().sum();
        (inner + 0.5 * (self.u[0] + self.u[n])) / n as f64
    }

    /// Largest minus smallest nodal temperature; `+inf` if any value is not finite (a diverged closure).
    pub fn spread(&self) -> f64 {
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        for &u in &self.u {
            if !u.is_finite() {
                return f64::INFINITY;
            }
            lo = lo.min(u);
            hi = hi.max(u);
        }
        hi - lo
    }

    /// Writes the temperature of each segment, the mean of its two end nodes, into `out` (`N` values).
    ///
    /// # Panics
    /// If `out` does not have `N` values.
    pub fn segment_temperatures(&self, out: &mut [f64]) {
        assert_eq!(out.len(), self.segments(), "one output value per segment");
        for (o, w) in out.iter_mut().zip(self.u.windows(2)) {
            *o = 0.5 * (w[0] + w[1]);
        }
    }
}

fn impose(holds: &[(Range<usize>, f64)], u: &mut [f64]) {
    for (nodes, value) in holds {
        u[nodes.clone()].fill(*value);
    }
}

#[cfg(test)]
mod tests;

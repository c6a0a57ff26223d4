//! Contact between conductors of a line: sub-conductors of a bundle that clash under the pinch of a short
//! circuit, phases that swing into each other ([`crate::scheme::conductor_contact`] evaluates it).
//!
//! # Model
//!
//! Two conductors `A` and `B` of radii `r_A`, `r_B` touch where their axes come closer than the gap
//! `g = r_A + r_B`. The contact is a penalty on a line of contact points: each segment of `A` (rest length
//! `l`) carries three points, at the midpoints of its thirds (`s` = 1/6, 1/2, 5/6), each standing for
//! `l / 3` of it. A point `x(s)` at the distance `d` from the nearest point `q(u)` of a segment of `B`
//! penetrates by `delta = g - d > 0` and is pushed along the normal `n = (x - q) / d` by
//!
//! ```text
//! F = max(0, k' (l/3) delta / 2 - c' (l/3) (v(s) - v(u)) . n / 2) n,
//!     on A's nodes (1 - s, s) F, on B's nodes -(1 - u, u) F
//! ```
//!
//! and likewise every point of `B` against the segments of `A` (each direction carries half the stiffness,
//! so that two parallel conductors in contact along a length `L` press with `k' delta` per unit length;
//! for a uniform penetration the nodal forces are exactly the consistent load of `k' delta`). No friction;
//! no adhesion (the force never pulls). Points rather than nodes: sub-conductors that roll over each other
//! cross at small angles (6 degrees in case h) with the deepest point inside a segment, where a node test
//! (the first version) let them pass.
//!
//! `k'` [N/m^2] is given ([`ConductorContact::stiffness_n_per_m2`]: the same spring on every grid, and the
//! line's step is lowered to `w_c dt = stiffness_dt` where it needs it, `w_c = sqrt(k' / mu)`), or by default
//! follows from the time step `dt` of the line and the pair's reduced linear
//! mass `mu = mu_A mu_B / (mu_A + mu_B)`: `k' = mu (w_c)^2` with `w_c dt = stiffness_dt` (default 0.5, the
//! largest allowed). `c' = 2 zeta sqrt(k' mu)` with `zeta = -ln e / sqrt(pi^2 + ln^2 e)` the damping ratio
//! of the restitution coefficient `e` of a linear spring-dashpot (default 0.5). The default penalty
//! stiffness grows as `dt^-2`, so the penetration under a given force falls as `dt^2`. Its frequency `w_c` adds
//! `w_c^2 dt^2 / 4 = 0.0625` and its damping `zeta w_c dt = 0.11` to the leapfrog's stability sum `W dt^2 /
//! 4 + D dt / 2 <= 1` ([`crate::scheme::line`]), which the line's step check does not include: a line at a
//! Courant number up to about 0.8 has that to spare (the short-circuit cases run at 0.5). Why the stiffest:
//! under the pinch of case h (63 kA on a twin 0.1 m apart) the sub-conductors meet at several m/s and the
//! attraction grows as `1/d`; at `w_c dt = 0.25` they penetrate 13 mm of the 43 mm gap and the tension
//! peaks of the first 0.4 s reach 58 kN, at 0.5 they penetrate 8 mm and the peaks are 36 kN
//! (docs/short_circuit.md): the dynamic tension of an effective clash depends on the contact's stiffness,
//! and the penalty stays as stiff as the explicit step allows. The restitution of clashing stranded
//! conductors is not a published value: 0.5 is an assumption; the contact forces (and the pinch tension of
//! an effective clash) depend on it, and the case's output names it.
//!
//! A crossing at an angle steeper than about `atan(6 g / l)` (`l` the segment length) can be missed, since
//! only the points are tested: conductors that run side by side (sub-conductors, phases of one span) meet
//! at small angles.

// Units in brackets would otherwise be taken for intra-doc links.
#![allow(rustdoc::broken_intra_doc_links)]

/// A pair of conductors that may touch.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ContactPair {
    /// the first conductor's index in the line model
    pub a: usize,
    /// the second conductor's index
    pub b: usize,
    /// the distance between the axes at which they touch, `r_A + r_B` [m], > 0
    pub gap_m: f64,
}

/// Contact between conductors of a line ([module doc](self)).
#[derive(Clone, Debug, PartialEq)]
pub struct ConductorContact {
    /// the pairs that may touch
    pub pairs: Vec<ContactPair>,
    /// coefficient of restitution `e` of a clash, in (0, 1] [-]; default 0.5 (an assumption, module doc)
    pub restitution: f64,
    /// penalty frequency times the line's time step, `w_c dt`, in (0, 0.5] [-]; default 0.5 (module doc).
    /// With a given [`stiffness_n_per_m2`](Self::stiffness_n_per_m2) the largest `w_c dt` the step may reach
    pub stiffness_dt: f64,
    /// penalty stiffness `k'` per unit length of contact [N/m^2] (force per unit length per metre of
    /// penetration), in [1e4, 1e12]; absent: scaled to the step, `k' = mu (stiffness_dt / dt)^2` (module doc)
    pub stiffness_n_per_m2: Option<f64>,
}

impl Default for ConductorContact {
    fn default() -> Self {
        ConductorContact { pairs: Vec::new(), restitution: 0.5, stiffness_dt: 0.5, stiffness_n_per_m2: None }
    }
}

/// A contact that does not fit the line.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ContactError {
    /// a pair names a conductor that does not exist, or one conductor twice
    #[error("contact pair {pair}: {detail}")]
    Pair {
        /// index of the pair
        pair: usize,
        /// what is wrong
        detail: String,
    },
    /// a value outside its range
    #[error("{what} = {value} must be {allowed}")]
    Value {
        /// which value
        what: String,
        /// the value
        value: f64,
        /// the allowed range
        allowed: &'static str,
    },
}

impl ConductorContact {
    /// The damping ratio `zeta = -ln e / sqrt(pi^2 + ln^2 e)` of the restitution coefficient [-].
    pub fn damping_ratio(&self) -> f64 {
        let l = self.restitution.ln();
        -l / (std::f64::consts::PI * std::f64::consts::PI + l * l).sqrt()
    }

    /// Check the pairs against a line of `conductors` conductors and the values against their ranges.
    pub fn check(&self, conductors: usize) -> Result<(), ContactError> {
        if !(self.restitution > 0.0 && self.restitution <= 1.0) {
            return Err(ContactError::Value {
                what: "restitution".into(),
                value: self.restitution,
                allowed: "in (0, 1]",
            });
        }
        if !(self.stiffness_dt > 0.0 && self.stiffness_dt <= 0.5) {
            return Err(ContactError::Value {
                what: "stiffness_dt".into(),
                value: self.stiffness_dt,
                allowed: "in (0, 0.5]",
            });
        }
        if let Some(k) = self.stiffness_n_per_m2
            && !((1e4..=1e12).contains(&k))
        {
            return Err(ContactError::Value { what: "stiffness_n_per_m2".into(), value: k, allowed: "in [1e4, 1e12]" });
        }
        for (k, p) in self.pairs.iter().enumerate() {
            if p.a >= conductors || p.b >= conductors {
                return Err(ContactError::Pair {
                    pair: k,
                    detail: format!("conductor {} or {} does not exist ({conductors} conductors)", p.a, p.b),
                });
            }
            if p.a == p.b {
                return Err(ContactError::Pair { pair: k, detail: format!("conductor {} with itself", p.a) });
            }
            if !(p.gap_m.is_finite() && p.gap_m > 0.0) {
                return Err(ContactError::Value {
                    what: format!("pairs[{k}].gap_m"),
                    value: p.gap_m,
                    allowed: "a finite number > 0",
                });
            }
        }
        Ok(())
    }
}

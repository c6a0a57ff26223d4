//! The axial law of a conductor of one or two materials (aluminium layers on a steel core), strained
//! together: both share the conductor's strain `e`, each less its own thermal strain,
//!
//! ```text
//! e_o = e - alpha_o (theta - theta_ref),   e_c = e - alpha_c (theta - theta_ref)
//! T(e, theta) = F_o(e_o; m_o) + F_c(e_c; m_c)
//! ```
//!
//! with `e` [-] the conductor's strain relative to its length at the reference temperature `theta_ref`
//! [K] (where the published curves were measured), `F_o`, `F_c` [N] the components' forces on their
//! loading paths ([`super::component`]) and `m_o`, `m_c` the largest strains each has reached (the
//! [`History`]). Above the temperature where `e_o` falls to the outer layers' permanent set, the aluminium
//! carries nothing and the conductor continues on the core alone: the knee point. `T` is nondecreasing in
//! `e` (each component's force is), so a tension has one strain ([`TwoMaterial::strain_at`]).

use super::component::{Component, CurveKind};
use crate::element::scalar::Scalar;

/// A conductor's axial law (module doc). `core: None` is a conductor of one material (AAAC, AAC, a steel
/// earth wire).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TwoMaterial {
    /// the outer layers (aluminium)
    pub outer: Component,
    /// the core (steel), if any
    pub core: Option<Component>,
    /// the reference temperature `theta_ref` [K] of the strains (the curves' test temperature)
    pub reference_temperature_k: f64,
}

/// What a conductor remembers: the curve it follows when loaded further and the largest mechanical
/// strain each component has reached on it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct History {
    /// the curve of both components (initial, or after creep)
    pub curve: CurveKind,
    /// largest mechanical strain reached `[m_o, m_c]` [-]
    pub max_strain: [f64; 2],
}

impl TwoMaterial {
    /// The components as a slice `[outer, core]` (one element without a core).
    fn components(&self) -> impl Iterator<Item = (usize, &Component)> {
        std::iter::once((0, &self.outer)).chain(self.core.iter().map(|c| (1, c)))
    }

    /// A conductor that has never been loaded, following the curve `curve`.
    pub fn virgin(&self, curve: CurveKind) -> History {
        let core = self.core.map_or(0.0, |c| c.virgin_strain(curve));
        History { curve, max_strain: [self.outer.virgin_strain(curve), core] }
    }

    /// The components' mechanical strains `[e_o, e_c]` [-] at the conductor strain `e` [-] and temperature
    /// `theta` [K].
    pub fn mechanical_strains(&self, strain: f64, temperature_k: f64) -> [f64; 2] {
        let d = temperature_k - self.reference_temperature_k;
        let core = self.core.map_or(strain, |c| strain - c.expansion_per_k * d);
        [strain - self.outer.expansion_per_k * d, core]
    }

    /// The tension `T` [N] at the conductor strain `e` [-] and temperature `theta` [K] (module doc).
    #[inline]
    pub fn tension<S: Scalar>(&self, strain: S, temperature_k: f64, h: &History) -> S {
        let d = temperature_k - self.reference_temperature_k;
        let fo = self.outer.force(strain - self.outer.expansion_per_k * d, h.curve, h.max_strain[0]);
        match &self.core {
            None => fo,
            Some(c) => fo + c.force(strain - c.expansion_per_k * d, h.curve, h.max_strain[1]),
        }
    }

    /// The components' forces `[F_o, F_c]` [N] (0 for a missing core).
    pub fn forces(&self, strain: f64, temperature_k: f64, h: &History) -> [f64; 2] {
        let e = self.mechanical_strains(strain, temperature_k);
        let mut f = [0.0; 2];
        for (k, c) in self.components() {
            f[k] = c.force(e[k], h.curve, h.max_strain[k]);
        }
        f
    }

    /// The tangent stiffness `dT/de` [N].
    pub fn stiffness(&self, strain: f64, temperature_k: f64, h: &History) -> f64 {
        let e = self.mechanical_strains(strain, temperature_k);
        self.components().map(|(k, c)| c.stiffness(e[k], h.curve, h.max_strain[k])).sum()
    }

    /// Loads the conductor to the strain `e` [-] at `theta` [K]: returns the tension [N] and moves each
    /// component's largest strain up where it is passed.
    pub fn load(&self, strain: f64, temperature_k: f64, h: &mut History) -> f64 {
        let e = self.mechanical_strains(strain, temperature_k);
        let mut t = 0.0;
        for (k, c) in self.components() {
            t += c.load(e[k], h.curve, &mut h.max_strain[k]);
        }
        t
    }

    /// Moves each component's largest strain up to its mechanical strain at the conductor strain `e` [-]
    /// and temperature `theta` [K] where it is passed: [`TwoMaterial::load`] without the tension (the
    /// explicit kernel folds its strains in once per step this way).
    #[inline]
    pub fn remember(&self, strain: f64, temperature_k: f64, h: &mut History) {
        let e = self.mechanical_strains(strain, temperature_k);
        for (k, _) in self.components() {
            if e[k] > h.max_strain[k] {
                h.max_strain[k] = e[k];
            }
        }
    }

    /// The conductor strain [-] at which the tension is `tension_n` [N] `> 0`, at `theta` [K] with the
    /// history `h` (bisection on the nondecreasing `T(e)`, to a relative 1e-15 of the strain bracket).
    pub fn strain_at(&self, tension_n: f64, temperature_k: f64, h: &History) -> f64 {
        let t = |e: f64| self.tension(e, temperature_k, h);
        let (mut lo, mut hi) = (-0.05, 0.01);
        while t(hi) < tension_n {
            hi *= 2.0;
            assert!(hi < 10.0, "no strain below 1000 % carries {tension_n} N");
        }
        while t(lo) >= tension_n && lo > -1.0 {
            lo *= 2.0;
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if t(mid) < tension_n { lo = mid } else { hi = mid }
        }
        hi
    }

    /// A creep-stretched history moved onto the initial curves (each component's
    /// [`Component::creep_stretch_on_initial`]): the same unloading lines, and short-term loads beyond
    /// them follow the initial curves. A history already on the initial curves is returned as it is.
    pub fn creep_history_on_initial(&self, h: &History) -> History {
        if h.curve == CurveKind::Initial {
            return *h;
        }
        let mut out = History { curve: CurveKind::Initial, max_strain: h.max_strain };
        for (k, c) in self.components() {
            out.max_strain[k] = c.creep_stretch_on_initial(h.max_strain[k]);
        }
        out
    }

    /// The conductor strain [-] below which the outer layers carry no tension at `theta` [K] (their
    /// permanent set plus their thermal strain): the knee point's strain.
    pub fn outer_slack_strain(&self, temperature_k: f64, h: &History) -> f64 {
        let d = temperature_k - self.reference_temperature_k;
        self.outer.permanent_set(h.curve, h.max_strain[0]) + self.outer.expansion_per_k * d
    }
}

#[cfg(test)]
mod tests {
    use super::super::curve::Curve;
    use super::*;

    /// Drake's components as published with the Aluminum Association's polynomials (psi on the total
    /// area 0.7264 in^2, strain in %; OTLS-Models test/factory.cc, docs/conductor_data.md).
    fn drake() -> TwoMaterial {
        let psi = 6894.757;
        let area = 0.7264 * 6.4516e-4;
        let p = |a: [f64; 5]| a.map(|x| x * psi);
        let al_i = Curve::from_percent(p([-1213.0, 44308.1, -14004.4, -37618.0, 30676.0]), area, Some(20252.0 * psi));
        let st_i = Curve::from_percent(p([-69.3, 38629.0, 3998.1, -45713.0, 27892.0]), area, Some(19154.0 * psi));
        let outer = Component {
            area_m2: 4.0283e-4,
            expansion_per_k: 12.8e-6 * 1.8,
            initial: al_i.unwrap(),
            creep: None,
            unloading_stiffness_n: 64000.0 * psi * 100.0 * area,
            compression_stiffness_n: 0.0,
        };
        let core = Component {
            area_m2: 6.560e-5,
            expansion_per_k: 6.4e-6 * 1.8,
            initial: st_i.unwrap(),
            creep: None,
            unloading_stiffness_n: 37000.0 * psi * 100.0 * area,
            compression_stiffness_n: 0.0,
        };
        TwoMaterial { outer, core: Some(core), reference_temperature_k: 294.261 }
    }

    #[test]
    fn unloading_returns_along_the_modulus_line_to_the_closed_form_permanent_set() {
        let c = drake().outer;
        let mut m = c.virgin_strain(CurveKind::Initial);
        let peak = 0.0025;
        let f_peak = c.load(peak, CurveKind::Initial, &mut m);
        assert_eq!(m, peak);
        // On the way down: exactly linear with the unloading stiffness from (m, C(m)).
        for k in 1..10 {
            let e = peak - 1e-4 * k as f64;
            let f = c.force(e, CurveKind::Initial, m);
            let line = f_peak + c.unloading_stiffness_n * (e - peak);
            assert!((f - line.max(0.0)).abs() <= 1e-9 * f_peak, "{f} vs {line}");
        }
        // The permanent set is where that line crosses zero: e_p = m - C(m) / K_u.
        let ep = c.permanent_set(CurveKind::Initial, m);
        assert!((ep - (peak - f_peak / c.unloading_stiffness_n)).abs() < 1e-15);
        assert!(ep > c.virgin_strain(CurveKind::Initial), "loading to 0.25 % leaves a permanent set");
        assert_eq!(c.force(ep - 1e-5, CurveKind::Initial, m), 0.0, "the aluminium carries no compression");
        // Reloading follows the line back up and rejoins the virgin curve at m.
        let f_again = c.force(peak, CurveKind::Initial, m);
        assert!((f_again - f_peak).abs() <= 1e-9 * f_peak);
    }

    #[test]
    fn a_creep_stretch_moved_onto_the_initial_curve_unloads_along_the_same_line() {
        // Drake's aluminium with its 10-year creep curve (OTLS-Models test/factory.cc), stretched to
        // 0.2 % on the creep curve.
        let psi = 6894.757;
        let area = 0.7264 * 6.4516e-4;
        let creep = [-544.8, 21426.8, -18842.2, 5495.0, 0.0].map(|x| x * psi);
        let mut c = drake().outer;
        c.creep = Some(Curve::from_percent(creep, area, Some(7535.0 * psi)).unwrap());
        let mc = 0.002;
        let mi = c.creep_stretch_on_initial(mc);
        // The closed form it solves: C_i(m_i) = C_c(m_c) + K_u (m_i - m_c), the unloading line meeting the
        // initial curve above m_c (the creep curve lies below the initial one at the same strain).
        let fc = c.creep.unwrap().force(mc);
        assert!(mi > mc);
        assert!((c.initial.force(mi) - fc - c.unloading_stiffness_n * (mi - mc)).abs() < 1e-9 * fc);
        // Below m_c both histories give the same force (the same line), to round-off of the line.
        for k in 0..20 {
            let e = mc - 1e-4 * k as f64;
            let on_creep = c.force(e, CurveKind::Creep, mc);
            let on_initial = c.force(e, CurveKind::Initial, mi);
            assert!((on_creep - on_initial).abs() < 1e-9 * fc, "{e}: {on_creep} vs {on_initial}");
        }
        // Beyond m_i the initial history follows the initial curve.
        assert_eq!(c.force(mi + 1e-4, CurveKind::Initial, mi), c.initial.force(mi + 1e-4));
    }

    #[test]
    fn strain_at_inverts_the_tension_and_the_knee_is_where_the_aluminium_goes_slack() {
        let d = drake();
        let h = d.virgin(CurveKind::Initial);
        for &(t, theta) in &[(20e3, 288.0), (30e3, 350.0), (10e3, 420.0)] {
            let e = d.strain_at(t, theta, &h);
            assert!((d.tension(e, theta, &h) - t).abs() < 1e-6 * t);
            let f = d.forces(e, theta, &h);
            assert!((f[0] + f[1] - t).abs() < 1e-6 * t);
        }
        let theta = 400.0;
        let ek = d.outer_slack_strain(theta, &h);
        assert!(d.forces(ek - 1e-7, theta, &h)[0] == 0.0 && d.forces(ek + 1e-6, theta, &h)[0] > 0.0);
    }
}

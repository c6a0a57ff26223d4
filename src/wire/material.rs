//! A wire whose segments follow the two-material law of a real conductor ([`crate::conductor`]): the law
//! and each segment's history, structure-of-arrays.
//!
//! ```text
//! T_{i+1/2} = T_c(e, theta_{i+1/2}; m_o, m_c) + eta de/dt   if T_c > 0, clamped at 0;   0 if T_c = 0
//! e = |r_{i+1} - r_i| / L_{i+1/2} - 1
//! ```
//!
//! with `T_c` the conductor's law ([`crate::conductor::TwoMaterial::tension`]: each material's quartic
//! loading curve, its unloading along the final modulus, its own thermal strain: the knee point), `eta`
//! the Kelvin-Voigt friction of (3.4), clamped like the tension-only law (the viscous part may reduce the
//! tension to zero, never make it negative, and a segment whose materials carry nothing carries nothing).
//!
//! Strain and temperature. The paper's law puts the thermal strain into the stress-free length `l0`
//! (5.5); a conductor of two materials has no single stress-free length (each material has its own
//! thermal strain). So a two-material segment keeps `l0 = L` ([`super::Wire::update_rest_lengths`]), its
//! length at the law's reference temperature `theta_ref` (where the published curves were measured and
//! both materials are at the conductor strain), and the law receives the segment's temperature
//! `theta_{i+1/2}` and subtracts each material's thermal strain itself (two_material.rs).
//!
//! History. `m_o`, `m_c` are the largest mechanical strains each material has reached (the permanent set
//! follows from them). The explicit kernel moves them up once per step from the strains of the level it
//! advances ([`Material::advance`]); the static solver holds them fixed during a solve (its residual is
//! the kernel's segment pass, which only records the strains), and a caller that wants the converged
//! state to stretch the conductor asks for it ([`super::Wire::load_history`]).

use crate::conductor::{CurveKind, History, TwoMaterial};
use crate::element::scalar::Scalar;

/// The tension `T` [N] of a segment with the history `h` at strain `e` [-], strain rate `edot` [1/s],
/// internal friction `eta` [N s] and temperature `theta` [K] (module doc): the one expression of
/// [`Material::tension`] and of the kernel's two-material pass, which reads the history from its arrays.
#[inline(always)]
pub fn segment_tension<S: Scalar>(law: &TwoMaterial, h: &History, e: S, edot: S, eta: f64, temperature_k: f64) -> S {
    let elastic = law.tension(e, temperature_k, h);
    if elastic.value() > 0.0 { (elastic + edot * eta).positive_part() } else { S::c(0.0) }
}

/// The two-material law of a wire and each segment's history (module doc).
#[derive(Clone, Debug, PartialEq)]
pub struct Material {
    /// the conductor's axial law
    pub law: TwoMaterial,
    /// the curve the materials follow when loaded beyond their history (initial, or after creep)
    pub curve: CurveKind,
    /// largest mechanical strain reached `[m_o, m_c]` [-] of each segment, each of length `N`
    pub max_strain: [Vec<f64>; 2],
    /// the conductor strain `e` [-] of each segment at the last segment pass, length `N` (what
    /// [`Material::advance`] folds into the history)
    pub last_strain: Vec<f64>,
}

impl Material {
    /// `segments` virgin segments of the law `law` on the curve `curve`.
    pub fn virgin(law: TwoMaterial, curve: CurveKind, segments: usize) -> Material {
        let h = law.virgin(curve);
        Material {
            law,
            curve,
            max_strain: [vec![h.max_strain[0]; segments], vec![h.max_strain[1]; segments]],
            last_strain: vec![f64::NEG_INFINITY; segments],
        }
    }

    /// The history of segment `j`.
    #[inline(always)]
    pub fn history(&self, j: usize) -> History {
        History { curve: self.curve, max_strain: [self.max_strain[0][j], self.max_strain[1][j]] }
    }

    /// Tension `T` [N] of segment `j` at strain `e` [-], strain rate `edot` [1/s], internal friction `eta`
    /// [N s] and temperature `theta` [K] (module doc), the history held fixed. Written once over
    /// [`Scalar`]: the kernel on `f64`, the static Jacobian on dual numbers.
    #[inline(always)]
    pub fn tension<S: Scalar>(&self, j: usize, e: S, edot: S, eta: f64, temperature_k: f64) -> S {
        segment_tension(&self.law, &self.history(j), e, edot, eta, temperature_k)
    }

    /// Moves segment `j`'s history up to the conductor strain `e` [-] at `theta` [K] where a material
    /// passes its largest strain ([`TwoMaterial::load`]).
    #[inline]
    pub fn load(&mut self, j: usize, e: f64, temperature_k: f64) {
        let mut h = self.history(j);
        self.law.remember(e, temperature_k, &mut h);
        self.max_strain[0][j] = h.max_strain[0];
        self.max_strain[1][j] = h.max_strain[1];
    }

    /// Folds the strains of the last segment pass into the history at the segment temperatures
    /// `temperature_k` [K] (one call per explicit step).
    pub fn advance(&mut self, temperature_k: &[f64]) {
        let n = self.last_strain.len();
        let (law, curve, last) = (&self.law, self.curve, &self.last_strain[..n]);
        let [m_o, m_c] = &mut self.max_strain;
        let (m_o, m_c, theta) = (&mut m_o[..n], &mut m_c[..n], &temperature_k[..n]);
        for j in 0..n {
            let e = last[j];
            if e > f64::NEG_INFINITY {
                let mut h = History { curve, max_strain: [m_o[j], m_c[j]] };
                law.remember(e, theta[j], &mut h);
                m_o[j] = h.max_strain[0];
                m_c[j] = h.max_strain[1];
            }
        }
    }

    /// Recoverable elastic energy per unit reference length [J/m] of segment `j` at strain `e` [-] and
    /// `theta` [K]: `int T de'` along the unloading path from `e` (the history moved up to `e` first, so
    /// the work spent in permanent set is not counted) down to the strain below which the materials carry
    /// nothing (composite Simpson, 64 panels: the diagnostics' energy, exact for the linear pieces and to
    /// `O(h^4)` on curved ones; a kink inside a panel costs `O(h^2)` of it). Compression of a material with
    /// `K_c > 0` is not counted.
    pub fn energy_density(&self, j: usize, e: f64, temperature_k: f64) -> f64 {
        let mut h = self.history(j);
        self.law.remember(e, temperature_k, &mut h);
        let law = &self.law;
        let d = temperature_k - law.reference_temperature_k;
        let mut lo = law.outer.permanent_set(h.curve, h.max_strain[0]) + law.outer.expansion_per_k * d;
        if let Some(c) = &law.core {
            lo = lo.min(c.permanent_set(h.curve, h.max_strain[1]) + c.expansion_per_k * d);
        }
        if e <= lo {
            return 0.0;
        }
        let n = 64;
        let step = (e - lo) / n as f64;
        let t = |x: f64| law.tension(x, temperature_k, &h).max(0.0);
        let mut s = t(lo) + t(e);
        for k in 1..n {
            s += if k % 2 == 1 { 4.0 } else { 2.0 } * t(lo + k as f64 * step);
        }
        s * step / 3.0
    }

    /// A bound on the tangent stiffness `dT/de` [N] over every state (the sum over the materials of the
    /// largest of their unloading and compression stiffness and of their curves' slopes on the fitted
    /// range, sampled at 200 points): the `EA` of the time step (3.7) and of the static solver's scales.
    pub fn max_stiffness(&self) -> f64 {
        let law = &self.law;
        let one = |c: &crate::conductor::Component| {
            let mut k = c.unloading_stiffness_n.max(c.compression_stiffness_n);
            for curve in [Some(c.initial), c.creep].into_iter().flatten() {
                let lo = curve.zero_strain();
                let hi = if curve.limit_strain.is_finite() { curve.limit_strain } else { lo + 0.02 };
                for i in 0..=200 {
                    k = k.max(curve.slope(lo + (hi - lo) * i as f64 / 200.0));
                }
            }
            k
        };
        one(&law.outer) + law.core.as_ref().map_or(0.0, one)
    }
}

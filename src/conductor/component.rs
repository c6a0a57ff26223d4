//! One material of a conductor (the aluminium layers, or the steel core) and its loading path:
//!
//! ```text
//! e >= m:            F = C(e)                                   (on the curve C: virgin or after creep)
//! e <  m:            F = C(m) + K_u (e - m)                     (unloading along the final modulus)
//! below F = 0:       F = K_c (e - e_p),   e_p = m - C(m) / K_u  (permanent set e_p; compression K_c)
//! ```
//!
//! `e` [-] is the component's mechanical strain (the conductor's strain less the component's thermal
//! strain, [`super::TwoMaterial`]), `m` [-] the largest mechanical strain the component has reached on its
//! curve `C` ([`super::curve`]), `K_u` [N] its unloading (final) stiffness, modulus times area, and `K_c`
//! [N] its stiffness in compression (0: carries none, the aluminium of most conductors). A virgin
//! component has `m = e_z`, the curve's zero. Loading beyond `m` moves `m` ([`Component::load`]); this
//! is how a conductor stretched by an ice load hangs lower afterwards (the Aluminum Association's graphic
//! method, Winkelman's "Analysis of Sag and Tension of ACSR": initial curve, final modulus line).

use super::curve::Curve;
use crate::element::scalar::Scalar;

/// One material of a conductor (module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Component {
    /// cross-section area `A` [m^2] of this material
    pub area_m2: f64,
    /// linear thermal expansion coefficient `alpha` [1/K]
    pub expansion_per_k: f64,
    /// the virgin (initial) loading curve `C_i(e)` [N]
    pub initial: Curve,
    /// the curve after long-term creep `C_c(e)` [N] (the published 10-year creep curve); `None`: no creep
    pub creep: Option<Curve>,
    /// unloading (final) stiffness `K_u` = final modulus times area [N]
    pub unloading_stiffness_n: f64,
    /// stiffness in compression `K_c` [N] (0: carries no compression)
    pub compression_stiffness_n: f64,
}

/// Which curve a conductor's components follow when loaded beyond what they have reached.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum CurveKind {
    /// the virgin curve (as strung: "initial")
    #[default]
    Initial,
    /// the curve after long-term creep ("final after creep")
    Creep,
}

impl Component {
    /// A linear material: `F = EA e` loading and unloading, no creep, no compression.
    pub fn linear(area_m2: f64, modulus_pa: f64, expansion_per_k: f64) -> Component {
        let k = modulus_pa * area_m2;
        Component {
            area_m2,
            expansion_per_k,
            initial: Curve::linear(k),
            creep: None,
            unloading_stiffness_n: k,
            compression_stiffness_n: 0.0,
        }
    }

    /// The curve followed under `kind` (the initial curve where there is no creep curve).
    pub fn curve(&self, kind: CurveKind) -> &Curve {
        match (kind, &self.creep) {
            (CurveKind::Creep, Some(c)) => c,
            _ => &self.initial,
        }
    }

    /// The largest strain of a virgin component on the curve `kind`: the curve's zero `e_z`.
    pub fn virgin_strain(&self, kind: CurveKind) -> f64 {
        self.curve(kind).zero_strain()
    }

    /// The force `F` [N] at the mechanical strain `e` [-], on the curve `kind` with the largest strain
    /// reached `m` [-] (module doc). Continuous in `e`; its derivative jumps at `m` and at the permanent set.
    #[inline]
    pub fn force<S: Scalar>(&self, e: S, kind: CurveKind, m: f64) -> S {
        let c = self.curve(kind);
        let m = m.max(c.zero_strain());
        if e.value() >= m {
            return c.force(e);
        }
        let fm = c.force(m);
        let unloaded = (e - m) * self.unloading_stiffness_n + fm;
        if unloaded.value() >= 0.0 {
            unloaded
        } else {
            let permanent = m - fm / self.unloading_stiffness_n;
            (e - permanent) * self.compression_stiffness_n
        }
    }

    /// The tangent stiffness `dF/de` [N] at `e` (the loading curve's slope at and beyond `m`).
    pub fn stiffness(&self, e: f64, kind: CurveKind, m: f64) -> f64 {
        let c = self.curve(kind);
        let m = m.max(c.zero_strain());
        if e >= m {
            c.slope(e)
        } else if self.force(e, kind, m) > 0.0 {
            self.unloading_stiffness_n
        } else {
            self.compression_stiffness_n
        }
    }

    /// The permanent set `e_p` [-]: the strain at which the component, unloaded from its largest strain
    /// `m` on curve `kind`, carries nothing.
    pub fn permanent_set(&self, kind: CurveKind, m: f64) -> f64 {
        let c = self.curve(kind);
        let m = m.max(c.zero_strain());
        m - c.force(m) / self.unloading_stiffness_n
    }

    /// The largest strain `m_i` [-] on the INITIAL curve equivalent to having reached `m_c` [-] on the
    /// creep curve: where the unloading line from `(m_c, C_c(m_c))` meets the initial curve,
    /// `C_i(m_i) = C_c(m_c) + K_u (m_i - m_c)`. Below `m_i` the two histories unload along the same line;
    /// beyond it a creep-stretched component loaded by a short-term load (ice, wind) follows its
    /// initial curve again, not the creep curve (the Aluminum Association's graphic method; the same
    /// transfer in OTLS-Models `CableComponentElongationModel::UpdateStretch`). `m_c` itself without a
    /// creep curve. Bisection on `C_i(x) - C_c(m_c) - K_u (x - m_c)`, decreasing in `x` wherever the
    /// initial curve is less stiff than the unloading line.
    pub fn creep_stretch_on_initial(&self, m_creep: f64) -> f64 {
        let Some(creep) = &self.creep else { return m_creep };
        let m = m_creep.max(creep.zero_strain());
        let fm = creep.force(m);
        let e_z = self.initial.zero_strain();
        let phi = |x: f64| self.initial.force(x.max(e_z)) - fm - self.unloading_stiffness_n * (x - m);
        let span = 0.01;
        let (mut lo, mut hi) = if phi(m) >= 0.0 { (m, m + span) } else { (m - span, m) };
        if phi(lo) < 0.0 || phi(hi) > 0.0 {
            return m;
        }
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if phi(mid) >= 0.0 { lo = mid } else { hi = mid }
        }
        0.5 * (lo + hi)
    }

    /// Loads the component to the strain `e` [-]: returns the force [N] and moves the largest strain
    /// reached `m` up to `e` when `e` passes it.
    pub fn load(&self, e: f64, kind: CurveKind, m: &mut f64) -> f64 {
        let f = self.force(e, kind, *m);
        if e > *m {
            *m = e;
        }
        f
    }
}

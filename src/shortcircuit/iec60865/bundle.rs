//! Bundle pinch, IEC 60865-1:2011 clause 6.4.1: the sub-conductors of a bundle "clash effectively" when
//!
//! ```text
//! a_s / d <= 2.0  and  l_s >= 50 a_s          (52)
//! a_s / d <= 2.5  and  l_s >= 70 a_s          (53)
//! ```
//!
//! (either), and then the pinch force is `F_pi = 1.1 F_t` (51). Otherwise clause 6.4.2 computes `F_pi`
//! from `nu_1` (55), `epsilon_st` (56), `epsilon_pi` (57), `j` (58) and the case distinction `j >= 1`
//! (59)-(61) / `j < 1` (62)-(64) with `xi`, `eta` and `nu_2`, `nu_3` of Annex A; that branch is not
//! implemented in this round (docs/short_circuit_iec60865.md says why: `nu_2` of Annex A.7 could not
//! be confirmed from a public source in time).

/// The pinch result of a bundle.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Pinch {
    /// Eq. (52) or (53) holds: `F_pi = 1.1 F_t` [N], eq. (51).
    EffectiveClash {
        /// `F_pi` [N]
        force_n: f64,
    },
    /// Neither (52) nor (53): `F_pi` needs clause 6.4.2, not computed here.
    NotClashing,
}

/// Eqs. (52), (53): whether the sub-conductors clash effectively; `a_s` and `d` [m], `l_s` [m].
pub fn clash_effectively(a_s: f64, d: f64, l_s: f64) -> bool {
    let ratio = a_s / d;
    (ratio <= 2.0 && l_s >= 50.0 * a_s) || (ratio <= 2.5 && l_s >= 70.0 * a_s)
}

/// Eq. (51) when (52) or (53) holds.
pub fn pinch(a_s: f64, d: f64, l_s: f64, f_t: f64) -> Pinch {
    if clash_effectively(a_s, d, l_s) { Pinch::EffectiveClash { force_n: 1.1 * f_t } } else { Pinch::NotClashing }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The criteria at their edges: (52) at a_s/d = 2 with l_s = 50 a_s exactly; (53) at 2.5 / 70 a_s; just
    /// outside both (a_s/d = 2.5 with l_s = 69 a_s; a_s/d = 2.51).
    #[test]
    fn criteria_edges() {
        let d = 0.04;
        assert!(clash_effectively(2.0 * d, d, 50.0 * 2.0 * d));
        assert!(!clash_effectively(2.0 * d, d, 49.0 * 2.0 * d));
        assert!(clash_effectively(2.5 * d, d, 70.0 * 2.5 * d));
        assert!(!clash_effectively(2.5 * d, d, 69.0 * 2.5 * d));
        assert!(!clash_effectively(2.51 * d, d, 1000.0));
        assert_eq!(pinch(0.08, d, 10.0, 1000.0), Pinch::EffectiveClash { force_n: 1.1 * 1000.0 });
    }
}

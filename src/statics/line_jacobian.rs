//! The Jacobian blocks a line adds to its conductors' own ([`super::jacobian::values`]): each link's
//! blocks and each elastic support's 2x2 block, the entries of
//!
//! ```text
//! A = dF/dy + cv dF/dv - cm M
//! ```
//!
//! in the order of the line's sparsity pattern ([`super::line::line_pattern`]). The line statics uses
//! them with `cv = cm = 0` (`A = dF/dy` at rest, [`super::line::solve_line`]); an implicit integrator
//! with `cv = 2/dt`, `cm = 4/dt^2` (Newmark's average acceleration).
//!
//! A link's force on its end `b` is the link element [`crate::element::link`] (`LinkLaw::force_on_b`,
//! the function the explicit step evaluates on `f64`) on dual numbers ([`super::dual`]); the force on
//! end `a` is its opposite. An elastic support's horizontal force is
//! `S = -k_l ((p - p0).e_l) e_l - k_t ((p - p0).e_t) e_t - c_d u` ([`crate::line::support`]), whose block
//! is `-k_l e_l e_l^T - k_t e_t e_t^T - (cv c_d + cm M_s) I`.

use super::dual::Dual;
use crate::element::LinkLaw;
use crate::line::dof::EndDofs;
use crate::line::support::ElasticSupport;

/// Position and velocity of a link's end [m], [m/s].
pub type EndState = ([f64; 3], [f64; 3]);

/// The blocks of one link with the law `law`, ends `a` and `b` at the states `a`, `b` and numbered by
/// `ends = [a's unknowns, b's unknowns]`, appended to `out`: for each end that moves (row end `a` then
/// `b`), for each end that moves (column end `a` then `b`), the `width x width` block row-major, entry
/// `sign (dF_b/dr + cv dF_b/dv)` with `sign` `+` for row end `b` and `-` for `a` (a support's
/// components are its two horizontal ones). `law` is the law to linearise (the statics passes a slack
/// string's linear law, module doc of [`super::line`]).
///
/// With `cv = 0` only the position derivatives are formed (6 dual slots, the velocities as constants),
/// so the entries are exactly `dF/dr`; otherwise 12 slots, positions then velocities.
pub fn link_block(law: &LinkLaw, a: EndState, b: EndState, ends: [EndDofs; 2], cv: f64, out: &mut Vec<f64>) {
    if cv == 0.0 {
        link_block_with::<6>(law, a, b, ends, 0.0, out)
    } else {
        link_block_with::<12>(law, a, b, ends, cv, out)
    }
}

fn link_block_with<const S: usize>(
    law: &LinkLaw,
    (ra, va): EndState,
    (rb, vb): EndState,
    ends: [EndDofs; 2],
    cv: f64,
    out: &mut Vec<f64>,
) {
    // Slot `slot + k` for the input's component `k`; a constant where there is no such slot (S = 6).
    let var = |x: [f64; 3], slot: usize| -> [Dual<S>; 3] {
        std::array::from_fn(|k| if slot + k < S { Dual::var(x[k], slot + k) } else { Dual::c(x[k]) })
    };
    let fb = law.force_on_b(var(ra, 0), var(rb, 3), var(va, 6), var(vb, 9));
    let ends = [(ends[0], -1.0, 0), (ends[1], 1.0, 3)];
    for (r, sign, _) in ends {
        if r.first.is_none() {
            continue;
        }
        for (c, _, slot) in ends {
            if c.first.is_none() {
                continue;
            }
            for k in 0..r.width {
                for l in 0..c.width {
                    let d = &fb[k].d;
                    out.push(if S > 6 {
                        sign * (d[slot + l] + cv * d[(6 + slot + l).min(S - 1)])
                    } else {
                        sign * d[slot + l]
                    });
                }
            }
        }
    }
}

/// The 2x2 block (row-major) of an elastic support `el` over its two horizontal translations, appended
/// to `out`: `-k_l e_l e_l^T - k_t e_t e_t^T`, and on the diagonal `-(cv c_d + cm M_s)` unless
/// `cv = cm = 0` (the static block is the springs' alone).
pub fn support_block(el: &ElasticSupport, cv: f64, cm: f64, out: &mut Vec<f64>) {
    let (e_l, e_t) = (el.along, el.across());
    for k in 0..2 {
        for l in 0..2 {
            let mut x = -el.along_n_per_m * e_l[k] * e_l[l] - el.across_n_per_m * e_t[k] * e_t[l];
            if k == l && (cv != 0.0 || cm != 0.0) {
                x -= cv * el.damping_n_s_per_m + cm * el.mass_kg;
            }
            out.push(x);
        }
    }
}

//! A dropper: a conductor that hangs from a node of another conductor (a slack substation span, a busbar)
//! down to an equipment terminal, or hangs free (issue 25: "slack conductors and droppers").
//!
//! The dropper is a conductor of its own (its own wire, material, segments and loads, [`super::LineConductor`])
//! of unstretched length `S` in `N` equal segments of `l0 = S / N`. Its first segment is the joint: a
//! [`super::LinkKind::Clamp`] link from the span conductor's node (or a support point) to the dropper
//! wire's first node, with the law of a segment of the dropper (the Kelvin-Voigt law (3.4) of the paper as
//! a link, [`crate::element::link`]):
//!
//! ```text
//! d = r_w0 - r_top,  e = |d| / l0 - 1,  T = EA e + eta edot  (tension only, as the conductor)      (3.4)
//! F on the wire's first node = -T d / |d|,  F on the span node = +T d / |d|
//! m_top += rho l0 / 2,  m_w0 += rho l0 / 2   (the joint segment's mass, lumped as a segment's is)
//! ```
//!
//! So the discrete dropper is exactly the paper's chain of `N` segments whose first node IS the span
//! conductor's node: the span node carries the joint segment's half mass and its tension; nothing else
//! joins the two conductors. The joint needs no stiffness of its own (it is as stiff as a segment of the
//! dropper, `EA / l0`), so it does not set the step: the wire's first node has the row of an interior
//! node of the dropper in the line's Gershgorin bound ([`crate::scheme::line`]: `K = 2 EA / l0`, mass
//! `rho l0`), and the span node gains `EA / l0` and `rho l0 / 2`, which for a dropper of the span's own
//! conductor and segment length keeps its row at `4 EA / (rho l0^2)`, an interior node's. The joint
//! segment carries no wind and no uniform load (the only difference from a segment of the wire: over one
//! segment of a few tens of centimetres).
//!
//! The lower end is a node fixed at the terminal point (a [`super::DeadEnd`] on a rigid support of its
//! own, so that the terminal's load is a support resultant), or free.
//!
//! Initial shape ([`dropper_nodes`]): with a terminal, the elastic catenary of unstretched length `S`
//! between the joint and the terminal under the dropper's weight ([`crate::exact::catenary`], as a
//! section's spans are strung), node `j` at its Lagrangian coordinate `s = j S / N`; where that has no
//! solution (no weight), the parabola of arc length `S` in the vertical plane through the chord, sagging
//! perpendicular to it (`y = 4 f u (1 - u)` over the chord `c`, of length `c/2 sqrt(1 + k^2) + c/(2k) asinh
//! k`, `k = 4 f / c`, the sag `f` by bisection), nodes equally spaced in arc length. A free dropper hangs
//! plumb, each segment stretched by the weight below it (`T_j = w l0 (N - j - 1/2)`, its discrete rest
//! state). The catenary is the continuous rest state of the dropper on a fixed joint: the span's node
//! moves under the dropper's weight, so `initial.shape = "equilibrium"` of a line finds the hanging shape
//! of both ([`crate::statics::solve_line`]: the joint is a link, already in its Jacobian). A taut start
//! matters: from a shape whose segments are all slack (a parabola of the unstretched length) the
//! regularised Newton iteration of a short stiff dropper (strain 1e-4 between slack and taut) does not
//! find the tension's switch-on (observed: no progress in 40 iterations on a 6.5 m 243-AL1 dropper).

use super::handle::{Endpoint, NodeRef};
use super::model::{DeadEnd, LineConductor, Link, LinkKind, Model, ModelError, PointMass};
use super::support::Support;
use crate::element::LinkLaw;
use crate::element::tension::LawKind;
use crate::wire::Constraint;

/// Why a dropper's shape cannot be built.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum DropperError {
    /// the unstretched length is shorter than the distance from the joint to the terminal
    #[error(
        "the dropper's length {length_m} m is shorter than the distance {chord_m} m from its joint to its terminal"
    )]
    TooShort {
        /// the unstretched length [m]
        length_m: f64,
        /// the distance from the joint to the terminal [m]
        chord_m: f64,
    },
    /// a slack dropper whose terminal is plumb below (or above) its joint: no vertical plane to sag in
    #[error(
        "the dropper's terminal is plumb below its joint (horizontal offset {horizontal_m} m, under 1e-3 of the distance {chord_m} m) but its length is longer than that distance: offset the terminal horizontally"
    )]
    Plumb {
        /// horizontal distance from the joint to the terminal [m]
        horizontal_m: f64,
        /// the distance from the joint to the terminal [m]
        chord_m: f64,
    },
    /// fewer than three segments (the joint and a wire of at least two)
    #[error("a dropper needs at least 3 segments (the joint and a wire of two), not {0}")]
    Segments(usize),
}

/// The `N + 1` node positions [m] of a dropper of unstretched length `length_m` [m] in `segments` (`N`)
/// equal segments, weight `weight_n_per_m` [N/m] per unstretched metre and axial stiffness `ea_n` [N], from
/// its joint at `top_m` to its terminal `terminal_m` (the elastic catenary of the module doc, or the
/// parabola without weight), or hanging plumb from `top_m` when `terminal_m` is `None`. Node 0 is the
/// joint (the span conductor's node); nodes `1..=N` are the dropper wire's.
pub fn dropper_nodes(
    top_m: [f64; 3],
    terminal_m: Option<[f64; 3]>,
    length_m: f64,
    segments: usize,
    weight_n_per_m: f64,
    ea_n: f64,
) -> Result<[Vec<f64>; 3], DropperError> {
    if segments < 3 {
        return Err(DropperError::Segments(segments));
    }
    let n = segments;
    let mut x = [vec![0.0; n + 1], vec![0.0; n + 1], vec![0.0; n + 1]];
    let l0 = length_m / n as f64;
    let Some(b) = terminal_m else {
        let mut z = top_m[2];
        for i in 0..=n {
            x[0][i] = top_m[0];
            x[1][i] = top_m[1];
            x[2][i] = z;
            // Segment i carries the weight of the nodes below it: N - i - 1/2 segments' worth.
            let t = weight_n_per_m * l0 * (n as f64 - i as f64 - 0.5);
            z -= l0 * (1.0 + t.max(0.0) / ea_n);
        }
        return Ok(x);
    };
    let taut = crate::exact::catenary::ElasticCatenary::solve(top_m, b, length_m, [0.0, 0.0, -weight_n_per_m], ea_n);
    let d = [b[0] - top_m[0], b[1] - top_m[1], b[2] - top_m[2]];
    let chord = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    let horizontal = (d[0] * d[0] + d[1] * d[1]).sqrt();
    // A relative rounding slack: a length equal to the distance written in the file is accepted.
    if length_m < chord * (1.0 - 1e-12) {
        return Err(DropperError::TooShort { length_m, chord_m: chord });
    }
    let slack = length_m > chord * (1.0 + 1e-12);
    if slack && horizontal < 1e-3 * chord {
        return Err(DropperError::Plumb { horizontal_m: horizontal, chord_m: chord });
    }
    if let Ok(c) = taut.as_ref()
        && horizontal >= 1e-3 * chord
    {
        for i in 0..=n {
            let p = c.position(length_m * i as f64 / n as f64);
            for k in 0..3 {
                x[k][i] = p[k];
            }
        }
        return Ok(x);
    }
    // Unit chord t, and the unit normal in the vertical plane through the chord pointing down:
    // nrm = (t (t . e3) - e3) / |...|.
    let t = d.map(|v| v / chord);
    let nrm = {
        let m = [t[0] * t[2], t[1] * t[2], t[2] * t[2] - 1.0];
        let l = (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt();
        if l > 0.0 { m.map(|v| v / l) } else { [0.0, 0.0, -1.0] }
    };
    let sag = if slack { parabola_sag(chord, length_m) } else { 0.0 };
    // Arc length from u = 0 of p(u) = a + u d + 4 f u (1 - u) nrm: s(u) = c/2 [P(2u - 1) + P(1)], with
    // P(w) the primitive of sqrt(1 + (k w)^2) in w (k = 4 f / c); inverted by bisection per node.
    let k = 4.0 * sag / chord;
    let prim = |w: f64| {
        let y = k * w;
        let asinh_ratio = if y.abs() < 1e-4 { 1.0 - y * y / 6.0 } else { y.asinh() / y };
        0.5 * w * ((1.0 + y * y).sqrt() + asinh_ratio)
    };
    let arc = |u: f64| 0.5 * chord * (prim(2.0 * u - 1.0) + prim(1.0));
    let total = arc(1.0);
    for i in 0..=n {
        let u = if i == 0 {
            0.0
        } else if i == n {
            1.0
        } else {
            let target = total * i as f64 / n as f64;
            let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
            while hi - lo > 1e-15 {
                let mid = 0.5 * (lo + hi);
                if arc(mid) < target { lo = mid } else { hi = mid }
            }
            0.5 * (lo + hi)
        };
        for c in 0..3 {
            x[c][i] = top_m[c] + u * d[c] + 4.0 * sag * u * (1.0 - u) * nrm[c];
        }
    }
    Ok(x)
}

/// Sag `f` [m] of the parabola over a chord `c` [m] whose arc length is `s >= c` [m] (bisection on the
/// closed-form length, which increases with `f`).
fn parabola_sag(c: f64, s: f64) -> f64 {
    let length = |f: f64| {
        let k = 4.0 * f / c;
        if k < 1e-8 { c } else { 0.5 * c * (1.0 + k * k).sqrt() + c / (2.0 * k) * k.asinh() }
    };
    let (mut lo, mut hi) = (0.0_f64, s);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if length(mid) < s { lo = mid } else { hi = mid }
    }
    0.5 * (lo + hi)
}

/// The droppers of a line: the conductors hung from their first node by a [`LinkKind::Clamp`] link.
pub fn droppers(links: &[Link]) -> Vec<usize> {
    links
        .iter()
        .filter(|l| l.kind == LinkKind::Clamp)
        .filter_map(|l| match l.b {
            Endpoint::Node(n) if n.node == 0 => Some(n.conductor),
            _ => None,
        })
        .collect()
}

/// Conductor groups (a phase, a bundle's sub-conductors, with the droppers hung from them) without their
/// droppers: the conductors that share a phase's current and whose ends carry its tension.
pub fn without_droppers(groups: &[Vec<usize>], links: &[Link]) -> Vec<Vec<usize>> {
    let d = droppers(links);
    groups.iter().map(|g| g.iter().copied().filter(|c| !d.contains(c)).collect()).collect()
}

/// Add a dropper to the model: `conductor`'s wire is the dropper without its joint segment (nodes `1..=N`
/// of [`dropper_nodes`], segments `2..=N`, each of `l0`); its first node is made free and joined to `top`
/// (the span conductor's node, or a support point) by a [`LinkKind::Clamp`] with the law of the wire's
/// first segment (its `l0`, `EA`, `eta`; tension only unless the wire's law is linear: a two-material
/// wire's joint is linear-elastic with its initial `EA`); the joint segment's mass `rho l0` is lumped half
/// at each end (at `top` only if it is a node). With `terminal`, the wire's last node stays fixed there, a
/// [`DeadEnd`] on a new rigid support named `"{name} terminal"`; without, it is freed. Returns the
/// dropper's conductor index and the clamp link's index.
pub fn add_dropper(
    model: &mut Model,
    mut conductor: LineConductor,
    top: Endpoint,
    terminal: bool,
) -> Result<(usize, usize), ModelError> {
    let w = &mut conductor.wire;
    let n = w.nodes();
    if let Endpoint::Node(r) = top {
        let ok = model.conductors.get(r.conductor).is_some_and(|c| r.node < c.wire.nodes());
        if !ok {
            return Err(ModelError::Handle {
                what: format!("dropper '{}'", conductor.name),
                detail: format!("its joint names node {} of conductor {}, which does not exist", r.node, r.conductor),
            });
        }
    }
    let l0 = w.rest_length[0];
    let rho = w.segment_mass[0] / l0;
    let law = LinkLaw {
        rest_length_m: l0,
        axial_stiffness_n: w.axial_stiffness_n[0],
        axial_damping_n_s: w.internal_friction_n_s[0],
        compression: w.law == LawKind::Linear,
    };
    w.set_constraint(0, Constraint::Free);
    let last = n - 1;
    let terminal_at = w.position(last);
    if !terminal {
        w.set_constraint(last, Constraint::Free);
    }
    let name = conductor.name.clone();
    let index = model.add_conductor(conductor);
    if terminal {
        let support = model.add_support(Support::rigid(format!("{name} terminal"), terminal_at));
        model.dead_ends.push(DeadEnd { node: NodeRef::new(index, last), support });
    }
    let half = 0.5 * rho * l0;
    model.point_masses.push(PointMass { node: NodeRef::new(index, 0), mass_kg: half });
    if let Endpoint::Node(r) = top {
        model.point_masses.push(PointMass { node: r, mass_kg: half });
    }
    let link = model.add_link(Link {
        kind: LinkKind::Clamp,
        a: top,
        b: Endpoint::Node(NodeRef::new(index, 0)),
        law,
        intact: true,
    });
    Ok((index, link))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn arc_lengths(x: &[Vec<f64>; 3]) -> Vec<f64> {
        (0..x[0].len() - 1).map(|i| (0..3).map(|k| (x[k][i + 1] - x[k][i]).powi(2)).sum::<f64>().sqrt()).collect()
    }

    /// Without weight, the parabola's nodes are equally spaced in arc length: the chord of an arc of length `l0` and
    /// curvature at most `kappa` is shorter by at most `l0^3 kappa^2 / 24`; here (sag 1.73 m on a chord of
    /// 5.83 m, `kappa <= 8 f / c^2 = 0.41 /m`, `l0 = 0.175 m`) that is 2.1e-4 of `l0`, so each chord is
    /// within 2.5e-4 of `S / N` and their sum within 2.5e-4 of `S`; a taut dropper is its chord.
    #[test]
    fn nodes_lie_on_a_parabola_of_the_given_length() {
        let (a, b) = ([0.0, 0.0, 10.0], [0.0, 3.0, 5.0]);
        let x = dropper_nodes(a, Some(b), 7.0, 40, 0.0, 1e7).unwrap();
        let l = arc_lengths(&x);
        let sum: f64 = l.iter().sum();
        assert!(sum < 7.0 && (sum - 7.0).abs() < 2.5e-4 * 7.0, "{sum}");
        assert!(l.iter().all(|v| *v <= 7.0 / 40.0 && (v - 7.0 / 40.0).abs() < 2.5e-4 * 7.0 / 40.0));
        assert_eq!([x[0][40], x[1][40], x[2][40]], b);
        // The sag is downwards: the middle node is below the chord.
        assert!(x[2][20] < 7.5);
        let taut = dropper_nodes(a, Some(b), 34.0_f64.sqrt(), 10, 0.0, 1e7).unwrap();
        assert!((arc_lengths(&taut).iter().sum::<f64>() - 34.0_f64.sqrt()).abs() < 1e-12);
    }

    #[test]
    fn refuses_a_short_or_plumb_slack_dropper() {
        let a = [0.0, 0.0, 10.0];
        assert!(matches!(
            dropper_nodes(a, Some([0.0, 3.0, 6.0]), 4.9, 10, 6.0, 1e7),
            Err(DropperError::TooShort { .. })
        ));
        assert!(matches!(dropper_nodes(a, Some([0.0, 0.0, 5.0]), 6.0, 10, 6.0, 1e7), Err(DropperError::Plumb { .. })));
        assert!(dropper_nodes(a, Some([0.0, 0.0, 5.0]), 5.0, 10, 6.0, 1e7).is_ok());
        assert_eq!(dropper_nodes(a, None, 5.0, 2, 6.0, 1e7), Err(DropperError::Segments(2)));
    }
}

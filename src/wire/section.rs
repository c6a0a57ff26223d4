//! A line section: spans between an ordered list of supports, built into one [`Wire`].
//!
//! The section's first and last supports are dead-ends (the conductor fixed to a point); between them,
//! suspension supports hang the conductor from insulator strings ([`super::insulator`]). The conductor is
//! continuous: span `k` runs from the clamp (or dead-end point) of support `k` to that of support `k + 1`
//! and owns nodes `first_node[k] ..= first_node[k + 1]` of the line; the node shared by two spans is the
//! clamp of the suspension support between them. Each span has its own conductor (axial stiffness,
//! internal friction, linear density) and segment count.
//!
//! Stringing. Lines are strung by tension: a span given a horizontal tension `H0` [N] gets the unstretched
//! length for which the elastic catenary between its clamps, with every insulator hanging plumb
//! (`clamp = pivot - L_i e3`), has the horizontal tension `H0` under the conductor's weight
//! ([`crate::exact::catenary::ElasticCatenary`], the length found by bisection). A span may instead state
//! its unstretched length. The initial shape of every span is its elastic catenary between the plumb
//! clamps (nodes at equal unstretched arc length), at rest: where the spans' horizontal tensions are equal
//! this is the continuous equilibrium, and the discrete one differs from it by `O(ds^2)`.

use super::insulator::{Crossarm, Insulator};
use super::{Conductor, Constraint, Wire};
use crate::exact::catenary::ElasticCatenary;

/// One support of a section.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Support {
    /// The conductor is fixed to `point_m` [m].
    DeadEnd {
        /// attachment point [m]
        point_m: [f64; 3],
    },
    /// The conductor hangs from an insulator string.
    Suspension {
        /// crossarm pivot (top of the string) [m]
        pivot_m: [f64; 3],
        /// string length `L_i` [m]
        length_m: f64,
        /// string mass `m_i` [kg], lumped at the clamp
        mass_kg: f64,
        /// string axial stiffness `EA_i` [N]
        stiffness_n: f64,
        /// an elastic crossarm: springs along and across the line [N/m], mass [kg], damping [N s/m]
        crossarm: Option<CrossarmSpec>,
    },
}

/// An elastic crossarm of a suspension support.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CrossarmSpec {
    /// spring along the line `k_l` [N/m]
    pub longitudinal_n_per_m: f64,
    /// spring across the line `k_t` [N/m]
    pub transverse_n_per_m: f64,
    /// mass moving with the pivot `M` [kg]
    pub mass_kg: f64,
    /// viscous damping `c_d` [N s/m]
    pub damping_n_s_per_m: f64,
}

/// How a span's unstretched length is set.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Stringing {
    /// horizontal tension `H0` [N] with every insulator plumb
    HorizontalTension(f64),
    /// unstretched length `S` [m]
    UnstretchedLength(f64),
    /// sag `f` [m]: the vertical distance from the chord down to the conductor at the span's horizontal
    /// middle, with every insulator plumb
    Sag(f64),
}

/// One span of a section.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Span {
    /// the conductor's axial stiffness, internal friction and law
    pub conductor: Conductor,
    /// linear density `rho0` [kg/m] per unit unstretched length
    pub linear_density_kg_per_m: f64,
    /// number of segments `N_k` [-]
    pub segments: usize,
    /// how the unstretched length is set
    pub stringing: Stringing,
}

/// A section to build.
#[derive(Clone, Debug, PartialEq)]
pub struct Section {
    /// supports, in order along the line (at least two; the first and last dead-ends)
    pub supports: Vec<Support>,
    /// spans, one fewer than the supports
    pub spans: Vec<Span>,
    /// gravitational acceleration `g` [m/s^2] (the stringing's weight)
    pub gravity_m_per_s2: f64,
}

/// Where the spans and supports lie on the built line.
#[derive(Clone, Debug, PartialEq)]
pub struct Layout {
    /// first node of each span, and the line's last node at the end (`spans + 1` values)
    pub first_node: Vec<usize>,
    /// unstretched length of each span [m]
    pub unstretched_length_m: Vec<f64>,
    /// horizontal tension of each span's initial catenary [N]
    pub horizontal_tension_n: Vec<f64>,
    /// the node of each support (dead-end point or clamp), in order
    pub support_node: Vec<usize>,
    /// horizontal unit vector along the line at each support [-] (the mean of the adjacent spans'
    /// horizontal directions)
    pub along: Vec<[f64; 3]>,
}

impl Layout {
    /// Nodes of span `k`.
    pub fn nodes(&self, k: usize) -> std::ops::RangeInclusive<usize> {
        self.first_node[k]..=self.first_node[k + 1]
    }

    /// Segments of span `k`.
    pub fn segments(&self, k: usize) -> std::ops::Range<usize> {
        self.first_node[k]..self.first_node[k + 1]
    }

    /// Node nearest to the fraction `f` [-] of span `k`'s unstretched length.
    pub fn node_at(&self, k: usize, f: f64) -> usize {
        let (a, b) = (self.first_node[k], self.first_node[k + 1]);
        a + ((f * (b - a) as f64).round().clamp(0.0, (b - a) as f64) as usize)
    }
}

/// Why a section could not be built.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum SectionError {
    /// The supports and spans do not fit together.
    #[error("section: {0}")]
    Shape(String),
    /// No catenary was found for a span.
    #[error("section: span {span}: {reason}")]
    Span {
        /// the span (0-based)
        span: usize,
        /// what failed
        reason: String,
    },
}

/// The conductor's attachment point at support `s` with the string plumb and carrying `tension_n` [N]
/// (its stretched length `L_i (1 + T / EA_i)` below the pivot) [m].
pub fn plumb_clamp(s: &Support, tension_n: f64) -> [f64; 3] {
    match *s {
        Support::DeadEnd { point_m } => point_m,
        Support::Suspension { pivot_m, length_m, stiffness_n, .. } => {
            [pivot_m[0], pivot_m[1], pivot_m[2] - length_m * (1.0 + tension_n / stiffness_n)]
        }
    }
}

/// The spans' catenaries between plumb clamps, each string stretched by the load it carries: the clamp
/// heights depend on the strings' tensions, which depend on the spans' end forces, so the two are
/// iterated to a fixed point (the stretch is millimetres and its change per sweep falls by the ratio of
/// string to span compliance, so a few sweeps reach rounding).
fn catenaries(section: &Section) -> Result<(Vec<ElasticCatenary>, Vec<f64>), SectionError> {
    let (sup, spans, g) = (&section.supports, &section.spans, section.gravity_m_per_s2);
    let mut string_tension = vec![0.0; sup.len()];
    let mut out = Vec::new();
    for _sweep in 0..100 {
        let clamps: Vec<[f64; 3]> = sup.iter().zip(&string_tension).map(|(s, &t)| plumb_clamp(s, t)).collect();
        out.clear();
        for (k, span) in spans.iter().enumerate() {
            let (a, b) = (clamps[k], clamps[k + 1]);
            let w = span.linear_density_kg_per_m * g;
            let ea = span.conductor.axial_stiffness_n;
            let l0 = match span.stringing {
                Stringing::UnstretchedLength(l) => l,
                Stringing::HorizontalTension(h) => {
                    length_for_tension(a, b, h, w, ea).map_err(|reason| SectionError::Span { span: k, reason })?
                }
                Stringing::Sag(f) => {
                    length_for_sag(a, b, f, w, ea).map_err(|reason| SectionError::Span { span: k, reason })?
                }
            };
            let cat = ElasticCatenary::solve(a, b, l0, [0.0, 0.0, -w], ea)
                .map_err(|e| SectionError::Span { span: k, reason: e.to_string() })?;
            out.push(cat);
        }
        let mut change: f64 = 0.0;
        for (k, s) in sup.iter().enumerate() {
            if let Support::Suspension { mass_kg, .. } = *s {
                // Vertical load on the clamp: the two spans' end reactions and the string's own weight.
                let t = out[k - 1].reaction_b_n() + out[k].reaction_a_n() + mass_kg * g;
                change = change.max((t - string_tension[k]).abs());
                string_tension[k] = t;
            }
        }
        if change <= 1e-12 * string_tension.iter().fold(1.0, |m, t| f64::max(m, *t)) {
            break;
        }
    }
    let lengths = out.iter().map(|c| c.unstretched_length_m()).collect();
    Ok((out, lengths))
}

/// Unstretched length [m] of an elastic catenary between `a` and `b` [m] with horizontal tension `h_n`
/// [N] under its weight `w_n_per_m` [N/m per unstretched length], for axial stiffness `ea_n` [N]: the
/// horizontal tension falls monotonically as the length grows, so bisection between a length at which it
/// is above `h_n` and one at which it is below converges (to the rounding of the length, 1e-15 relative).
pub fn length_for_tension(a: [f64; 3], b: [f64; 3], h_n: f64, w_n_per_m: f64, ea_n: f64) -> Result<f64, String> {
    let chord = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2) + (b[2] - a[2]).powi(2)).sqrt();
    let h_of = |l0: f64| {
        ElasticCatenary::solve(a, b, l0, [0.0, 0.0, -w_n_per_m], ea_n)
            .map(|c| c.horizontal_tension_n())
            .map_err(|e| e.to_string())
    };
    let (mut lo, mut hi) = (0.5 * chord, 2.0 * chord);
    if h_of(lo)? < h_n || h_of(hi)? > h_n {
        return Err(format!(
            "no unstretched length between {lo} m and {hi} m gives the horizontal tension {h_n} N (chord {chord} m)"
        ));
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if h_of(mid)? > h_n {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// Sag [m] of a catenary: the vertical distance from the chord `a`-`b` down to the curve at the
/// horizontal middle of the span (the arc-length parameter found by bisection: the horizontal distance
/// from `a` grows along the curve).
pub fn midspan_sag_m(cat: &ElasticCatenary, a: [f64; 3], b: [f64; 3]) -> f64 {
    let (h1, h2) = (b[0] - a[0], b[1] - a[1]);
    let span2 = h1 * h1 + h2 * h2;
    let fraction = |p: [f64; 3]| ((p[0] - a[0]) * h1 + (p[1] - a[1]) * h2) / span2;
    let (mut lo, mut hi) = (0.0, cat.unstretched_length_m());
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if fraction(cat.position(mid)) < 0.5 {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let p = cat.position(0.5 * (lo + hi));
    0.5 * (a[2] + b[2]) - p[2]
}

/// Unstretched length [m] of an elastic catenary between `a` and `b` [m] whose [`midspan_sag_m`] is
/// `sag_m` [m] under its weight `w_n_per_m` [N/m per unstretched length], for axial stiffness `ea_n` [N]:
/// the sag grows monotonically with the length, so bisection converges.
pub fn length_for_sag(a: [f64; 3], b: [f64; 3], sag_m: f64, w_n_per_m: f64, ea_n: f64) -> Result<f64, String> {
    let chord = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2) + (b[2] - a[2]).powi(2)).sqrt();
    let sag_of = |l0: f64| {
        ElasticCatenary::solve(a, b, l0, [0.0, 0.0, -w_n_per_m], ea_n)
            .map(|c| midspan_sag_m(&c, a, b))
            .map_err(|e| e.to_string())
    };
    let (mut lo, mut hi) = (0.5 * chord, 2.0 * chord);
    if sag_of(lo)? > sag_m || sag_of(hi)? < sag_m {
        return Err(format!(
            "no unstretched length between {lo} m and {hi} m gives the sag {sag_m} m (chord {chord} m)"
        ));
    }
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if sag_of(mid)? < sag_m {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

/// Build the line of a section: nodes on each span's catenary between the plumb clamps, dead-ends fixed,
/// suspension clamps hung from their strings (with their crossarms). Returns the wire and its layout.
pub fn build(section: &Section) -> Result<(Wire, Layout), SectionError> {
    let (sup, spans) = (&section.supports, &section.spans);
    if sup.len() < 2 || spans.len() + 1 != sup.len() {
        return Err(SectionError::Shape(format!(
            "{} supports need {} spans, not {}",
            sup.len(),
            sup.len().saturating_sub(1),
            spans.len()
        )));
    }
    let ends = [sup[0], sup[sup.len() - 1]];
    if ends.iter().any(|s| !matches!(s, Support::DeadEnd { .. })) {
        return Err(SectionError::Shape("the first and last supports must be dead-ends".into()));
    }
    let (cats, lengths) = catenaries(section)?;
    let mut first_node = vec![0];
    let tensions: Vec<f64> = cats.iter().map(|c| c.horizontal_tension_n()).collect();
    let (mut x, mut rest, mut seg_ea, mut seg_eta, mut seg_rho) =
        ([Vec::new(), Vec::new(), Vec::new()], Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for (k, (span, cat)) in spans.iter().zip(&cats).enumerate() {
        let (ea, l0) = (span.conductor.axial_stiffness_n, lengths[k]);
        let n = span.segments;
        let start = usize::from(k > 0);
        for i in start..=n {
            let p = cat.position(l0 * i as f64 / n as f64);
            for c in 0..3 {
                x[c].push(p[c]);
            }
        }
        for _ in 0..n {
            rest.push(l0 / n as f64);
            seg_ea.push(ea);
            seg_eta.push(span.conductor.internal_friction_n_s);
            seg_rho.push(span.linear_density_kg_per_m);
        }
        first_node.push(first_node[k] + n);
    }
    let law = spans[0].conductor.law;
    if spans.iter().any(|s| s.conductor.law != law) {
        return Err(SectionError::Shape("every span must use the same tension law".into()));
    }
    let mut wire = Wire::new(spans[0].conductor, x, rest, spans[0].linear_density_kg_per_m);
    wire.axial_stiffness_n = seg_ea;
    wire.internal_friction_n_s = seg_eta;
    for j in 0..wire.segments() {
        wire.segment_mass[j] = wire.reference_length[j] * seg_rho[j];
    }
    wire.update_node_masses();
    // Horizontal direction along the line at each support: the mean of the adjacent spans' directions.
    let horizontal = |k: usize| {
        let (a, b) = (plumb_clamp(&sup[k], 0.0), plumb_clamp(&sup[k + 1], 0.0));
        let d = [b[0] - a[0], b[1] - a[1]];
        let n = (d[0] * d[0] + d[1] * d[1]).sqrt();
        if n > 0.0 { [d[0] / n, d[1] / n, 0.0] } else { [0.0, 1.0, 0.0] }
    };
    let mut along = Vec::with_capacity(sup.len());
    for k in 0..sup.len() {
        let (l, r) = (if k > 0 { horizontal(k - 1) } else { horizontal(0) }, horizontal(k.min(spans.len() - 1)));
        let m = [l[0] + r[0], l[1] + r[1]];
        let n = (m[0] * m[0] + m[1] * m[1]).sqrt();
        along.push(if n > 0.0 { [m[0] / n, m[1] / n, 0.0] } else { r });
    }
    let support_node: Vec<usize> = (0..sup.len()).map(|k| first_node[k]).collect();
    for (k, s) in sup.iter().enumerate() {
        let node = support_node[k];
        match *s {
            Support::DeadEnd { .. } => wire.set_constraint(node, Constraint::Fixed),
            Support::Suspension { pivot_m, length_m, mass_kg, stiffness_n, crossarm } => {
                wire.set_constraint(node, Constraint::Free);
                wire.add_insulator(Insulator {
                    node,
                    pivot_m,
                    length_m,
                    stiffness_n,
                    damping_n_s: 0.0,
                    mass_kg,
                    intact: true,
                    along: along[k],
                    crossarm: crossarm.map(|c| Crossarm {
                        rest_m: pivot_m,
                        longitudinal: along[k],
                        longitudinal_n_per_m: c.longitudinal_n_per_m,
                        transverse_n_per_m: c.transverse_n_per_m,
                        mass_kg: c.mass_kg,
                        damping_n_s_per_m: c.damping_n_s_per_m,
                        velocity_m_per_s: [0.0; 3],
                    }),
                });
            }
        }
    }
    Ok((
        wire,
        Layout { first_node, unstretched_length_m: lengths, horizontal_tension_n: tensions, support_node, along },
    ))
}

//! A dropper in a line scenario: `dropper = { from, span, at_fraction, length_m, segments, to_m }` in a
//! conductor of `[[line.conductors]]` ([`crate::line::dropper`]).
//!
//! The dropper's conductor is its `conductor` table (material, catalogue entry) with no `section`: it
//! hangs from the node of conductor `from` nearest to `at_fraction` of span `span`'s unstretched length
//! (a section's spans have equal segments, so the node `first + round(f N_k)`, kept off the span's ends,
//! as a spacer's), over an unstretched length `length_m` in `segments` equal segments, the first of them
//! the joint, down to the terminal `to_m` (fixed) or free. Its wire is built by the single-conductor code
//! (a `[geometry]` of its last `segments - 1` segments, with the file's `[loads]`, `[numerics]`,
//! `[duration]`, `[output]`, `[ground]` and `[[events]]`), then strung on its elastic catenary between
//! the joint (as the span is strung) and the terminal.

use serde::Deserialize;

use super::build::{Plan, build};
use super::schema::{GeometrySpec, InitialSpec, Scenario, SectionSpec};
use super::validate::{Check, Problem};

/// `dropper` of a line conductor.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DropperToml {
    /// name of the conductor it hangs from: one listed before it, not a bundle and not a dropper
    pub from: String,
    /// span of that conductor's section (0 = its first span); default 0
    #[serde(default)]
    pub span: usize,
    /// where along the span, a fraction of its unstretched length in (0, 1): the nearest node
    pub at_fraction: f64,
    /// unstretched length `S` [m] from the joint to the lower end, in [d, 1000] with `d` the distance from
    /// the joint (as strung) to `to_m`; (0, 1000] for a free dropper
    pub length_m: f64,
    /// segments `N` [-], in [3, 1e5], the first of them the joint (`S / N` each)
    pub segments: usize,
    /// the equipment terminal `(x1, x2, x3)` [m], each within 1e5 m, where the lower end is fixed; absent:
    /// the lower end is free
    #[serde(default)]
    pub to_m: Option<[f64; 3]>,
}

/// The section of a dropper: none (`section` is not given for a dropper).
pub fn no_section() -> SectionSpec {
    SectionSpec {
        horizontal_tension_n: None,
        tension_fraction_of_rts: None,
        stringing_temperature_k: None,
        segments_per_span: None,
        supports: Vec::new(),
        spans: Vec::new(),
    }
}

/// The joint node of span `span` at `fraction` for a plan's spans `(first, last)`: `None` if the span
/// does not exist.
pub fn joint_node(spans: &[(usize, usize)], span: usize, fraction: f64) -> Option<usize> {
    let &(first, last) = spans.get(span)?;
    let count = last - first;
    Some(first + ((fraction * count as f64).round() as usize).clamp(1, count.max(2) - 1))
}

/// Check a dropper whose joint is at `joint_m` [m] (`None`: the conductor it hangs from is invalid, its
/// own checks report it) and build its plan from `base` (its single-conductor scenario without a
/// section). `f` names a field under the conductor.
pub fn plan(
    c: &mut Check,
    f: &dyn Fn(&str) -> String,
    d: &DropperToml,
    joint_m: Option<[f64; 3]>,
    base: Scenario,
) -> Option<Plan> {
    let mut ok = true;
    if !(d.at_fraction.is_finite() && d.at_fraction > 0.0 && d.at_fraction < 1.0) {
        c.fail(&f("dropper.at_fraction"), d.at_fraction, "must be in (0, 1)");
        ok = false;
    }
    if !(3..=100_000).contains(&d.segments) {
        c.fail(&f("dropper.segments"), d.segments, "must be in [3, 1e5] (the joint and a wire of at least two)");
        ok = false;
    }
    if let Some(t) = d.to_m {
        ok &= c.coordinates(&f("dropper.to_m"), t);
    }
    let a = joint_m?;
    let at = format!("[{:.3}, {:.3}, {:.3}] m", a[0], a[1], a[2]);
    let distance =
        d.to_m.map_or(0.0, |t| ((t[0] - a[0]).powi(2) + (t[1] - a[1]).powi(2) + (t[2] - a[2]).powi(2)).sqrt());
    let length_ok = d.length_m.is_finite() && d.length_m > 0.0 && d.length_m <= 1000.0;
    if !length_ok || (d.to_m.is_some() && d.length_m < distance * (1.0 - 1e-12)) {
        let allowed = match d.to_m {
            Some(_) => format!(
                "must be in [{distance:.4}, 1000] m: at least the distance from the joint ({at}, as strung) to the terminal to_m"
            ),
            None => "must be in (0, 1000] m".into(),
        };
        c.fail(&f("dropper.length_m"), d.length_m, &allowed);
        return None;
    }
    if let Some(t) = d.to_m {
        let horizontal = ((t[0] - a[0]).powi(2) + (t[1] - a[1]).powi(2)).sqrt();
        if d.length_m > distance * (1.0 + 1e-12) && horizontal < 1e-3 * distance {
            c.fail(
                &f("dropper.to_m"),
                format!("{t:?}"),
                &format!(
                    "is plumb below the joint ({at}) but the dropper is longer than that distance ({distance:.4} m): offset the terminal horizontally by at least 1e-3 of it ({:.2e} m), or make length_m equal to it",
                    1e-3 * distance
                ),
            );
            return None;
        }
    }
    if !ok {
        return None;
    }
    // The wire's geometry: its last N - 1 segments, provisionally straight (strung below).
    let n = d.segments;
    let end = d.to_m.unwrap_or([a[0], a[1], a[2] - d.length_m]);
    let first = [0, 1, 2].map(|k| a[k] + (end[k] - a[k]) / n as f64);
    let s = Scenario {
        geometry: Some(GeometrySpec {
            left_support_m: first,
            right_support_m: end,
            segments: n - 1,
            unstretched_length_m: Some(d.length_m * (n - 1) as f64 / n as f64),
        }),
        section: None,
        initial: InitialSpec::default(),
        ..base
    };
    let mut plan = match build(&s) {
        Ok(p) => p,
        Err(ps) => {
            for p in ps {
                c.fail(&f("dropper"), format!("{} = {}", p.field, p.value), &format!("its wire: {}", p.allowed));
            }
            return None;
        }
    };
    let w = plan.solver.wire();
    let weight = w.segment_mass[0] / w.rest_length[0] * plan.solver.loads().gravity_m_per_s2;
    let ea = w.axial_stiffness_n[0];
    match crate::line::dropper::dropper_nodes(a, d.to_m, d.length_m, n, weight, ea) {
        Ok(x) => {
            let w = plan.solver.wire_mut();
            for k in 0..3 {
                w.x[k].copy_from_slice(&x[k][1..]);
            }
            Some(plan)
        }
        Err(e) => {
            c.fail(&f("dropper"), "(shape)", &e.to_string());
            None
        }
    }
}

/// A problem of a dropper's own fields that its `from` conductor makes: `None` if `from` is valid.
pub fn check_from(spec: &[super::line::LineConductorSpec], k: usize) -> Option<Problem> {
    let d = spec[k].dropper.as_ref()?;
    let field = format!("line.conductors[{k}].dropper.from");
    let fail = |why: &str| Some(Problem { field: field.clone(), value: format!("{:?}", d.from), allowed: why.into() });
    match spec[..k].iter().position(|o| o.name == d.from) {
        None => fail("must name a conductor of line.conductors listed before this one"),
        Some(j) if spec[j].dropper.is_some() => fail("must name a conductor that is not itself a dropper"),
        Some(j) if spec[j].bundle.is_some() => {
            fail("must name a single conductor, not a bundle (a dropper on a bundle's yoke is not modelled)")
        }
        Some(j) if d.span + 2 > spec[j].section.supports.len() => Some(Problem {
            field: format!("line.conductors[{k}].dropper.span"),
            value: d.span.to_string(),
            allowed: format!(
                "must be a span of conductor {:?}: 0 to {}",
                d.from,
                spec[j].section.supports.len().saturating_sub(2)
            ),
        }),
        Some(_) => None,
    }
}

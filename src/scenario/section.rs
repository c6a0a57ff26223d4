//! The `[section]` of a scenario: checked field by field like the rest of the file, then built into the
//! line of [`crate::wire::section`] (spans strung by tension with the strings plumb). What the rest of
//! validation needs from it (segment counts and lengths per span, the time-step limit of the clamps, the
//! lowest initial point) is derived here once.
//!
//! Time step. The conductor's step is `C min_k(l0_k) / c` over the spans' segment lengths. Each clamp's
//! stable step ([`crate::wire::insulator::clamp_stable_step_s`]) is also multiplied by `C`, and the run
//! takes the smaller: for real strings the clamp never governs (module doc of the insulator).

use super::schema::{Scenario, SectionSpec, ShapeSpec, SupportSpec};
use super::validate::{Check, MAX_SEGMENTS, MAX_SPAN_M, number};
use crate::wire::insulator::clamp_stable_step_s;
use crate::wire::section::{self, CrossarmSpec, Layout, Section, Span, Stringing, Support, plumb_clamp};
use crate::wire::{Conductor, Wire};

/// Largest number of segments in one span.
pub const MAX_SEGMENTS_PER_SPAN: usize = 1_000_000;

/// What validation derives from a valid `[section]`.
#[derive(Clone, Debug)]
pub(crate) struct SectionGrid {
    /// the built line at its initial (strung) state
    pub wire: Wire,
    /// where spans and supports lie on it
    pub layout: Layout,
    /// distance between the two dead-ends [m] (the length scale of `tau`)
    pub chord_m: f64,
    /// shortest unstretched segment [m]
    pub ds_min_m: f64,
    /// smallest stable step of the clamps [s] (infinite without suspension supports)
    pub clamp_step_s: f64,
    /// lowest initial node height [m]
    pub lowest_m: f64,
}

/// Check `[section]` and build it; `None` if anything is invalid (each problem recorded in `c`).
/// `conductor` is the validated `[conductor]` (with the run's internal friction), `None` if invalid.
pub(crate) fn check(
    c: &mut Check,
    s: &Scenario,
    sec: &SectionSpec,
    conductor: Option<(Conductor, f64)>,
) -> Option<SectionGrid> {
    let n_sup = sec.supports.len();
    let mut ok = true;
    if n_sup < 2 {
        c.fail("section.supports", n_sup, "a section needs at least two supports (dead-ends at both ends)");
        return None;
    }
    let mut supports = Vec::with_capacity(n_sup);
    for (k, sp) in sec.supports.iter().enumerate() {
        let f = |name: &str| format!("section.supports[{k}].{name}");
        let end = k == 0 || k + 1 == n_sup;
        match sp {
            SupportSpec::DeadEnd { point_m } => {
                ok &= c.coordinates(&f("point_m"), *point_m);
                supports.push(Support::DeadEnd { point_m: *point_m });
            }
            SupportSpec::Suspension {
                pivot_m,
                insulator_length_m,
                insulator_mass_kg,
                insulator_stiffness_n,
                crossarm,
            } => {
                if end {
                    ok = false;
                    c.fail(&f("kind"), "\"suspension\"", "the first and last supports of a section must be dead-ends");
                }
                ok &= c.coordinates(&f("pivot_m"), *pivot_m);
                ok &= c.within(&f("insulator_length_m"), *insulator_length_m, 0.01, 20.0, "must be in [0.01, 20] m");
                ok &= c.within(&f("insulator_mass_kg"), *insulator_mass_kg, 0.0, 5000.0, "must be in [0, 5000] kg");
                ok &= c.within(
                    &f("insulator_stiffness_n"),
                    *insulator_stiffness_n,
                    1.0e4,
                    1.0e10,
                    "must be in [1e4, 1e10] N (strings are about 1e7 to 1e8 N)",
                );
                let arm = crossarm.map(|a| {
                    let g = |name: &str| format!("section.supports[{k}].crossarm.{name}");
                    let spring = "must be in (0, 1e10] N/m";
                    ok &= c.within(&g("longitudinal_n_per_m"), a.longitudinal_n_per_m, f64::MIN_POSITIVE, 1e10, spring);
                    ok &= c.within(&g("transverse_n_per_m"), a.transverse_n_per_m, f64::MIN_POSITIVE, 1e10, spring);
                    ok &= c.within(&g("mass_kg"), a.mass_kg, f64::MIN_POSITIVE, 1e6, "must be in (0, 1e6] kg");
                    ok &= c.within(&g("damping_n_s_per_m"), a.damping_n_s_per_m, 0.0, 1e9, "must be in [0, 1e9] N s/m");
                    CrossarmSpec {
                        longitudinal_n_per_m: a.longitudinal_n_per_m,
                        transverse_n_per_m: a.transverse_n_per_m,
                        mass_kg: a.mass_kg,
                        damping_n_s_per_m: a.damping_n_s_per_m,
                    }
                });
                supports.push(Support::Suspension {
                    pivot_m: *pivot_m,
                    length_m: *insulator_length_m,
                    mass_kg: *insulator_mass_kg,
                    stiffness_n: *insulator_stiffness_n,
                    crossarm: arm,
                });
            }
        }
    }
    if !ok {
        return None;
    }
    // Spans: horizontal distance along x2 between consecutive attachment points.
    let n_spans = n_sup - 1;
    if !sec.spans.is_empty() && sec.spans.len() != n_spans {
        c.fail(
            "section.spans",
            format!("{} tables", sec.spans.len()),
            &format!("give one [[section.spans]] per span ({n_spans} for {n_sup} supports), or none"),
        );
        return None;
    }
    let mut spans = Vec::with_capacity(n_spans);
    let mut total = 0usize;
    for k in 0..n_spans {
        let (a, b) = (plumb_clamp(&supports[k], 0.0), plumb_clamp(&supports[k + 1], 0.0));
        let d: f64 = (0..3).map(|i| (b[i] - a[i]).powi(2)).sum::<f64>().sqrt();
        let f = |name: &str| format!("section.spans[{k}].{name}");
        if !(b[1] - a[1] >= 1.0 && d <= MAX_SPAN_M) {
            ok = false;
            c.fail(
                &format!("section.supports[{}]", k + 1),
                format!("{b:?}"),
                &format!(
                    "attachment points must advance along x2 by at least 1 m per span and be at most {MAX_SPAN_M} m \
                     apart (span {k} runs from {a:?} to {b:?})"
                ),
            );
        }
        let sp = sec.spans.get(k).cloned().unwrap_or_default();
        let segments = sp.segments.or(sec.segments_per_span);
        let n = match segments {
            Some(n) if (2..=MAX_SEGMENTS_PER_SPAN).contains(&n) => n,
            Some(n) => {
                ok = false;
                c.fail(&f("segments"), n, &format!("must be an integer in [2, {MAX_SEGMENTS_PER_SPAN}]"));
                0
            }
            None => {
                ok = false;
                c.fail(&f("segments"), "(missing)", "give section.segments_per_span or the span's own segments");
                0
            }
        };
        total += n;
        let stringing = match (sp.unstretched_length_m, sp.horizontal_tension_n.or(sec.horizontal_tension_n)) {
            (Some(l), Some(_)) if sp.horizontal_tension_n.is_some() => {
                ok = false;
                c.fail(
                    &f("unstretched_length_m"),
                    number(l),
                    "give the span's unstretched length or its tension, not both",
                );
                None
            }
            (Some(l), _) => {
                let in_range = c.within(
                    &f("unstretched_length_m"),
                    l,
                    0.5 * d,
                    2.0 * d,
                    &format!("must be in [chord / 2, 2 chord] = [{}, {}] m", 0.5 * d, 2.0 * d),
                );
                ok &= in_range;
                Some(Stringing::UnstretchedLength(l))
            }
            (None, Some(h)) => {
                ok &= c.within(
                    &f("horizontal_tension_n"),
                    h,
                    f64::MIN_POSITIVE,
                    1.0e7,
                    "must be in (0, 1e7] N (lines are strung at 10 to 25 % of the rated strength)",
                );
                if s.loads.gravity_m_per_s2 <= 0.0 {
                    ok = false;
                    c.fail(
                        &f("horizontal_tension_n"),
                        number(h),
                        "stringing by tension needs loads.gravity_m_per_s2 > 0",
                    );
                }
                Some(Stringing::HorizontalTension(h))
            }
            (None, None) => {
                ok = false;
                c.fail(
                    &f("horizontal_tension_n"),
                    "(missing)",
                    "give section.horizontal_tension_n [N], or the span's horizontal_tension_n or unstretched_length_m",
                );
                None
            }
        };
        if let (Some(stringing), Some((conductor, rho))) = (stringing, conductor) {
            spans.push(Span { conductor, linear_density_kg_per_m: rho, segments: n, stringing });
        }
    }
    if total > MAX_SEGMENTS {
        ok = false;
        c.fail("section.segments_per_span", total, &format!("the section has {total} segments, above {MAX_SEGMENTS}"));
    }
    match (s.initial.shape, s.initial.sag_m) {
        (ShapeSpec::Parabola, _) => {
            ok = false;
            c.fail(
                "initial.shape",
                "\"parabola\"",
                "a section starts as strung (\"straight\", the default: each span's catenary) or at \"equilibrium\"",
            );
        }
        (_, Some(f)) => {
            ok = false;
            c.fail("initial.sag_m", number(f), "not used by a section (its spans are strung by tension or length)");
        }
        _ => {}
    }
    if !ok || conductor.is_none() || spans.len() != n_spans {
        return None;
    }
    let built = section::build(&Section { supports, spans, gravity_m_per_s2: s.loads.gravity_m_per_s2 });
    let (wire, layout) = match built {
        Ok(b) => b,
        Err(e) => {
            c.fail("section", "(as given)", &format!("cannot be strung: {e}"));
            return None;
        }
    };
    let a = wire.position(0);
    let b = wire.position(wire.segments());
    let chord_m = (0..3).map(|i| (b[i] - a[i]).powi(2)).sum::<f64>().sqrt();
    let ds_min_m = wire.rest_length.iter().copied().fold(f64::INFINITY, f64::min);
    let mut clamp_step_s = f64::INFINITY;
    for ins in &wire.insulators {
        let i = ins.node;
        let side = |j: usize| wire.axial_stiffness_n[j] / wire.rest_length[j];
        let dt = clamp_stable_step_s(wire.mass[i], ins.stiffness_n / ins.length_m, side(i - 1), side(i));
        clamp_step_s = clamp_step_s.min(dt);
    }
    let lowest_m = wire.x[2].iter().copied().fold(f64::INFINITY, f64::min);
    Some(SectionGrid { wire, layout, chord_m, ds_min_m, clamp_step_s, lowest_m })
}

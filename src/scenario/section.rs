//! The `[section]` of a scenario: checked field by field like the rest of the file, then built into the
//! line of [`crate::wire::section`] (spans strung by tension with the strings plumb). What the rest of
//! validation needs from it (segment counts and lengths per span, the time-step limit of the clamps, the
//! is derived here once.
//!
//! Time step. The conductor's step is `C min_k(l0_k) / c` over the spans' segment lengths. Each clamp's
//! stable step ([`crate::wire::insulator::damped_clamp_stable_step_s`], with the string's damper, and the
//! string counted twice where an elastic crossarm's pivot moves at its other end) and each elastic
//! crossarm pivot's ([`crate::wire::insulator::pivot_stable_step_s`]) is also multiplied by `C`, and the
//! run takes the smallest: for real strings and tower tops neither governs (module doc of the insulator),
//! unless a string's damper is far beyond a string's or a crossarm is stiff on a light pivot. Where one
//! does, the run says which ([`StepLimit`], a warning of [`super::warnings`]).

use super::range::{
    AXIAL_STIFFNESS_N, INSULATOR_DAMPING_N_S, INSULATOR_LENGTH_M, INSULATOR_MASS_KG, INSULATOR_STIFFNESS_N,
    LINEAR_DENSITY_KG_PER_M, RATED_TENSILE_STRENGTH_N, Range as Allowed,
};
use super::schema::{Scenario, SectionSpec, ShapeSpec, SupportSpec};
use super::validate::{Check, MAX_SEGMENTS, MAX_SPAN_M, number};
use crate::conductor::{CurveKind, TwoMaterial};
use crate::sagtension::StringingTarget;
use crate::sagtension::catenary::{DEFAULT_PANELS, SpanLaw};
use crate::sagtension::stringing::unstressed_length_m;
use crate::wire::insulator::{damped_clamp_stable_step_s, pivot_stable_step_s};
use crate::wire::section::{self, CrossarmSpec, Layout, Section, Span, Stringing, Support, plumb_clamp};
use crate::wire::{Conductor, Wire};

/// Horizontal stringing tension of a span [N] (`section.horizontal_tension_n`, a span's own).
const HORIZONTAL_TENSION_N: Allowed =
    Allowed::open_closed(0.0, 1.0e7, "N").note(" (lines are strung at 10 to 25 % of the rated strength)");

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
    /// smallest stable step of the clamps and of the elastic crossarms' pivots [s] (infinite without
    /// suspension supports)
    pub clamp_step_s: f64,
    /// the clamp or pivot with that smallest step
    pub step_limit: Option<StepLimit>,
    /// largest longitudinal wave speed `sqrt(EA / rho0)` over the spans [m/s]
    pub wave_speed_max_m_per_s: f64,
    /// smallest crossing time of a segment by that wave, `min_j l0_j / c_j` [s] (the step at Courant 1)
    pub crossing_time_s: f64,
}

/// The clamp or elastic crossarm of a section with the smallest stable step (module doc).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct StepLimit {
    /// the support's field in the file: `section.supports[k]` (its string's clamp) or
    /// `section.supports[k].crossarm` (the pivot)
    pub field: String,
    /// the element's values as the file gives them
    pub value: String,
    /// the element, its stiffness, damping and mass, as its Gershgorin bound counts them
    pub what: String,
    /// its stable step [s], before the Courant factor
    pub step_s: f64,
}

/// Check `[section]` and build it; `None` if anything is invalid (each problem recorded in `c`).
/// `conductor` is the validated `[conductor]` (with the run's internal friction), `None` if invalid;
/// `material` its two-material law and curve ([`super::two_material::check`]), which strings the spans.
pub(crate) fn check(
    c: &mut Check,
    s: &Scenario,
    sec: &SectionSpec,
    conductor: Option<(Conductor, f64)>,
    material: Option<(TwoMaterial, CurveKind)>,
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
                insulator_damping_n_s,
                crossarm,
            } => {
                if end {
                    ok = false;
                    c.fail(&f("kind"), "\"suspension\"", "the first and last supports of a section must be dead-ends");
                }
                ok &= c.coordinates(&f("pivot_m"), *pivot_m);
                ok &= c.range(&f("insulator_length_m"), *insulator_length_m, &INSULATOR_LENGTH_M);
                ok &= c.range(&f("insulator_mass_kg"), *insulator_mass_kg, &INSULATOR_MASS_KG);
                ok &= c.range(
                    &f("insulator_stiffness_n"),
                    *insulator_stiffness_n,
                    &INSULATOR_STIFFNESS_N.note(" (strings are about 1e7 to 1e8 N)"),
                );
                ok &= c.range(
                    &f("insulator_damping_n_s"),
                    *insulator_damping_n_s,
                    &INSULATOR_DAMPING_N_S.note(" (1e4 N s damps a string's ringing in a few periods)"),
                );
                let arm = crossarm.map(|a| {
                    let g = |name: &str| format!("section.supports[{k}].crossarm.{name}");
                    let spring = Allowed::open_closed(0.0, 1.0e10, "N/m");
                    ok &= c.range(&g("longitudinal_n_per_m"), a.longitudinal_n_per_m, &spring);
                    ok &= c.range(&g("transverse_n_per_m"), a.transverse_n_per_m, &spring);
                    ok &= c.range(&g("mass_kg"), a.mass_kg, &Allowed::open_closed(0.0, 1.0e6, "kg"));
                    ok &= c.range(&g("damping_n_s_per_m"), a.damping_n_s_per_m, &Allowed::closed(0.0, 1.0e9, "N s/m"));
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
    if let Some(h) = sec.horizontal_tension_n {
        ok &= c.range("section.horizontal_tension_n", h, &HORIZONTAL_TENSION_N);
    }
    // The section's tension, once for all spans.
    let rts = s.conductor.rated_tensile_strength_n;
    let section_h = match (sec.horizontal_tension_n, sec.tension_fraction_of_rts) {
        (Some(h), Some(fr)) => {
            ok = false;
            c.fail("section.tension_fraction_of_rts", number(fr), "give it or section.horizontal_tension_n, not both");
            Some(h)
        }
        (Some(h), None) => Some(h),
        (None, Some(fr)) => {
            ok &= c.range("section.tension_fraction_of_rts", fr, &Allowed::open_closed(0.0, 0.6, ""));
            match rts {
                Some(r) => {
                    // Reported with [conductor] (`super::validate`).
                    ok &= RATED_TENSILE_STRENGTH_N.contains(r);
                    Some(fr * r)
                }
                None => {
                    ok = false;
                    c.fail(
                        "conductor.rated_tensile_strength_n",
                        "(missing)",
                        "required with section.tension_fraction_of_rts",
                    );
                    None
                }
            }
        }
        (None, None) => None,
    };
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
                // Name the field the value was written in: the span's own, or the section's (once).
                let allowed = format!("must be an integer in [2, {MAX_SEGMENTS_PER_SPAN}]");
                if sp.segments.is_some() {
                    c.fail(&f("segments"), n, &allowed);
                } else if !c.0.iter().any(|p| p.field == "section.segments_per_span") {
                    c.fail("section.segments_per_span", n, &allowed);
                }
                0
            }
            None => {
                ok = false;
                c.fail(&f("segments"), "(missing)", "give section.segments_per_span or the span's own segments");
                0
            }
        };
        total += n;
        let rho = match sp.linear_density_kg_per_m {
            Some(r) => {
                ok &= c.range(&f("linear_density_kg_per_m"), r, &LINEAR_DENSITY_KG_PER_M);
                Some(r)
            }
            None => None,
        };
        let span_ea = match sp.axial_stiffness_n {
            Some(e) => {
                ok &= c.range(&f("axial_stiffness_n"), e, &AXIAL_STIFFNESS_N);
                Some(e)
            }
            None => None,
        };
        // One stringing per span: its own length, sag or tension, else the section's tension.
        let own: Vec<&str> = [
            sp.unstretched_length_m.map(|_| "unstretched_length_m"),
            sp.sag_m.map(|_| "sag_m"),
            sp.horizontal_tension_n.map(|_| "horizontal_tension_n"),
        ]
        .into_iter()
        .flatten()
        .collect();
        let stringing = match (sp.unstretched_length_m, sp.sag_m, sp.horizontal_tension_n.or(section_h)) {
            _ if own.len() > 1 => {
                ok = false;
                c.fail(
                    &f(own[1]),
                    "(given)",
                    &format!(
                        "give one of the span's unstretched_length_m, sag_m and horizontal_tension_n, not {}",
                        own.join(" and ")
                    ),
                );
                None
            }
            (Some(l), _, _) => {
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
            (None, Some(sag), _) => {
                ok &= c.within(
                    &f("sag_m"),
                    sag,
                    f64::MIN_POSITIVE,
                    0.5 * d,
                    &format!("must be in (0, chord / 2] = (0, {}] m (spans sag 1 to 10 % of their length)", 0.5 * d),
                );
                if s.loads.gravity_m_per_s2 <= 0.0 {
                    ok = false;
                    c.fail(&f("sag_m"), number(sag), "stringing by sag needs loads.gravity_m_per_s2 > 0");
                }
                Some(Stringing::Sag(sag))
            }
            (None, None, Some(h)) => {
                // Name the field the value was written in: the span's own, or the section's (reported once,
                // before the spans).
                ok &= HORIZONTAL_TENSION_N.contains(h);
                if sp.horizontal_tension_n.is_some() {
                    c.range(&f("horizontal_tension_n"), h, &HORIZONTAL_TENSION_N);
                }
                if s.loads.gravity_m_per_s2 <= 0.0 {
                    ok = false;
                    c.fail(
                        &f("horizontal_tension_n"),
                        number(h),
                        "stringing by tension needs loads.gravity_m_per_s2 > 0",
                    );
                }
                // A tension at or above the rated tensile strength breaks the conductor (lines are strung
                // at 10 to 25 % of it); the field named is the one the value was written in.
                if let Some(r) = rts.filter(|&r| r > 0.0 && h >= r) {
                    let field = if sp.horizontal_tension_n.is_some() {
                        f("horizontal_tension_n")
                    } else {
                        "section.horizontal_tension_n".to_string()
                    };
                    if !c.0.iter().any(|p| p.field == field) {
                        ok = false;
                        c.fail(
                            &field,
                            number(h),
                            &format!(
                                "must be below conductor.rated_tensile_strength_n = {} N: the conductor would break \
                                 (lines are strung at 10 to 25 % of it)",
                                number(r)
                            ),
                        );
                    }
                }
                Some(Stringing::HorizontalTension(h))
            }
            (None, None, None) => {
                ok = false;
                c.fail(
                    &f("horizontal_tension_n"),
                    "(missing)",
                    "give section.horizontal_tension_n [N], or the span's horizontal_tension_n, sag_m or unstretched_length_m",
                );
                None
            }
        };
        if let (Some(stringing), Some((conductor, bare))) = (stringing, conductor) {
            let conductor =
                Conductor { axial_stiffness_n: span_ea.unwrap_or(conductor.axial_stiffness_n), ..conductor };
            spans.push(Span { conductor, linear_density_kg_per_m: rho.unwrap_or(bare), segments: n, stringing });
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
    // The stringing temperature: where it is not the initial one, the strung shape is not at rest.
    let t_ref = s.conductor.reference_temperature_k;
    let two_material = material;
    if two_material.is_some() && s.initial.shape != ShapeSpec::Equilibrium {
        c.fail(
            "initial.shape",
            format!("{:?}", format!("{:?}", s.initial.shape).to_lowercase()),
            "a section of a two-material conductor (conductor.tension_law = \"two_material\") starts at \
             \"equilibrium\": its strung catenaries are those of the linear law, at rest only in the equilibrium \
             of the real one",
        );
        return None;
    }
    let stringing_factor = match sec.stringing_temperature_k {
        Some(t0) => {
            if !c.range("section.stringing_temperature_k", t0, &super::range::STRINGING_TEMPERATURE_K) {
                return None;
            }
            // A two-material conductor is strung at t0 by its own law below: no rescaling.
            let alpha = if two_material.is_some() { 0.0 } else { s.conductor.thermal_expansion_per_k };
            let factor = crate::wire::thermal_factor(alpha, t0, t_ref);
            if factor != 1.0 && s.initial.shape != ShapeSpec::Equilibrium {
                c.fail(
                    "section.stringing_temperature_k",
                    number(t0),
                    &format!(
                        "differs from the initial temperature conductor.reference_temperature_k = {} K (with \
                         conductor.thermal_expansion_per_k = {} 1/K): the strung shape is not at rest there; use \
                         initial.shape = \"equilibrium\"",
                        number(t_ref),
                        number(s.conductor.thermal_expansion_per_k)
                    ),
                );
                return None;
            }
            factor
        }
        None => 1.0,
    };
    let mut sect = Section { supports, spans, gravity_m_per_s2: s.loads.gravity_m_per_s2 };
    let built = section::build(&sect);
    let (mut wire, mut layout) = match built {
        Ok(b) => b,
        Err(e) => {
            c.fail("section", "(as given)", &format!("cannot be strung: {e}"));
            return None;
        }
    };
    if let Some((law, curve)) = two_material {
        // Strung by the real law: each span strung by tension or sag gets the unstressed length (at the law's
        // reference temperature) that gives it that tension or sag at the stringing temperature, between the
        // clamps of the linear stringing (the strings' stretch differs by micrometres), virgin on `curve`.
        let t0 = sec.stringing_temperature_k.unwrap_or(t_ref);
        for k in 0..sect.spans.len() {
            let target = match sect.spans[k].stringing {
                Stringing::UnstretchedLength(_) => continue,
                Stringing::HorizontalTension(h) => StringingTarget::HorizontalTension(h),
                Stringing::Sag(f) => StringingTarget::Sag(f),
            };
            let (a, b) = (wire.position(layout.support_node[k]), wire.position(layout.support_node[k + 1]));
            let span = SpanLaw {
                law: &law,
                history: law.virgin(curve),
                temperature_k: t0,
                load_n_per_m: sect.spans[k].linear_density_kg_per_m * s.loads.gravity_m_per_s2,
                span_m: (b[0] - a[0]).hypot(b[1] - a[1]),
                rise_m: b[2] - a[2],
                unstressed_length_m: 0.0,
                panels: DEFAULT_PANELS,
            };
            match unstressed_length_m(&span, target) {
                Ok(l) => sect.spans[k].stringing = Stringing::UnstretchedLength(l),
                Err(e) => {
                    c.fail(
                        &format!("section.spans[{k}]"),
                        "(as strung)",
                        &format!("cannot be strung with the two-material law of conductor.catalog: {e}"),
                    );
                    return None;
                }
            }
        }
        match section::build(&sect) {
            Ok((w, l)) => (wire, layout) = (w, l),
            Err(e) => {
                c.fail("section", "(as given)", &format!("cannot be strung: {e}"));
                return None;
            }
        }
    }
    // The strings' axial damping (not part of the stringing): the string of support k is the wire's
    // string at that support's node.
    for (k, sp) in sec.supports.iter().enumerate() {
        if let SupportSpec::Suspension { insulator_damping_n_s, .. } = sp
            && let Some(ins) = wire.insulators.iter_mut().find(|i| i.node == layout.support_node[k])
        {
            ins.damping_n_s = *insulator_damping_n_s;
        }
    }
    if stringing_factor != 1.0 {
        // Strung at T0: the stress-free lengths at the initial temperature T_ref are l0 / (1 + alpha (T0 - T_ref));
        // the conductor's mass stays.
        for j in 0..wire.segments() {
            wire.reference_length[j] = wire.rest_length[j] / stringing_factor;
            wire.rest_length[j] = wire.reference_length[j];
        }
    }
    let a = wire.position(0);
    let b = wire.position(wire.segments());
    let chord_m = (0..3).map(|i| (b[i] - a[i]).powi(2)).sum::<f64>().sqrt();
    let mut clamp_step_s = f64::INFINITY;
    let mut step_limit = None;
    for (sup, spec) in sec.supports.iter().enumerate() {
        let Some(ins) = wire.insulators.iter().find(|i| i.node == layout.support_node[sup]) else { continue };
        let i = ins.node;
        let side = |j: usize| wire.axial_stiffness_n[j] / wire.rest_length[j];
        let (k, c) = (ins.stiffness_n / ins.length_m, ins.damping_n_s / ins.length_m);
        // The string couples the clamp to a moving pivot too (module doc of the insulator).
        let coupled = if ins.crossarm.is_some() { 2.0 } else { 1.0 };
        let twice = if ins.crossarm.is_some() { " counted twice (its pivot moves)" } else { "" };
        let (kc, cc) = (coupled * k, coupled * c);
        let (left, right) = (side(i - 1), side(i));
        let clamp = damped_clamp_stable_step_s(wire.mass[i], kc, left, right, cc);
        let mut candidates = vec![(
            clamp,
            format!("section.supports[{sup}]"),
            format!(
                "insulator_stiffness_n = {}, insulator_mass_kg = {}, insulator_damping_n_s = {}",
                number(ins.stiffness_n),
                number(ins.mass_kg),
                number(ins.damping_n_s)
            ),
            format!(
                "the string's clamp ({:.4e} kg: string {:.4e} N/m{twice}, conductor segments {:.4e} and {:.4e} N/m, \
                 string damper {:.4e} N s/m{twice})",
                wire.mass[i], k, left, right, c
            ),
        )];
        if let (Some(arm), SupportSpec::Suspension { crossarm: Some(a), .. }) = (&ins.crossarm, spec) {
            let spring = arm.longitudinal_n_per_m.max(arm.transverse_n_per_m);
            let pivot = pivot_stable_step_s(arm.mass_kg, spring, k, arm.damping_n_s_per_m, c);
            candidates.push((
                pivot,
                format!("section.supports[{sup}].crossarm"),
                format!(
                    "{{ longitudinal_n_per_m = {}, transverse_n_per_m = {}, mass_kg = {}, damping_n_s_per_m = {} }}",
                    number(a.longitudinal_n_per_m),
                    number(a.transverse_n_per_m),
                    number(a.mass_kg),
                    number(a.damping_n_s_per_m)
                ),
                format!(
                    "the elastic crossarm's pivot ({} kg: spring {} N/m, string {:.4e} N/m counted twice, damping {} \
                     N s/m, string damper {:.4e} N s/m counted twice)",
                    number(arm.mass_kg),
                    number(spring),
                    k,
                    number(arm.damping_n_s_per_m),
                    c
                ),
            ));
        }
        for (dt, field, value, what) in candidates {
            if dt < clamp_step_s {
                clamp_step_s = dt;
                step_limit = Some(StepLimit { field, value, what, step_s: dt });
            }
        }
    }
    let (mut wave_speed_max_m_per_s, mut crossing_time_s) = (0.0_f64, f64::INFINITY);
    for j in 0..wire.segments() {
        let rho = wire.segment_mass[j] / wire.reference_length[j];
        let c = (wire.axial_stiffness_n[j] / rho).sqrt();
        wave_speed_max_m_per_s = wave_speed_max_m_per_s.max(c);
        crossing_time_s = crossing_time_s.min(wire.rest_length[j] / c);
    }
    Some(SectionGrid { wire, layout, chord_m, clamp_step_s, step_limit, wave_speed_max_m_per_s, crossing_time_s })
}

#[cfg(test)]
mod tests {
    use crate::scenario::{self, Scenario};

    const SECTION: &str = "[conductor]\naxial_stiffness_n = 2.9e7\nlinear_density_kg_per_m = 1.628\n\
        rated_tensile_strength_n = 140000.0\n[section]\ntension_fraction_of_rts = 0.2\nsegments_per_span = 10\n\
        supports = [\n{ kind = \"dead_end\", point_m = [0.0, 0.0, 30.0] },\n\
        { kind = \"suspension\", pivot_m = [0.0, 400.0, 33.5], insulator_length_m = 3.5, insulator_mass_kg = 100.0, \
        insulator_stiffness_n = 5.0e7 },\n{ kind = \"dead_end\", point_m = [0.0, 700.0, 30.0] },\n]\n\
        [[section.spans]]\n[[section.spans]]\nsegments = 20\nlinear_density_kg_per_m = 0.5\naxial_stiffness_n = 1.0e7\n\
        [duration]\nend_time_s = 1.0\n";

    #[test]
    fn spans_take_their_own_conductor_and_the_fastest_wave_sets_the_step() {
        let sc: Scenario = toml::from_str(SECTION).unwrap();
        let plan = scenario::plan(&sc, "section").unwrap();
        let w = plan.solver.wire();
        assert_eq!(w.segments(), 30);
        assert_eq!((w.axial_stiffness_n[0], w.axial_stiffness_n[29]), (2.9e7, 1.0e7));
        assert!((w.segment_mass[29] / w.reference_length[29] - 0.5).abs() < 1e-15);
        // Span 0: c = sqrt(2.9e7 / 1.628) = 4220.6 m/s on 40 m segments (9.5 ms); span 1: c = 4472.1 m/s
        // on 15 m segments (3.4 ms): the second governs, dt = C l0 / c with the default C = 0.9.
        let l0 = w.rest_length[29];
        let expect = 0.9 * l0 / (1.0e7f64 / 0.5).sqrt();
        assert!(
            (plan.solver.params().dt_s - expect).abs() < 1e-15 * expect,
            "{} vs {expect}",
            plan.solver.params().dt_s
        );
        // Both spans strung at 20 % of 140 kN.
        let sc2: Scenario = toml::from_str(&SECTION.replace("tension_fraction_of_rts = 0.2", "")).unwrap();
        let e = scenario::plan(&sc2, "section").unwrap_err().to_string();
        assert!(e.contains("section.spans[0].horizontal_tension_n` = (missing)"), "{e}");
    }
}

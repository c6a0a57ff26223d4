//! Validation of a parsed scenario: every field is checked before anything runs, and each problem
//! names the field, its value and what is allowed. Nothing here panics on any input.

use std::fmt;

use std::ops::Range;

use super::events::{EventSpec, GroundSpec, HeatBoundarySpec, break_segment, node_range, segment_range};
use super::range::{
    AXIAL_STIFFNESS_N, EVENT_TEMPERATURE_K, ICE_DENSITY_KG_PER_M3, LINEAR_DENSITY_KG_PER_M, RADIAL_ICE_M,
    RATED_TENSILE_STRENGTH_N, REFERENCE_TEMPERATURE_K, Range as Allowed, THERMAL_EXPANSION_PER_K,
};
use super::schema::{Scenario, ShapeSpec, SupportSpec, TensionLawSpec, WindLawSpec};
use super::section::SectionGrid;
use crate::element::tension::LawKind;
use crate::scheme::courant;
use crate::wire::Conductor;

/// One invalid field.
#[derive(Clone, Debug, PartialEq)]
pub struct Problem {
    /// dotted path of the field, e.g. `numerics.courant`
    pub field: String,
    /// the value found, as written
    pub value: String,
    /// what is allowed
    pub allowed: String,
}

impl fmt::Display for Problem {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "field `{}` = {} is not allowed: {}", self.field, self.value, self.allowed)
    }
}

/// A number as a reader would write it: plain decimal where that is short (`0.5`, `1000000`), otherwise
/// in exponent form (`1e-300`, `1e308`).
pub fn number(x: f64) -> String {
    let plain = x.to_string();
    if plain.len() > 12 { format!("{x:e}") } else { plain }
}

/// Collects problems (also used by the validators of the files the applications read).
#[derive(Debug, Default)]
pub struct Check(pub Vec<Problem>);

impl Check {
    /// Record that `field` = `value` is not allowed, with what is.
    pub fn fail(&mut self, field: &str, value: impl fmt::Display, allowed: &str) {
        self.0.push(Problem { field: field.into(), value: value.to_string(), allowed: allowed.into() });
    }
    /// As [`Check::fail`] for a number, written short: `1e308`, not 309 digits.
    fn fail_number(&mut self, field: &str, x: f64, allowed: &str) {
        self.fail(field, number(x), allowed);
    }
    /// `x` finite and `> 0`.
    pub fn positive(&mut self, field: &str, x: f64) -> bool {
        let ok = x.is_finite() && x > 0.0;
        if !ok {
            self.fail_number(field, x, "must be a finite number > 0");
        }
        ok
    }
    /// `x` finite and `>= 0`.
    pub fn non_negative(&mut self, field: &str, x: f64) -> bool {
        let ok = x.is_finite() && x >= 0.0;
        if !ok {
            self.fail_number(field, x, "must be a finite number >= 0");
        }
        ok
    }
    /// `x` in `range` ([`super::range::Range`]); its text says what is allowed.
    pub fn range(&mut self, field: &str, x: f64, range: &super::range::Range) -> bool {
        let ok = range.contains(x);
        if !ok {
            self.fail_number(field, x, &range.to_string());
        }
        ok
    }
    /// `lo <= x <= hi`, for a range whose ends depend on other fields (else [`Check::range`]).
    pub fn within(&mut self, field: &str, x: f64, lo: f64, hi: f64, allowed: &str) -> bool {
        let ok = x.is_finite() && x >= lo && x <= hi;
        if !ok {
            self.fail_number(field, x, allowed);
        }
        ok
    }
    fn finite3(&mut self, field: &str, v: [f64; 3]) -> bool {
        let ok = v.iter().all(|c| c.is_finite());
        if !ok {
            self.fail(field, format!("{v:?}"), "all three components must be finite numbers");
        }
        ok
    }
}

/// Largest number of segments accepted (memory and run time stay sane).
pub const MAX_SEGMENTS: usize = 10_000_000;

/// Largest chord `|B - A|` accepted [m]: the longest overhead spans built are about 5.4 km.
pub const MAX_SPAN_M: f64 = 10_000.0;

/// Largest magnitude of a support coordinate [m]: scenarios are written in a local frame around the span.
pub const MAX_COORDINATE_M: f64 = 1.0e5;

/// Largest wind speed accepted [m/s]: design wind speeds are below about 70 m/s.
pub const MAX_WIND_SPEED_M_PER_S: f64 = 100.0;

/// Least wind speed accepted above 0 [m/s]. The damping (2.6) divides by `U`: `(1 - mu V_n / U)^2`
/// overflows for a vanishing `U` while `q ~ U^2` underflows, giving `inf * 0`. From 0.01 m/s, with node
/// speeds below the 1e7 m/s speed bound, `mu V_n / U < 1e9`: no overflow. `U = 0` itself is still air (no
/// drag, no damping from it: the build takes `mu / U` as 0), so that a sweep over `U` can start there.
pub const MIN_WIND_SPEED_M_PER_S: f64 = 0.01;

/// Largest air density accepted [kg/m^3]: 1.225 at sea level, about 1.5 in the coldest air.
pub const MAX_AIR_DENSITY_KG_PER_M3: f64 = 2.0;

/// Least thermal length factor `1 + alpha_t (u - u_ref)` accepted [-]: a thermal strain of -50 %.
pub const MIN_THERMAL_FACTOR: f64 = 0.5;

/// Least number of time steps per gust period [-] (the law `|sin(pi t / P)|` must be resolved).
pub const MIN_STEPS_PER_GUST: f64 = 10.0;

/// Largest time accepted anywhere [s] (about three years).
pub const MAX_TIME_S: f64 = 1.0e8;

/// Lowest stress-free (stringing) temperature of a conductor [K]: -100 C, below the coldest air measured on
/// Earth (-89.2 C, Vostok 1983, WMO). A value below it is a temperature typed in Celsius (15 for 15 C).
pub const MIN_REFERENCE_TEMPERATURE_K: f64 = 173.15;

/// All problems of a scenario; empty when it is valid.
pub fn validate(s: &Scenario) -> Vec<Problem> {
    check(s).0
}

/// The quantities validation derives on the way, each `None` where its inputs were invalid. The builder
/// uses these and derives none of them again.
#[derive(Clone, Debug, Default)]
pub(crate) struct Derived {
    /// axial stiffness `EA` [N]
    pub ea_n: Option<f64>,
    /// chord length `|B - A|` [m]
    pub chord_m: Option<f64>,
    /// unstretched length `S` [m]
    pub length_m: Option<f64>,
    /// wave speed `c` [m/s]
    pub wave_speed_m_per_s: Option<f64>,
    /// nominal time step (3.7) [s]
    pub dt_s: Option<f64>,
    /// the built line of a `[section]`
    pub section: Option<SectionGrid>,
    /// the two-material law and its curve (`conductor.tension_law = "two_material"`)
    pub material: Option<(crate::conductor::TwoMaterial, crate::conductor::CurveKind)>,
}

/// Every problem of a scenario, and what was derived from its valid parts.
pub(crate) fn check(s: &Scenario) -> (Vec<Problem>, Derived) {
    let mut c = Check(Vec::new());
    let mut derived = Derived::default();

    // Conductor.
    let cd = &s.conductor;
    let rho_ok = c.range("conductor.linear_density_kg_per_m", cd.linear_density_kg_per_m, &CONDUCTOR_DENSITY);
    c.range(
        "conductor.thermal_expansion_per_k",
        cd.thermal_expansion_per_k,
        &THERMAL_EXPANSION_PER_K.note(" (aluminium: 23.8e-6, section 5.4)"),
    );
    c.range("conductor.reference_temperature_k", cd.reference_temperature_k, &REFERENCE_TEMPERATURE_K);
    if let Some(r) = cd.rated_tensile_strength_n {
        c.range("conductor.rated_tensile_strength_n", r, &RATED_TENSILE_STRENGTH_N);
    }
    let d_ok = match cd.diameter_m {
        Some(d) => c.range(
            "conductor.diameter_m",
            d,
            &Allowed::closed(1.0e-4, 1.0, "m").finite().note(" (conductors are 5 to 50 mm)"),
        ),
        None => false,
    };
    let ea = match (cd.axial_stiffness_n, cd.youngs_modulus_pa) {
        (Some(_), Some(e)) => {
            c.fail(
                "conductor.youngs_modulus_pa",
                e,
                "give either conductor.axial_stiffness_n or conductor.youngs_modulus_pa, not both",
            );
            None
        }
        (Some(ea), None) => c.range("conductor.axial_stiffness_n", ea, &EA_ALLOWED).then_some(ea),
        (None, Some(e)) => {
            let e_ok = c.range(
                "conductor.youngs_modulus_pa",
                e,
                &Allowed::closed(1.0e6, 1.0e12, "Pa").finite().note(" (aluminium 6.25e10, steel 2e11)"),
            );
            match cd.diameter_m {
                None => {
                    c.fail("conductor.diameter_m", "(missing)", "required with conductor.youngs_modulus_pa");
                    None
                }
                Some(d) if e_ok && d_ok => {
                    let ea = e * std::f64::consts::PI * d * d / 4.0;
                    let ok = EA_ALLOWED.contains(ea);
                    if !ok {
                        c.fail_number(
                            "conductor.youngs_modulus_pa",
                            ea,
                            &format!("{EA_ALLOWED}: E pi d^2 / 4 = {ea:e} N"),
                        );
                    }
                    ok.then_some(ea)
                }
                Some(_) => None,
            }
        }
        (None, None) => {
            c.fail(
                "conductor.axial_stiffness_n",
                "(missing)",
                "give conductor.axial_stiffness_n [N], or conductor.youngs_modulus_pa [Pa] with conductor.diameter_m [m]",
            );
            None
        }
    };

    // Geometry: one span (`[geometry]`) or a section of several (`[section]`).
    let mut chord = None;
    let mut n_ok = false;
    let mut n_total = 0usize;
    let mut length: Option<f64> = None;
    let mut section_grid: Option<SectionGrid> = None;
    // The two-material law (the section strings its spans with it; the stability limits take its stiffness).
    let material = super::two_material::check(&mut c, cd);
    match (&s.geometry, &s.section) {
        (Some(g), None) => {
            let a_ok = c.coordinates("geometry.left_support_m", g.left_support_m);
            let b_ok = c.coordinates("geometry.right_support_m", g.right_support_m);
            if a_ok && b_ok {
                let d: f64 = (0..3).map(|k| (g.right_support_m[k] - g.left_support_m[k]).powi(2)).sum::<f64>().sqrt();
                if d <= 1.0e-6 {
                    c.fail(
                        "geometry.right_support_m",
                        format!("{:?}", g.right_support_m),
                        "the supports must be at least 1e-6 m apart (it coincides with geometry.left_support_m)",
                    );
                } else if d > MAX_SPAN_M {
                    c.fail(
                        "geometry.right_support_m",
                        format!("{:?}", g.right_support_m),
                        &format!(
                            "the span |B - A| = {d} m is above {MAX_SPAN_M} m (the longest overhead spans built are \
                             about 5.4 km): check the unit (m) and geometry.left_support_m"
                        ),
                    );
                } else {
                    chord = Some(d);
                }
            }
            n_ok = g.segments >= 2 && g.segments <= MAX_SEGMENTS;
            n_total = g.segments;
            if !n_ok {
                c.fail("geometry.segments", g.segments, &format!("must be an integer in [2, {MAX_SEGMENTS}]"));
            }
            let mut length_ok = true;
            if let Some(l) = g.unstretched_length_m {
                length_ok = c.positive("geometry.unstretched_length_m", l);
                if let (true, Some(ch)) = (length_ok, chord)
                    && !(0.5 * ch..=100.0 * ch).contains(&l)
                {
                    length_ok = false;
                    c.fail(
                        "geometry.unstretched_length_m",
                        number(l),
                        &format!(
                            "must be in [chord / 2, 100 chord] = [{}, {}] m for the chord |B - A| = {ch} m (a strain of \
                             100 % is beyond any conductor)",
                            0.5 * ch,
                            100.0 * ch
                        ),
                    );
                }
            }

            // Initial shape.
            let ini = &s.initial;
            let mut shape_length = chord;
            match (ini.shape, ini.sag_m) {
                (ShapeSpec::Straight, Some(f)) => c.fail("initial.sag_m", f, "only with initial.shape = \"parabola\""),
                (ShapeSpec::Straight, None) => {}
                (ShapeSpec::Parabola, None) => {
                    c.fail("initial.sag_m", "(missing)", "required with initial.shape = \"parabola\"")
                }
                (ShapeSpec::Equilibrium, None) => {}
                (ShapeSpec::Parabola | ShapeSpec::Equilibrium, Some(f)) => {
                    let hi = chord.unwrap_or(f64::INFINITY);
                    if c.within("initial.sag_m", f, f64::MIN_POSITIVE, hi, "must be > 0 and at most the chord length") {
                        shape_length = chord.map(|l| super::build::parabola_length(l, f));
                        if let Some(l) = chord {
                            let (a, b) = (g.left_support_m, g.right_support_m);
                            let horizontal = (b[0] - a[0]).hypot(b[1] - a[1]);
                            if horizontal < 1.0e-3 * l {
                                shape_length = None;
                                c.fail(
                                    "initial.shape",
                                    format!("{:?}", ini.shape).to_lowercase(),
                                    &format!(
                                        "a parabola needs a chord that is not vertical: it sags vertically, in the plane \
                                         of the chord (the supports are {} m apart horizontally, less than \
                                         1e-3 of the chord {l} m); use initial.shape = \"straight\"",
                                        number(horizontal)
                                    ),
                                );
                            }
                        }
                    }
                }
            }
            if length_ok {
                length = g.unstretched_length_m.or(shape_length);
            }
        }
        (None, Some(sec)) => {
            let law = match cd.tension_law {
                // A section is strung with the conductor's EA (tension-only) also for a two-material law,
                // which the builder then installs (docs/scenario.md, "two_material").
                TensionLawSpec::TensionOnly | TensionLawSpec::TwoMaterial => LawKind::TensionOnly,
                TensionLawSpec::Linear => LawKind::Linear,
            };
            let conductor = ea.filter(|_| rho_ok).map(|ea| {
                let c = Conductor { axial_stiffness_n: ea, internal_friction_n_s: s.numerics.eta_n_s, law };
                (c, cd.linear_density_kg_per_m)
            });
            section_grid = super::section::check(&mut c, s, sec, conductor, material);
            if let Some(sg) = &section_grid {
                chord = Some(sg.chord_m);
                n_ok = true;
                n_total = sg.wire.segments();
                length = Some(sg.wire.total_rest_length());
            }
        }
        (Some(_), Some(_)) => c.fail(
            "section",
            "(given with [geometry])",
            "give either [geometry] (one span) or [section] (several spans), not both",
        ),
        (None, None) => c.fail(
            "geometry",
            "(missing)",
            "give [geometry] (one span between two supports) or [section] (several spans on insulator strings)",
        ),
    }

    // Loads.
    let ld = &s.loads;
    c.range("loads.gravity_m_per_s2", ld.gravity_m_per_s2, &Allowed::closed(0.0, 100.0, "m/s^2"));
    if c.finite3("loads.uniform_load_n_per_m", ld.uniform_load_n_per_m)
        && ld.uniform_load_n_per_m.iter().any(|q| q.abs() > 1.0e4)
    {
        c.fail(
            "loads.uniform_load_n_per_m",
            format!("{:?}", ld.uniform_load_n_per_m),
            "each component must be within 1e4 N/m (ten times the weight of the heaviest iced conductor)",
        );
    }
    if let Some(w) = &ld.wind {
        if c.finite3("loads.wind.direction", w.direction) {
            if w.direction.iter().any(|x| x.abs() > 1.0e6) {
                c.fail(
                    "loads.wind.direction",
                    format!("{:?}", w.direction),
                    "each component must be within 1e6 (only the direction counts: it is normalised on reading)",
                );
            } else {
                let norm: f64 = w.direction.iter().map(|x| x * x).sum::<f64>().sqrt();
                if norm < 1.0e-12 {
                    c.fail("loads.wind.direction", format!("{:?}", w.direction), "must be a non-zero vector");
                }
            }
        }
        if c.range("loads.wind.speed_m_per_s", w.speed_m_per_s, &WIND_SPEED)
            && w.speed_m_per_s > 0.0
            && w.speed_m_per_s < MIN_WIND_SPEED_M_PER_S
        {
            c.fail_number(
                "loads.wind.speed_m_per_s",
                w.speed_m_per_s,
                "must be 0 (still air) or at least 0.01 m/s: the damping (2.6) divides by the speed",
            );
        }
        c.range("loads.wind.ramp_s", w.ramp_s, &Allowed::closed(0.0, MAX_TIME_S, "s").at_most());
        c.range("loads.wind.air_density_kg_per_m3", w.air_density_kg_per_m3, &AIR_DENSITY);
        c.range("loads.wind.normal_coefficient", w.normal_coefficient, &COEFFICIENT_ALLOWED);
        c.range("loads.wind.tangential_coefficient", w.tangential_coefficient, &COEFFICIENT_ALLOWED);
        c.range("loads.wind.initial_scale", w.initial_scale, &SCALE_ALLOWED);
        match (w.law, w.pressure_n_per_m) {
            (WindLawSpec::UniformNormal, Some(p)) => {
                let pressure = Allowed::closed(0.0, 1.0e4, "N/m").at_most().note(" (section 4.1: 3.805 N/m)");
                c.range("loads.wind.pressure_n_per_m", p, &pressure);
            }
            (WindLawSpec::UniformNormal, None) => {
                c.fail("loads.wind.pressure_n_per_m", "(missing)", "required with loads.wind.law = \"uniform_normal\"")
            }
            (WindLawSpec::Aerodynamic, Some(p)) => {
                c.fail("loads.wind.pressure_n_per_m", p, "only with loads.wind.law = \"uniform_normal\"")
            }
            (WindLawSpec::Aerodynamic, None) => {
                if cd.diameter_m.is_none() {
                    c.fail("conductor.diameter_m", "(missing)", "required with loads.wind.law = \"aerodynamic\"");
                }
            }
        }
    }

    // Numerics.
    let nm = &s.numerics;
    let courant_ok = c.range("numerics.courant", nm.courant, &Allowed::open_closed(0.0, 1.0, ""));
    c.range("numerics.smoothing", nm.smoothing, &Allowed::closed(0.0, 0.25, "").note(" (stability of (3.3))"));
    c.range("numerics.mu", nm.mu, &Allowed::closed(0.0, 1.0, "").note(" (paper section 3: 0.1 to 0.2)"));
    let eta = Allowed::closed(0.0, 1.0e9, "N s").at_most().note(" (section 5.6: 4242.9 N s)");
    let eta_ok = c.range("numerics.eta_n_s", nm.eta_n_s, &eta);
    let zeta_ok = c.non_negative("numerics.mass_damping_per_s", nm.mass_damping_per_s);
    if let Some(v) = nm.max_speed_m_per_s {
        c.range("numerics.max_speed_m_per_s", v, &Allowed::open_closed(0.0, 1.0e7, "m/s").at_most());
    }
    // Stability limits need EA, rho0, the segment length: check them only when those are valid. A
    // two-material conductor's EA is its law's stiffness bound (wire::material), not the catalogue's EA.
    let ea = match &material {
        Some((law, curve)) => ea.map(|_| crate::wire::Material::virgin(*law, *curve, 0).max_stiffness()),
        None => ea,
    };
    derived.material = material;
    derived.ea_n = ea;
    derived.chord_m = chord;
    derived.length_m = length.filter(|l| l.is_finite() && *l > 0.0);
    if let (Some(ea), true, true, Some(len)) = (ea, rho_ok, n_ok, length)
        && len.is_finite()
        && len > 0.0
    {
        // A section's spans may differ: its fastest wave and shortest crossing time govern.
        let cw = section_grid
            .as_ref()
            .map_or(courant::wave_speed(ea, cd.linear_density_kg_per_m), |sg| sg.wave_speed_max_m_per_s);
        let ds = section_grid.as_ref().map_or(len / n_total as f64, |sg| sg.crossing_time_s * cw);
        derived.wave_speed_m_per_s = Some(cw);
        if courant_ok && eta_ok {
            let z = courant::friction_number(ea, nm.eta_n_s, cw, ds);
            let limit = courant::stable_courant(z);
            if nm.courant > limit {
                c.fail(
                    "numerics.courant",
                    nm.courant,
                    &format!(
                        "must be at most sqrt(1 + z^2) - z = {limit:.6} for internal friction eta = {} N s \
                         (z = eta c / (EA ds) = {z:.4e}): the explicit Kelvin-Voigt term lowers the stable step",
                        nm.eta_n_s
                    ),
                );
            }
            // A section's clamps may need a shorter step (module doc of `super::section`).
            let clamp = section_grid.as_ref().map_or(f64::INFINITY, |sg| nm.courant * sg.clamp_step_s);
            let dt = courant::time_step(nm.courant, ds, cw).min(clamp);
            derived.dt_s = Some(dt);
            if zeta_ok && nm.mass_damping_per_s * dt >= 1.0 {
                c.fail(
                    "numerics.mass_damping_per_s",
                    nm.mass_damping_per_s,
                    &format!("must satisfy zeta dt < 1 (dt = {dt:.4e} s), i.e. zeta < {:.4e} 1/s", 1.0 / dt),
                );
            }
        }
    }

    // Duration.
    let du = &s.duration;
    let end = match (du.end_time_s, &du.until_settled) {
        (Some(t), None) => c.time("duration.end_time_s", t).then_some(t),
        (None, Some(st)) => {
            c.range(
                "duration.until_settled.kinetic_energy_fraction",
                st.kinetic_energy_fraction,
                &Allowed::open(0.0, 1.0, ""),
            );
            c.time("duration.until_settled.window_s", st.window_s);
            c.time("duration.until_settled.max_time_s", st.max_time_s).then_some(st.max_time_s)
        }
        (Some(t), Some(_)) => {
            c.fail("duration.end_time_s", t, "give either duration.end_time_s or duration.until_settled, not both");
            None
        }
        (None, None) => {
            c.fail("duration", "(empty)", "give duration.end_time_s [s] or duration.until_settled");
            None
        }
    };

    // Output.
    let out = &s.output;
    c.time("output.sample_interval_s", out.sample_interval_s);
    c.range(
        "output.tau_speed_m_per_s",
        out.tau_speed_m_per_s,
        &Allowed::closed(1.0e-3, 1.0e3, "m/s").finite().note(" (the speed U of tau = t U / l; the paper's is 20)"),
    );
    for (k, &t) in out.snapshot_times_s.iter().enumerate() {
        let hi = end.unwrap_or(f64::INFINITY);
        c.within(
            &format!("output.snapshot_times_s[{k}]"),
            t,
            0.0,
            hi,
            "must be in [0, end time] (duration.end_time_s or duration.until_settled.max_time_s)",
        );
    }
    for (k, p) in out.probes.iter().enumerate() {
        let field = |f: &str| format!("output.probes[{k}].{f}");
        let name_ok = !p.name.is_empty()
            && p.name.chars().all(|ch| ch.is_ascii_alphanumeric() || ch == '_')
            && p.name != crate::output::probe::MIDSPAN;
        if !name_ok {
            c.fail(&field("name"), format!("{:?}", p.name), "must be letters, digits and _ only, and not \"mid\"");
        }
        if out.probes[..k].iter().any(|q| q.name == p.name) {
            c.fail(&field("name"), format!("{:?}", p.name), "must differ from the names of the earlier probes");
        }
        c.range(
            &field("at_fraction"),
            p.at_fraction,
            &Allowed::closed(0.0, 1.0, "").words("must be a fraction of the span in"),
        );
    }
    if let Some(t) = out.peaks_from_s {
        c.within("output.peaks_from_s", t, 0.0, end.unwrap_or(f64::INFINITY), "must be in [0, end time] [s]");
    }
    // The grid of each span: (first segment, segments, unstretched segment length); one for [geometry].
    let spans: Vec<SpanGrid> = match &section_grid {
        Some(sg) => (0..sg.layout.first_node.len() - 1)
            .map(|k| {
                let seg = sg.layout.segments(k);
                let rho = sg.wire.segment_mass[seg.start] / sg.wire.reference_length[seg.start];
                SpanGrid { first: seg.start, n: seg.len(), ds: Some(sg.wire.rest_length[seg.start]), rho }
            })
            .collect(),
        None if n_ok && rho_ok => {
            let rho = cd.linear_density_kg_per_m;
            vec![SpanGrid { first: 0, n: n_total, ds: derived.length_m.map(|l| l / n_total as f64), rho }]
        }
        None => Vec::new(),
    };
    let initial = section_grid.as_ref().map(|sg| &sg.wire.x);
    check_ground_and_events(&mut c, s, end, &spans, n_total, initial, derived.dt_s);
    if let Some(t) = &s.thermal {
        let temperature_event = s.events.iter().position(|e| {
            matches!(
                e,
                EventSpec::Temperature { .. } | EventSpec::HeatConduction { .. } | EventSpec::HeatConductionOff { .. }
            )
        });
        super::thermal::check(&mut c, t, temperature_event);
        if let (Some(d), Some(sg)) = (&t.deicing, &section_grid)
            && let Some(list) = &d.spans
        {
            let n_spans = sg.layout.first_node.len() - 1;
            for (k, &span) in list.iter().enumerate() {
                if span >= n_spans {
                    c.fail(
                        &format!("thermal.deicing.spans[{k}]"),
                        span,
                        &format!("must be a span of the section, in [0, {}]", n_spans - 1),
                    );
                }
            }
        }
    }
    if let Some(r) = &s.rating {
        super::rating::check(&mut c, s, r);
    }
    derived.section = section_grid;
    (c.0, derived)
}

const CONDUCTOR_DENSITY: Allowed =
    LINEAR_DENSITY_KG_PER_M.finite().note(" (bare conductors 0.1 to 5 kg/m, heavily iced ones up to about 30 kg/m)");
const EA_ALLOWED: Allowed = AXIAL_STIFFNESS_N.finite().note(" (section 4: 7.9e5 N; conductors are 1e6 to 1e9 N)");
/// Wind speed [m/s], from 0 (still air) to [`MAX_WIND_SPEED_M_PER_S`]; above 0 at least
/// [`MIN_WIND_SPEED_M_PER_S`] (a check of its own).
const WIND_SPEED: Allowed = Allowed::closed(0.0, MAX_WIND_SPEED_M_PER_S, "m/s")
    .note(" (design wind speeds are below about 70 m/s; check the unit: m/s, not km/h; 0 is still air)");
/// Air density [kg/m^3], up to [`MAX_AIR_DENSITY_KG_PER_M3`].
const AIR_DENSITY: Allowed = Allowed::open_closed(0.0, MAX_AIR_DENSITY_KG_PER_M3, "kg/m^3")
    .at_most()
    .note(" (sea level 1.225; check the unit: kg/m^3, not g/m^3)");
/// Force coefficients of the aerodynamic law (2.5) [-].
const COEFFICIENT_ALLOWED: Allowed = Allowed::closed(0.0, 10.0, "").at_most().note(" (cylinders: about 1 to 2)");
/// Multipliers on the wind load [-] (`initial_scale`, `scale`, `amplitude`).
const SCALE_ALLOWED: Allowed = Allowed::closed(0.0, 100.0, "").at_most().note(" (a multiplier on the scenario's wind)");
/// A duration or time [s], up to [`MAX_TIME_S`].
const TIME_ALLOWED: Allowed = Allowed::open_closed(0.0, MAX_TIME_S, "s").at_most();

impl Check {
    /// Three finite coordinates within [`MAX_COORDINATE_M`].
    pub(crate) fn coordinates(&mut self, field: &str, v: [f64; 3]) -> bool {
        if !self.finite3(field, v) {
            return false;
        }
        let ok = v.iter().all(|x| x.abs() <= MAX_COORDINATE_M);
        if !ok {
            self.fail(field, format!("{v:?}"), "each coordinate must be within 1e5 m (a local frame around the span)");
        }
        ok
    }
    /// A duration or time `(0, MAX_TIME_S]` [s].
    fn time(&mut self, field: &str, t: f64) -> bool {
        self.range(field, t, &TIME_ALLOWED)
    }
}

/// The lowest point of the initial parabola `A + u (B - A) - 4 f u (1 - u) e3`: `(u, x3)`.
fn parabola_lowest(a: [f64; 3], b: [f64; 3], f: f64) -> (f64, f64) {
    let d3 = b[2] - a[2];
    let x3 = |u: f64| a[2] + u * d3 - 4.0 * f * u * (1.0 - u);
    let u_star = ((4.0 * f - d3) / (8.0 * f)).clamp(0.0, 1.0);
    [0.0, u_star, 1.0].into_iter().map(|u| (u, x3(u))).fold((0.0, f64::INFINITY), |m, p| if p.1 < m.1 { p } else { m })
}

fn range_ok(c: &mut Check, field: &str, r: [f64; 2]) -> bool {
    let ok = r.iter().all(|x| x.is_finite()) && 0.0 <= r[0] && r[0] < r[1] && r[1] <= 1.0;
    if !ok {
        c.fail(field, format!("{r:?}"), "must be [a, b] with 0 <= a < b <= 1 (fractions of the unstretched length)");
    }
    ok
}

/// The corrected closure (5.4), `boundary = "linear"`, updates an end node by
/// `u_0' = (1 + r) u_0 - 2 r u_1 + r u_2` (`src/heat/boundary.rs`). When node 1 is held and node 0 is not, a
/// disturbance of `u_0` grows by `1 + r` per heat sub-step and the temperatures overflow (found by the
/// fuzzer; measured at r = 0.1, 0.3 and 0.5 on 20 segments: every hold that contains node 1 or N - 1 without
/// the end diverges, and no other hold does).
fn linear_closure_stable(c: &mut Check, field: &str, held: Range<usize>, n: usize) {
    for (end, next) in [(0, 1), (n, n - 1)] {
        if held.contains(&next) && !held.contains(&end) {
            c.fail(
                field,
                "\"linear\"",
                &format!(
                    "diverges with the hold range reaching node {next}, next to the free end node {end}: the end \
                     update u' = (1 + r) u_end - 2 r u_next + r u_next2 then amplifies the end by 1 + r per heat \
                     sub-step; use boundary = \"zero_flux\" (the default) or extend the hold range to the end"
                ),
            );
            return;
        }
    }
}

/// The segments of a valid line (for the ranges of events over the whole line).
#[derive(Clone, Copy)]
struct Grid {
    n: usize,
}

/// The segments of one span: the first, their number and, when the length is valid, their unstretched
/// length [m]. A `[geometry]` scenario has one span.
#[derive(Clone, Copy, Debug)]
struct SpanGrid {
    first: usize,
    n: usize,
    ds: Option<f64>,
    /// the span's bare linear density [kg/m]
    rho: f64,
}

/// The span an event addresses (`span`, default 0) and its grid, `None` (with a problem recorded) for
/// a span that does not exist, or when the grid is not valid.
fn span_of(
    c: &mut Check,
    field: &str,
    span: Option<usize>,
    spans: &[SpanGrid],
    section: bool,
) -> Option<(usize, SpanGrid)> {
    let k = span.unwrap_or(0);
    if span.is_some() && !section {
        c.fail(field, k, "only in a scenario with [section] (a [geometry] scenario has one span)");
        return None;
    }
    if spans.is_empty() {
        return None;
    }
    match spans.get(k) {
        Some(g) => Some((k, *g)),
        None => {
            c.fail(field, k, &format!("must be a span of the section, 0 to {}", spans.len() - 1));
            None
        }
    }
}

/// A range that selects no segment on the grid is an event that does nothing.
fn segments_of(c: &mut Check, field: &str, r: [f64; 2], grid: Option<Grid>) -> Option<Range<usize>> {
    let n = grid?.n;
    let seg = segment_range(r, n);
    if seg.is_empty() {
        c.fail(
            field,
            format!("{r:?}"),
            &format!(
                "selects no segment of the {n} of geometry.segments (segments lie between the nodes nearest to a \
                 and b, here both node {}): widen it to at least 1/{n} of the span",
                seg.start
            ),
        );
        return None;
    }
    Some(seg)
}

/// One ice event resolved on the grid: index in `[[events]]`, segments, change of linear density [kg/m].
pub(crate) type IceEvent = (usize, Range<usize>, f64);

/// An ice event that leaves part of the span lighter than the bare wire: (its index in `[[events]]`, the
/// segments concerned, their least linear density [kg/m]).
pub(crate) type IceShortfall = (usize, Range<usize>, f64);

/// The segment masses of an `n`-segment wire of segment length `ds` [m] and bare linear density `rho`
/// [kg/m] under `events`, in the order they apply, computed exactly as
/// [`crate::wire::Wire::add_linear_density`] does (`m_j += delta ds`, per segment, in time order). Every
/// event after which some segment is lighter than the bare wire (by more than 4 ulps of the largest mass
/// that segment has had: the rounding of the changes), or not heavier than zero, is returned.
///
/// Segments between the same range ends receive the same changes, so they are computed once per stretch:
/// `O(e log e + e s)` for `e` events over `s <= min(2 e + 1, n)` stretches.
pub(crate) fn ice_shortfalls(n: usize, ds: f64, rho: f64, events: &[IceEvent]) -> Vec<IceShortfall> {
    let mut ends: Vec<usize> = events.iter().flat_map(|e| [e.1.start, e.1.end]).chain([0, n]).collect();
    ends.sort_unstable();
    ends.dedup();
    let bare = rho * ds;
    let stretches = ends.len() - 1;
    let mut mass = vec![bare; stretches];
    let mut most = vec![bare; stretches];
    let mut out = Vec::new();
    for (k, r, delta) in events {
        let (first, last) = (ends.partition_point(|&e| e < r.start), ends.partition_point(|&e| e < r.end));
        let mut worst: Option<(usize, f64)> = None;
        for i in first..last {
            mass[i] += delta * ds;
            most[i] = most[i].max(mass[i]);
            let short = mass[i].is_nan() || mass[i] <= 0.0 || mass[i] < bare - 4.0 * f64::EPSILON * most[i];
            if short && worst.is_none_or(|(_, m)| mass[i] < m) {
                worst = Some((i, mass[i]));
            }
        }
        if let Some((i, m)) = worst {
            out.push((*k, ends[i]..ends[i + 1], m / ds));
        }
    }
    out
}

/// `[ground]`: a level plane or a terrain profile (one of the two), restitution and friction, and the
/// ground below every support and the initial shape (the section's initial nodes `initial`, or the
/// single span's supports and its initial parabola).
fn check_ground(c: &mut Check, s: &Scenario, gr: &GroundSpec, initial: Option<&[Vec<f64>; 3]>) {
    let restitution = Allowed::closed(0.0, 1.0, "").note(" (0.6 returns 36 % of the energy)");
    c.range("ground.restitution", gr.restitution, &restitution);
    c.range(
        "ground.friction",
        gr.friction,
        &Allowed::closed(0.0, 2.0, "").note(" (conductor on soil or grass: about 0.5)"),
    );
    let p = &gr.profile_m;
    let (field, value) = match (gr.height_m, p.is_empty()) {
        (None, true) => {
            let why = "give ground.height_m (a level plane) or ground.profile_m (a terrain profile)";
            return c.fail("ground.height_m", "(missing)", why);
        }
        (Some(_), false) => {
            return c.fail(
                "ground.profile_m",
                format!("{p:?}"),
                "give either ground.height_m or ground.profile_m, not both",
            );
        }
        (Some(h), true) => {
            if !h.is_finite() {
                return c.fail_number("ground.height_m", h, "must be a finite height below every support");
            }
            ("ground.height_m", number(h))
        }
        (None, false) => {
            let finite = p.iter().flatten().all(|x| x.is_finite());
            let increasing = p.windows(2).all(|w| w[1][0] > w[0][0]);
            let slope = p.windows(2).map(|w| ((w[1][1] - w[0][1]) / (w[1][0] - w[0][0])).abs()).fold(0.0, f64::max);
            if p.len() < 2 || !finite || !increasing || slope > 2.0 {
                let why = format!(
                    "must be at least two finite points [x2, x3] [m] with x2 strictly increasing and slopes at most 2 \
                     (63 degrees){}",
                    if increasing && finite && p.len() >= 2 {
                        format!("; the steepest piece has slope {slope:.3}")
                    } else {
                        String::new()
                    }
                );
                return c.fail("ground.profile_m", format!("{p:?}"), &why);
            }
            ("ground.profile_m", format!("{p:?}"))
        }
    };
    let g = gr.ground();
    let level = p.is_empty();
    // The points that must be above the ground, with what they are.
    let mut points: Vec<([f64; 3], String)> = Vec::new();
    if let Some(x) = initial {
        points
            .extend((0..x[0].len()).map(|i| ([x[0][i], x[1][i], x[2][i]], format!("the section's initial node {i}"))));
    } else if let Some(geo) = &s.geometry {
        let (a, b) = (geo.left_support_m, geo.right_support_m);
        points.push((a, "the left support".into()));
        points.push((b, "the right support".into()));
        if let Some(f) = s.initial.sag_m
            && s.initial.shape == ShapeSpec::Parabola
            && f.is_finite()
            && f > 0.0
        {
            // the parabola A + u (B - A) - 4 f u (1 - u) e3: its lowest point, and 200 points for a profile
            let (u, low) = parabola_lowest(a, b, f);
            let at = |u: f64| {
                [a[0] + u * (b[0] - a[0]), a[1] + u * (b[1] - a[1]), a[2] + u * (b[2] - a[2]) - 4.0 * f * u * (1.0 - u)]
            };
            let mut us: Vec<f64> = if level { vec![u] } else { (0..=200).map(|k| k as f64 / 200.0).collect() };
            us.retain(|&v| v > 0.0 && v < 1.0);
            for v in us {
                let x = if level { [f64::NAN, f64::NAN, low] } else { at(v) };
                points.push((x, format!("the initial parabola (initial.sag_m = {f} m) at {v:.4} of the chord")));
            }
        }
    }
    let below = points
        .iter()
        .map(|(x, what)| (if level { x[2] - g.height_m } else { g.clearance_m(*x) }, x, what))
        .filter(|(clr, _, _)| clr.is_nan() || *clr <= 0.0)
        .min_by(|a, b| a.0.total_cmp(&b.0));
    if let Some((clr, x, what)) = below {
        let why = if level {
            format!(
                "must be a finite height below both supports and the initial shape (every initial node of a section): \
                 {what} reaches x3 = {} m, below the ground",
                number(x[2])
            )
        } else {
            format!(
                "the ground must lie below every support and the initial shape: {what} at x2 = {} m, x3 = {} m is {} m below the ground there",
                number(x[1]),
                number(x[2]),
                number(-clr)
            )
        };
        c.fail(field, value, &why);
    }
}

/// The ice types behind the density range of a radial shell (docs/loads.md).
const ICE_DENSITY_NOTE: &str = " (glaze 900 to 917, hard rime 600 to 900, soft rime 300 to 600, wet snow 100 to 850)";

/// `[ground]` and `[[events]]`.
fn check_ground_and_events(
    c: &mut Check,
    s: &Scenario,
    end: Option<f64>,
    spans: &[SpanGrid],
    n_total: usize,
    initial: Option<&[Vec<f64>; 3]>,
    dt: Option<f64>,
) {
    let grid = (!spans.is_empty()).then_some(Grid { n: n_total });
    if let Some(gr) = &s.ground {
        check_ground(c, s, gr, initial);
    }
    let hi = end.unwrap_or(f64::INFINITY);
    let cd = &s.conductor;
    let alpha = cd.thermal_expansion_per_k;
    let u_ref = cd.reference_temperature_k;
    let thermal = |c: &mut Check, field: &str, u: f64| {
        let factor = 1.0 + alpha * (u - u_ref);
        if alpha.is_finite() && u_ref.is_finite() && (factor.is_nan() || factor < MIN_THERMAL_FACTOR) {
            c.fail(
                field,
                number(u),
                &format!(
                    "would shorten the stress-free length to {factor:.6} of the unstretched length: \
                     1 + alpha_t (u - u_ref) with conductor.thermal_expansion_per_k = {alpha} 1/K and \
                     conductor.reference_temperature_k = {u_ref} K must be at least {MIN_THERMAL_FACTOR} \
                     (a thermal strain of -50 %), i.e. u >= {} K",
                    u_ref - (1.0 - MIN_THERMAL_FACTOR) / alpha
                ),
            );
        }
    };
    // Events in the order they apply (the builder's stable sort by time).
    let mut order: Vec<usize> = (0..s.events.len()).collect();
    order.sort_by(|&a, &b| s.events[a].time_s().total_cmp(&s.events[b].time_s()));
    let mut ice: Vec<Vec<IceEvent>> = vec![Vec::new(); spans.len()];
    let mut broken: Vec<(usize, usize)> = Vec::new(); // (segment, event index)
    let mut failed: Vec<(usize, usize)> = Vec::new(); // (support, event index)
    let mut released: Vec<(usize, usize)> = Vec::new(); // (support, event index)
    for k in order {
        let e = &s.events[k];
        let f = |name: &str| format!("events[{k}].{name}");
        c.within(
            &f("time_s"),
            e.time_s(),
            0.0,
            hi,
            "must be in [0, end time] (duration.end_time_s or duration.until_settled.max_time_s)",
        );
        let needs_wind = matches!(e, EventSpec::Wind { .. } | EventSpec::Gust { .. });
        if needs_wind && s.loads.wind.is_none() {
            c.fail(&f("action"), format!("\"{}\"", e.action()), "needs a wind load ([loads.wind]) to switch");
        }
        let span = span_of(c, &f("span"), e.span(), spans, s.section.is_some());
        match *e {
            EventSpec::Break { at_fraction, .. } => {
                let ok = c.range(&f("at_fraction"), at_fraction, &Allowed::open(0.0, 1.0, ""));
                if let (true, Some((_, gd))) = (ok, span) {
                    let j = gd.first + break_segment(at_fraction, gd.n);
                    if let Some(&(_, first)) = broken.iter().find(|b| b.0 == j) {
                        c.fail(
                            &f("at_fraction"),
                            number(at_fraction),
                            &format!(
                                "breaks segment {j} (at_fraction in [{j}/{n}, {}/{n})), which events[{first}] \
                                 (at_fraction = {}) has already broken: a segment breaks once",
                                j + 1,
                                s.events[first].break_fraction().unwrap_or(f64::NAN),
                                n = gd.n
                            ),
                        );
                    } else {
                        broken.push((j, k));
                    }
                }
            }
            EventSpec::Ice {
                linear_density_kg_per_m,
                radial_thickness_m,
                density_kg_per_m3,
                range,
                front_speed_m_per_s,
                ..
            } => {
                // Exactly one form: a change of linear density, or a radial shell (thickness and density).
                let change =
                    Allowed::closed(-1.0e3, 1.0e3, "kg/m").words("must be a finite change of linear density in");
                let d_ok = match (linear_density_kg_per_m, radial_thickness_m, density_kg_per_m3) {
                    (Some(d), None, None) => c.range(&f("linear_density_kg_per_m"), d, &change),
                    (None, Some(t), Some(rho)) => {
                        c.range(&f("radial_thickness_m"), t, &RADIAL_ICE_M);
                        c.range(&f("density_kg_per_m3"), rho, &ICE_DENSITY_KG_PER_M3.note(ICE_DENSITY_NOTE));
                        if cd.diameter_m.is_none() {
                            c.fail(
                                "conductor.diameter_m",
                                "(missing)",
                                "required with an ice event's radial_thickness_m",
                            );
                        }
                        false
                    }
                    (None, Some(_), None) => {
                        c.fail(&f("density_kg_per_m3"), "(missing)", "required with radial_thickness_m");
                        false
                    }
                    (None, None, Some(_)) => {
                        c.fail(&f("radial_thickness_m"), "(missing)", "required with density_kg_per_m3");
                        false
                    }
                    (Some(d), ..) => {
                        c.fail(
                            &f("linear_density_kg_per_m"),
                            number(d),
                            "give the ice in one form: linear_density_kg_per_m [kg/m], or radial_thickness_m [m] \
                             with density_kg_per_m3 [kg/m^3], not both",
                        );
                        false
                    }
                    (None, None, None) => {
                        c.fail(
                            &f("action"),
                            "\"ice\"",
                            "needs linear_density_kg_per_m [kg/m], or radial_thickness_m [m] with density_kg_per_m3 \
                             [kg/m^3]",
                        );
                        false
                    }
                };
                if let Some(v) = front_speed_m_per_s {
                    c.range(&f("front_speed_m_per_s"), v, &Allowed::closed(0.1, 1.0e4, "m/s"));
                }
                // A shell never takes a segment below the bare wire (it replaces a shell, never the wire's
                // mass): only the changes of linear density are followed for that.
                if range_ok(c, &f("range"), range)
                    && let Some((sp, gd)) = span
                    && let Some(seg) = segments_of(c, &f("range"), range, Some(Grid { n: gd.n }))
                    && d_ok
                    && let Some(d) = linear_density_kg_per_m
                {
                    ice[sp].push((k, seg, d));
                }
            }
            EventSpec::InsulatorFailure { support, .. } | EventSpec::ClampSlip { support, .. } => {
                let suspension = s.section.as_ref().and_then(|sec| sec.supports.get(support));
                if !matches!(suspension, Some(SupportSpec::Suspension { .. })) {
                    c.fail(&f("support"), support, "must be the index of a suspension support of [section]");
                } else if let Some(&(_, first)) = failed.iter().find(|x| x.0 == support) {
                    c.fail(
                        &f("support"),
                        support,
                        &format!("its string already lets the conductor go at events[{first}]"),
                    );
                } else {
                    failed.push((support, k));
                }
            }
            EventSpec::Release { support, .. } => {
                let dead_end = s.section.as_ref().and_then(|sec| sec.supports.get(support));
                if !matches!(dead_end, Some(SupportSpec::DeadEnd { .. })) {
                    c.fail(&f("support"), support, "must be the index of a dead-end support of [section]");
                } else if let Some(&(_, first)) = released.iter().find(|x| x.0 == support) {
                    c.fail(&f("support"), support, &format!("already released at events[{first}]"));
                } else {
                    released.push((support, k));
                }
            }
            EventSpec::Wind { scale, ramp_s, .. } => {
                c.range(&f("scale"), scale, &SCALE_ALLOWED);
                c.range(&f("ramp_s"), ramp_s, &Allowed::closed(0.0, MAX_TIME_S, "s").at_most());
            }
            EventSpec::Gust { period_s, amplitude, .. } => {
                if c.time(&f("period_s"), period_s)
                    && let Some(dt) = dt
                    && period_s < MIN_STEPS_PER_GUST * dt
                {
                    c.fail(
                        &f("period_s"),
                        number(period_s),
                        &format!(
                            "must be at least {MIN_STEPS_PER_GUST} time steps, {:.4e} s (dt = {dt:.4e} s), to resolve \
                             |sin(pi t / P)|",
                            MIN_STEPS_PER_GUST * dt
                        ),
                    );
                }
                c.range(&f("amplitude"), amplitude, &SCALE_ALLOWED);
            }
            EventSpec::Temperature { temperature_k, range, ramp_s, .. } => {
                if c.range(&f("temperature_k"), temperature_k, &EVENT_TEMPERATURE_K) {
                    thermal(c, &f("temperature_k"), temperature_k);
                }
                if !(alpha.is_finite() && alpha > 0.0) {
                    c.fail(
                        &f("action"),
                        "\"temperature\"",
                        &format!(
                            "needs conductor.thermal_expansion_per_k > 0 (it is {alpha} 1/K): without thermal \
                             expansion a temperature changes nothing (aluminium: 23.8e-6 1/K)"
                        ),
                    );
                }
                if range_ok(c, &f("range"), range) {
                    segments_of(c, &f("range"), range, grid);
                }
                c.range(&f("ramp_s"), ramp_s, &Allowed::closed(0.0, MAX_TIME_S, "s").at_most());
            }
            EventSpec::HeatConduction { hold_range, hold_temperature_k, heat_time_per_s, boundary, .. } => {
                if range_ok(c, &f("hold_range"), hold_range)
                    && boundary == HeatBoundarySpec::Linear
                    && let Some(Grid { n }) = grid
                {
                    linear_closure_stable(c, &f("boundary"), node_range(hold_range, n), n);
                }
                if c.range(&f("hold_temperature_k"), hold_temperature_k, &EVENT_TEMPERATURE_K) {
                    thermal(c, &f("hold_temperature_k"), hold_temperature_k);
                }
                c.range(&f("heat_time_per_s"), heat_time_per_s, &Allowed::open_closed(0.0, 1.0e3, "1/s"));
                if !(alpha.is_finite() && alpha > 0.0) {
                    c.fail(
                        &f("action"),
                        "\"heat_conduction\"",
                        &format!(
                            "needs conductor.thermal_expansion_per_k > 0 (it is {alpha} 1/K): without thermal \
                             expansion the conducted temperature changes neither the wire nor any output \
                             (aluminium: 23.8e-6 1/K)"
                        ),
                    );
                }
            }
            EventSpec::HeatConductionOff { .. } => {}
            EventSpec::Ground { .. } => {
                if s.ground.is_none() {
                    c.fail(&f("action"), "\"ground\"", "needs a [ground] section (height_m, restitution)");
                }
            }
        }
    }
    // Ice: the linear density of every segment, as the events change it in the order they apply (span by
    // span: an ice event lies in one span; a progressive one counts as applied at its start).
    for (sg, ice) in spans.iter().zip(&ice) {
        let Some(ds) = sg.ds else { continue };
        let rho = sg.rho;
        for (k, seg, least) in ice_shortfalls(sg.n, ds, rho, ice) {
            let d = match s.events[k] {
                EventSpec::Ice { linear_density_kg_per_m: Some(d), .. } => d,
                _ => f64::NAN,
            };
            c.fail(
                &format!("events[{k}].linear_density_kg_per_m"),
                number(d),
                &format!(
                    "would leave segments {seg:?} at {least} kg/m, below conductor.linear_density_kg_per_m = {rho} \
                     kg/m (ice can only be dropped down to the bare wire, for which the time step is set; the \
                     events apply in time order)"
                ),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    const BASE: &str = "[conductor]\naxial_stiffness_n = 792000.0\nlinear_density_kg_per_m = 1.0\n\
        [geometry]\nleft_support_m = [0.0, 0.0, 0.0]\nright_support_m = [0.0, 160.0, 0.0]\nsegments = 20\n\
        [duration]\nend_time_s = 0.5\n";

    fn ice(t: f64, d: f64, range: [f64; 2]) -> String {
        format!("[[events]]\ntime_s = {t}\naction = \"ice\"\nlinear_density_kg_per_m = {d}\nrange = {range:?}\n")
    }

    fn problems(events: &str) -> Vec<Problem> {
        let s: Scenario = toml::from_str(&format!("{BASE}{events}")).unwrap();
        validate(&s)
    }

    #[test]
    fn ice_dropped_in_two_parts_is_accepted_despite_rounding() {
        // 0.3 - 0.1 - 0.2 is -2.8e-17 in floating point: the old summed check refused this legal drop.
        let (a, b, c) = (std::hint::black_box(0.3_f64), 0.1, 0.2);
        assert!(a - b - c < 0.0);
        let ev = [ice(0.1, 0.3, [0.0, 1.0]), ice(0.2, -0.1, [0.0, 1.0]), ice(0.3, -0.2, [0.0, 1.0])].concat();
        assert_eq!(problems(&ev), vec![]);
        // And the same on part of the span, dropped in two parts over two sub-ranges.
        let ev = [
            ice(0.1, 0.7, [0.2, 0.8]),
            ice(0.2, -0.3, [0.2, 0.5]),
            ice(0.2, -0.4, [0.2, 0.8]),
            ice(0.3, -0.3, [0.5, 0.8]),
        ]
        .concat();
        assert_eq!(problems(&ev), vec![]);
    }

    #[test]
    fn ice_is_checked_per_segment_in_the_order_the_events_apply() {
        // Listed first but applied second: the drop at t = 0.1 comes before the ice it drops.
        let p = problems(&[ice(0.2, 0.5, [0.0, 1.0]), ice(0.1, -0.5, [0.0, 1.0])].concat());
        assert_eq!(p.len(), 1, "{p:?}");
        assert_eq!(p[0].field, "events[1].linear_density_kg_per_m");
        assert!(p[0].allowed.contains("segments 0..20 at 0.5 kg/m"), "{}", p[0].allowed);
        // Partial overlap: only the segments the drop reaches beyond the ice go below the bare wire.
        let p = problems(&[ice(0.1, 0.5, [0.0, 0.5]), ice(0.2, -0.5, [0.25, 0.75])].concat());
        assert_eq!(p.len(), 1, "{p:?}");
        assert!(p[0].allowed.contains("segments 10..15 at 0.5 kg/m"), "{}", p[0].allowed);
        // Exactly the bare wire again is fine; one ulp of real excess ice dropped is not refused either,
        // but a drop of 1e-9 kg/m more than was added is.
        assert_eq!(problems(&[ice(0.1, 0.5, [0.0, 1.0]), ice(0.2, -0.5, [0.0, 1.0])].concat()), vec![]);
        let p = problems(&[ice(0.1, 0.5, [0.0, 1.0]), ice(0.2, -0.500000001, [0.0, 1.0])].concat());
        assert_eq!(p.len(), 1, "{p:?}");
    }

    #[test]
    fn validation_agrees_with_the_wire_and_never_leaves_a_segment_weightless() {
        // The lightest wire accepted, heavily iced and de-iced: the wire's own arithmetic keeps it positive.
        let (n, ds, rho) = (20, 8.0, 1.0e-3);
        let events: Vec<IceEvent> = vec![(0, 0..20, 1.0e3), (1, 0..20, -1.0e3)];
        assert!(ice_shortfalls(n, ds, rho, &events).is_empty());
        let conductor = crate::wire::Conductor {
            axial_stiffness_n: 1.0,
            internal_friction_n_s: 0.0,
            law: crate::element::tension::LawKind::TensionOnly,
        };
        let x = [vec![0.0; n + 1], (0..=n).map(|i| i as f64 * ds).collect(), vec![0.0; n + 1]];
        let mut w = crate::wire::Wire::new(conductor, x, vec![ds; n], rho);
        assert!(w.add_linear_density(0..20, 1.0e3) && w.add_linear_density(0..20, -1.0e3));
        assert!(w.segment_mass.iter().all(|&m| m > 0.0));
        // A change that would leave a mass at zero is refused by the wire itself, not a panic.
        let before = w.segment_mass.clone();
        assert!(!w.add_linear_density(3..5, -1.0));
        assert_eq!(w.segment_mass, before);
        assert!(!w.add_linear_density(0..99, 1.0));
    }

    #[test]
    fn thousands_of_ice_events_validate_quickly() {
        // 20000 events on 1e6 segments: O(e log e + e s) with s <= 2 e + 1 stretches, well under a second
        // (the former check was O(e^3)).
        let n = 1_000_000;
        let events: Vec<IceEvent> = (0..20_000)
            .map(|k| {
                let a = (k * 7919) % (n - 10);
                (k, a..a + 10, if k % 2 == 0 { 0.5 } else { -0.25 })
            })
            .collect();
        let started = std::time::Instant::now();
        let short = ice_shortfalls(n, 0.16, 1.0, &events);
        assert!(started.elapsed().as_secs_f64() < 5.0, "{:?}", started.elapsed());
        assert!(short.iter().all(|s| s.2 < 1.0));
    }

    #[test]
    fn numbers_are_written_short() {
        assert_eq!(number(1.0e308), "1e308");
        assert_eq!(number(1.0e-300), "1e-300");
        assert_eq!(number(1_000_000.0), "1000000");
        assert_eq!(number(0.5), "0.5");
        assert_eq!(number(f64::NAN), "NaN");
    }
}

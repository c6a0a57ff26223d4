//! Study `thermal`: the conductor heat balance of `ohl::thermal` (IEEE Std 738-2012 and CIGRE TB 601 (2014))
//! against the standards' printed worked examples, and its steady, transient and de-icing solvers against
//! their own exact properties.
//!
//! # What is compared
//!
//! 1. **Worked examples**, term by term next to the printed numbers. The examples' inputs are rebuilt here
//!    (the library's fixtures are `cfg(test)`), from the same sources the unit tests cite:
//!    * IEEE Std 738-2012 Annex B: ACSR Drake (D = 28.14 mm, R(25 C) = 7.283e-5, R(75 C) = 8.688e-5 ohm/m,
//!      emissivity = absorptivity = 0.8) at T_s = 100 C in air at 40 C, wind 0.61 m/s perpendicular, sea level,
//!      latitude 30 N, 10 June (day 161) 11:00, an east-west line, clear atmosphere. Printed (as quoted by
//!      eurobios-mews-labs/thermohl `test/test_ieee.py` and tommz9/pylinerating `tests/test_ieee.py`):
//!      N_Re = 865, q_c1 = 81.93, q_c2 = 77.06, q_cn = 42.4, q_r = 39.1, q_s = 22.44 W/m, R(100 C) = 9.390e-5
//!      ohm/m, I = 1025 A. The printed q_c1 is **not reproduced**: eq. (3a) at the annex's own printed
//!      intermediates gives 82.10 W/m and no rounding of them reaches 81.93; it is tabulated as such, and only
//!      our q_c1 against eq. (3a) at those intermediates is checked.
//!    * CIGRE TB 601 Annex E (p. 79), Examples A and B (as quoted by statnett/linerate
//!      `tests/acceptance_tests/test_cigre_ampacity_cases.py`): P_c = 77.6 / 172.1, P_r = 39.1 / 54,
//!      P_S = 27.2 / 13.7 W/m, R(100 C) = 9.3905e-5 ohm/m, I = 976 / 1504 A.
//!    * TB 601's transient example (section 4, as quoted by linerate
//!      `tests/acceptance_tests/test_cigre_transient_cases.py`): the steady start at 802 A (42.01 C), then ten
//!      minutes at 819 A and ten at 856 A in changed weather, printed every minute to 0.001 C. The start is
//!      reproduced. The printed tracking is forward Euler with 60 s steps from the printed start 42.01 C with
//!      eq. (27)'s `+ 273`: our terms integrated that way reproduce it within one unit of its last digit. The
//!      accurate integral (RK4, 1 s) rises more slowly, by forward Euler's error at 60 s (0.04 K and 0.23 K at
//!      the ends of the stages), which is pinned with the unit test's bounds so that a change that widens it
//!      fails here.
//! 2. **Steady state**: `steady::ampacity` at T_max = 50 ... 150 C and `steady::temperature` at that current
//!    are inverse, in both standards, by day and by night; the net heat at both solutions vanishes. Where the
//!    sun alone holds the conductor above T_max the library must refuse (`SunAlone`): checked against the terms.
//! 3. **Transient** (`transient::Transient`, RK4 landing on the schedule's points): catalogue Drake in the
//!    Annex B weather, a step 400 A -> 1200 A from the steady state at 400 A. The temperature 20 min after the
//!    step with steps of 120, 60, 30, 15 s against 1 s (observed order); the run after 30 time constants
//!    against `steady::temperature`; `time_to_reach` (30 s steps) for 90 % of the rise against a 0.125 s run.
//! 4. **De-icing** (`deicing::Deicing`): catalogue Drake, IEEE 738 losses, night, air -10 C, wind 2 m/s
//!    perpendicular, 10 mm of glaze, slot criterion unless said: the energy budget, the order of the shed
//!    time in the step (h = 40 ... 5 s against 0.5 s), the closed form when phase 1 has no length (air at
//!    0 C; conductor started at 0 C), the shed time at 1200 A, the current that sheds in 30 min, and a
//!    table over ice thickness, current and criterion.
//! 5. **Correlation joins**: the rows of TB 601 Table 4 (Re = 2650, 5000, 50000) and Table 5 (Gr Pr = 1e2,
//!    1e4, 1e7) are separate published fits; their relative jumps at the boundaries are tabulated. IEEE 738's
//!    forced convection is the larger of eqs. (3a) and (3b) and natural convection eq. (5a) is used when
//!    larger: checked over a sweep of wind speeds, with the crossings located and the used value continuous.
//!
//! # Tolerances and why
//!
//! * Printed values: half a unit of the printed last digit, plus the effect of the rounded intermediate
//!   values the standard computed from (propagated through the equation), plus, where our interface differs
//!   from the standard's arithmetic, that computed difference (radiation converted with 273.15 instead of
//!   273: `4 pi D sigma eps (T_s^3 - T_a^3) 0.15 K`; Annex B's truncated solar altitude through eq. (9)).
//!   These are the unit tests' tolerances, recomputed here. The ampacities carry the terms' tolerances through
//!   `dI/I = d(q_c + q_r - q_s) / (2 (q_c + q_r - q_s))`; the IEEE one includes the 0.25 % bound of the
//!   unexplained q_c1 gap, as the unit test does (the table also states the margin without it).
//! * TB 601 CIGRE convection: half a unit plus 0.1 % of the value for the brochure's rounded air properties,
//!   Re and Nu (the unit tests' allowance).
//! * TB 601 transient tracking: forward Euler at 60 s against the printed digits within 1e-3 K (one unit of
//!   the printed 0.001 C; the rest is the brochure's rounded intermediate values). The accurate integral's
//!   difference from the printed series is pinned below 0.045 K (stage 1) and 0.235 K (stage 2), the unit
//!   test's bounds; that the RK4 run is accurate is checked by halving the step (2 s -> 1 s changes the
//!   printed minutes by less than 1e-6 K).
//! * Steady inverse: `steady::temperature` narrows its bracket to 1e-9 K, so the round trip is within 1e-8 K;
//!   the net heat at the temperature solution is below `|dN/dT| 1e-9 K` plus 1e-12 of the terms (rounding),
//!   and at the closed-form ampacity below 1e-12 of the terms.
//! * RK4 order 4 +- 0.2 (least squares over the three finest steps): the step lands on the current step, so
//!   the right-hand side is smooth inside every step; the reference's own error is (1/15)^4 = 2e-5 of the
//!   finest error. De-icing: 4 +- 0.5 (the unit test's band: the landing on the switch to melting is found by
//!   Brent to 1e-12 h).
//! * Steady limit: after 30 time constants the transient is `e^-30` (1e-13) of the rise from it; the steady
//!   state is a fixed point of RK4, and the steady solve is good to 1e-9 K: 1e-6 K.
//! * `time_to_reach`: the fine run at the time found must be at the limit within twice the 30 s run's largest
//!   error on its grid (the crossing lies inside a step: the propagated error plus at most one local error)
//!   plus the bisection's 1e-6 s times the rate.
//! * De-icing energy closure below 1e-9 of the Joule energy: `H - E_J + E_loss` is a linear invariant of the
//!   integrated system, which RK4 conserves exactly, so only rounding remains. Closed forms 1e-9 relative:
//!   phase 1 has no length and phase 2 is closed form; the surface root finder leaves at most `G 1e-12 K`
//!   (3e-11 W/m, 3e-13 of q_J). Current to shed in 30 min: the run at it sheds within
//!   `1.5 |dt/dI| tol_I` before 30 min (the unit test's bound), the current less by `tol_I` does not.
//! * Correlation joins: below 2 %, a loose bound on a published table (the observed jumps are stated). The
//!   IEEE choice is exact (the maximum of the three rates, by `==`); its continuity at the crossings 1e-6.
//!
//! # Output
//!
//! Tables `thermal_worked_examples`, `thermal_tb601_transient`, `thermal_steady_inverse`,
//! `thermal_transient_order`, `thermal_deicing`, `thermal_deicing_order`, `thermal_deicing_times`,
//! `thermal_joins`, `thermal_ieee_convection` (CSV); figures `thermal_transient` (temperature after the step
//! with the steady state dashed; error against the step on log-log axes with a slope-4 line) and
//! `thermal_deicing` (conductor temperature and melted fraction against time for 1000, 1200, 1500 A, shed
//! times marked), PNG and SVG.

use crate::convergence::{ls_order, pair_orders};
use crate::report::{Budget, StudyReport, Table, sci};
use ohl::thermal::cigre601::Cigre601;
use ohl::thermal::cigre601::convection as tb_conv;
use ohl::thermal::deicing::{Deicing, DeicingOptions, DeicingResult, IceShell, MELTING_POINT_K, ShedCriterion};
use ohl::thermal::examples::{annex_b, tb601};
use ohl::thermal::ieee738::Ieee738;
use ohl::thermal::ieee738::air::Air;
use ohl::thermal::ieee738::convection as ieee_conv;
use ohl::thermal::ieee738::solar as ieee_solar;
use ohl::thermal::radiation::{STEFAN_BOLTZMANN_W_PER_M2_K4, radiation_w_per_m};
use ohl::thermal::steady::{self, SteadyError};
use ohl::thermal::transient::{CurrentSchedule, Sample, Transient, time_to_reach};
use ohl::thermal::{HeatBalance, HeatTerms, Model, Standard, ThermalConductor, Weather, catalog, joule};
use ohl_app::plot::{Chart, Series, Style};
use std::path::Path;

/// Offset between the kelvin and degree Celsius scales \[K\].
const K: f64 = 273.15;

// ---------------------------------------------------------------------------------------------------------
// The examples' inputs
// ---------------------------------------------------------------------------------------------------------

// The inputs themselves are the library's record of the published examples (`ohl::thermal::examples`), shared
// with its unit tests; the printed numbers they are checked against are in the checks below.

/// A TB 601 heat balance whose radiation converts degrees Celsius with `+ 273`, as the brochure evaluates its
/// eq. (27): the interface's kelvin lowered by 0.15 K in the radiation term only.
struct Plus273<'a>(&'a Cigre601);

impl HeatBalance for Plus273<'_> {
    fn terms(&self, temperature_k: f64, current_a: f64) -> HeatTerms {
        let m = self.0;
        let mut q = m.terms(temperature_k, current_a);
        q.radiation_w_per_m = tb601::radiation_plus_273(m, temperature_k);
        q
    }

    fn heat_capacity_j_per_m_k(&self, temperature_k: f64) -> f64 {
        self.0.heat_capacity_j_per_m_k(temperature_k)
    }

    fn air_temperature_k(&self) -> f64 {
        self.0.air_temperature_k()
    }
}

/// Catalogue Drake (`catalog::find("drake")`): Annex B's diameter and resistances, TB 601's layer masses and
/// specific heats with their temperature coefficients.
fn catalogue_drake() -> Result<ThermalConductor, String> {
    Ok(catalog::find("drake").map_err(|e| e.to_string())?.thermal())
}

// ---------------------------------------------------------------------------------------------------------
// Helpers
// ---------------------------------------------------------------------------------------------------------

/// A number for a table: four decimals in a moderate range, else five significant digits in scientific form.
fn num(v: f64) -> String {
    if (1e-2..1e5).contains(&v.abs()) { format!("{v:.4}") } else { format!("{v:.4e}") }
}

/// One printed number of a worked example against ours.
struct Worked<'a> {
    example: &'a str,
    quantity: &'a str,
    printed: f64,
    computed: f64,
    tolerance: f64,
    why: &'a str,
}

impl<'a> Worked<'a> {
    fn new(example: &'a str, quantity: &'a str, printed: f64, computed: f64, tolerance: f64, why: &'a str) -> Self {
        Worked { example, quantity, printed, computed, tolerance, why }
    }
}

/// Tabulate a worked-example comparison and check it.
fn reproduce(rep: &mut StudyReport, table: &mut Table, w: Worked) {
    let diff = (w.computed - w.printed).abs();
    let pass = diff <= w.tolerance;
    table.row(vec![
        w.example.into(),
        w.quantity.into(),
        num(w.printed),
        num(w.computed),
        sci(diff),
        sci(w.tolerance),
        w.why.into(),
        if pass { "reproduced" } else { "NOT reproduced" }.into(),
    ]);
    rep.check(
        format!("{}: {}", w.example, w.quantity),
        format!("printed {} +- {} ({})", num(w.printed), sci(w.tolerance), w.why),
        format!("{} (off by {})", num(w.computed), sci(diff)),
        pass,
    );
}

/// Largest magnitude of the terms of a heat balance \[W/m\] (the scale of their rounding).
fn scale(q: &HeatTerms) -> f64 {
    q.joule_w_per_m.abs().max(q.solar_w_per_m.abs()).max(q.convection_w_per_m.abs()).max(q.radiation_w_per_m.abs())
}

/// Bisection for the sign change of `f` in `[lo, hi]` to 100 halvings.
fn bisect(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64) -> f64 {
    let f_lo = f(lo);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if (f(mid) > 0.0) == (f_lo > 0.0) { lo = mid } else { hi = mid }
    }
    0.5 * (lo + hi)
}

/// The sample of `run` at time `t` \[s\] (the runs land on multiples of their step).
fn at_time(run: &[Sample], t: f64) -> Option<&Sample> {
    let k = run.partition_point(|s| s.time_s < t - 1e-6);
    run.get(k).filter(|s| (s.time_s - t).abs() < 1e-6)
}

// ---------------------------------------------------------------------------------------------------------
// Item 1: worked examples
// ---------------------------------------------------------------------------------------------------------

/// Numbers item 1 hands to the discussion.
struct WorkedSummary {
    q_c1: f64,
    q_c1_eq3a_printed_inputs: f64,
    ieee_ampacity_a: f64,
    ieee_ampacity_tol_a: f64,
    ieee_ampacity_tol_without_gap_a: f64,
    a_ampacity_a: f64,
    b_ampacity_a: f64,
    tb601_start_c: f64,
    tb601_start_plus273_c: f64,
    tracking_worst_k: [f64; 2],
    tracking_step_effect_k: f64,
    tracking_rise_k: [[f64; 2]; 2],
    tracking_euler_worst_k: f64,
    tracking_euler_same_digits: usize,
}

fn worked_examples(rep: &mut StudyReport) -> Result<(Table, Table, WorkedSummary), String> {
    let mut table = Table::new(
        "thermal_worked_examples",
        "Worked examples of IEEE 738-2012 Annex B and CIGRE TB 601 Annex E against the printed numbers \
         (W/m, ohm/m, A, C)",
        &["example", "quantity", "printed", "computed", "|difference|", "tolerance", "tolerance from", "status"],
    );

    // ---- IEEE 738-2012 Annex B: Drake at 100 C ----
    const EX: &str = "IEEE 738 Annex B";
    let m = Ieee738 { conductor: annex_b::drake(), weather: annex_b::weather() };
    let (t_s, t_a) = (K + 100.0, K + 40.0);
    let d = m.conductor.diameter_m;
    let conv = m.convection(t_s);
    let terms = m.terms(t_s, 0.0);
    // The annex's printed intermediates (pylinerating tests/test_ieee.py): rho_f, mu_f, k_f, N_Re.
    let (rho_p, mu_p, kf_p, re_p) = (1.029, 2.043e-5, 0.02945, 865.0);
    // Relative rounding of N_Re: rho_f and mu_f to four digits before eq. (2c), and N_Re's own half unit.
    let re_rounding = 0.0005 / rho_p + 0.0005e-5 / mu_p + 0.5 / re_p;
    let re = ieee_conv::reynolds_number(d, 0.61, &Air::at(t_s, t_a, 0.0));
    reproduce(
        rep,
        &mut table,
        Worked::new(EX, "N_Re (eq. 2c)", re_p, re, re_rounding * re_p, "rho_f, mu_f rounded to 4 digits + half unit"),
    );
    let kf_rounding = 0.000005 / kf_p;
    reproduce(
        rep,
        &mut table,
        Worked::new(
            EX,
            "q_c2 (eq. 3b) [W/m]",
            77.06,
            conv.forced_high_wind_w_per_m,
            0.005 + 77.06 * (0.6 * re_rounding + kf_rounding),
            "half unit + N_Re^0.6 k_f rounding",
        ),
    );
    // q_c1: our value against eq. (3a) at the printed intermediates (reproducible) ...
    let q1_printed_inputs = ieee_conv::forced_low_wind_w_per_m(1.0, re_p, kf_p, 60.0);
    let exponent = {
        let a = 1.35 * re_p.powf(0.52);
        0.52 * a / (1.01 + a)
    };
    reproduce(
        rep,
        &mut table,
        Worked::new(
            EX,
            "q_c1 vs eq. (3a) at the printed N_Re, k_f [W/m]",
            q1_printed_inputs,
            conv.forced_low_wind_w_per_m,
            q1_printed_inputs * (exponent * re_rounding + kf_rounding),
            "N_Re^0.509 k_f rounding (the 'printed' column is eq. 3a at printed inputs)",
        ),
    );
    // ... and the printed 81.93, which is not reproduced: a row, not a check.
    let q1 = conv.forced_low_wind_w_per_m;
    table.row(vec![
        EX.into(),
        "q_c1 (eq. 3a) [W/m]".into(),
        num(81.93),
        num(q1),
        sci((q1 - 81.93).abs()),
        "-".into(),
        format!(
            "eq. (3a) at the annex's own printed intermediates gives {q1_printed_inputs:.2} W/m; no rounding of them \
             reaches 81.93 ({:.2} % below its own equation; pylinerating and thermohl meet the same gap)",
            100.0 * (1.0 - 81.93 / q1_printed_inputs)
        ),
        "NOT reproduced (known)".into(),
    ]);
    reproduce(
        rep,
        &mut table,
        Worked::new(
            EX,
            "q_cn (eq. 5a) [W/m]",
            42.4,
            conv.natural_w_per_m,
            0.05 + 42.4 * 0.5 * 0.0005 / rho_p,
            "half unit + rho_f^0.5 rounding",
        ),
    );
    // q_r: the standard converts with 273; our interface with 273.15. The offset effect, first order.
    let c = &m.conductor;
    let offset = 4.0
        * std::f64::consts::PI
        * c.diameter_m
        * STEFAN_BOLTZMANN_W_PER_M2_K4
        * c.emissivity
        * (373.0_f64.powi(3) - 313.0_f64.powi(3))
        * 0.15;
    reproduce(
        rep,
        &mut table,
        Worked::new(
            EX,
            "q_r with the standard's +273 (eq. 7a) [W/m]",
            39.1,
            radiation_w_per_m(c.diameter_m, c.emissivity, 373.0, 313.0),
            0.05,
            "half unit",
        ),
    );
    reproduce(
        rep,
        &mut table,
        Worked::new(
            EX,
            "q_r, model (+273.15) [W/m]",
            39.1,
            terms.radiation_w_per_m,
            0.05 + offset,
            "half unit + 0.15 K offset effect 4 pi D sigma eps (T_s^3 - T_a^3) 0.15",
        ),
    );
    // q_s: the annex carried a truncated H_c (74.8 for 74.89) and a rounded Z_c into eq. (9).
    let p = ieee_solar::SolarPosition::new(&annex_b::sun(), 0.0);
    let slope = |f: &dyn Fn(f64) -> f64, x: f64| (f(x + 1e-4) - f(x - 1e-4)) / 2e-4;
    let d_hc = slope(&|h| ieee_solar::incidence_angle_deg(h, p.azimuth_deg, 90.0), p.altitude_deg).abs();
    let d_zc = slope(&|z| ieee_solar::incidence_angle_deg(p.altitude_deg, z, 90.0), p.azimuth_deg).abs();
    let theta_tol = (0.05 + 0.1 * d_hc + 0.05 * d_zc).to_radians();
    let qs = terms.solar_w_per_m;
    let qs_tol = 0.005 + qs / p.incidence_deg.to_radians().tan() * theta_tol + qs * 0.5 / 1027.0;
    reproduce(
        rep,
        &mut table,
        Worked::new(
            EX,
            "q_s (eq. 8) [W/m]",
            22.44,
            qs,
            qs_tol,
            "half unit + truncated H_c, rounded Z_c, theta through eq. (9) + Q_s half unit",
        ),
    );
    let r100 = joule::resistance_ohm_per_m(c, t_s);
    reproduce(
        rep,
        &mut table,
        Worked::new(
            EX,
            "R(100 C) (eq. 10) [ohm/m]",
            9.390e-5,
            r100,
            0.0005e-5 + 1e-18,
            "half unit (9.3905e-5 is on the rounding tie)",
        ),
    );
    let net_printed: f64 = 81.93 + 39.1 - 22.44;
    reproduce(
        rep,
        &mut table,
        Worked::new(
            EX,
            "I from the printed terms (eq. 1b) [A]",
            1025.0,
            (net_printed / 9.390e-5).sqrt(),
            0.5,
            "half unit (the annex's own arithmetic)",
        ),
    );
    let amp = steady::ampacity(&m, t_s).map_err(|e| e.to_string())?;
    let gap_bound = 2.5e-3 * 81.93;
    let d_terms = (0.05 + offset) + qs_tol;
    let amp_tol = 0.5 + 1025.0 * (gap_bound + d_terms) / (2.0 * net_printed);
    let amp_tol_without_gap = 0.5 + 1025.0 * d_terms / (2.0 * net_printed);
    reproduce(
        rep,
        &mut table,
        Worked::new(
            EX,
            "ampacity at 100 C (steady::ampacity) [A]",
            1025.0,
            amp.current_a,
            amp_tol,
            "half unit + term tolerances through eq. (1b), incl. the 0.25 % q_c1 gap",
        ),
    );
    rep.check(
        "IEEE 738 Annex B: the model's q_c is q_c1 (the larger of eqs. 3a, 3b, 5a)",
        "q_c = q_c1 > q_c2 > q_cn",
        format!(
            "q_c {:.4} = q_c1; q_c2 {:.4}, q_cn {:.4}",
            terms.convection_w_per_m, conv.forced_high_wind_w_per_m, conv.natural_w_per_m
        ),
        terms.convection_w_per_m == q1
            && q1 > conv.forced_high_wind_w_per_m
            && conv.forced_high_wind_w_per_m > conv.natural_w_per_m,
    );

    // ---- CIGRE TB 601 Annex E, Examples A and B ----
    let mut tb_amp = [0.0; 2];
    for (k, (label, model, printed, tol_r, net_p)) in [
        ("TB 601 Example A", tb601::example_a().0, [77.6, 39.1, 27.2, 976.0], 0.05, 77.6 + 39.1 - 27.2),
        ("TB 601 Example B", tb601::example_b().0, [172.1, 54.0, 13.7, 1504.0], 0.5, 172.1 + 54.0 - 13.7),
    ]
    .into_iter()
    .enumerate()
    {
        let t = K + 100.0;
        let q = model.terms(t, 1.0);
        let tol_c = 0.05 + 1e-3 * printed[0];
        reproduce(
            rep,
            &mut table,
            Worked::new(label, "R(100 C) [ohm/m]", 9.3905e-5, q.joule_w_per_m, 0.00005e-5, "half unit"),
        );
        reproduce(
            rep,
            &mut table,
            Worked::new(
                label,
                "P_c (eq. 17) [W/m]",
                printed[0],
                q.convection_w_per_m,
                tol_c,
                "half unit + 0.1 % for rounded air properties, Re, Nu",
            ),
        );
        reproduce(
            rep,
            &mut table,
            Worked::new(
                label,
                "P_r with the brochure's +273 (eq. 27) [W/m]",
                printed[1],
                Plus273(&model).terms(t, 1.0).radiation_w_per_m,
                0.05,
                "half a unit of 0.1 W/m",
            ),
        );
        reproduce(
            rep,
            &mut table,
            Worked::new(
                label,
                "P_r, model (+273.15) [W/m]",
                printed[1],
                q.radiation_w_per_m,
                tol_r,
                if k == 0 { "half unit" } else { "half unit (printed 54)" },
            ),
        );
        reproduce(
            rep,
            &mut table,
            Worked::new(label, "P_S (eq. 8) [W/m]", printed[2], q.solar_w_per_m, 0.05, "half unit"),
        );
        let a = steady::ampacity(&model, t).map_err(|e| e.to_string())?;
        tb_amp[k] = a.current_a;
        reproduce(
            rep,
            &mut table,
            Worked::new(
                label,
                "ampacity at 100 C (steady::ampacity) [A]",
                printed[3],
                a.current_a,
                0.5 + 0.5 * printed[3] * (tol_c + tol_r + 0.05) / net_p,
                "half unit + term tolerances through I^2 R = P_c + P_r - P_S",
            ),
        );
    }

    // ---- TB 601 transient example ----
    const TR: &str = "TB 601 transient example";
    let start_model = tb601::transient(24.0, 1.9, 55.0);
    let start = steady::temperature(&start_model, 802.0).map_err(|e| e.to_string())?.temperature_k;
    let start_273 = steady::temperature(&Plus273(&start_model), 802.0).map_err(|e| e.to_string())?.temperature_k;
    reproduce(
        rep,
        &mut table,
        Worked::new(TR, "steady start at 802 A, radiation with +273 [C]", 42.01, start_273 - K, 0.005, "half unit"),
    );
    reproduce(
        rep,
        &mut table,
        Worked::new(
            TR,
            "steady start at 802 A, model (+273.15) [C]",
            42.01,
            start - K,
            0.005 + (start_273 - start).abs(),
            "half unit + the computed +273 shift",
        ),
    );
    let printed = [
        [42.175, 42.321, 42.449, 42.562, 42.662, 42.750, 42.828, 42.897, 42.958, 43.011],
        [44.147, 45.199, 46.174, 47.075, 47.910, 48.682, 49.396, 50.057, 50.668, 51.233],
    ];
    let stages = [(tb601::transient(23.7, 1.7, 62.0), 819.0), (tb601::transient(23.5, 0.8, 37.0), 856.0)];
    let mut track = Table::new(
        "thermal_tb601_transient",
        "TB 601 transient example: printed temperature every minute against ours integrated as the brochure \
         did (forward Euler, 60 s steps, from the printed 42.01 C, +273 in eq. (27)) and accurately (RK4, 1 s \
         steps, from our steady start)",
        &[
            "stage",
            "current [A]",
            "minute",
            "printed [C]",
            "forward Euler 60 s [C]",
            "Euler - printed [K]",
            "RK4 1 s [C]",
            "RK4 - printed [K]",
        ],
    );
    let mut worst = [0.0_f64; 2];
    let mut rise = [[0.0_f64; 2]; 2];
    let mut temp = start;
    // The same chain with 2 s steps: the integration's share of the gap.
    let mut temp_2s = start;
    let mut step_effect = 0.0_f64;
    let mut printed_first = 42.01;
    // The brochure's own integration: forward Euler, 60 s steps, from its printed start, + 273 in eq. (27).
    let mut euler = K + 42.01;
    let (mut euler_worst, mut euler_same) = (0.0_f64, 0_usize);
    for (k, ((model, current), printed)) in stages.iter().zip(printed).enumerate() {
        let sched = CurrentSchedule::constant(*current);
        let tr = Transient { model, current: &sched, step_s: 1.0 };
        let run = tr.run(0.0, temp, 600.0);
        let run_2s = Transient { step_s: 2.0, ..tr }.run(0.0, temp_2s, 600.0);
        let first = temp;
        for (minute, p) in printed.iter().enumerate() {
            let s = at_time(&run, 60.0 * (minute + 1) as f64).ok_or("transient sample missing")?;
            let got = s.temperature_k - K;
            worst[k] = worst[k].max((got - p).abs());
            let s2 = at_time(&run_2s, s.time_s).ok_or("transient sample missing")?;
            step_effect = step_effect.max((s2.temperature_k - s.temperature_k).abs());
            let brochure = Plus273(model);
            euler += 60.0 * brochure.terms(euler, *current).net_w_per_m() / brochure.heat_capacity_j_per_m_k(euler);
            let e = euler - K;
            euler_worst = euler_worst.max((e - p).abs());
            euler_same += usize::from((e * 1e3).round() == (p * 1e3).round());
            track.row(vec![
                (k + 1).to_string(),
                format!("{current:.0}"),
                (minute + 1).to_string(),
                format!("{p:.3}"),
                format!("{e:.4}"),
                format!("{:+.4}", e - p),
                format!("{got:.4}"),
                format!("{:+.4}", got - p),
            ]);
        }
        temp = run.last().ok_or("empty transient")?.temperature_k;
        temp_2s = run_2s.last().ok_or("empty transient")?.temperature_k;
        rise[k] = [temp - first, printed[9] - printed_first];
        printed_first = printed[9];
    }
    rep.check(
        format!("{TR}: the printed series is forward Euler at 60 s from 42.01 C, +273 in eq. (27) (20 minutes)"),
        "every printed minute within 1e-3 K (one unit of the printed 0.001 C)",
        format!("{euler_worst:.4} K at worst; {euler_same} of 20 equal to the printed digits"),
        euler_worst < 1e-3,
    );
    rep.check(
        format!("{TR}: the RK4 run's own error (1 s against 2 s steps, every printed minute)"),
        "below 1e-6 K, i.e. far below the 1e-3 K printed digit and the gap (RK4: the 1 s error is 1/16 of it)",
        format!("{} K", sci(step_effect)),
        step_effect < 1e-6,
    );
    for (k, bound) in [0.045, 0.235].into_iter().enumerate() {
        rep.check(
            format!("{TR}: stage {}, the accurate integral (RK4) against the printed forward-Euler series", k + 1),
            format!("largest |RK4 - printed| < {bound} K (the unit test's bound on Euler's 60 s error)"),
            format!("{:.4} K (rise over the stage {:.3} K, printed {:.3} K)", worst[k], rise[k][0], rise[k][1]),
            worst[k] < bound,
        );
    }
    Ok((
        table,
        track,
        WorkedSummary {
            q_c1: q1,
            q_c1_eq3a_printed_inputs: q1_printed_inputs,
            ieee_ampacity_a: amp.current_a,
            ieee_ampacity_tol_a: amp_tol,
            ieee_ampacity_tol_without_gap_a: amp_tol_without_gap,
            a_ampacity_a: tb_amp[0],
            b_ampacity_a: tb_amp[1],
            tb601_start_c: start - K,
            tb601_start_plus273_c: start_273 - K,
            tracking_worst_k: worst,
            tracking_step_effect_k: step_effect,
            tracking_rise_k: rise,
            tracking_euler_worst_k: euler_worst,
            tracking_euler_same_digits: euler_same,
        },
    ))
}

// ---------------------------------------------------------------------------------------------------------
// Item 2: steady state
// ---------------------------------------------------------------------------------------------------------

fn steady_inverse(rep: &mut StudyReport) -> Result<(Table, f64, Vec<String>), String> {
    let mut table = Table::new(
        "thermal_steady_inverse",
        "steady::ampacity at T_max, then steady::temperature at that current: round trip and the net heat",
        &[
            "model",
            "T_max [C]",
            "ampacity [A]",
            "|T - T_max| [K]",
            "net at temperature [W/m]",
            "bound [W/m]",
            "net at ampacity / terms",
            "evaluations",
        ],
    );
    let ieee = Ieee738 { conductor: annex_b::drake(), weather: annex_b::weather() };
    let mut ieee_night = ieee.clone();
    ieee_night.weather.sun = None;
    let a = tb601::example_a().0;
    let mut a_night = a.clone();
    a_night.weather.sun = None;
    let cases = [
        ("IEEE 738, Annex B weather (day)", Model::Ieee738(ieee)),
        ("IEEE 738, Annex B weather at night", Model::Ieee738(ieee_night)),
        ("TB 601, Example A weather (day)", Model::Cigre601(a)),
        ("TB 601, Example A weather at night", Model::Cigre601(a_night)),
    ];
    let mut overall = 0.0_f64;
    let mut refusals = vec![];
    for (label, model) in &cases {
        let (mut worst_t, mut worst_net_ratio, mut worst_amp_net) = (0.0_f64, 0.0_f64, 0.0_f64);
        let (mut solved, mut refused, mut refusals_right) = (0, 0, true);
        for t_max_c in [50.0, 75.0, 100.0, 125.0, 150.0] {
            let t_max = K + t_max_c;
            match steady::ampacity(model, t_max) {
                Ok(a) => {
                    let s = steady::temperature(model, a.current_a).map_err(|e| e.to_string())?;
                    let i = a.current_a;
                    let dn = (model.terms(s.temperature_k + 1e-3, i).net_w_per_m()
                        - model.terms(s.temperature_k - 1e-3, i).net_w_per_m())
                        / 2e-3;
                    let bound = dn.abs() * 1e-9 + 1e-12 * scale(&s.terms);
                    let net = s.terms.net_w_per_m();
                    let amp_net = a.terms.net_w_per_m().abs() / scale(&a.terms);
                    let dt = (s.temperature_k - t_max).abs();
                    worst_t = worst_t.max(dt);
                    worst_net_ratio = worst_net_ratio.max(net.abs() / bound);
                    worst_amp_net = worst_amp_net.max(amp_net);
                    solved += 1;
                    table.row(vec![
                        label.to_string(),
                        format!("{t_max_c:.0}"),
                        format!("{i:.3}"),
                        sci(dt),
                        sci(net),
                        sci(bound),
                        sci(amp_net),
                        s.evaluations.to_string(),
                    ]);
                }
                Err(SteadyError::SunAlone { solar_w_per_m, cooling_w_per_m, .. }) => {
                    // Independently: at T_max without current the sun heats at least as much as the air cools.
                    let q = model.terms(t_max, 0.0);
                    refusals_right &= q.solar_w_per_m >= q.convection_w_per_m + q.radiation_w_per_m;
                    refused += 1;
                    refusals.push(format!("{label} at {t_max_c:.0} C"));
                    table.row(vec![
                        label.to_string(),
                        format!("{t_max_c:.0}"),
                        format!(
                            "none: the sun alone ({solar_w_per_m:.2} W/m) exceeds the cooling ({cooling_w_per_m:.2} W/m)"
                        ),
                        "-".into(),
                        "-".into(),
                        "-".into(),
                        "-".into(),
                        "-".into(),
                    ]);
                }
                Err(e) => return Err(e.to_string()),
            }
        }
        overall = overall.max(worst_t);
        rep.check(
            format!("steady inverse, {label}: temperature(ampacity(T_max)) = T_max, T_max = 50..150 C"),
            "|T - T_max| < 1e-8 K (bracket 1e-9 K); net at T below |dN/dT| 1e-9 K + 1e-12 terms; net at the \
             ampacity below 1e-12 of the terms"
                .to_string(),
            format!(
                "{solved} solved: largest |T - T_max| {}, net/bound {}, net at ampacity {}{}",
                sci(worst_t),
                sci(worst_net_ratio),
                sci(worst_amp_net),
                if refused > 0 { format!("; {refused} refused (sun alone)") } else { String::new() }
            ),
            solved > 0 && worst_t < 1e-8 && worst_net_ratio <= 1.0 && worst_amp_net < 1e-12 && refusals_right,
        );
    }
    Ok((table, overall, refusals))
}

// ---------------------------------------------------------------------------------------------------------
// Item 3: transient
// ---------------------------------------------------------------------------------------------------------

/// Numbers item 3 hands on.
struct TransientSummary {
    tau_s: f64,
    t0_k: f64,
    t_ss_k: f64,
    order: f64,
    pairs: Vec<f64>,
    limit_error_k: f64,
    reach_s: f64,
}

fn transient(rep: &mut StudyReport, dir: &Path, drake: &ThermalConductor) -> Result<(Table, TransientSummary), String> {
    let model = Ieee738 { conductor: drake.clone(), weather: annex_b::weather() };
    let (i0, i1) = (400.0, 1200.0);
    let t0 = steady::temperature(&model, i0).map_err(|e| e.to_string())?.temperature_k;
    let t_ss = steady::temperature(&model, i1).map_err(|e| e.to_string())?.temperature_k;
    // Time constant at the new steady state: m c / (-dN/dT).
    let dn = (model.terms(t_ss + 1e-3, i1).net_w_per_m() - model.terms(t_ss - 1e-3, i1).net_w_per_m()) / 2e-3;
    let tau = model.heat_capacity_j_per_m_k(t_ss) / -dn;
    let sched = CurrentSchedule::step(0.0, i0, i1);
    let start = -600.0;
    let tr = |h: f64| Transient { model: &model, current: &sched, step_s: h };

    // Order: the temperature 20 min after the step.
    let t_end = 1200.0;
    let reference = tr(1.0).final_temperature_k(start, t0, t_end);
    let steps = [120.0, 60.0, 30.0, 15.0];
    let finals: Vec<f64> = steps.iter().map(|&h| tr(h).final_temperature_k(start, t0, t_end)).collect();
    let errors: Vec<f64> = finals.iter().map(|t| (t - reference).abs()).collect();
    let order = ls_order(&steps[1..], &errors[1..]);
    let pairs = pair_orders(&steps, &errors);
    let mut table = Table::new(
        "thermal_transient_order",
        "Transient after 400 A -> 1200 A (catalogue Drake, Annex B weather): temperature 20 min after the step \
         against a 1 s run",
        &["step h [s]", "T(20 min) [C]", "error [K]", "pair order"],
    );
    for (k, &h) in steps.iter().enumerate() {
        table.row(vec![
            format!("{h:.0}"),
            format!("{:.9}", finals[k] - K),
            sci(errors[k]),
            if k == 0 { "-".into() } else { format!("{:.3}", pairs[k - 1]) },
        ]);
    }
    table.row(vec!["1 (reference)".into(), format!("{:.9}", reference - K), "-".into(), "-".into()]);
    rep.check(
        "transient: RK4 order on a current step (T 20 min after the step, h = 60, 30, 15 s vs 1 s)",
        "4 +- 0.2 (least squares over the three finest; the step lands on the current step)",
        format!(
            "{order:.3} (pairs {}; errors {} .. {} K)",
            pairs.iter().map(|p| format!("{p:.3}")).collect::<Vec<_>>().join(", "),
            sci(errors[0]),
            sci(errors[3])
        ),
        (order - 4.0).abs() <= 0.2,
    );

    // Convergence to the steady state after 30 time constants.
    let late = tr(10.0).final_temperature_k(start, t0, 30.0 * tau);
    rep.check(
        "transient: 30 time constants after the step it is at steady::temperature(1200 A)",
        format!("|T - T_ss| < 1e-6 K (e^-30 of the {:.1} K rise is 1e-11 K; RK4 fixed point)", t_ss - t0),
        format!("{} K (tau = {:.1} s, h = 10 s)", sci((late - t_ss).abs()), tau),
        (late - t_ss).abs() < 1e-6,
    );

    // time_to_reach for 90 % of the rise, against a fine run. The horizon after the step is a whole number of
    // 30 s steps, so that time_to_reach's steps are exactly 30 s and its grid is the 30 s run's.
    let limit = t0 + 0.9 * (t_ss - t0);
    let coarse = tr(30.0);
    let horizon = -start + 30.0 * tau.ceil();
    let reach = time_to_reach(&coarse, start, t0, limit, horizon).ok_or("90 % of the rise not reached")?;
    let fine_at = tr(0.125).final_temperature_k(start, t0, reach);
    // The 30 s run's error on its grid up to the first grid time past the crossing, against a 0.125 s run.
    let grid_end = 30.0 * (reach / 30.0).ceil();
    let coarse_run = coarse.run(start, t0, grid_end);
    let fine_run = tr(0.125).run(start, t0, grid_end);
    let mut coarse_error = 0.0_f64;
    let mut compared = 0;
    for s in &coarse_run {
        if let Some(f) = at_time(&fine_run, s.time_s) {
            coarse_error = coarse_error.max((s.temperature_k - f.temperature_k).abs());
            compared += 1;
        }
    }
    if compared + 1 < coarse_run.len() {
        return Err(format!("the 30 s and 0.125 s grids meet at {compared} of {} points", coarse_run.len()));
    }
    let rate = model.terms(limit, i1).net_w_per_m() / model.heat_capacity_j_per_m_k(limit);
    let tol = 2.0 * coarse_error + rate.abs() * 1e-6 + 1e-9;
    rep.check(
        "transient: time_to_reach (30 s steps) for 90 % of the rise, the 0.125 s run there (a binary fraction: the grids meet exactly)",
        format!("|T_fine(t) - limit| <= 2 x the 30 s run's largest grid error + rate x 1e-6 s = {}", sci(tol)),
        format!("{} K at t = {:.4} s after the step", sci((fine_at - limit).abs()), reach),
        (fine_at - limit).abs() <= tol,
    );
    let unreachable = time_to_reach(&coarse, start, t0, t_ss + 1.0, horizon);
    rep.check(
        "transient: time_to_reach of a limit 1 K above the steady state",
        "None",
        format!("{unreachable:?}"),
        unreachable.is_none(),
    );

    // Figure.
    let show = tr(10.0).run(start, t0, 120.0 * 60.0);
    let curve: Vec<(f64, f64)> = show.iter().map(|s| (s.time_s / 60.0, s.temperature_k - K)).collect();
    let (x0, x1) = (start / 60.0, 120.0);
    let panel_t = Chart {
        title: "Drake, 400 A -> 1200 A at t = 0, IEEE 738 Annex B weather".into(),
        x_label: "time [min]".into(),
        y_label: "conductor temperature [C]".into(),
        series: vec![
            Series::new("RK4, h = 10 s", curve, Style::Line, 0),
            Series::new(
                format!("steady state at 1200 A ({:.2} C)", t_ss - K),
                vec![(x0, t_ss - K), (x1, t_ss - K)],
                Style::Dashed,
                1,
            ),
            Series::new(
                format!("time_to_reach 90 % ({:.1} min)", reach / 60.0),
                vec![(reach / 60.0, limit - K)],
                Style::Markers,
                2,
            ),
        ],
        ..Default::default()
    };
    let slope: Vec<(f64, f64)> = steps.iter().map(|&h| (h, errors[3] * (h / steps[3]).powi(4))).collect();
    let panel_e = Chart {
        title: "RK4 error 20 min after the step (vs h = 1 s)".into(),
        x_label: "step h [s]".into(),
        y_label: "|T_h - T_ref| [K]".into(),
        series: vec![
            Series::new("error", steps.iter().copied().zip(errors.iter().copied()).collect(), Style::LineMarkers, 0),
            Series::new("slope 4", slope, Style::Dashed, 1),
        ],
        log_x: true,
        log_y: true,
        ..Default::default()
    };
    rep.figure(
        &[panel_t, panel_e],
        2,
        (640, 460),
        "thermal: IEEE 738 / CIGRE TB 601 heat balance of ACSR Drake (catalogue data)",
        dir,
        "thermal_transient",
    )?;
    Ok((
        table,
        TransientSummary {
            tau_s: tau,
            t0_k: t0,
            t_ss_k: t_ss,
            order,
            pairs,
            limit_error_k: (fine_at - limit).abs(),
            reach_s: reach,
        },
    ))
}

// ---------------------------------------------------------------------------------------------------------
// Item 4: de-icing
// ---------------------------------------------------------------------------------------------------------

/// The de-icing case: catalogue Drake, IEEE 738 losses, night, `air_k`, 2 m/s perpendicular, sea level,
/// `thickness_m` of glaze.
fn deicing_case(drake: &ThermalConductor, thickness_m: f64, air_k: f64, criterion: ShedCriterion) -> Deicing {
    let weather = Weather {
        air_temperature_k: air_k,
        wind_speed_m_per_s: 2.0,
        wind_angle_deg: 90.0,
        elevation_m: 0.0,
        sun: None,
    };
    let mut d = Deicing::new(drake.clone(), weather, Standard::Ieee738, IceShell::glaze(thickness_m));
    d.criterion = criterion;
    d
}

fn opts(step_s: f64) -> DeicingOptions {
    DeicingOptions { step_s, ..DeicingOptions::default() }
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

/// Numbers item 4 hands on.
struct DeicingSummary {
    at_1200: DeicingResult,
    closure: f64,
    order: f64,
    pairs: Vec<f64>,
    current_30_min_a: f64,
    shed_at_it_s: f64,
    minimum_a: f64,
}

fn deicing(
    rep: &mut StudyReport,
    dir: &Path,
    drake: &ThermalConductor,
) -> Result<(Vec<Table>, DeicingSummary), String> {
    let cold = K - 10.0;
    let base = deicing_case(drake, 10e-3, cold, ShedCriterion::Slot);
    let err = |e: ohl::thermal::deicing::DeicingError| e.to_string();

    // ---- energy budget at 1200 A ----
    let r = base.run(1200.0, &opts(1.0)).map_err(err)?;
    let r40 = base.run(1200.0, &opts(40.0)).map_err(err)?;
    let mut budget = Table::new(
        "thermal_deicing",
        "De-icing, Drake, IEEE 738, night, -10 C, 2 m/s, 10 mm glaze, slot criterion: times and energy budget [J/m]",
        &[
            "current [A]",
            "step [s]",
            "warm to 0 C [s]",
            "shed [s]",
            "Joule",
            "sensible",
            "latent",
            "losses",
            "closure / Joule",
        ],
    );
    let mut closure = 0.0_f64;
    for (h, res) in [(1.0, &r), (40.0, &r40)] {
        let e = res.energy;
        let c = e.closure_j_per_m / e.joule_j_per_m;
        closure = closure.max(c.abs());
        budget.row(vec![
            "1200".into(),
            format!("{h:.0}"),
            format!("{:.3}", res.warm_time_s),
            format!("{:.3}", res.shed_time_s),
            sci(e.joule_j_per_m),
            sci(e.sensible_j_per_m),
            sci(e.latent_j_per_m),
            sci(e.losses_j_per_m),
            sci(c),
        ]);
    }
    rep.check(
        "de-icing: energy closure Joule = sensible + latent + losses (1200 A, h = 1 s and 40 s)",
        "|closure| < 1e-9 of the Joule energy (a linear invariant RK4 conserves; rounding only)",
        sci(closure),
        closure < 1e-9,
    );

    // ---- phase-2 bookkeeping at 1200 A ----
    let q_m = base.surface(MELTING_POINT_K).map_err(err)?.conduction_w_per_m;
    let qj_m = joule::joule_w_per_m(drake, MELTING_POINT_K, 1200.0);
    let m_slot = 900.0 * drake.diameter_m * 10e-3;
    let phase2 = r.warm_time_s + 334.0e3 * m_slot / (qj_m - q_m);
    rep.check(
        "de-icing: shed time at 1200 A = warm time + L_f rho_i D t / (q_J(0 C) - q(0 C))",
        "1e-12 relative (phase 2 is closed form)",
        format!(
            "{:.3} s = {:.2} min (warm {:.1} s); off by {}",
            r.shed_time_s,
            r.shed_time_s / 60.0,
            r.warm_time_s,
            sci(rel(r.shed_time_s, phase2))
        ),
        rel(r.shed_time_s, phase2) < 1e-12,
    );

    // ---- order in the step ----
    let shed = |h: f64| base.run(1200.0, &opts(h)).map(|r| r.shed_time_s).map_err(err);
    let reference = shed(0.5)?;
    let steps = [40.0, 20.0, 10.0, 5.0];
    let times: Vec<f64> = steps.iter().map(|&h| shed(h)).collect::<Result<_, _>>()?;
    let errors: Vec<f64> = times.iter().map(|t| (t - reference).abs()).collect();
    let order = ls_order(&steps, &errors);
    let pairs = pair_orders(&steps, &errors);
    let mut otable = Table::new(
        "thermal_deicing_order",
        "De-icing shed time at 1200 A against the step of phase 1 (reference h = 0.5 s)",
        &["step h [s]", "shed time [s]", "error [s]", "pair order"],
    );
    for (k, &h) in steps.iter().enumerate() {
        otable.row(vec![
            format!("{h:.0}"),
            format!("{:.9}", times[k]),
            sci(errors[k]),
            if k == 0 { "-".into() } else { format!("{:.3}", pairs[k - 1]) },
        ]);
    }
    otable.row(vec!["0.5 (reference)".into(), format!("{reference:.9}"), "-".into(), "-".into()]);
    rep.check(
        "de-icing: order of the shed time in the step (h = 40, 20, 10, 5 s vs 0.5 s)",
        "4 +- 0.5 (least squares over the four, and every pair)",
        format!("{order:.3} (pairs {})", pairs.iter().map(|p| format!("{p:.3}")).collect::<Vec<_>>().join(", ")),
        (order - 4.0).abs() <= 0.5 && pairs.iter().all(|p| (p - 4.0).abs() <= 0.5),
    );

    // ---- closed forms ----
    let mut worst_a = 0.0_f64;
    let mut worst_b = 0.0_f64;
    for criterion in [ShedCriterion::Slot, ShedCriterion::FullMelt] {
        let (rc, ro) = (0.5 * drake.diameter_m, 0.5 * drake.diameter_m + 10e-3);
        let m_shed = match criterion {
            ShedCriterion::Slot => m_slot,
            ShedCriterion::FullMelt => 900.0 * std::f64::consts::PI * (ro * ro - rc * rc),
        };
        // (a) air at 0 C: no warming, no loss (T_o = T_a without sun): L_f m_shed / (I^2 R(T_m)).
        let d0 = deicing_case(drake, 10e-3, K, criterion);
        let t0 = d0.run(1200.0, &opts(1.0)).map_err(err)?;
        worst_a = worst_a.max(rel(t0.shed_time_s, 334.0e3 * m_shed / qj_m));
        // (b) air at -10 C, conductor started at 0 C: L_f m_shed / (q_J(T_m) - q(T_m)).
        let db = deicing_case(drake, 10e-3, cold, criterion);
        let o = DeicingOptions { initial_temperature_k: Some(MELTING_POINT_K), ..opts(1.0) };
        let tb = db.run(1200.0, &o).map_err(err)?;
        worst_b = worst_b.max(rel(tb.shed_time_s, 334.0e3 * m_shed / (qj_m - q_m)));
    }
    rep.check(
        "de-icing: air at 0 C, shed time = L_f m_shed / (I^2 R(0 C)) (slot and full melt)",
        "1e-9 relative (no phase 1; q(T_m) <= G 1e-12 K)",
        sci(worst_a),
        worst_a < 1e-9,
    );
    rep.check(
        "de-icing: -10 C air, conductor from 0 C, shed time = L_f m_shed / (q_J - q_loss) (slot and full melt)",
        "1e-9 relative (no phase 1; constant rates)",
        sci(worst_b),
        worst_b < 1e-9,
    );

    // ---- current to shed in 30 min ----
    let o = opts(1.0);
    let target = 1800.0;
    let i30 = base.current_to_shed_in(target, &o).map_err(err)?;
    let t30 = base.run(i30, &o).map_err(err)?.shed_time_s;
    let slope = (base.run(i30 + 10.0, &o).map_err(err)?.shed_time_s
        - base.run(i30 - 10.0, &o).map_err(err)?.shed_time_s)
        / 20.0;
    let window = 1.5 * slope.abs() * o.current_tolerance_a;
    let below = base.run(i30 - o.current_tolerance_a, &o).map_err(err)?.shed_time_s;
    rep.check(
        "de-icing: current_to_shed_in(30 min), and a run at it",
        format!(
            "sheds in [30 min - 1.5 |dt/dI| tol, 30 min] = [{:.6}, 1800] s; at I - tol ({} A) later than 30 min",
            target - window,
            o.current_tolerance_a
        ),
        format!("I = {i30:.4} A sheds at {t30:.6} s; I - tol at {below:.6} s (dt/dI = {slope:.3} s/A)"),
        t30 <= target && target - t30 <= window && below > target,
    );
    let minimum_a = base.minimum_current_a().map_err(err)?;

    // ---- time to shed over thickness, current and criterion ----
    let mut times_t = Table::new(
        "thermal_deicing_times",
        "De-icing time to shed [min] (Drake, IEEE 738, night, -10 C, 2 m/s, glaze; h = 1 s)",
        &["criterion", "ice [mm]", "1000 A", "1200 A", "1500 A"],
    );
    let currents = [1000.0, 1200.0, 1500.0];
    let mut monotone = true;
    let mut slot_times: Vec<Vec<Option<f64>>> = vec![];
    for criterion in [ShedCriterion::Slot, ShedCriterion::FullMelt] {
        let mut previous: Option<Vec<Option<f64>>> = None;
        for (k, mm) in [2.0, 5.0, 10.0, 15.0, 20.0].into_iter().enumerate() {
            let d = deicing_case(drake, mm * 1e-3, cold, criterion);
            let row: Vec<Option<f64>> = currents.iter().map(|&i| d.run(i, &o).ok().map(|r| r.shed_time_s)).collect();
            // More current sheds sooner.
            let known: Vec<f64> = row.iter().flatten().copied().collect();
            monotone &= known.windows(2).all(|w| w[1] < w[0]);
            // Thicker ice sheds later.
            if let Some(prev) = &previous {
                for (a, b) in prev.iter().zip(&row) {
                    if let (Some(a), Some(b)) = (a, b) {
                        monotone &= b > a;
                    }
                }
            }
            // The whole shell takes longer than the slot.
            if criterion == ShedCriterion::FullMelt {
                for (a, b) in slot_times[k].iter().zip(&row) {
                    if let (Some(a), Some(b)) = (a, b) {
                        monotone &= b > a;
                    }
                }
            }
            let cells = row.iter().map(|t| t.map_or("no shedding".into(), |t| format!("{:.2}", t / 60.0)));
            times_t.row([format!("{criterion:?}"), format!("{mm:.0}")].into_iter().chain(cells).collect());
            if criterion == ShedCriterion::Slot {
                slot_times.push(row.clone());
            }
            previous = Some(row);
        }
    }
    rep.check(
        "de-icing: time to shed over 2..20 mm x 1000..1500 A x {slot, full melt}",
        "rises with the thickness, falls with the current, full melt later than the slot",
        if monotone { "all 30 ordered so" } else { "not ordered" },
        monotone,
    );

    // ---- figure ----
    let mut temp_series = vec![];
    let mut melt_series = vec![];
    let rec = DeicingOptions { record_every_s: 10.0, ..opts(1.0) };
    for (color, &i) in currents.iter().enumerate() {
        let res = base.run(i, &rec).map_err(err)?;
        let m = res.shed_mass_kg_per_m;
        let shed_min = res.shed_time_s / 60.0;
        temp_series.push(Series::new(
            format!("{i:.0} A (shed {shed_min:.1} min)"),
            res.series.iter().map(|s| (s.time_s / 60.0, s.conductor_k - K)).collect(),
            Style::Line,
            color,
        ));
        temp_series.push(Series::new("", vec![(shed_min, 0.0)], Style::Markers, color));
        melt_series.push(Series::new(
            format!("{i:.0} A"),
            res.series.iter().map(|s| (s.time_s / 60.0, s.melted_kg_per_m / m)).collect(),
            Style::Line,
            color,
        ));
        melt_series.push(Series::new("", vec![(shed_min, 1.0)], Style::Markers, color));
    }
    let panels = [
        Chart {
            title: "Drake, 10 mm glaze, -10 C, 2 m/s: conductor temperature (dots: shedding)".into(),
            x_label: "time [min]".into(),
            y_label: "conductor temperature [C]".into(),
            series: temp_series,
            ..Default::default()
        },
        Chart {
            title: "melted fraction of the slot mass rho_i D t (dots: shedding)".into(),
            x_label: "time [min]".into(),
            y_label: "melted fraction [-]".into(),
            series: melt_series,
            ..Default::default()
        },
    ];
    rep.figure(
        &panels,
        2,
        (640, 460),
        "thermal: IEEE 738 / CIGRE TB 601 heat balance of ACSR Drake (catalogue data)",
        dir,
        "thermal_deicing",
    )?;

    Ok((
        vec![budget, otable, times_t],
        DeicingSummary { at_1200: r, closure, order, pairs, current_30_min_a: i30, shed_at_it_s: t30, minimum_a },
    ))
}

// ---------------------------------------------------------------------------------------------------------
// Item 5: correlation joins
// ---------------------------------------------------------------------------------------------------------

/// The observed joins: where, and the relative jump \[-\].
type Jumps = Vec<(String, f64)>;

fn joins(rep: &mut StudyReport) -> Result<(Vec<Table>, Jumps), String> {
    let mut table = Table::new(
        "thermal_joins",
        "CIGRE TB 601 Table 4 (Nu_90 = B Re^n) and Table 5 (Nu_nat = A_2 (Gr Pr)^m_2): relative jump where the \
         rows meet (published-table discontinuities, not smoothed)",
        &["table", "boundary", "row below", "row above", "value below", "value above", "jump [%]"],
    );
    let mut observed = vec![];
    let below_eps = 1.0 - 1e-12;
    let forced = [
        (2650.0, 0.04, "stranded R_s <= 0.05"),
        (2650.0, 0.09, "stranded R_s > 0.05"),
        (5.0e3, 0.0, "smooth"),
        (5.0e4, 0.0, "smooth"),
    ];
    let mut rows: Vec<(String, String, tb_conv::PowerLaw, tb_conv::PowerLaw, f64)> = vec![];
    for (re, rs, surface) in forced {
        let below = tb_conv::forced_coefficients(re * below_eps, rs);
        let above = tb_conv::forced_coefficients(re, rs);
        rows.push((format!("Table 4, {surface}"), format!("Re = {re:.0}"), below, above, re));
    }
    for x in [1.0e2, 1.0e4, 1.0e7] {
        let below = tb_conv::natural_coefficients(x * below_eps);
        let above = tb_conv::natural_coefficients(x);
        rows.push(("Table 5".into(), format!("Gr Pr = {x:.0e}"), below, above, x));
    }
    for (tab, boundary, below, above, x) in rows {
        let (vb, va) = (below.eval(x), above.eval(x));
        let jump = va / vb - 1.0;
        table.row(vec![
            tab.clone(),
            boundary.clone(),
            format!("{} x^{}", below.coefficient, below.exponent),
            format!("{} x^{}", above.coefficient, above.exponent),
            format!("{vb:.4}"),
            format!("{va:.4}"),
            format!("{:+.3}", 100.0 * jump),
        ]);
        rep.check(
            format!("{tab}: join at {boundary}"),
            "a row change there, relative jump below 2 % (a published-table discontinuity, stated)",
            format!("{:+.3} %", 100.0 * jump),
            below != above && jump.abs() < 0.02,
        );
        observed.push((format!("{tab} at {boundary}"), jump));
    }

    // ---- IEEE 738: the larger of the forced correlations, natural convection when larger ----
    let d = 28.14e-3;
    let (t_s, t_a) = (K + 100.0, K + 40.0);
    let conv = |v: f64| ieee_conv::Convection::new(d, t_s, t_a, 0.0, v, 90.0);
    let air = Air::at(t_s, t_a, 0.0);
    let speed_of = |re: f64| re * air.dynamic_viscosity_kg_per_m_s / (air.density_kg_per_m3 * d);
    // Crossing of eqs. (3a) and (3b) in N_Re (independent of the conductor and the air).
    let gap = |n: f64| {
        ieee_conv::forced_low_wind_w_per_m(1.0, n, 1.0, 1.0) - ieee_conv::forced_high_wind_w_per_m(1.0, n, 1.0, 1.0)
    };
    let re_cross = bisect(gap, 100.0, 1e5);
    let v_cross = speed_of(re_cross);
    // Crossing of forced and natural convection in the wind speed (Annex B conditions).
    let v_nat = bisect(|v| conv(v).forced_w_per_m() - conv(v).natural_w_per_m, 0.0, 2.0);
    let mut ieee = Table::new(
        "thermal_ieee_convection",
        "IEEE 738 convection of Drake at 100 C in 40 C air (Annex B), wind perpendicular: the rate used is the \
         largest of q_c1 (3a), q_c2 (3b), q_cn (5a)",
        &["wind [m/s]", "N_Re", "q_c1 [W/m]", "q_c2 [W/m]", "q_cn [W/m]", "q_c used [W/m]", "used"],
    );
    let mut speeds = vec![0.0, 0.05, 0.1, 0.15, v_nat, 0.2, 0.3, 0.5, 0.61, 1.0, v_cross, 1.5, 2.0, 3.0, 5.0, 10.0];
    speeds.sort_by(f64::total_cmp);
    let mut all_max = true;
    let mut natural_below = true;
    for &v in &speeds {
        let c = conv(v);
        let (q1, q2, qn) = (c.forced_low_wind_w_per_m, c.forced_high_wind_w_per_m, c.natural_w_per_m);
        let used = c.w_per_m();
        all_max &= used == q1.max(q2).max(qn);
        if v < v_nat {
            natural_below &= used == qn;
        }
        let which = if used == qn {
            "natural (5a)"
        } else if used == q1 {
            "low wind (3a)"
        } else {
            "high wind (3b)"
        };
        ieee.row(vec![
            format!("{v:.4}"),
            format!("{:.2}", ieee_conv::reynolds_number(d, v, &air)),
            format!("{q1:.4}"),
            format!("{q2:.4}"),
            format!("{qn:.4}"),
            format!("{used:.4}"),
            which.into(),
        ]);
    }
    rep.check(
        "IEEE 738: q_c is the largest of q_c1, q_c2, q_cn over winds 0..10 m/s",
        "equal (==) at every wind speed; natural convection below the forced/natural crossing",
        format!(
            "{} speeds; natural used below {v_nat:.4} m/s: {}",
            speeds.len(),
            if natural_below { "yes" } else { "no" }
        ),
        all_max && natural_below,
    );
    let jump_at = |v: f64| {
        let (lo, hi) = (conv(v * (1.0 - 1e-9)).w_per_m(), conv(v * (1.0 + 1e-9)).w_per_m());
        (hi - lo).abs() / hi
    };
    let (j_cross, j_nat) = (jump_at(v_cross), jump_at(v_nat));
    rep.check(
        "IEEE 738: eqs. (3a) and (3b) cross at the N_Re stated in the module doc, q_c continuous there",
        "N_Re = 1757.25 +- 0.005 (six digits); relative change of q_c over +-1e-9 of the speed < 1e-6",
        format!("N_Re = {re_cross:.4} (wind {v_cross:.4} m/s), change {}", sci(j_cross)),
        (re_cross - 1757.25).abs() <= 0.005 && j_cross < 1e-6,
    );
    rep.check(
        "IEEE 738: forced and natural convection cross continuously",
        "relative change of q_c over +-1e-9 of the speed < 1e-6",
        format!("at {v_nat:.4} m/s (N_Re {:.1}), change {}", ieee_conv::reynolds_number(d, v_nat, &air), sci(j_nat)),
        j_nat < 1e-6,
    );
    Ok((vec![table, ieee], observed))
}

// ---------------------------------------------------------------------------------------------------------
// The study
// ---------------------------------------------------------------------------------------------------------

/// Run the study. It is cheap (about a second), so both budgets do the same work.
pub fn run(_budget: Budget, dir: &Path) -> Result<StudyReport, String> {
    let mut rep = StudyReport {
        title: "Thermal: IEEE 738 / CIGRE TB 601 heat balance, steady, transient and de-icing solvers".into(),
        summary: "The conductor heat balance of `ohl::thermal` against the standards' worked examples (IEEE Std \
                  738-2012 Annex B, Drake at 100 C; CIGRE TB 601 Annex E Examples A and B; TB 601's transient \
                  example), term by term next to the printed numbers with tolerances derived from the printed \
                  digits and the standards' rounded intermediates. Then the solvers against exact properties: \
                  steady ampacity and temperature as inverses (both standards, 50 ... 150 C); the transient's RK4 \
                  order on a current step, its limit and `time_to_reach` (Drake, 400 A -> 1200 A); de-icing of \
                  10 mm of glaze at -10 C (energy closure, order in the step, closed forms, the current that sheds \
                  in 30 min, a table over thickness, current and shedding criterion); and the joins of TB 601's \
                  Tables 4 and 5 and IEEE 738's choice among its convection correlations."
            .into(),
        ..Default::default()
    };
    let drake = catalogue_drake()?;
    let annex = annex_b::drake();
    let same = drake.diameter_m == annex.diameter_m
        && drake.resistance_low_ohm_per_m == annex.resistance_low_ohm_per_m
        && drake.resistance_high_ohm_per_m == annex.resistance_high_ohm_per_m
        && drake.temperature_low_k == annex.temperature_low_k
        && drake.temperature_high_k == annex.temperature_high_k
        && (drake.emissivity, drake.absorptivity) == (annex.emissivity, annex.absorptivity);
    rep.check(
        "catalogue Drake carries IEEE 738 Annex B's data (D, R(25 C), R(75 C), emissivity, absorptivity)",
        "exactly equal",
        format!(
            "D {} m, R {:e} / {:e} ohm/m, eps {}, alpha {}",
            drake.diameter_m,
            drake.resistance_low_ohm_per_m,
            drake.resistance_high_ohm_per_m,
            drake.emissivity,
            drake.absorptivity
        ),
        same,
    );

    let (worked, track, w) = worked_examples(&mut rep)?;
    let (steady_t, steady_worst, refusals) = steady_inverse(&mut rep)?;
    let (order_t, tr) = transient(&mut rep, dir, &drake)?;
    let (deice_t, de) = deicing(&mut rep, dir, &drake)?;
    let (join_t, jumps) = joins(&mut rep)?;
    rep.tables.extend([worked, track, steady_t, order_t]);
    rep.tables.extend(deice_t);
    rep.tables.extend(join_t);

    let largest_jump = jumps.iter().map(|(_, j)| j.abs()).fold(0.0, f64::max);
    let refused = if refusals.is_empty() {
        "no case was refused".to_string()
    } else {
        format!(
            "where the sun alone outweighs the cooling at T_max ({}) the library refuses with `SunAlone`, as it \
             must (checked against the terms)",
            refusals.join(", ")
        )
    };
    let without_gap = if (w.ieee_ampacity_a - 1025.0).abs() <= w.ieee_ampacity_tol_without_gap_a {
        "it passes without the gap too"
    } else {
        "it passes only with the gap"
    };
    let faster_rk4 = if w.tracking_rise_k[1][1] > w.tracking_rise_k[1][0] { "more slowly" } else { "faster" };
    let jump_list = jumps.iter().map(|(w, j)| format!("{w}: {:+.2} %", 100.0 * j)).collect::<Vec<_>>().join("; ");
    let e = de.at_1200.energy;
    rep.discussion = format!(
        "**Reproduced.** IEEE 738 Annex B: N_Re, q_c2, q_cn, q_r, q_s, R(100 C) within the printed digits and the \
         rounding of the annex's intermediates; the ampacity is {:.2} A against the printed 1025 A (tolerance \
         {:.2} A including the 0.25 % q_c1 gap, {:.2} A without it: {without_gap}). TB 601 Examples A and B: \
         every term and the ratings, {:.2} A (976 A) and {:.2} A (1504 A). TB 601's transient example starts at \
         {:.4} C with the brochure's +273 in the radiation and {:.4} C with the exact kelvin (printed 42.01 C). \
         Its printed tracking is forward Euler with 60 s steps from the printed 42.01 C with +273 in eq. (27): \
         integrated that way our terms give every printed minute within {:.4} K ({} of 20 to the digit). The \
         accurate integral (RK4, 1 s) rises {faster_rk4}: {:.4} K below the printed series at worst in stage 1 \
         (rise {:.3} K against the printed {:.3} K) and {:.4} K in stage 2 (rise {:.3} K against {:.3} K), \
         {:.1} % of the stage-2 rise; this is forward Euler's error at 60 s steps, the RK4 run being accurate \
         (halving its step from 2 s to 1 s changes the temperatures by {} K at most). The bounds 0.045 K and \
         0.235 K pin that difference.\n\n\
         **Not reproduced.** IEEE 738 Annex B's q_c1 = 81.93 W/m: ours is {:.3} W/m, and eq. (3a) at the \
         annex's own printed N_Re = 865 and k_f = 0.02945 gives {:.3} W/m; no rounding of those reaches 81.93, so \
         the printed value is {:.2} % below its own equation (a known discrepancy that other implementations meet \
         too). Only our q_c1 against eq. (3a) at the printed intermediates is checked.\n\n\
         **Solvers.** Steady: ampacity and temperature invert each other to {} K at worst, the net heat vanishes at \
         both; {refused}. Transient (catalogue Drake, Annex B weather, 400 A -> 1200 A: {:.2} C -> \
         {:.2} C, time constant {:.1} min): RK4 order {:.3} (pairs {}), at the steady state after 30 time \
         constants, `time_to_reach` for 90 % of the rise {:.1} s after the step, where the fine run is {} K from \
         the limit. De-icing (10 mm glaze, -10 C, 2 m/s, slot): 1200 A warms the conductor to 0 C in {:.1} s and \
         sheds at {:.1} s ({:.1} min); the budget (Joule {} J/m = sensible {} + latent {} + losses {}) closes to \
         {} of the Joule energy; the shed time converges at order {:.3} (pairs {}); {:.3} A sheds in 30 min \
         (at {:.3} s), and nothing below {:.1} A melts at all.\n\n\
         **Correlations.** TB 601's tables are separate fits whose rows do not meet exactly: {jump_list}. The largest is \
         {:.2} %, so the cooling steps by that much as Re or Gr Pr crosses a boundary (a steady or transient \
         solve across one sees a step in N(T): the bracketed root finder keeps a sign change across it, and a root \
         that falls on the step is the step itself, to 1e-9 K). IEEE 738's rate is \
         continuous: the maximum of continuous correlations.\n\n\
         The study does the same work at both budgets (it is cheap).",
        w.ieee_ampacity_a,
        w.ieee_ampacity_tol_a,
        w.ieee_ampacity_tol_without_gap_a,
        w.a_ampacity_a,
        w.b_ampacity_a,
        w.tb601_start_plus273_c,
        w.tb601_start_c,
        w.tracking_euler_worst_k,
        w.tracking_euler_same_digits,
        w.tracking_worst_k[0],
        w.tracking_rise_k[0][0],
        w.tracking_rise_k[0][1],
        w.tracking_worst_k[1],
        w.tracking_rise_k[1][0],
        w.tracking_rise_k[1][1],
        100.0 * (1.0 - w.tracking_rise_k[1][0] / w.tracking_rise_k[1][1]).abs(),
        sci(w.tracking_step_effect_k),
        w.q_c1,
        w.q_c1_eq3a_printed_inputs,
        100.0 * (1.0 - 81.93 / w.q_c1_eq3a_printed_inputs),
        sci(steady_worst),
        tr.t0_k - K,
        tr.t_ss_k - K,
        tr.tau_s / 60.0,
        tr.order,
        tr.pairs.iter().map(|p| format!("{p:.3}")).collect::<Vec<_>>().join(", "),
        tr.reach_s,
        sci(tr.limit_error_k),
        de.at_1200.warm_time_s,
        de.at_1200.shed_time_s,
        de.at_1200.shed_time_s / 60.0,
        sci(e.joule_j_per_m),
        sci(e.sensible_j_per_m),
        sci(e.latent_j_per_m),
        sci(e.losses_j_per_m),
        sci(de.closure),
        de.order,
        de.pairs.iter().map(|p| format!("{p:.3}")).collect::<Vec<_>>().join(", "),
        de.current_30_min_a,
        de.shed_at_it_s,
        de.minimum_a,
        100.0 * largest_jump,
    );
    Ok(rep)
}

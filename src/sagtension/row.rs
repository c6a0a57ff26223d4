//! One row of a sag-tension table: a weather condition in a state, and what a line designer reads off.
//!
//! Conventions: the sag is the distance from the chord to the conductor measured against the load
//! (vertically without wind, in the swung plane with it); `sag_midspan_m` at the horizontal mid-point
//! of the span `x = l / 2` (the usual table sag; for a level span also the largest), `sag_max_m` where
//! the conductor is parallel to the chord. Component forces are at the support with the larger
//! tension (the most strained point) and, as OTLS-Models reports them, averaged over the unstressed
//! length. The knee is passed when the outer layers carry nothing at that support, so nowhere in the
//! span: the whole span then hangs on the core.

use super::catenary::{SpanLaw, SpanSolution};
use super::{Problem, SagTensionError, State, Weather};

/// One row of a sag-tension table (module doc).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Row {
    /// the weather condition
    pub weather: Weather,
    /// the state asked for
    pub state: State,
    /// the state whose history was used (FINAL: the governing one)
    pub history_of: State,
    /// resultant load per unit length `w` [N/m]
    pub load_n_per_m: f64,
    /// horizontal tension `H` [N]
    pub horizontal_tension_n: f64,
    /// tension at support A [N]
    pub support_tension_a_n: f64,
    /// tension at support B [N]
    pub support_tension_b_n: f64,
    /// tension averaged over the unstressed length [N] (what SAG10-type programs strain the conductor at)
    pub tension_mean_n: f64,
    /// the larger support tension as a fraction of the rated tensile strength [-]
    pub max_tension_fraction_rts: f64,
    /// sag below the chord at mid-span `x = l / 2` [m] (module doc)
    pub sag_midspan_m: f64,
    /// largest sag below the chord [m]
    pub sag_max_m: f64,
    /// conductor length between the supports [m]
    pub length_m: f64,
    /// unstressed length at the reference temperature `L0` [m]
    pub unstressed_length_m: f64,
    /// conductor strain at the more tensioned support [-]
    pub strain_max: f64,
    /// force in the outer layers at the more tensioned support [N]
    pub outer_force_n: f64,
    /// force in the core there [N] (0 without a core)
    pub core_force_n: f64,
    /// outer layers' force averaged over the length [N]
    pub outer_force_mean_n: f64,
    /// core force averaged over the length [N]
    pub core_force_mean_n: f64,
    /// outer stress on the outer layers' own area at the more tensioned support [Pa]
    pub outer_stress_pa: f64,
    /// core stress on the core's own area there [Pa] (0 without a core)
    pub core_stress_pa: f64,
    /// outer force over the whole conductor's area (the published stress-strain form) [Pa]
    pub outer_stress_total_area_pa: f64,
    /// core force over the whole conductor's area [Pa]
    pub core_stress_total_area_pa: f64,
    /// whether the knee is passed: the outer layers carry no tension anywhere in the span
    pub knee_passed: bool,
}

impl Row {
    pub(crate) fn new(
        p: &Problem,
        weather: &Weather,
        state: State,
        history_of: State,
        span: &SpanLaw<'_>,
        sol: &SpanSolution,
    ) -> Result<Row, SagTensionError> {
        let hv = sol.hv();
        let l0 = span.unstressed_length_m;
        let ta = span.tension_at(0.0, hv);
        let tb = span.tension_at(l0, hv);
        let t_max = ta.max(tb);
        let e = span.strain(t_max)?;
        let law = &p.conductor.law;
        // `+ 0.0`: a slack component's `0 * (e - e_p)` is -0.0; tables print 0
        let f = law.forces(e, weather.temperature_k, &span.history).map(|x| x + 0.0);
        let (means, length) = span.means(hv)?;
        let a_o = law.outer.area_m2;
        let a_c = law.core.map_or(0.0, |c| c.area_m2);
        let total = a_o + a_c;
        Ok(Row {
            weather: *weather,
            state,
            history_of,
            load_n_per_m: span.load_n_per_m,
            horizontal_tension_n: hv[0],
            support_tension_a_n: ta,
            support_tension_b_n: tb,
            tension_mean_n: means[0],
            max_tension_fraction_rts: t_max / p.conductor.rated_tensile_strength_n,
            sag_midspan_m: span.sag_at_x(0.5 * span.span_m, hv)?,
            sag_max_m: span.max_sag(hv)?,
            length_m: length,
            unstressed_length_m: l0,
            strain_max: e,
            outer_force_n: f[0],
            core_force_n: f[1],
            outer_force_mean_n: means[1] + 0.0,
            core_force_mean_n: means[2] + 0.0,
            outer_stress_pa: f[0] / a_o,
            core_stress_pa: if a_c > 0.0 { f[1] / a_c } else { 0.0 },
            outer_stress_total_area_pa: f[0] / total,
            core_stress_total_area_pa: f[1] / total,
            knee_passed: law.core.is_some() && e <= law.outer_slack_strain(weather.temperature_k, &span.history),
        })
    }
}

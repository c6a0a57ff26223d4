//! A heat-conduction case file: the insulated rod of the paper's test 5.4 (two halves at different
//! temperatures) run with one or more boundary closures of section 5.3, and the thermal expansion
//! (5.5)-(5.6) of the equalised wire. It is a paper case ([`crate::paper`]) without a wire: the file has a
//! `[rod]` section instead of `[conductor]`, and `ohl paper <case>` recognises it by that section.
//!
//! ```toml
//! name = "heat_two_halves"
//! description = "Paper 5.4: equalisation of an insulated wire's hot and cold halves"
//!
//! [rod]
//! segments = 50
//! left_temperature_k = 473.15        # 200 C
//! right_temperature_k = 268.15       # -5 C
//! temperature_scale_k = 273.15       # the paper's u = T / 273.15 K
//!
//! [material]                          # aluminium of section 5.4
//! span_m = 160.0
//! thermal_conductivity_w_per_m_k = 209.0
//! density_kg_per_m3 = 2700.0
//! specific_heat_j_per_kg_k = 900.0
//! thermal_expansion_per_k = 23.8e-6
//! youngs_modulus_pa = 6.25e10
//! diameter_m = 0.0147
//! reference_temperature_k = 268.15    # stress-free temperature (the ambient -5 C)
//!
//! [stop]
//! spread = 1e-6                       # equalised: max - min of u below this [-]
//! max_time = 10.0                     # dimensionless time cap
//!
//! [[runs]]
//! label = "zero flux, r = 1/2"
//! boundary = "zero_flux"
//! step_ratio = 0.5                    # r = tau / h^2 of (5.2)
//!
//! [paper]
//! section = "5.4"
//! title = "..."
//!
//! [[paper.checks]]
//! quantity = "equalisation temperature, zero flux"
//! paper = 1.35695
//! unit = "one"
//! source = "section 5.4: exact value 1.35695"
//! extract = { kind = "equalised_temperature", run = "zero flux, r = 1/2" }
//! reference = "exact_equalisation"
//! tolerance = 7.4e-5
//! justification = "..."
//! ```

use serde::Deserialize;

use ohl::scenario::validate::number;
use ohl::scenario::validate::{Check, Problem};
use ohl::scenario::work::{BUDGET_NODE_STEPS, BUDGET_WALL_S};
use ohl::scenario::{InputError, from_toml};

use super::spec::{CheckSpec, check_row};
use ohl::heat::HeatBoundary;

/// A heat case file.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HeatCase {
    /// short name
    pub name: String,
    /// one line describing the case
    #[serde(default)]
    pub description: String,
    /// the rod and its initial temperatures
    pub rod: RodSpec,
    /// material data: the time scale of conduction and the expansion (5.5)-(5.6)
    pub material: MaterialSpec,
    /// when a run counts as equalised or diverged
    pub stop: StopSpec,
    /// the runs, one per boundary closure and step ratio
    pub runs: Vec<RunSpec>,
    /// dimensionless times at which the profiles `u(s)` are recorded for the figure; default
    /// `[0, 0.002, 0.01, 0.04, 0.15]`
    #[serde(default = "default_profile_times")]
    pub profile_times: Vec<f64>,
    /// the paper's values checked, and the figure
    pub paper: HeatPaperSpec,
}

fn default_profile_times() -> Vec<f64> {
    vec![0.0, 0.002, 0.01, 0.04, 0.15]
}

/// The rod: its grid and the two halves' temperatures.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RodSpec {
    /// number of segments `N` [-], even (a node at mid-span takes the mean of the halves)
    pub segments: usize,
    /// initial temperature of the left half `T_L` [K], in (0, 1e4]
    pub left_temperature_k: f64,
    /// initial temperature of the right half `T_R` [K], in (0, 1e4]
    pub right_temperature_k: f64,
    /// temperature scale of the paper's dimensionless `u = T / T_s` [K], in [1, 1e4] (273.15 K in section
    /// 5.4)
    pub temperature_scale_k: f64,
}

/// Material data of the wire.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialSpec {
    /// span `l` [m]: the length scale of the dimensionless coordinate `s = x / l`
    pub span_m: f64,
    /// thermal conductivity `k` [W/(m K)]
    pub thermal_conductivity_w_per_m_k: f64,
    /// density of the wire material `rho` [kg/m^3]
    pub density_kg_per_m3: f64,
    /// specific heat `c` [J/(kg K)]
    pub specific_heat_j_per_kg_k: f64,
    /// coefficient of linear thermal expansion `alpha_t` [1/K]
    pub thermal_expansion_per_k: f64,
    /// Young's modulus `E` [Pa]
    pub youngs_modulus_pa: f64,
    /// wire diameter `d` [m]
    pub diameter_m: f64,
    /// stress-free temperature: the rise `du` of (5.5) is counted from it [K]
    pub reference_temperature_k: f64,
}

/// Stopping rule of each run.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StopSpec {
    /// a run has equalised when the spread `max u - min u` of the nodal temperatures is below this [-]
    /// (dimensionless `u`; the paper does not state its criterion)
    pub spread: f64,
    /// dimensionless time cap `t_max` [-]
    pub max_time: f64,
    /// a run has diverged when the spread exceeds this [-]; default 10 (the initial spread is 0.75)
    #[serde(default = "default_divergence")]
    pub divergence_spread: f64,
}

fn default_divergence() -> f64 {
    10.0
}

/// Boundary closure of a run (see [`ohl::heat::boundary`]).
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum BoundarySpec {
    /// conservative ghost-node zero flux
    ZeroFlux,
    /// option 1 of section 5.3 (three-point Lagrange polynomial), re-derived
    LagrangeQuadratic,
    /// option 2 of section 5.3, (5.4) with its coefficient 1 + 2r corrected to 1 + r
    Linear,
    /// (5.3) exactly as printed
    LagrangeQuadraticAsPrinted,
    /// (5.4) exactly as printed
    LinearAsPrinted,
}

impl BoundarySpec {
    /// The solver's closure.
    pub fn closure(self) -> HeatBoundary {
        match self {
            BoundarySpec::ZeroFlux => HeatBoundary::ZeroFlux,
            BoundarySpec::LagrangeQuadratic => HeatBoundary::LagrangeQuadratic,
            BoundarySpec::Linear => HeatBoundary::Linear,
            BoundarySpec::LagrangeQuadraticAsPrinted => HeatBoundary::LagrangeQuadraticAsPrinted,
            BoundarySpec::LinearAsPrinted => HeatBoundary::LinearAsPrinted,
        }
    }
}

/// One run of the rod.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RunSpec {
    /// name of the run (checks and figure refer to it)
    pub label: String,
    /// closure at both ends
    pub boundary: BoundarySpec,
    /// `r = tau / h^2` of (5.2) [-], in (0, 1/2] (the paper's `tau = alpha h^2 / 2`, `r = alpha / 2`)
    pub step_ratio: f64,
}

/// What is extracted from a run.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum HeatExtractKind {
    /// mean nodal temperature when the run has equalised [-] (dimensionless `u`)
    EqualisedTemperature,
    /// dimensionless time at which it equalised [-]
    EqualisationTime,
    /// dimensionless time at which it diverged [-]
    DivergenceTime,
    /// thermal strain (5.5) of the equalised wire, `alpha_t (T_eq - T_ref)` [-]
    ThermalStrain,
    /// force (5.6) of the equalised wire held at its length, `E eps_t pi d^2 / 4` [N]
    ThermalForce,
}

/// How to extract a computed value.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HeatExtractSpec {
    /// the extractor
    pub kind: HeatExtractKind,
    /// label of the run it is taken from
    pub run: String,
}

/// Independent references.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum HeatReferenceKind {
    /// the exact equalisation temperature, the mean `(u_L + u_R) / 2` (conservation of heat) [-]
    ExactEqualisation,
    /// the time at which the exact solution's spread falls below `stop.spread`: the slowest Fourier
    /// mode `a_1 cos(pi s) e^{-pi^2 t}` spans `2 |a_1| e^{-pi^2 t}` [-]
    SlowestModeTime,
    /// (5.5) with the exact equalisation temperature [-]
    ThermalStrain,
    /// (5.6) with the exact equalisation temperature [N]
    ThermalForce,
}

/// One checked value of a heat case.
pub type HeatCheckSpec = CheckSpec<HeatExtractSpec, HeatReferenceKind>;

/// The `[paper]` section of a heat case.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct HeatPaperSpec {
    /// section of the paper
    pub section: String,
    /// figure title
    pub title: String,
    /// notes printed under the case
    #[serde(default)]
    pub notes: Vec<String>,
    /// the checked values
    #[serde(default)]
    pub checks: Vec<HeatCheckSpec>,
    /// label of the run whose profiles the figure compares with the exact solution
    pub profile_run: String,
}

/// All problems of a heat case; empty when it is valid.
pub fn validate(h: &HeatCase) -> Vec<Problem> {
    let mut c = Check::default();
    let r = &h.rod;
    if r.segments < 2 || !r.segments.is_multiple_of(2) || r.segments > 100_000 {
        c.fail("rod.segments", r.segments, "must be an even number in [2, 100000] (a node at mid-span)");
    }
    let temperature = "must be a finite number > 0, at most 1e4 K";
    c.within("rod.left_temperature_k", r.left_temperature_k, f64::MIN_POSITIVE, 1.0e4, temperature);
    c.within("rod.right_temperature_k", r.right_temperature_k, f64::MIN_POSITIVE, 1.0e4, temperature);
    // u = T / T_s must stay a modest number: a tiny scale overflows it to infinity.
    c.within(
        "rod.temperature_scale_k",
        r.temperature_scale_k,
        1.0,
        1.0e4,
        "must be in [1, 1e4] K (the paper's u = T / 273.15 K; a tiny scale makes u = T / T_s overflow)",
    );
    let m = &h.material;
    c.positive("material.span_m", m.span_m);
    c.positive("material.thermal_conductivity_w_per_m_k", m.thermal_conductivity_w_per_m_k);
    c.positive("material.density_kg_per_m3", m.density_kg_per_m3);
    c.positive("material.specific_heat_j_per_kg_k", m.specific_heat_j_per_kg_k);
    c.within(
        "material.thermal_expansion_per_k",
        m.thermal_expansion_per_k,
        0.0,
        1e-3,
        "must be in [0, 1e-3] 1/K (metals: 1e-5 to 3e-5)",
    );
    c.positive("material.youngs_modulus_pa", m.youngs_modulus_pa);
    c.positive("material.diameter_m", m.diameter_m);
    c.positive("material.reference_temperature_k", m.reference_temperature_k);
    c.within("stop.spread", h.stop.spread, 1e-14, 1.0, "must be in [1e-14, 1] (dimensionless temperature)");
    c.within("stop.max_time", h.stop.max_time, 1e-6, 100.0, "must be in [1e-6, 100] (dimensionless time)");
    c.within(
        "stop.divergence_spread",
        h.stop.divergence_spread,
        1.0,
        1e6,
        "must be in [1, 1e6] (dimensionless temperature)",
    );
    if h.runs.is_empty() {
        c.fail("runs", "[]", "at least one [[runs]] entry");
    }
    // The least step ratio within the work budget; above 1/2 no run fits, whatever its ratio.
    let n = r.segments as f64;
    let least_ratio = (n + 1.0) * h.stop.max_time * n * n / BUDGET_NODE_STEPS;
    if least_ratio > 0.5 && least_ratio.is_finite() {
        c.fail(
            "rod.segments",
            r.segments,
            &format!(
                "with stop.max_time = {} a run takes at least {:.3e} node updates even at the largest step ratio \
                 1/2 ((N + 1) stop.max_time N^2 / r), above the budget of {BUDGET_NODE_STEPS:.1e} (about \
                 {BUDGET_WALL_S:.0} s): lower rod.segments (the paper's test uses 50) or stop.max_time",
                number(h.stop.max_time),
                2.0 * least_ratio * BUDGET_NODE_STEPS
            ),
        );
    }
    for (k, run) in h.runs.iter().enumerate() {
        c.within(
            &format!("runs[{k}].step_ratio"),
            run.step_ratio,
            f64::MIN_POSITIVE,
            0.5,
            "must be in (0, 1/2]: (5.2) is stable for r = tau / h^2 <= 1/2",
        );
        // The work of the run: (N + 1) nodes over max_time / tau steps of tau = r h^2, h = 1 / N (it may stop
        // earlier, when equalised); the same budget as a wire run (`ohl::scenario::work`).
        let updates = (n + 1.0) * (h.stop.max_time * n * n / run.step_ratio).ceil();
        if least_ratio <= 0.5 && run.step_ratio > 0.0 && !(updates <= BUDGET_NODE_STEPS) {
            c.fail(
                &format!("runs[{k}].step_ratio"),
                number(run.step_ratio),
                &format!(
                    "the run would take up to {updates:.3e} node updates ((N + 1) stop.max_time N^2 / r with \
                     rod.segments N = {} and stop.max_time = {}), above the budget of {BUDGET_NODE_STEPS:.1e} \
                     (about {BUDGET_WALL_S:.0} s): raise it to at least {} (at most 1/2), or lower rod.segments \
                     or stop.max_time",
                    r.segments,
                    number(h.stop.max_time),
                    number(least_ratio)
                ),
            );
        }
        if h.runs[..k].iter().any(|o| o.label == run.label) {
            c.fail(&format!("runs[{k}].label"), format!("{:?}", run.label), "labels must be unique");
        }
    }
    for (k, t) in h.profile_times.iter().enumerate() {
        c.within(&format!("profile_times[{k}]"), *t, 0.0, h.stop.max_time, "must be in [0, stop.max_time]");
    }
    let known = |label: &str| h.runs.iter().any(|r| r.label == label);
    let labels = || h.runs.iter().map(|r| format!("{:?}", r.label)).collect::<Vec<_>>().join(", ");
    if !known(&h.paper.profile_run) {
        c.fail("paper.profile_run", format!("{:?}", h.paper.profile_run), &format!("must be one of {}", labels()));
    }
    for (k, ch) in h.paper.checks.iter().enumerate() {
        let f = |name: &str| format!("paper.checks[{k}].{name}");
        check_row(&mut c, &f, ch.paper, ch.reference.is_some(), ch.compare, ch.tolerance);
        if !known(&ch.extract.run) {
            c.fail(&f("extract.run"), format!("{:?}", ch.extract.run), &format!("must be one of {}", labels()));
        }
    }
    c.0
}

/// Parse and validate a heat case from TOML text; `file` names it in messages.
pub fn parse(text: &str, file: &str) -> Result<HeatCase, InputError> {
    let case: HeatCase = from_toml(text, file)?;
    let problems = validate(&case);
    if problems.is_empty() { Ok(case) } else { Err(InputError::Invalid { file: file.to_string(), problems }) }
}

/// Whether TOML text is a heat case (it has a top-level `[rod]` table) rather than a wire scenario.
/// Text that does not parse as TOML is not a heat case (the wire parser then reports the syntax error).
pub fn is_heat_case(text: &str) -> bool {
    toml::from_str::<toml::Table>(text).is_ok_and(|t| t.contains_key("rod"))
}

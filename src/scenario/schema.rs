//! The scenario file: a TOML document in SI units, read with serde (`deny_unknown_fields` everywhere, so a
//! misspelt key is an error, not a silently ignored value). Every field names its unit and symbol.
//! Defaults cite their source. A scenario is data; [`super::validate`] checks it before anything runs and
//! [`super::build`] turns it into a solver.

use serde::{Deserialize, Deserializer};

pub use super::events::{EventSpec, GateSpec, GroundSpec, HeatBoundarySpec};

/// A complete scenario.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Scenario {
    /// short name of the case (free text)
    #[serde(default)]
    pub name: Option<String>,
    /// what the case is and where it comes from (free text)
    #[serde(default)]
    pub description: Option<String>,
    /// the conductor's material and section
    pub conductor: ConductorSpec,
    /// supports and discretisation of a single span (give exactly one of `[geometry]` and `[section]`)
    #[serde(default)]
    pub geometry: Option<GeometrySpec>,
    /// a line section: several spans on suspension insulator strings between two dead-ends
    #[serde(default)]
    pub section: Option<SectionSpec>,
    /// initial shape (at rest)
    #[serde(default)]
    pub initial: InitialSpec,
    /// gravity, uniform loads and wind
    #[serde(default)]
    pub loads: LoadsSpec,
    /// time step, smoothing and damping
    #[serde(default)]
    pub numerics: NumericsSpec,
    /// when the run ends
    pub duration: DurationSpec,
    /// what is written
    #[serde(default)]
    pub output: OutputSpec,
    /// ground plane, if any (section 4.4)
    #[serde(default)]
    pub ground: Option<GroundSpec>,
    /// the event timeline (breaks, ice, wind and gusts, temperature, heat conduction, ground contact)
    #[serde(default)]
    pub events: Vec<EventSpec>,
    /// the conductor's temperature from its current and the weather (IEEE 738 / CIGRE TB 601), and an
    /// optional de-icing ([`super::thermal`])
    #[serde(default)]
    pub thermal: Option<super::thermal::ThermalSpec>,
    /// a thermal rating by clearance or sag (`ohl rating`; ignored by `ohl run`, but validated)
    #[serde(default)]
    pub rating: Option<super::rating::RatingSpec>,
    /// the `[paper]` table of a case of `paper_cases/`: checks read by the paper tool (`ohl paper`, in the
    /// `ohl-app` crate); ignored by the library, which does not know its schema
    #[serde(default)]
    pub paper: Option<toml::Value>,
    /// the temperature fields the file gave in degrees Celsius (set by [`super::parse`], not a key of the
    /// file): the problems about them are written in Celsius ([`super::temperature`])
    #[serde(skip)]
    pub celsius: super::temperature::Celsius,
}

/// Constitutive law selector.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum TensionLawSpec {
    /// `T = max(EA e + eta de/dt, 0)` for `e > 0`, else 0 (a conductor cannot be compressed; default)
    #[default]
    TensionOnly,
    /// `T = EA e + eta de/dt`, compression allowed (analytic tests)
    Linear,
    /// the two-material law of the catalogue conductor `conductor.catalog` (aluminium on a steel core,
    /// each material's stress-strain polynomial, permanent set, own thermal strain: the knee point;
    /// [`crate::wire::material`]), with `eta de/dt` clamped like the tension-only law
    TwoMaterial,
}

/// The curve a two-material conductor's materials follow when loaded beyond their history.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum CurveSpec {
    /// the virgin curve: the conductor as strung (default)
    Initial,
    /// the curve after long-term creep (the published 10-year creep curve)
    Creep,
}

/// The conductor. Give the axial stiffness either directly (`axial_stiffness_n`) or as Young's modulus
/// and diameter (`youngs_modulus_pa` with `diameter_m`, `EA = E pi d^2 / 4`).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ConductorSpec {
    /// a conductor of the catalogue (`data/conductors.toml`, e.g. "ACSR Drake"): the fields below that the
    /// table does not give are taken from it (linear density, diameter, RTS, thermal expansion, and `EA`
    /// unless `youngs_modulus_pa` is given); fields given here win
    #[serde(default)]
    pub catalog: Option<String>,
    /// axial stiffness `EA` [N], in [1, 1e10] (section 4: "E = 80734 g [N]" = 7.9e5 N is this force;
    /// conductors are 1e6 to 1e9 N)
    #[serde(default)]
    pub axial_stiffness_n: Option<f64>,
    /// Young's modulus `E` [Pa], in [1e6, 1e12] (section 5: 6.25e10 Pa for aluminium; steel 2e11);
    /// needs `diameter_m`
    #[serde(default)]
    pub youngs_modulus_pa: Option<f64>,
    /// conductor diameter `d` [m], in [1e-4, 1] (conductors are 5 to 50 mm): the aerodynamic law (2.5)
    /// and `EA` from `E`
    #[serde(default)]
    pub diameter_m: Option<f64>,
    /// rated tensile strength (RTS) [N], in (0, 1e7] (ACSR Drake: about 140 kN): the reference of a
    /// section strung at a fraction of it (`section.tension_fraction_of_rts`)
    #[serde(default)]
    pub rated_tensile_strength_n: Option<f64>,
    /// linear density `rho0` [kg/m] per unit unstretched length (wire plus ice, if iced), in [1e-3, 1e3]
    /// (bare conductors are 0.1 to 5 kg/m, heavily iced ones up to about 30 kg/m)
    pub linear_density_kg_per_m: f64,
    /// constitutive law; default `"tension_only"`
    #[serde(default)]
    pub tension_law: TensionLawSpec,
    /// with `tension_law = "two_material"`: the curve its materials follow, `"initial"` (default, as
    /// strung) or `"creep"` (after the long-term creep); not allowed with the other laws
    #[serde(default)]
    pub curve: Option<CurveSpec>,
    /// linear thermal expansion coefficient `alpha_t` [1/K], in [0, 1e-3], eq. (5.5); default 0 (section
    /// 5.4 gives 23.8e-6 for aluminium; metals are 1e-5 to 3e-5)
    #[serde(default)]
    pub thermal_expansion_per_k: f64,
    /// temperature at which the wire is stress-free at its unstretched length, and its initial
    /// temperature `u_ref` [K], in [173.15, 5000] (kelvin: -100 C is the floor); default 268.15 K (-5 C, the ambient temperature of section 5.4)
    #[serde(default = "default_reference_temperature")]
    pub reference_temperature_k: f64,
}

fn default_reference_temperature() -> f64 {
    crate::wire::REFERENCE_TEMPERATURE_K
}

/// Supports and grid.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GeometrySpec {
    /// left support position `A = (x1, x2, x3)` [m]: exactly three components, each within
    /// `MAX_COORDINATE_M` = 1e5 m (a local frame around the span)
    #[serde(deserialize_with = "three")]
    pub left_support_m: [f64; 3],
    /// right support position `B = (x1, x2, x3)` [m]; heights may differ. The chord `|B - A|` is in
    /// [1e-6, 1e4] m (`MAX_SPAN_M`: the longest overhead spans built are about 5.4 km)
    #[serde(deserialize_with = "three")]
    pub right_support_m: [f64; 3],
    /// number of segments `N` [-] (nodes `0..=N`), in [2, 1e7]; even `N` puts a node at mid-span
    pub segments: usize,
    /// unstretched (stress-free) length of the wire `S` [m], in [chord / 2, 100 chord] (a strain of 100 %
    /// is beyond any conductor; a wire 100 times its span is not a line); default: the length of the
    /// initial shape, so that the wire starts unstressed
    #[serde(default)]
    pub unstretched_length_m: Option<f64>,
}

/// A line section: an ordered list of supports (the first and last dead-ends, suspension strings
/// between) and the spans between them, all of the `[conductor]`. Coordinates as for `[geometry]`; the
/// section runs along `x2` (its supports in increasing `x2`), `x3` up.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SectionSpec {
    /// horizontal tension `H0` [N] at which every span is strung, with the strings hanging plumb, at the
    /// stringing temperature; in (0, 1e7] (a per-span tension, sag or unstretched length overrides it)
    #[serde(default)]
    pub horizontal_tension_n: Option<f64>,
    /// the same tension as a fraction of `conductor.rated_tensile_strength_n` [-], in (0, 0.6] (lines are
    /// strung at 0.1 to 0.25 of RTS); give this or `horizontal_tension_n`, not both
    #[serde(default)]
    pub tension_fraction_of_rts: Option<f64>,
    /// temperature `T0` [K] at which the stringing (tension, sag or unstretched length) is stated, in
    /// [223.15, 373.15]; default `conductor.reference_temperature_k`, the line's initial temperature. Where
    /// they differ, every span's stress-free length is rescaled by `1 / (1 + alpha_t (T0 - T_ref))` and the
    /// run must start from `initial.shape = "equilibrium"` (the strung shape is not at rest at `T_ref`)
    #[serde(default)]
    pub stringing_temperature_k: Option<f64>,
    /// segments per span `N_k` [-] unless a span states its own, in [2, 1e6]
    #[serde(default)]
    pub segments_per_span: Option<usize>,
    /// the supports, in order along the line (at least two)
    pub supports: Vec<SupportSpec>,
    /// the spans, one fewer than the supports (optional: each span defaults to the section's values)
    #[serde(default)]
    pub spans: Vec<SpanSpec>,
}

/// One support of a section.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields, tag = "kind", rename_all = "snake_case")]
pub enum SupportSpec {
    /// the conductor fixed to a point (a strain tower)
    DeadEnd {
        /// attachment point `(x1, x2, x3)` [m], each within 1e5 m
        #[serde(deserialize_with = "three")]
        point_m: [f64; 3],
    },
    /// a suspension insulator string hanging from a crossarm pivot to the conductor clamp
    Suspension {
        /// crossarm pivot (top of the string) `(x1, x2, x3)` [m], each within 1e5 m
        #[serde(deserialize_with = "three")]
        pivot_m: [f64; 3],
        /// string length `L_i` [m], in [0.01, 20] (suspension strings are 1 to 10 m)
        insulator_length_m: f64,
        /// string mass `m_i` [kg], lumped at the clamp, in [0, 5000] (50 to 150 kg for 3 to 5 m strings)
        insulator_mass_kg: f64,
        /// string axial stiffness `EA_i` [N], in [1e4, 1e10] (long-rod and cap-and-pin strings: about 1e7
        /// to 1e8 N)
        insulator_stiffness_n: f64,
        /// string axial damping `BA_i` [N s] (MoorDyn's `BA`: a damper `BA_i / L_i` [N s/m] along the
        /// string), in [0, 1e7]; default 0 (undamped: a clamp rings on the string's axial mode, about 50 to
        /// 100 Hz, after a sudden unloading; 1e4 N s damps it in a few periods)
        #[serde(default)]
        insulator_damping_n_s: f64,
        /// an elastic crossarm (tower flexibility); default rigid
        #[serde(default)]
        crossarm: Option<CrossarmSpecToml>,
    },
}

/// Springs, mass and damping of an elastic crossarm (horizontal motion of the pivot).
#[derive(Clone, Copy, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CrossarmSpecToml {
    /// spring along the line `k_l` [N/m], in (0, 1e10]
    pub longitudinal_n_per_m: f64,
    /// spring across the line `k_t` [N/m], in (0, 1e10]
    pub transverse_n_per_m: f64,
    /// mass moving with the pivot `M` [kg], in (0, 1e6]
    pub mass_kg: f64,
    /// viscous damping `c_d` [N s/m], in [0, 1e9]; default 0
    #[serde(default)]
    pub damping_n_s_per_m: f64,
}

/// One span of a section: what differs from the section's defaults.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SpanSpec {
    /// segments `N_k` [-], in [2, 1e6]; default `section.segments_per_span`
    #[serde(default)]
    pub segments: Option<usize>,
    /// horizontal tension `H0` [N] at stringing, in (0, 1e7]; default `section.horizontal_tension_n`
    #[serde(default)]
    pub horizontal_tension_n: Option<f64>,
    /// unstretched length `S_k` [m] instead of a stringing tension, in [chord / 2, 2 chord]
    #[serde(default)]
    pub unstretched_length_m: Option<f64>,
    /// sag `f_k` [m] instead of a stringing tension: the vertical distance from the chord between the
    /// plumb clamps down to the conductor at the span's horizontal middle, in (0, chord / 2]
    #[serde(default)]
    pub sag_m: Option<f64>,
    /// this span's conductor linear density `rho0` [kg/m], in [1e-3, 1e3]; default `[conductor]`'s (a
    /// section joining conductors of different kinds)
    #[serde(default)]
    pub linear_density_kg_per_m: Option<f64>,
    /// this span's axial stiffness `EA` [N], in [1, 1e10]; default `[conductor]`'s
    #[serde(default)]
    pub axial_stiffness_n: Option<f64>,
}

/// Initial shape kind.
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum ShapeSpec {
    /// the straight chord from `A` to `B` (the paper's start, sections 4.1-4.3; default)
    #[default]
    Straight,
    /// a parabola in the vertical plane through the chord, sagging `sag_m` below the chord's midpoint
    Parabola,
    /// at rest on the static equilibrium of the loads at `t = 0` (weight, uniform load, the wind at its
    /// initial scale, and the ice of events at `t = 0`, which then are part of the initial state rather
    /// than events of the run), solved by Newton's method on the scheme's own discrete equations
    /// ([`crate::statics`]); the unstretched length is `geometry.unstretched_length_m`, or the length of
    /// the parabola of `sag_m` if given, or the chord
    Equilibrium,
}

/// Initial state. The wire starts at rest; nodes are equally spaced in arc length along the shape.
#[derive(Clone, Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct InitialSpec {
    /// `"straight"` (default), `"parabola"` or `"equilibrium"`
    #[serde(default)]
    pub shape: ShapeSpec,
    /// mid-span sag `f` [m] below the chord, measured vertically, in (0, chord]; the chord must not be
    /// vertical (at least 1e-3 of it horizontal); required with `shape = "parabola"`,
    /// optional with `"equilibrium"` (then the start of the Newton iteration and the default length)
    #[serde(default)]
    pub sag_m: Option<f64>,
}

/// Loads.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LoadsSpec {
    /// gravitational acceleration `g` [m/s^2] along `-x3`, in [0, 100]; default 9.81 (the paper's value,
    /// 4.1); 0 for none
    #[serde(default = "default_gravity")]
    pub gravity_m_per_s2: f64,
    /// uniform force per unit unstretched length `q` [N/m] in a fixed direction (e.g. a wind drag that
    /// does not turn with the wire), each component within 1e4 N/m (ten times the weight of the heaviest
    /// iced conductor); default zero
    #[serde(default, deserialize_with = "three")]
    pub uniform_load_n_per_m: [f64; 3],
    /// wind, if any
    #[serde(default)]
    pub wind: Option<WindSpec>,
}

impl Default for LoadsSpec {
    fn default() -> Self {
        LoadsSpec { gravity_m_per_s2: default_gravity(), uniform_load_n_per_m: [0.0; 3], wind: None }
    }
}

fn default_gravity() -> f64 {
    9.81
}

/// Wind law selector.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum WindLawSpec {
    /// the aerodynamic law (2.5): `F_n = q d (c_n sin^2 a + c_tau sin a)`, `F_tau = q d c_tau cos^2 a`
    Aerodynamic,
    /// a uniform pressure `p` [N/m] normal to the wire in the plane of wire and wind (section 4.1)
    UniformNormal,
}

/// Wind. Its direction is the flow direction (the paper's `x1`).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WindSpec {
    /// `"aerodynamic"` or `"uniform_normal"`
    pub law: WindLawSpec,
    /// flow direction `w` [-], normalised on reading: three components, each within 1e6, not all zero
    /// (norm at least 1e-12); default `[1, 0, 0]` (the paper's `x1`)
    #[serde(default = "default_wind_direction", deserialize_with = "three")]
    pub direction: [f64; 3],
    /// undisturbed wind speed `U` [m/s], 0 (still air: no drag and no aerodynamic damping, so that a sweep
    /// can start there) or in [0.01, 100] (design wind speeds are below about 70 m/s; the strongest gust
    /// measured, 113 m/s, was not a steady wind); scales the damping (2.6) and, for the aerodynamic law, `q`
    pub speed_m_per_s: f64,
    /// air density `rho_air` [kg/m^3], in (0, 2] (1.225 at sea level, ISA; the densest cold air is about
    /// 1.5: a value above 2 is another unit, e.g. g/m^3); default 1.225 (docs/paper_notes.md, ISA sea level)
    #[serde(default = "default_air_density")]
    pub air_density_kg_per_m3: f64,
    /// normal force coefficient `c_n` [-], in [0, 10] (drag coefficients of cylinders are about 1 to 2);
    /// default 1.8446 (paper, after (2.5))
    #[serde(default = "default_cn")]
    pub normal_coefficient: f64,
    /// tangential force coefficient `c_tau` [-], in [0, 10]; default 0.0554 (paper, after (2.5))
    #[serde(default = "default_ct")]
    pub tangential_coefficient: f64,
    /// line pressure `p` [N/m] per unit deformed length, in [0, 1e4], for `law = "uniform_normal"` only
    /// (section 4.1 uses `p = rho_air U^2 d / 2 = 3.805 N/m`)
    #[serde(default)]
    pub pressure_n_per_m: Option<f64>,
    /// multiplier on the wind load at the start [-], in [0, 100]; default 1 (on). Events `wind` and `gust`
    /// change it during the run.
    #[serde(default = "default_initial_scale")]
    pub initial_scale: f64,
    /// ramp time `R` [s], in [0, 1e8]: the multiplier goes linearly from 0 at `t = 0` to `initial_scale` at
    /// `t = R` ([`crate::events::WindRamp`]); default 0, a step (the wind is on at full scale from `t = 0`).
    /// A ramp of several periods of the span's first mode keeps the dynamic amplification near 1
    /// (docs/scenario.md, "Design loads without start-up overshoot").
    #[serde(default)]
    pub ramp_s: f64,
}

fn default_initial_scale() -> f64 {
    1.0
}

fn default_wind_direction() -> [f64; 3] {
    [1.0, 0.0, 0.0]
}
fn default_air_density() -> f64 {
    1.225
}
fn default_cn() -> f64 {
    1.8446
}
fn default_ct() -> f64 {
    0.0554
}

/// Numerical parameters. Defaults: Courant 0.9 and the paper's velocity smoothing (3.3) `b = 0.02`, the
/// least damping that keeps the tension-only law stable in long runs; physical damping (`mu`, `eta`) is
/// stated by the scenario (docs/architecture.md, "stable defaults").
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct NumericsSpec {
    /// Courant number `C = c dt / ds` [-] with `c = sqrt(EA / rho0)` (3.7); in (0, 1] and below the
    /// internal-friction limit `sqrt(1 + z^2) - z`; default 0.9 (paper section 3: 0.5 to 1)
    #[serde(default = "default_courant")]
    pub courant: f64,
    /// velocity smoothing per step `b = beta / ds^2` [-] (3.3), in [0, 0.25]; paper range 0.015 to 0.03;
    /// default 0.02, the middle of the paper's range: without any damping the tension-only law can go
    /// unstable in long runs, and 0.02 kept every tested configuration stable (docs/architecture.md,
    /// "stable defaults"); 0 turns it off (then [`super::warnings`] warns unless other damping is stated)
    #[serde(default = "default_smoothing")]
    pub smoothing: f64,
    /// aerodynamic damping coefficient `mu` [-] of (2.6), in [0, 1]; paper range 0.1 to 0.2; default 0
    #[serde(default)]
    pub mu: f64,
    /// Kelvin-Voigt internal friction `eta` [N s] of (3.4), in [0, 1e9]; default 0
    #[serde(default)]
    pub eta_n_s: f64,
    /// mass-proportional damping `zeta` [1/s] (not in the paper: still-air drag or a dynamic-relaxation
    /// aid), >= 0 with `zeta dt < 1` (the step's damping factor stays positive); default 0
    #[serde(default)]
    pub mass_damping_per_s: f64,
    /// speed bound [m/s], in (0, 1e7], above which a run is stopped as unstable; default: the longitudinal wave
    /// speed `c`, which no material point of a stable solution approaches
    #[serde(default)]
    pub max_speed_m_per_s: Option<f64>,
}

impl Default for NumericsSpec {
    fn default() -> Self {
        NumericsSpec {
            courant: default_courant(),
            smoothing: default_smoothing(),
            mu: 0.0,
            eta_n_s: 0.0,
            mass_damping_per_s: 0.0,
            max_speed_m_per_s: None,
        }
    }
}

fn default_courant() -> f64 {
    0.9
}

fn default_smoothing() -> f64 {
    0.02
}

/// Duration: give exactly one of `end_time_s` and `until_settled`.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DurationSpec {
    /// end time `t_end` [s], in (0, 1e8] (about three years)
    #[serde(default)]
    pub end_time_s: Option<f64>,
    /// run until the wire settles
    #[serde(default)]
    pub until_settled: Option<SettleSpec>,
}

/// "Until settled": the kinetic energy stays below `kinetic_energy_fraction` of its peak for
/// `window_s` seconds, or the time cap is reached (then the run ends with `settled = false`).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SettleSpec {
    /// threshold as a fraction of the peak kinetic energy [-], in (0, 1)
    pub kinetic_energy_fraction: f64,
    /// how long the kinetic energy must stay below the threshold [s], in (0, 1e8]; default 1 s
    #[serde(default = "default_window")]
    pub window_s: f64,
    /// time cap [s], in (0, 1e8]
    pub max_time_s: f64,
}

fn default_window() -> f64 {
    1.0
}

/// Output.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct OutputSpec {
    /// interval between rows of `timeseries.csv` [s], in (0, 1e8]; default 0.05
    #[serde(default = "default_sample")]
    pub sample_interval_s: f64,
    /// times at which the whole shape goes to `snapshots.csv` [s], each in [0, end time]: taken at the first time step at or
    /// after each (the rows record the actual time; outputs never shorten a step); the final state is
    /// always written too
    #[serde(default)]
    pub snapshot_times_s: Vec<f64>,
    /// named points of the wire followed in `timeseries.csv` and `summary.json`, besides mid-span
    #[serde(default)]
    pub probes: Vec<ProbeSpec>,
    /// the peaks of `summary.json` count from this time [s], in [0, end time]; default: the first event's time (so a
    /// settle-then-break run reports the break's peaks), or 0 without events. Every phase between events
    /// has its own peaks in `summary.json` regardless.
    #[serde(default)]
    pub peaks_from_s: Option<f64>,
    /// speed `U` [m/s] of the dimensionless time `tau = t U / l` (l = chord length), in [1e-3, 1e3];
    /// default 20 (the paper's wind speed, section 4)
    #[serde(default = "default_tau_speed")]
    pub tau_speed_m_per_s: f64,
}

impl Default for OutputSpec {
    fn default() -> Self {
        OutputSpec {
            sample_interval_s: default_sample(),
            snapshot_times_s: Vec::new(),
            probes: Vec::new(),
            peaks_from_s: None,
            tau_speed_m_per_s: default_tau_speed(),
        }
    }
}

/// A named point of the wire at a fixed Lagrangian coordinate.
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ProbeSpec {
    /// name: letters, digits and `_`, not `mid` (the mid-span probe every run has); used in column names
    pub name: String,
    /// position as a fraction `f` of the unstretched length from the left support [-], in [0, 1]
    pub at_fraction: f64,
}

fn default_sample() -> f64 {
    0.05
}
fn default_tau_speed() -> f64 {
    20.0
}

/// `[f64; 3]` from a TOML array of exactly three numbers. (serde's own `[f64; 3]` takes the first three of
/// a longer TOML array and silently drops the rest.)
pub(crate) fn three<'de, D: Deserializer<'de>>(d: D) -> Result<[f64; 3], D::Error> {
    exactly(d)
}

/// `[f64; 2]` from a TOML array of exactly two numbers (span ranges `[a, b]`).
pub(crate) fn two<'de, D: Deserializer<'de>>(d: D) -> Result<[f64; 2], D::Error> {
    exactly(d)
}

/// `Vec<[f64; 2]>` from a TOML array of points of exactly two numbers each (`[t, value]` schedules,
/// ground profiles); the message names the point.
pub(crate) fn pairs<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<[f64; 2]>, D::Error> {
    let v: Vec<Vec<f64>> = Vec::deserialize(d)?;
    v.iter()
        .enumerate()
        .map(|(k, p)| {
            <[f64; 2]>::try_from(p.as_slice()).map_err(|_| {
                serde::de::Error::custom(format!(
                    "point [{k}] has {} numbers {p:?}: each point is exactly two numbers",
                    p.len()
                ))
            })
        })
        .collect()
}

fn exactly<'de, D: Deserializer<'de>, const K: usize>(d: D) -> Result<[f64; K], D::Error> {
    let v: Vec<f64> = Vec::deserialize(d)?;
    <[f64; K]>::try_from(v.as_slice()).map_err(|_| {
        let expected = format!("exactly {K} components");
        serde::de::Error::invalid_length(v.len(), &expected.as_str())
    })
}

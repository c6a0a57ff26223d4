//! `[short_circuit]` of a line scenario: the fault current that loads the phases (issue 25), and the inputs
//! of the IEC 60865-1 simplified method that the line itself cannot give.
//!
//! The fault: its kind, the conductors carrying the phases L1, L2, L3 (a bundle's name means all its
//! sub-conductors, the current shared equally), the initial symmetrical short-circuit current `I''k`
//! (r.m.s.), the frequency, the decaying DC component from the peak factor `kappa` or from `R/X`
//! (IEC 60909-0:2016, eq. (55): `kappa = 1.02 + 0.98 e^(-3 R/X)`), the angle of the voltage at inception
//! (absent: the worst case), the start and duration `T_k1` of the first current flow and an optional
//! auto-reclose (a dead time, then a second flow). The line applies the electromagnetic forces of these
//! currents between every pair of current-carrying conductors (docs/short_circuit.md).
//!
//! The IEC-only inputs: the thermal constant `c_th` of eq. (35), the conductor's cross-section `A_s` where
//! no catalogue entry gives it, and an optional spring constant `S` overriding the one taken from the
//! portals' springs (`ohl shortcircuit`, [`super::short_circuit_iec`]).

use serde::Deserialize;

use super::line::{LineSpec, RoleSpec};
use super::range::Range as Allowed;
use super::validate::Check;
use super::validate::MAX_TIME_S;

/// The kind of the short circuit.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum FaultKindSpec {
    /// L1, L2 and L3 (`phases` names three conductors)
    ThreePhase,
    /// L1 and L2 (`phases` names two or three conductors; L3 carries none)
    LineToLine,
    /// L1 to earth (`phases` names one to three conductors; L2 and L3 carry none)
    LineToEarth,
}

impl FaultKindSpec {
    /// The least number of conductors `phases` must name.
    pub fn least_phases(self) -> usize {
        match self {
            FaultKindSpec::ThreePhase => 3,
            FaultKindSpec::LineToLine => 2,
            FaultKindSpec::LineToEarth => 1,
        }
    }

    /// As written in the file.
    pub fn name(self) -> &'static str {
        match self {
            FaultKindSpec::ThreePhase => "three_phase",
            FaultKindSpec::LineToLine => "line_to_line",
            FaultKindSpec::LineToEarth => "line_to_earth",
        }
    }
}

/// An auto-reclose: the line is switched on again into the fault after a dead time.
#[derive(Clone, Copy, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct RecloseSpec {
    /// dead time between the end of the first flow and the second [s], in [0.05, 600] (distribution
    /// reclosers: 0.3 to a few seconds; transmission high-speed reclosing: 0.3 to 1 s)
    pub dead_time_s: f64,
    /// duration of the second flow [s], in (0, 10]
    pub duration_s: f64,
}

/// `[short_circuit]`.
#[derive(Clone, Debug, Deserialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct ShortCircuitSpec {
    /// `"three_phase"`, `"line_to_line"` or `"line_to_earth"`
    pub kind: FaultKindSpec,
    /// the conductors (names of `line.conductors`, phases) carrying L1, L2, L3, in that order; a bundle's
    /// name means all its sub-conductors (the current shared equally)
    pub phases: Vec<String>,
    /// initial symmetrical short-circuit current `I''k` (r.m.s.) [A], in [100, 3e5] (substation
    /// switchgear is rated up to 63-80 kA; distribution 5-25 kA)
    pub initial_current_a: f64,
    /// system frequency `f` [Hz], in [10, 1000]; default 50
    #[serde(default = "default_frequency")]
    pub frequency_hz: f64,
    /// peak factor `kappa` (IEC 60909-0), in (1.02, 2): the DC component; give this or `r_over_x`
    #[serde(default)]
    pub peak_factor: Option<f64>,
    /// `R/X` of the short-circuit impedance [-], in (0, 10]: the DC component decays with `tau = X / (2 pi
    /// f R)`; give this or `peak_factor`
    #[serde(default)]
    pub r_over_x: Option<f64>,
    /// angle of the source voltage of L1 at inception [deg], in [-360, 360]; absent: the angle that gives
    /// the largest peak current (the worst case)
    #[serde(default)]
    pub inception_angle_deg: Option<f64>,
    /// time of fault inception [s], in [0, 1e8], before the end time
    pub start_s: f64,
    /// duration of the first current flow `T_k1` [s], in (0, 10]
    pub duration_s: f64,
    /// an auto-reclose into the fault; absent: none
    #[serde(default)]
    pub reclose: Option<RecloseSpec>,
    /// electromagnetic numerics: mechanical segments per chord on which the force is evaluated, in [1,
    /// 1000]; absent: the library's default (docs/short_circuit.md, "Cost")
    #[serde(default)]
    pub chord_segments: Option<usize>,
    /// electromagnetic numerics: steps between re-evaluations of the geometric factors, in [1, 1000];
    /// absent: the library's default
    #[serde(default)]
    pub refresh_steps: Option<usize>,
    /// contact between conductors (the sub-conductors of each bundle, and the conductors of different
    /// phases named in `phases`): a penalty that keeps them from passing through each other when they
    /// clash ([`crate::line::contact`]); default true. Without it a bundle's sub-conductors that clash
    /// under the pinch cross and the force between them diverges (docs/short_circuit.md)
    #[serde(default = "default_contact")]
    pub contact: bool,
    /// coefficient of restitution of a clash between conductors [-], in (0, 1]; default 0.5 (an
    /// assumption: no published value for stranded conductors, [`crate::line::contact`])
    #[serde(default = "default_restitution")]
    pub contact_restitution: f64,
    /// stiffness of the contact per unit length `k'` [N/m^2] (the force per metre of contact per metre of
    /// penetration), in [1e4, 1e12]; the line's step is lowered where the contact needs it (`w_c dt <=
    /// 0.5`, `w_c = sqrt(k' / mu)`); absent: a penalty scaled to the step, `k' = mu (0.5 / dt)^2`, which
    /// stiffens as the grid is refined ([`crate::line::contact`], docs/short_circuit.md, "Contact")
    #[serde(default)]
    pub contact_stiffness_n_per_m2: Option<f64>,
    /// IEC 60865-1 eq. (35): material constant `c_th` [m^4/(A^2 s)], in [1e-20, 1e-17]; default 0.27e-18
    /// (Al, Al alloy and Al/St with section ratio > 6, IEC 60865-1:2011, clause 6.2.4, as used for the
    /// TR 60865-2 examples: docs/short_circuit_iec60865.md)
    #[serde(default = "default_thermal_constant")]
    pub thermal_constant_m4_per_a2s: f64,
    /// IEC 60865-1 eq. (25): resultant spring constant `S` of both supports of the span [N/m], in [1e3,
    /// 1e10]; absent: from the portals' springs along the line (`ohl shortcircuit`)
    #[serde(default)]
    pub spring_constant_n_per_m: Option<f64>,
    /// IEC 60865-1 eq. (25), (35): cross-section `A_s` of one sub-conductor [m^2], in [1e-6, 1e-2]; absent:
    /// the catalogue entry's total area (the conductor's `catalog`); its modulus is then `E = EA / A_s`
    #[serde(default)]
    pub conductor_area_m2: Option<f64>,
}

fn default_contact() -> bool {
    true
}

fn default_restitution() -> f64 {
    crate::line::contact::ConductorContact::default().restitution
}

/// 50 Hz: the frequency of most of the world's grids (IEC 60909-0 examples).
fn default_frequency() -> f64 {
    50.0
}

/// IEC 60865-1:2011, clause 6.2.4 (Al, Al alloy, Al/St with section ratio > 6).
pub const DEFAULT_THERMAL_CONSTANT_M4_PER_A2S: f64 = 0.27e-18;

fn default_thermal_constant() -> f64 {
    DEFAULT_THERMAL_CONSTANT_M4_PER_A2S
}

/// Allowed `I''k` [A].
pub const INITIAL_CURRENT_A: Allowed = Allowed::closed(100.0, 3.0e5, "A");
/// Allowed frequencies [Hz].
pub const FREQUENCY_HZ: Allowed = Allowed::closed(10.0, 1000.0, "Hz");
/// Allowed `kappa` [-]: IEC 60909-0 `1.02 + 0.98 e^(-3 R/X)` for `R/X` in (0, inf).
pub const PEAK_FACTOR: Allowed = Allowed::open(1.02, 2.0, "").note(" (IEC 60909-0: 1.02 + 0.98 exp(-3 R/X))");
/// Allowed `R/X` [-].
pub const R_OVER_X: Allowed = Allowed::open_closed(0.0, 10.0, "");
/// Allowed durations of a current flow [s].
pub const FLOW_DURATION_S: Allowed = Allowed::open_closed(0.0, 10.0, "s");

impl ShortCircuitSpec {
    /// The peak factor `kappa`: given, or from `R/X` (IEC 60909-0:2016, eq. (55)).
    pub fn kappa(&self) -> f64 {
        match (self.peak_factor, self.r_over_x) {
            (Some(k), _) => k,
            (None, Some(r)) => 1.02 + 0.98 * (-3.0 * r).exp(),
            (None, None) => f64::NAN,
        }
    }

    /// `R/X`: given, or from `kappa` (the inverse of IEC 60909-0 eq. (55)).
    pub fn r_over_x(&self) -> f64 {
        match (self.r_over_x, self.peak_factor) {
            (Some(r), _) => r,
            (None, Some(k)) => -((k - 1.02) / 0.98).ln() / 3.0,
            (None, None) => f64::NAN,
        }
    }

    /// When the last current flow ends [s].
    pub fn end_s(&self) -> f64 {
        let first = self.start_s + self.duration_s;
        self.reclose.map_or(first, |r| first + r.dead_time_s + r.duration_s)
    }

    /// Check every field; `end_time_s` is the run's end time, if it has one.
    pub fn check(&self, line: &LineSpec, end_time_s: Option<f64>, c: &mut Check) {
        let f = |name: &str| format!("short_circuit.{name}");
        c.range(&f("initial_current_a"), self.initial_current_a, &INITIAL_CURRENT_A);
        c.range(&f("frequency_hz"), self.frequency_hz, &FREQUENCY_HZ);
        match (self.peak_factor, self.r_over_x) {
            (Some(_), Some(r)) => {
                c.fail(&f("r_over_x"), r, "give either peak_factor or r_over_x (the DC component), not both");
            }
            (None, None) => c.fail(
                &f("peak_factor"),
                "(missing)",
                "give peak_factor (kappa, IEC 60909-0, in (1.02, 2)) or r_over_x (in (0, 10])",
            ),
            (Some(k), None) => {
                c.range(&f("peak_factor"), k, &PEAK_FACTOR);
            }
            (None, Some(r)) => {
                c.range(&f("r_over_x"), r, &R_OVER_X);
            }
        }
        if let Some(a) = self.inception_angle_deg {
            c.range(&f("inception_angle_deg"), a, &Allowed::closed(-360.0, 360.0, "deg"));
        }
        if c.range(&f("start_s"), self.start_s, &Allowed::closed(0.0, MAX_TIME_S, "s"))
            && let Some(end) = end_time_s
            && end.is_finite()
            && self.start_s >= end
        {
            c.fail(&f("start_s"), self.start_s, &format!("must be before the end time duration.end_time_s = {end} s"));
        }
        c.range(&f("duration_s"), self.duration_s, &FLOW_DURATION_S);
        if let Some(r) = self.reclose {
            c.range(&f("reclose.dead_time_s"), r.dead_time_s, &Allowed::closed(0.05, 600.0, "s"));
            c.range(&f("reclose.duration_s"), r.duration_s, &FLOW_DURATION_S);
        }
        for (name, v) in [("chord_segments", self.chord_segments), ("refresh_steps", self.refresh_steps)] {
            if let Some(v) = v
                && !(1..=1000).contains(&v)
            {
                c.fail(&f(name), v, "must be a whole number in [1, 1000]");
            }
        }
        c.range(&f("contact_restitution"), self.contact_restitution, &Allowed::open_closed(0.0, 1.0, ""));
        if let Some(k) = self.contact_stiffness_n_per_m2 {
            c.range(&f("contact_stiffness_n_per_m2"), k, &Allowed::closed(1.0e4, 1.0e12, "N/m^2"));
        }
        c.range(
            &f("thermal_constant_m4_per_a2s"),
            self.thermal_constant_m4_per_a2s,
            &Allowed::closed(1.0e-20, 1.0e-17, "m^4/(A^2 s)").note(" (IEC 60865-1: 0.27e-18 for Al and Al/St)"),
        );
        if let Some(s) = self.spring_constant_n_per_m {
            c.range(&f("spring_constant_n_per_m"), s, &Allowed::closed(1.0e3, 1.0e10, "N/m"));
        }
        if let Some(a) = self.conductor_area_m2 {
            c.range(&f("conductor_area_m2"), a, &Allowed::closed(1.0e-6, 1.0e-2, "m^2").note(" (1 to 10000 mm^2)"));
        }
        // The phases: names of phase conductors of the line, each once, as many as the kind needs.
        let least = self.kind.least_phases();
        if self.phases.len() < least || self.phases.len() > 3 {
            c.fail(
                &f("phases"),
                format!("{:?}", self.phases),
                &format!(
                    "must name {} conductors for kind = \"{}\" (L1, L2, L3 in that order, at most 3)",
                    if least == 3 { "3".to_string() } else { format!("{least} to 3") },
                    self.kind.name()
                ),
            );
        }
        for (j, p) in self.phases.iter().enumerate() {
            let field = f(&format!("phases[{j}]"));
            match line.conductors.iter().find(|x| &x.name == p) {
                None => {
                    let names: Vec<&str> = line.conductors.iter().map(|x| x.name.as_str()).collect();
                    c.fail(
                        &field,
                        format!("{p:?}"),
                        &format!("must name a conductor of the line: {}", names.join(", ")),
                    );
                }
                Some(x) if x.role == RoleSpec::EarthWire => {
                    c.fail(&field, format!("{p:?}"), "names an earth wire: the phases must be phase conductors");
                }
                Some(_) => {}
            }
            if let Some(x) = line.conductors.iter().position(|x| &x.name == p)
                && line.conductors[x].conductor.diameter_m.is_none()
            {
                c.fail(
                    &format!("line.conductors[{x}].conductor.diameter_m"),
                    "(missing)",
                    "a phase of [short_circuit] needs its diameter: the core radius of its current filament",
                );
            }
            if self.phases[..j].contains(p) {
                c.fail(
                    &field,
                    format!("{p:?}"),
                    "names a conductor already named: each phase is a different conductor",
                );
            }
        }
    }
}

impl ShortCircuitSpec {
    /// The fault current of the library ([`crate::shortcircuit::current`]) from this table (validated).
    pub fn fault_current_spec(&self) -> crate::shortcircuit::current::FaultCurrentSpec {
        use crate::shortcircuit::current::{FaultCurrentSpec, FaultKind, Reclose};
        FaultCurrentSpec {
            kind: match self.kind {
                FaultKindSpec::ThreePhase => FaultKind::ThreePhase,
                FaultKindSpec::LineToLine => FaultKind::LineToLine,
                FaultKindSpec::LineToEarth => FaultKind::LineToEarth,
            },
            initial_current_a: self.initial_current_a,
            frequency_hz: self.frequency_hz,
            r_over_x: self.r_over_x(),
            inception_angle_deg: self.inception_angle_deg,
            start_s: self.start_s,
            duration_s: self.duration_s,
            reclose: self.reclose.map(|r| Reclose { dead_time_s: r.dead_time_s, duration_s: r.duration_s }),
        }
    }

    /// The electromagnetic load of the line: one carrier per conductor of each phase (a bundle's
    /// sub-conductors each with `1/n` of the phase current), its core radius the conductor's radius, its
    /// share negative where the conductor is strung against L1's direction (from its section's first
    /// support to its last). `groups` and `names` are the line's conductor groups and their names
    /// ([`super::line::LinePlan`]), `radius_m` the radius of each group's conductor and `direction` the
    /// horizontal direction of each group's section. `Err`: the field and why.
    pub fn electromagnetic(
        &self,
        names: &[String],
        groups: &[Vec<usize>],
        radius_m: &[f64],
        direction: &[[f64; 2]],
    ) -> Result<crate::line::electromagnetic::Electromagnetic, (String, String)> {
        use crate::line::electromagnetic::{Carrier, Electromagnetic, EmNumerics};
        use crate::shortcircuit::current::FaultCurrent;
        let current = FaultCurrent::new(self.fault_current_spec())
            .map_err(|e| ("short_circuit".to_string(), format!("the fault current: {e}")))?;
        let mut carriers = Vec::new();
        let mut reference: Option<[f64; 2]> = None;
        for (phase, name) in self.phases.iter().enumerate() {
            let g = names
                .iter()
                .position(|n| n == name)
                .ok_or_else(|| (format!("short_circuit.phases[{phase}]"), "not a conductor of the line".to_string()))?;
            let d = direction[g];
            let r = *reference.get_or_insert(d);
            let sign = if d[0] * r[0] + d[1] * r[1] < 0.0 { -1.0 } else { 1.0 };
            let share = sign / groups[g].len() as f64;
            for &conductor in &groups[g] {
                carriers.push(Carrier { conductor, phase, share, core_radius_m: radius_m[g] });
            }
        }
        let mut numerics = EmNumerics::default();
        if let Some(k) = self.chord_segments {
            numerics.chord_segments = k;
        }
        if let Some(m) = self.refresh_steps {
            numerics.refresh_steps = m;
        }
        Ok(Electromagnetic { carriers, current, numerics })
    }
}

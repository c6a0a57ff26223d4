//! The event timeline of a scenario (`[[events]]` tables) and the ground plane (`[ground]`), in their
//! TOML form. Each event happens at `time_s` [s]; the run steps exactly onto that time and applies it
//! before the next step (see [`crate::events`] for what each one does to the solver).
//!
//! ```toml
//! [ground]                       # section 4.4: a ground plane, restitution 0.6 = 36 % rebound energy
//! height_m = -25.0
//! restitution = 0.6
//!
//! [[events]]                     # break the segment at mid-span, (3.5)
//! time_s = 326.0
//! action = "break"
//! at_fraction = 0.5
//! ```
//!
//! Span ranges `range = [a, b]` are fractions of the unstretched length measured from the left
//! support (`0 <= a < b <= 1`); they cover the segments between the nodes nearest to `a` and `b`, so a
//! range is independent of the number of segments.

use serde::Deserialize;

/// The ground (section 4.4): a level plane `x3 = height_m`, or a terrain profile `profile_m` along the
/// line's horizontal coordinate `x2` (give one of the two).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct GroundSpec {
    /// height of a level ground plane `x3` [m]; must lie below every support and below the initial shape
    #[serde(default)]
    pub height_m: Option<f64>,
    /// terrain profile: points `[x2, x3]` [m] along the line's horizontal coordinate, `x2` strictly
    /// increasing, at least two, slopes at most 2 (63 degrees); the ground is linear between them and
    /// level beyond the first and last; every support and the initial shape must lie above it. A height
    /// per span is a profile with a point under each support.
    #[serde(default, deserialize_with = "super::schema::pairs")]
    pub profile_m: Vec<[f64; 2]>,
    /// coefficient of restitution on the normal velocity [-], in [0, 1]; the paper's 36 % of the
    /// vertical impact energy returned on rebound is 0.6 (0.6^2 = 0.36, section 4.4)
    pub restitution: f64,
    /// whether contact is on from the start; default true (an `action = "ground"` event switches it)
    #[serde(default = "yes")]
    pub active: bool,
    /// Coulomb friction coefficient `mu_g` [-] of a node on the ground, in [0, 2]; default 0
    /// (frictionless, the paper's section 4.4); about 0.5 for a conductor on grass or soil
    #[serde(default)]
    pub friction: f64,
}

impl GroundSpec {
    /// The library's ground (a profile, or the level plane; the plane at 0 m where neither is given,
    /// which validation refuses).
    pub fn ground(&self) -> crate::scheme::Ground {
        crate::scheme::Ground {
            height_m: self.height_m.unwrap_or(0.0),
            restitution: self.restitution,
            friction: self.friction,
            profile_m: self.profile_m.clone(),
        }
    }
}

fn yes() -> bool {
    true
}

/// Where a wind load acts (see [`crate::scheme::WindGate`]).
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum GateSpec {
    /// on every segment (default)
    #[default]
    Always,
    /// only on segments moving downwind (the "dancing wires" gust of section 4.5)
    Downwind,
}

/// Boundary treatment of the heat equation (5.2) at the wire's ends (see [`crate::heat`]).
#[derive(Clone, Copy, Debug, Default, Deserialize, PartialEq, Eq)]
#[serde(rename_all = "snake_case")]
pub enum HeatBoundarySpec {
    /// option 1 of section 5.3 (three-point Lagrange polynomial), re-derived
    LagrangeQuadratic,
    /// option 2 of section 5.3, eq. (5.4) with its misprinted coefficient 1 + 2r corrected to 1 + r
    /// (the literal (5.4) diverges for every step; see [`crate::heat::boundary`])
    Linear,
    /// conservative zero-flux (insulated) boundary; default
    #[default]
    ZeroFlux,
}

/// One event of the timeline. `action` selects the kind; every kind has `time_s` [s].
#[derive(Clone, Debug, Deserialize)]
#[serde(tag = "action", rename_all = "snake_case", deny_unknown_fields)]
pub enum EventSpec {
    /// Break the segment that contains the Lagrangian point `at_fraction` of the span (3.5); both parts
    /// continue as free-ended wires.
    Break {
        /// event time [s]
        time_s: f64,
        /// position of the break as a fraction of the unstretched length from the left support [-], in
        /// (0, 1); the segment `floor(at_fraction N)` breaks (for 0.5 and even N: the segment right of
        /// the mid-span node). A segment breaks once: two breaks in one segment are refused
        at_fraction: f64,
        /// in a `[section]`: the span (0-based) that `at_fraction` refers to; default 0
        #[serde(default)]
        span: Option<usize>,
    },
    /// Ice over a span range, in one of two forms (exactly one per event): a change of linear density
    /// (`linear_density_kg_per_m`, added or dropped; it does not enlarge the diameter the wind acts on), or
    /// a radial shell (`radial_thickness_m` with `density_kg_per_m3`) that replaces the range's shell: mass
    /// `rho_ice pi t (d + t)` per metre and the wind on the iced diameter `d + 2 t` (docs/loads.md).
    Ice {
        /// event time [s]
        time_s: f64,
        /// change of linear density `delta rho0` [kg/m] per unit unstretched length (negative drops ice), in
        /// [-1e3, 1e3]; applied in time order, no segment may become lighter than the bare wire
        /// (`conductor.linear_density_kg_per_m`, for which the time step is set)
        #[serde(default)]
        linear_density_kg_per_m: Option<f64>,
        /// radial ice thickness `t` [m] of the shell the range carries from now on, in [0, 0.2] (0 sheds
        /// it; 0.2 m is four times the thickest design glaze of the codes, about 50 mm, and the size of
        /// the largest rime and wet-snow sleeves; a thicker deposit is no longer a concentric shell);
        /// needs `conductor.diameter_m` and `density_kg_per_m3`
        #[serde(default)]
        radial_thickness_m: Option<f64>,
        /// density of the ice `rho_ice` [kg/m^3], in [100, 1000]: glaze 900 to 917 (solid ice), hard rime
        /// 600 to 900, soft rime 300 to 600, wet snow 100 to 850 (IEC 60826 and EN 50341-1 ice types;
        /// docs/loads.md); with `radial_thickness_m`
        #[serde(default)]
        density_kg_per_m3: Option<f64>,
        /// span range `[a, b]` as fractions of the unstretched length [-], selecting at least one segment;
        /// default the whole span
        #[serde(default = "whole_span", deserialize_with = "super::schema::two")]
        range: [f64; 2],
        /// in a `[section]`: the span (0-based) that `range` refers to; default 0
        #[serde(default)]
        span: Option<usize>,
        /// progressive change (ice shedding along the span): a front starting at the range's first end
        /// at `time_s` and moving at this speed [m/s] along the unstretched length, changing each segment
        /// when it reaches the segment's middle; in [0.1, 1e4] m/s (shedding fronts run at metres to tens
        /// of metres per second); default: the whole range at once
        #[serde(default)]
        front_speed_m_per_s: Option<f64>,
    },
    /// A suspension insulator string fails: from then on it carries nothing (its mass stays at the clamp:
    /// the string falls with the conductor).
    InsulatorFailure {
        /// event time [s]
        time_s: f64,
        /// the support (0-based, in `section.supports`), which must be a suspension
        support: usize,
    },
    /// The conductor slips out of a suspension clamp: the string stays on the tower (its mass leaves the
    /// conductor) and holds the conductor no more.
    ClampSlip {
        /// event time [s]
        time_s: f64,
        /// the support (0-based, in `section.supports`), which must be a suspension
        support: usize,
    },
    /// The conductor is released from a dead-end: its end becomes free.
    Release {
        /// event time [s]
        time_s: f64,
        /// the support (0-based, in `section.supports`), which must be a dead-end
        support: usize,
    },
    /// Set the wind to a constant multiple of the scenario's wind load (0 = off, 1 = on); ends a gust.
    Wind {
        /// event time [s]
        time_s: f64,
        /// multiplier on the wind load [-], in [0, 100]; needs `[loads.wind]`
        scale: f64,
        /// where it acts; default `"always"`
        #[serde(default)]
        gate: GateSpec,
        /// ramp time [s], in [0, 1e8]: the multiplier goes linearly from its value at `time_s` to `scale`
        /// over `ramp_s`; default 0, a step
        #[serde(default)]
        ramp_s: f64,
    },
    /// Start a gust, law (4.5) written with its physical period `P` (docs/paper_notes.md: the paper counts time in
    /// integration steps): the wind load is multiplied by `amplitude |sin(pi (t - time_s) / P)|`.
    Gust {
        /// event time [s]: the gust starts here
        time_s: f64,
        /// period `P` of `|sin(pi t / P)|` [s], at least 10 time steps and at most 1e8 s; needs `[loads.wind]`
        period_s: f64,
        /// peak multiplier on the wind load [-], in [0, 100]; default 1 (the full pressure head `q0 d`)
        #[serde(default = "one")]
        amplitude: f64,
        /// where it acts; default `"always"` (`"downwind"` is the dancing-wires variant of 4.5)
        #[serde(default)]
        gate: GateSpec,
    },
    /// Set the temperature of a span range, at once or as a linear ramp; thermal strain enters through
    /// each segment's stress-free length (5.5). Stops heat conduction if it is running.
    Temperature {
        /// event time [s]
        time_s: f64,
        /// target temperature `u` [K], in (0, 5000], with `1 + alpha_t (u - u_ref) >= 0.5` (a thermal strain
        /// of at least -50 %); needs `conductor.thermal_expansion_per_k > 0` (else it changes nothing)
        temperature_k: f64,
        /// span range `[a, b]` [-], selecting at least one segment; default the whole span
        #[serde(default = "whole_span", deserialize_with = "super::schema::two")]
        range: [f64; 2],
        /// duration of a linear ramp from each segment's current temperature to the target [s], in [0, 1e8];
        /// default 0 (a step)
        #[serde(default)]
        ramp_s: f64,
    },
    /// Start heat conduction along the wire, eq. (5.2), with a span range held at a fixed temperature.
    HeatConduction {
        /// event time [s]
        time_s: f64,
        /// span range held at `hold_temperature_k` [-]
        #[serde(deserialize_with = "super::schema::two")]
        hold_range: [f64; 2],
        /// temperature of the held range [K], in (0, 5000], with `1 + alpha_t (u - u_ref) >= 0.5`
        hold_temperature_k: f64,
        /// dimensionless heat time (the `t` of (5.1), length scaled by the span) per second of the
        /// mechanical run [1/s], in (0, 1000]. Physical conduction in aluminium would be `k / (rho c S^2)`, about
        /// 3.4e-9 1/s for a 160 m span (docs/paper_notes.md); the paper's de-icing sequence needs about 1.
        heat_time_per_s: f64,
        /// boundary treatment at the wire's ends; default `"zero_flux"`
        #[serde(default)]
        boundary: HeatBoundarySpec,
    },
    /// Stop heat conduction; the temperatures stay as they are.
    HeatConductionOff {
        /// event time [s]
        time_s: f64,
    },
    /// Switch ground contact on or off (needs a `[ground]` section).
    Ground {
        /// event time [s]
        time_s: f64,
        /// true: contact on
        on: bool,
    },
}

fn whole_span() -> [f64; 2] {
    [0.0, 1.0]
}
fn one() -> f64 {
    1.0
}

impl EventSpec {
    /// The event's time [s].
    pub fn time_s(&self) -> f64 {
        match *self {
            EventSpec::Break { time_s, .. }
            | EventSpec::Ice { time_s, .. }
            | EventSpec::Wind { time_s, .. }
            | EventSpec::Gust { time_s, .. }
            | EventSpec::Temperature { time_s, .. }
            | EventSpec::HeatConduction { time_s, .. }
            | EventSpec::HeatConductionOff { time_s }
            | EventSpec::InsulatorFailure { time_s, .. }
            | EventSpec::ClampSlip { time_s, .. }
            | EventSpec::Release { time_s, .. }
            | EventSpec::Ground { time_s, .. } => time_s,
        }
    }

    /// The span a break or an ice event addresses in a `[section]` (`None`: not given).
    pub fn span(&self) -> Option<usize> {
        match *self {
            EventSpec::Break { span, .. } | EventSpec::Ice { span, .. } => span,
            _ => None,
        }
    }

    /// The `at_fraction` of a break, `None` for any other event.
    pub fn break_fraction(&self) -> Option<f64> {
        match *self {
            EventSpec::Break { at_fraction, .. } => Some(at_fraction),
            _ => None,
        }
    }

    /// The `action` name as written in the file.
    pub fn action(&self) -> &'static str {
        match self {
            EventSpec::Break { .. } => "break",
            EventSpec::Ice { .. } => "ice",
            EventSpec::Wind { .. } => "wind",
            EventSpec::Gust { .. } => "gust",
            EventSpec::Temperature { .. } => "temperature",
            EventSpec::HeatConduction { .. } => "heat_conduction",
            EventSpec::HeatConductionOff { .. } => "heat_conduction_off",
            EventSpec::InsulatorFailure { .. } => "insulator_failure",
            EventSpec::ClampSlip { .. } => "clamp_slip",
            EventSpec::Release { .. } => "release",
            EventSpec::Ground { .. } => "ground",
        }
    }
}

/// Segments of an `n`-segment wire in the span range `[a, b]`: those between the nodes nearest to
/// `a S` and `b S`, i.e. `round(a n) .. round(b n)`.
pub fn segment_range(range: [f64; 2], n: usize) -> std::ops::Range<usize> {
    let (lo, hi) = node_bounds(range, n);
    lo..hi
}

/// Nodes of an `n`-segment wire in the span range `[a, b]`: `round(a n) ..= round(b n)`.
pub fn node_range(range: [f64; 2], n: usize) -> std::ops::Range<usize> {
    let (lo, hi) = node_bounds(range, n);
    lo..hi + 1
}

fn node_bounds(range: [f64; 2], n: usize) -> (usize, usize) {
    let nf = n as f64;
    let lo = (range[0] * nf).round().clamp(0.0, nf) as usize;
    let hi = (range[1] * nf).round().clamp(0.0, nf) as usize;
    (lo.min(hi), hi)
}

/// The segment that breaks for `at_fraction` on an `n`-segment wire.
pub fn break_segment(at_fraction: f64, n: usize) -> usize {
    ((at_fraction * n as f64).floor().max(0.0) as usize).min(n - 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ranges_select_segments_by_midpoint_and_nodes_by_position() {
        assert_eq!(segment_range([0.0, 1.0], 50), 0..50);
        assert_eq!(segment_range([0.45, 0.55], 50), 23..28);
        assert_eq!(segment_range([0.0, 0.5], 50), 0..25);
        assert_eq!(segment_range([0.5, 1.0], 50), 25..50);
        assert_eq!(node_range([0.45, 0.55], 50), 23..29);
        assert_eq!(node_range([0.0, 1.0], 50), 0..51);
        assert_eq!(break_segment(0.5, 50), 25);
        assert_eq!(break_segment(0.999, 50), 49);
    }

    #[test]
    fn events_parse_from_toml_and_refuse_unknown_fields() {
        #[derive(Deserialize)]
        struct Doc {
            events: Vec<EventSpec>,
        }
        let d: Doc = toml::from_str(
            r#"
            [[events]]
            time_s = 1.0
            action = "gust"
            period_s = 2.0
            gate = "downwind"
            [[events]]
            time_s = 3.0
            action = "ice"
            linear_density_kg_per_m = -0.5
            "#,
        )
        .unwrap();
        assert_eq!(d.events.len(), 2);
        assert!(matches!(d.events[0], EventSpec::Gust { amplitude, gate: GateSpec::Downwind, .. } if amplitude == 1.0));
        assert!(matches!(d.events[1], EventSpec::Ice { range: [0.0, 1.0], linear_density_kg_per_m: Some(-0.5), .. }));
        let bad = toml::from_str::<Doc>("[[events]]\ntime_s = 1.0\naction = \"break\"\nat_fractoin = 0.5\n");
        assert!(bad.is_err());
    }
}

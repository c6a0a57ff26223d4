//! An event of the timeline in the model's terms: what happens, at which time, to which segments or
//! nodes. Built from the scenario's `[[events]]` tables by [`crate::scenario::build`], which resolves
//! span fractions to index ranges once; the run applies them ([`super::EventState`]).

use std::ops::Range;

use crate::heat::boundary::HeatBoundary;
use crate::scheme::WindGate;

/// What an event does.
#[derive(Clone, Debug, PartialEq)]
pub enum Action {
    /// Break segment `segment` (3.5); both parts continue as free-ended wires.
    Break {
        /// the segment index
        segment: usize,
    },
    /// Change the linear density of `segments` by `delta_kg_per_m` [kg/m] per unit unstretched length
    /// (ice on, or off when negative).
    Ice {
        /// the segments
        segments: Range<usize>,
        /// change of linear density `delta rho0` [kg/m]
        delta_kg_per_m: f64,
    },
    /// Set the radial ice shell of `segments` (replacing theirs): its mass `rho_ice pi t (d + t)` [kg/m]
    /// per unit unstretched length and the wind diameter factor `(d + 2 t) / d` [-] (thickness `t` = 0:
    /// the shell is shed).
    RadialIce {
        /// the segments
        segments: Range<usize>,
        /// shell mass per unit length [kg/m]
        kg_per_m: f64,
        /// iced over bare diameter [-]
        diameter_factor: f64,
    },
    /// Set the wind multiplier to `scale` [-] (at once, `ramp_s = 0`, or as a linear ramp from its current
    /// value over `ramp_s` [s], [`super::WindRamp`]) and its gate; ends a gust or an earlier ramp.
    Wind {
        /// multiplier on the wind load [-]
        scale: f64,
        /// where the wind acts
        gate: WindGate,
        /// ramp duration [s] (0: a step)
        ramp_s: f64,
    },
    /// Start a gust `amplitude |sin(pi (t - t_event) / period_s)|` (law (4.5) with a physical period).
    Gust {
        /// period `P` [s]
        period_s: f64,
        /// peak multiplier [-]
        amplitude: f64,
        /// where the wind acts
        gate: WindGate,
    },
    /// Set the temperature of `segments` to `temperature_k` [K], at once (`ramp_s = 0`) or as a linear
    /// ramp over `ramp_s` [s]; stops heat conduction.
    Temperature {
        /// the segments
        segments: Range<usize>,
        /// target temperature `u` [K]
        temperature_k: f64,
        /// ramp duration [s]
        ramp_s: f64,
    },
    /// Start heat conduction (5.2) with `hold_nodes` held at `hold_temperature_k` [K].
    HeatConduction {
        /// the held nodes
        hold_nodes: Range<usize>,
        /// their temperature [K]
        hold_temperature_k: f64,
        /// dimensionless heat time per second of the run [1/s]
        heat_time_per_s: f64,
        /// boundary treatment at the wire's ends
        boundary: HeatBoundary,
    },
    /// Stop heat conduction.
    HeatConductionOff,
    /// Insulator string `insulator` (index in `Wire::insulators`) fails: it carries nothing from now on.
    InsulatorFailure {
        /// the string
        insulator: usize,
    },
    /// The conductor slips out of the clamp of string `insulator`: the string holds it no more and its
    /// mass leaves the clamp node.
    ClampSlip {
        /// the string
        insulator: usize,
    },
    /// Node `node` (a dead-end) is released: it becomes free.
    Release {
        /// the node
        node: usize,
    },
    /// Switch contact with the scenario's ground plane on or off.
    Ground {
        /// true: contact on
        on: bool,
    },
}

impl Action {
    /// Whether the action changes the ice (either form): at `t = 0` with a static start it is part of the
    /// initial state.
    pub fn is_ice(&self) -> bool {
        matches!(self, Action::Ice { .. } | Action::RadialIce { .. })
    }

    /// Apply an ice action to `wire`: `Some(true)` done, `Some(false)` refused (the wire unchanged: a
    /// segment mass would become non-positive), `None` not an ice action.
    pub fn apply_ice(&self, wire: &mut crate::wire::Wire) -> Option<bool> {
        match self {
            Action::Ice { segments, delta_kg_per_m } => {
                Some(wire.add_linear_density(segments.clone(), *delta_kg_per_m))
            }
            Action::RadialIce { segments, kg_per_m, diameter_factor } => {
                Some(wire.set_radial_ice(segments.clone(), *kg_per_m, *diameter_factor))
            }
            _ => None,
        }
    }
}

/// An action at a time.
#[derive(Clone, Debug, PartialEq)]
pub struct Event {
    /// when [s]
    pub time_s: f64,
    /// what
    pub action: Action,
}

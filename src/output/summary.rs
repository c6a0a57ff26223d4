//! `summary.json`: the outcome of a run in one JSON object, written whole or not at all (a temporary
//! file renamed into place, [`super::rows::write_atomically`]).

use serde::Serialize;

pub use super::peaks::{LeastLength, Peak, PeakForce, Phase, SpanPeaks, SupportPeaks};

/// Details of an instability, as written to the summary.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct InstabilityReport {
    /// time [s]
    pub time_s: f64,
    /// node index
    pub node: usize,
    /// what happened
    pub reason: String,
}

/// One support (a fixed node).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SupportSummary {
    /// node index
    pub node: usize,
    /// position of the support [m]
    pub position_m: [f64; 3],
    /// force the wire applies to the support at the end `[F1, F2, F3]` [N]
    pub final_force_n: [f64; 3],
    /// its peaks from `peaks_from_s` on, every time level
    pub peaks: SupportPeaks,
}

/// One span of a section.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct SpanSummary {
    /// span index (0 first)
    pub span: usize,
    /// its first and last node
    pub nodes: [usize; 2],
    /// its largest segment tension at the end [N]
    pub final_max_tension_n: f64,
    /// its least vertical clearance above the ground at the end [m] (with a ground)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub final_least_clearance_m: Option<f64>,
    /// its sag at the end: vertical distance from the chord down to the conductor at the horizontal
    /// middle of the span [m] ([`super::spans`]; absent for a broken span)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub final_sag_m: Option<f64>,
    /// its horizontal tension at the end: the tension's component along the horizontal chord direction at
    /// the middle of the span [N] ([`super::spans`]; absent for a broken span)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub final_horizontal_tension_n: Option<f64>,
    /// its peaks from `peaks_from_s` on, every time level
    pub peaks: SpanPeaks,
}

/// One probe (a Lagrangian point; the first is mid-span).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ProbeSummary {
    /// name
    pub name: String,
    /// fraction of the unstretched length from the first node [-]
    pub at_fraction: f64,
    /// displacement from the chord point at the same fraction at the end [m]
    pub final_displacement_m: [f64; 3],
    /// largest-magnitude displacement per component from `peaks_from_s` on, every time level [m]
    pub peak_displacement_m: [Peak; 3],
    /// largest increase of the displacement per component from its value at `peaks_from_s`, `>= 0`,
    /// every time level (the jump of an ice-shedding span is component 3) [m]
    pub peak_rise_m: [Peak; 3],
    /// largest decrease likewise, `<= 0` [m]
    pub peak_fall_m: [Peak; 3],
    /// mean period of each component's oscillation about the chord point from `peaks_from_s` on, from
    /// its sign changes interpolated between time levels (`crate::output::peaks`); `null` without two
    /// crossings in the same direction [s]
    pub period_about_chord_s: [Option<f64>; 3],
}

/// The static solve that gave the initial state (`[initial] shape = "equilibrium"`).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct EquilibriumReport {
    /// Newton iterations
    pub iterations: usize,
    /// largest nodal force residual at the end [N]
    pub residual_n: f64,
    /// the tolerance it met [N]
    pub tolerance_n: f64,
}

/// An event applied during the run.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct EventRecord {
    /// when [s]
    pub time_s: f64,
    /// what was done
    pub what: String,
}

/// Everything `summary.json` holds.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Summary {
    /// scenario name
    pub name: String,
    /// "completed" (end time reached), "settled", "not_settled" (time cap reached) or "unstable"
    pub status: String,
    /// true if the run ended because the wire settled (after its last event)
    pub settled: bool,
    /// when the settled stretch began [s] (present when settled)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub settled_since_s: Option<f64>,
    /// time at the end of the run [s]
    pub final_time_s: f64,
    /// dimensionless end time `tau` [-]
    pub final_tau: f64,
    /// mid-span displacement relative to the chord midpoint at the end, `[x1, x2, x3]` [m]
    pub final_midspan_displacement_m: [f64; 3],
    /// largest segment tension at the end [N]
    pub final_max_tension_n: f64,
    /// the peaks below count from this time [s]: the first event's time, or 0 without events
    pub peaks_from_s: f64,
    /// largest-magnitude mid-span displacement per component, every time level from `peaks_from_s` on
    pub peak_midspan_displacement_m: [Peak; 3],
    /// largest segment tension, every time level from `peaks_from_s` on [N]
    pub peak_max_tension_n: f64,
    /// when it occurred [s]
    pub peak_max_tension_time_s: f64,
    /// kinetic energy at the end [J]
    pub final_kinetic_j: f64,
    /// number of time steps
    pub steps: u64,
    /// number of segments `N`
    pub segments: usize,
    /// nominal time step [s]
    pub dt_s: f64,
    /// Courant number [-]
    pub courant: f64,
    /// longitudinal wave speed `c` [m/s]
    pub wave_speed_m_per_s: f64,
    /// wall-clock time of the time loop [s]
    pub wall_time_s: f64,
    /// throughput of the time loop, nodes x steps / wall time [1/s] (falls when other processes share
    /// the processor)
    pub node_steps_per_second: f64,
    /// CPU time of the time loop, the thread's ([`crate::output::cpu_time`]) [s]; absent where the system
    /// has no thread clock
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cpu_time_s: Option<f64>,
    /// throughput of the time loop per CPU second, nodes x steps / `cpu_time_s` [1/s]: the machine's
    /// speed with this run, nearly independent of its load
    #[serde(skip_serializing_if = "Option::is_none")]
    pub cpu_node_steps_per_second: Option<f64>,
    /// the static solve of the initial state, when the run started from equilibrium
    #[serde(skip_serializing_if = "Option::is_none")]
    pub initial_equilibrium: Option<EquilibriumReport>,
    /// valid but doubtful input values (field, value, reason): a result computed from them carries the doubt
    pub warnings: Vec<crate::scenario::Warning>,
    /// the supports, in node order
    pub supports: Vec<SupportSummary>,
    /// the probes (mid-span first)
    pub probes: Vec<ProbeSummary>,
    /// the spans of a section (empty for one span)
    pub spans: Vec<SpanSummary>,
    /// which peaks come from the start: present when the wind is raised during the run or acts from
    /// `t = 0` on a shape that is not its equilibrium ([`super::start_up`])
    #[serde(skip_serializing_if = "Option::is_none")]
    pub start_up: Option<super::start_up::StartUp>,
    /// the phases between events, each with its own peaks (every time level)
    pub phases: Vec<Phase>,
    /// the events applied
    pub events: Vec<EventRecord>,
    /// present when the run was stopped as unstable
    #[serde(skip_serializing_if = "Option::is_none")]
    pub instability: Option<InstabilityReport>,
    /// the conductor temperature of a `[thermal]` table
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thermal: Option<ThermalSummary>,
}

/// The conductor temperature of a `[thermal]` run (from its temperature history, computed at every RK4
/// step of the heat balance).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ThermalSummary {
    /// the catalogue conductor
    pub conductor: String,
    /// "ieee738" or "cigre601"
    pub standard: String,
    /// temperature at t = 0 [K]
    pub initial_temperature_k: f64,
    /// temperature at the end of the run [K]
    pub final_temperature_k: f64,
    /// highest temperature up to the end of the run [K]
    pub peak_temperature_k: f64,
    /// when it was reached [s]
    pub peak_temperature_time_s: f64,
    /// a de-icing: when melting began [s] (the conductor reached 0 C)
    #[serde(skip_serializing_if = "Option::is_none")]
    pub melting_from_s: Option<f64>,
    /// a de-icing: when the shell shed [s]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub shed_time_s: Option<f64>,
    /// a de-icing: the shell's mass [kg/m]
    #[serde(skip_serializing_if = "Option::is_none")]
    pub ice_kg_per_m: Option<f64>,
}

//! `summary.json`: the outcome of a run in one small JSON object.

use serde::Serialize;

/// The extreme of one component of the mid-span displacement.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct Peak {
    /// the displacement of largest magnitude, with its sign [m]
    pub value_m: f64,
    /// when it occurred [s]
    pub time_s: f64,
    /// when it occurred, dimensionless `tau = t U / l` [-]
    pub tau: f64,
}

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

/// Everything `summary.json` holds.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Summary {
    /// scenario name
    pub name: String,
    /// "completed" (end time reached), "settled", "not_settled" (time cap reached) or "unstable"
    pub status: String,
    /// true if the run ended because the wire settled
    pub settled: bool,
    /// time at the end of the run [s]
    pub final_time_s: f64,
    /// dimensionless end time `tau` [-]
    pub final_tau: f64,
    /// mid-span displacement relative to the chord midpoint at the end, `[x1, x2, x3]` [m]
    pub final_midspan_displacement_m: [f64; 3],
    /// largest segment tension at the end [N]
    pub final_max_tension_n: f64,
    /// largest-magnitude mid-span displacement per component, over all steps
    pub peak_midspan_displacement_m: [Peak; 3],
    /// largest segment tension over all samples [N]
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
    /// throughput of the time loop, nodes x steps / wall time [1/s]
    pub node_steps_per_second: f64,
    /// present when the run was stopped as unstable
    #[serde(skip_serializing_if = "Option::is_none")]
    pub instability: Option<InstabilityReport>,
}

//! The one conversion of a scenario into a run plan ([`build`]): every field checked, then the model
//! built from the quantities the checks derived (`EA`, chord, length, wave speed, time step): the
//! initial shape with equally spaced nodes (or the static equilibrium), the loads, the events in their
//! domain form ([`crate::events::Event`]) and the outputs asked for.

use super::events::{EventSpec, GateSpec, GroundSpec, HeatBoundarySpec, break_segment, node_range, segment_range};
use super::schema::{GeometrySpec, Scenario, ShapeSpec, TensionLawSpec, WindLawSpec};
use super::validate::Problem;
use crate::element::aero::{Aerodynamic, UniformNormal};
use crate::element::tension::LawKind;
use crate::events::{Action, Event};
use crate::heat::HeatBoundary;
use crate::output::probe::ProbeAt;
use crate::scheme::{Explicit, Ground, Loads, StepParams, WindGate, WindLoad};
use crate::statics::{self, StaticOptions, StaticReport};
use crate::wire::{Conductor, Wire};

/// When the run stops.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Stop {
    /// at a fixed time [s]
    EndTime(f64),
    /// when the kinetic energy has stayed below `fraction` of its peak for `window_s`, or at `max_time_s`
    Settled {
        /// threshold as a fraction of the peak kinetic energy [-]
        fraction: f64,
        /// how long it must stay below [s]
        window_s: f64,
        /// time cap [s]
        max_time_s: f64,
    },
}

impl Stop {
    /// The latest time the run may reach [s].
    pub fn horizon_s(&self) -> f64 {
        match *self {
            Stop::EndTime(t) => t,
            Stop::Settled { max_time_s, .. } => max_time_s,
        }
    }
}

/// A solver at `t = 0` with everything the driver needs to run it.
#[derive(Clone, Debug)]
pub struct Plan {
    /// scenario name (or "scenario")
    pub name: String,
    /// the solver, at its initial state
    pub solver: Explicit,
    /// left support `A` [m]
    pub left_support_m: [f64; 3],
    /// right support `B` [m]
    pub right_support_m: [f64; 3],
    /// chord length `l = |B - A|` [m]
    pub chord_m: f64,
    /// longitudinal wave speed `c = sqrt(EA / rho0)` [m/s]
    pub wave_speed_m_per_s: f64,
    /// Courant number of (3.7) [-]
    pub courant: f64,
    /// when to stop
    pub stop: Stop,
    /// interval between time-series rows [s]
    pub sample_interval_s: f64,
    /// snapshot times, sorted [s]
    pub snapshot_times_s: Vec<f64>,
    /// speed of the dimensionless time `tau = t U / l` [m/s]
    pub tau_speed_m_per_s: f64,
    /// the event timeline, sorted by time (stable: events at the same time keep the file's order)
    pub events: Vec<Event>,
    /// the ground plane, if the scenario has one (on the solver from the start if it is active)
    pub ground: Option<Ground>,
    /// named probes besides mid-span: (name, fraction of the unstretched length [-])
    pub probes: Vec<(String, ProbeAt)>,
    /// the run's peaks count from this time [s]; default the first event's time (0 without events)
    pub peaks_from_s: Option<f64>,
    /// the static solve of `[initial] shape = "equilibrium"` (iterations, residual), if the scenario asked
    pub initial_equilibrium: Option<StaticReport>,
    /// valid but doubtful values ([`super::warnings`]), in the order of the file
    pub warnings: Vec<super::Warning>,
    /// the spans of a `[section]` as (first node, last node); empty for a `[geometry]` scenario
    pub spans: Vec<(usize, usize)>,
    /// the conductor's temperature history of a `[thermal]` table, played onto the wire during the run
    pub thermal: Option<super::thermal::ThermalHistory>,
    /// the `[[events]]` index of each `heat_conduction` event, in the order of `events` (by time, then
    /// the file's order), to name the event in messages
    pub heat_conduction_events: Vec<usize>,
}

impl Plan {
    /// Dimensionless time `tau = t U / l` of the paper (section 2).
    pub fn tau(&self, t_s: f64) -> f64 {
        t_s * self.tau_speed_m_per_s / self.chord_m
    }
    /// The plan's event timeline at `t = 0` (its events, the ground plane its `ground` events switch, the
    /// temperature history of its `[thermal]` table).
    pub fn timeline(&self) -> crate::events::EventState {
        let heating = self.thermal.as_ref().map(|h| crate::events::Heating::new(h.samples.clone()));
        crate::events::EventState::new(self.events.clone(), self.ground.clone(), heating)
    }

    /// Midpoint of the chord `(A + B) / 2` [m].
    pub fn chord_midpoint(&self) -> [f64; 3] {
        [0, 1, 2].map(|k| 0.5 * (self.left_support_m[k] + self.right_support_m[k]))
    }
}

/// Arc length of the parabola `y = 4 f u (1 - u)` over a chord `l` (`u` in [0, 1]) [m].
pub fn parabola_length(chord_m: f64, sag_m: f64) -> f64 {
    // Exact: with k = 4 f / l, L = l/2 sqrt(1 + k^2) + l/(2k) asinh(k) = l P_k(1).
    chord_m * arc_primitive(4.0 * sag_m / chord_m, 1.0)
}

/// `P_k(t) = prim(k t) / k` with `prim(y) = (y sqrt(1 + y^2) + asinh y) / 2`, the primitive of
/// `sqrt(1 + (k t)^2)` in `t`, written so that it stays exact as `k -> 0` (a sag of 1e-300 m is a straight
/// wire, not `inf * 0`): `asinh(y) / k = t asinh(y) / y`, and `asinh(y) / y = 1 - y^2/6 + 3 y^4/40` below
/// `|y| = 1e-4` (next term `5 y^6 / 112 < 1e-25`).
fn arc_primitive(k: f64, t: f64) -> f64 {
    let y = k * t;
    let asinh_ratio = if y.abs() < 1.0e-4 {
        let y2 = y * y;
        1.0 - y2 / 6.0 + 3.0 * y2 * y2 / 40.0
    } else {
        y.asinh() / y
    };
    0.5 * t * ((1.0 + y * y).sqrt() + asinh_ratio)
}

/// The bisection of `[0, 1]` for `arc(u) = target` that places the nodes of the parabola start: halve
/// `[lo, hi]` on the comparison `arc(mid) < target` until `hi - lo < 1e-16` (53 halvings), returning
/// `(lo, hi)` (or earlier where a halving no longer changes them). `side(mid)` gives the comparison where it is certain without evaluating `arc`
/// ([`certain_side`]; `None`: evaluate), so the halvings, and the result, are bitwise those of
/// evaluating `arc` at every midpoint.
fn bisect_arc(arc: impl Fn(f64) -> f64, side: impl Fn(f64) -> Option<bool>, target: f64) -> (f64, f64) {
    let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        let before = (lo, hi);
        if side(mid).unwrap_or_else(|| arc(mid) < target) {
            lo = mid
        } else {
            hi = mid
        }
        if hi - lo < 1e-16 || (lo, hi) == before {
            // Unchanged (adjacent doubles above 1/2, 1.1e-16 apart: `mid` is `lo` or `hi`): every later
            // halving repeats this one, so the loop as first written ends with this `(lo, hi)` too.
            break;
        }
    }
    (lo, hi)
}

/// Where the comparison `arc(u) < target` of [`bisect_arc`] is certain: for `u` more than `eps` below
/// a Newton root `u*` of `arc(u) = target` it holds, more than `eps` above it it does not.
///
/// Why: the arc length `A(u)` grows at `dA/du = l sqrt(1 + (k (1 - 2u))^2) >= l` (the chord `l`), and
/// the computed `arc` is within `delta` of `A` everywhere, `delta = 1e-13 total` (the closed form's few
/// rounding errors are about `3e-15 total`: a 30-fold margin). With `r = |arc(u*) - target|`,
/// `|A(u*) - target| <= r + delta`, so for `u < u* - eps`: `arc(u) <= A(u) + delta <= A(u*) - l eps +
/// delta <= target + r + 2 delta - l eps < target` once `l eps > r + 2 delta`; symmetrically above. Here
/// `eps = 2 (r + 3 delta) / l`. Near `u*` (the last dozen halvings) `arc` is evaluated. A root that is
/// not finite decides nothing.
fn certain_side(
    arc: impl Fn(f64) -> f64,
    slope: impl Fn(f64) -> f64,
    target: f64,
    total: f64,
    chord: f64,
) -> CertainSide {
    let mut u = if total > 0.0 { (target / total).clamp(0.0, 1.0) } else { 0.5 };
    for _ in 0..8 {
        let step = (arc(u) - target) / slope(u);
        u = (u - step).clamp(0.0, 1.0);
        if step.abs() <= 1e-15 || step.is_nan() {
            break;
        }
    }
    let r = (arc(u) - target).abs();
    let eps = 2.0 * (r + 3.0 * 1.0e-13 * total) / chord;
    CertainSide { u, eps, known: u.is_finite() && eps.is_finite() && eps >= 0.0 }
}

/// The Newton root `u` and the half-width `eps` around it of [`certain_side`].
#[derive(Clone, Copy, Debug)]
struct CertainSide {
    u: f64,
    eps: f64,
    known: bool,
}

impl CertainSide {
    /// `arc(mid) < target` where certain, `None` where `arc` must be evaluated.
    fn side(&self, mid: f64) -> Option<bool> {
        if !self.known {
            None
        } else if mid < self.u - self.eps {
            Some(true)
        } else if mid > self.u + self.eps {
            Some(false)
        } else {
            None
        }
    }
}

/// Nodes equally spaced in arc length along the initial shape; returns positions and the shape's length.
fn initial_nodes(s: &Scenario, g: &GeometrySpec) -> ([Vec<f64>; 3], f64) {
    let (a, b) = (g.left_support_m, g.right_support_m);
    let n = g.segments;
    let d = [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let chord = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
    let mut x = [vec![0.0; n + 1], vec![0.0; n + 1], vec![0.0; n + 1]];
    match (s.initial.shape, s.initial.sag_m) {
        (ShapeSpec::Parabola | ShapeSpec::Equilibrium, Some(f)) => {
            // p(u) = A + u (B - A) - 4 f u (1 - u) e3; the arc length s(u) has a closed form (below),
            // inverted by bisection for each node ([`bisect_arc`], its comparisons decided from a Newton
            // root where they are certain).
            let total = parabola_length(chord, f);
            let k = 4.0 * f / chord;
            // s(u) = (l / (2k)) [prim(k (2u - 1)) + prim(k)] = (l / 2) [P_k(2u - 1) + P_k(1)] is the arc length
            // from u = 0 (ds/du = l sqrt(1 + (k(1-2u))^2)).
            let arc = |u: f64| 0.5 * chord * (arc_primitive(k, 2.0 * u - 1.0) + arc_primitive(k, 1.0));
            let slope = |u: f64| chord * (1.0 + (k * (2.0 * u - 1.0)).powi(2)).sqrt();
            for i in 0..=n {
                let target = total * i as f64 / n as f64;
                let side = certain_side(arc, slope, target, total, chord);
                let (lo, hi) = bisect_arc(arc, |mid| side.side(mid), target);
                let u = if i == n {
                    1.0
                } else if i == 0 {
                    0.0
                } else {
                    0.5 * (lo + hi)
                };
                for kk in 0..3 {
                    x[kk][i] = a[kk] + u * d[kk];
                }
                x[2][i] -= 4.0 * f * u * (1.0 - u);
            }
            (x, total)
        }
        _ => {
            for i in 0..=n {
                let u = i as f64 / n as f64;
                for kk in 0..3 {
                    x[kk][i] = a[kk] + u * d[kk];
                }
            }
            (x, chord)
        }
    }
}

fn gate(g: GateSpec) -> WindGate {
    match g {
        GateSpec::Always => WindGate::Always,
        GateSpec::Downwind => WindGate::Downwind,
    }
}

/// The action of an ice event on `segments`: a change of linear density, or a radial shell of thickness
/// `t` and density `rho_ice` on the conductor's diameter `d` ([`crate::loads::radial_ice`]).
fn ice_action(e: &EventSpec, segments: std::ops::Range<usize>, diameter_m: Option<f64>) -> Action {
    match *e {
        EventSpec::Ice { radial_thickness_m: Some(t), density_kg_per_m3, .. } => {
            let shell = crate::loads::RadialIce { thickness_m: t, density_kg_per_m3: density_kg_per_m3.unwrap_or(0.0) };
            let d = diameter_m.unwrap_or(0.0);
            Action::RadialIce { segments, kg_per_m: shell.kg_per_m(d), diameter_factor: shell.diameter_factor(d) }
        }
        EventSpec::Ice { linear_density_kg_per_m, .. } => {
            Action::Ice { segments, delta_kg_per_m: linear_density_kg_per_m.unwrap_or(0.0) }
        }
        _ => unreachable!("ice_action is called on ice events"),
    }
}

/// The events of an `[[events]]` table on an `n`-segment wire: span fractions resolved to indices, a
/// break or ice event in the span (first segment, segments) it names (`spans[0]` by default), a failing
/// string by its support's node. A progressive ice change (a shedding front moving at `v` [m/s]) becomes
/// one change per segment, at the time the front reaches the segment's middle.
fn events_of(
    e: &EventSpec,
    n: usize,
    spans: &[(usize, usize)],
    wire: &Wire,
    support_node: &[usize],
    diameter_m: Option<f64>,
) -> Vec<Event> {
    let (first, n_span) = spans[e.span().unwrap_or(0)];
    let shift = |r: std::ops::Range<usize>| first + r.start..first + r.end;
    let action = match *e {
        EventSpec::Break { at_fraction, .. } => Action::Break { segment: first + break_segment(at_fraction, n_span) },
        EventSpec::Ice { range, front_speed_m_per_s: Some(v), time_s, .. } => {
            // The front starts at the range's first end (a < b) and moves toward its second.
            let mut s_m = 0.0;
            return shift(segment_range(range, n_span))
                .map(|j| {
                    let l = wire.reference_length[j];
                    let middle = s_m + 0.5 * l;
                    s_m += l;
                    Event { time_s: time_s + middle / v, action: ice_action(e, j..j + 1, diameter_m) }
                })
                .collect();
        }
        EventSpec::Ice { range, .. } => ice_action(e, shift(segment_range(range, n_span)), diameter_m),
        EventSpec::InsulatorFailure { support, .. } | EventSpec::ClampSlip { support, .. } => {
            let node = support_node.get(support).copied().unwrap_or(usize::MAX);
            let insulator = wire.insulators.iter().position(|i| i.node == node).unwrap_or(usize::MAX);
            if matches!(e, EventSpec::ClampSlip { .. }) {
                Action::ClampSlip { insulator }
            } else {
                Action::InsulatorFailure { insulator }
            }
        }
        EventSpec::Release { support, .. } => Action::Release { node: support_node.get(support).copied().unwrap_or(0) },
        EventSpec::Wind { scale, gate: g, ramp_s, .. } => Action::Wind { scale, gate: gate(g), ramp_s },
        EventSpec::Gust { period_s, amplitude, gate: g, .. } => Action::Gust { period_s, amplitude, gate: gate(g) },
        EventSpec::Temperature { temperature_k, range, ramp_s, .. } => {
            Action::Temperature { segments: segment_range(range, n), temperature_k, ramp_s }
        }
        EventSpec::HeatConduction { hold_range, hold_temperature_k, heat_time_per_s, boundary, .. } => {
            Action::HeatConduction {
                hold_nodes: node_range(hold_range, n),
                hold_temperature_k,
                heat_time_per_s,
                boundary: match boundary {
                    HeatBoundarySpec::LagrangeQuadratic => HeatBoundary::LagrangeQuadratic,
                    HeatBoundarySpec::Linear => HeatBoundary::Linear,
                    HeatBoundarySpec::ZeroFlux => HeatBoundary::ZeroFlux,
                },
            }
        }
        EventSpec::HeatConductionOff { .. } => Action::HeatConductionOff,
        EventSpec::Ground { on, .. } => Action::Ground { on },
    };
    vec![Event { time_s: e.time_s(), action }]
}

/// The one conversion of a scenario into a solver and its run plan: every field is checked
/// ([`super::validate`]) and, if all are valid, the model is built from the quantities the checks derived
/// (`EA`, chord, length, wave speed, time step). Errors list every problem found.
pub fn build(s: &Scenario) -> Result<Plan, Vec<Problem>> {
    let (problems, d) = super::validate::check(s);
    if !problems.is_empty() {
        return Err(problems);
    }
    let missing = |what: &str| Problem {
        field: what.into(),
        value: "(not derived)".into(),
        allowed: "internal error: validation passed without deriving it; please report".into(),
    };
    let ea = d.ea_n.ok_or_else(|| vec![missing("conductor.axial_stiffness_n")])?;
    let chord_m = d.chord_m.ok_or_else(|| vec![missing("geometry.right_support_m")])?;
    let length = d.length_m.ok_or_else(|| vec![missing("geometry.unstretched_length_m")])?;
    let c = d.wave_speed_m_per_s.ok_or_else(|| vec![missing("conductor.linear_density_kg_per_m")])?;
    let dt = d.dt_s.ok_or_else(|| vec![missing("numerics.courant")])?;
    let cd = &s.conductor;
    let rho = cd.linear_density_kg_per_m;
    let (mut wire, spans, support_node) = match (&d.section, &s.geometry) {
        (Some(sg), _) => {
            let l = &sg.layout;
            let spans = (0..l.first_node.len() - 1).map(|k| (l.first_node[k], l.first_node[k + 1] - l.first_node[k]));
            (sg.wire.clone(), spans.collect(), l.support_node.clone())
        }
        (None, Some(g)) => {
            let n = g.segments;
            let (x, _) = initial_nodes(s, g);
            let law = match cd.tension_law {
                TensionLawSpec::TensionOnly | TensionLawSpec::TwoMaterial => LawKind::TensionOnly,
                TensionLawSpec::Linear => LawKind::Linear,
            };
            let conductor = Conductor { axial_stiffness_n: ea, internal_friction_n_s: s.numerics.eta_n_s, law };
            (Wire::new(conductor, x, vec![length / n as f64; n], rho), vec![(0, n)], vec![0, n])
        }
        (None, None) => return Err(vec![missing("geometry")]),
    };
    let n = wire.segments();
    wire.thermal_expansion_per_k = cd.thermal_expansion_per_k;
    wire.reference_temperature_k = cd.reference_temperature_k;
    wire.temperature_k.fill(cd.reference_temperature_k);
    if let Some((law, curve)) = d.material {
        wire.set_two_material(law, curve);
    }

    let wind = s.loads.wind.as_ref().map(|w| {
        let norm: f64 = w.direction.iter().map(|v| v * v).sum::<f64>().sqrt();
        let direction = w.direction.map(|v| v / norm);
        // Still air (`U = 0`): no drag and no aerodynamic damping (2.6), whose `mu / U` is then taken as 0
        // (the load it multiplies is 0 anyway; validation refuses 0 < U < 0.01, where `mu / U` overflows).
        let mu_over_u = if w.speed_m_per_s > 0.0 { s.numerics.mu / w.speed_m_per_s } else { 0.0 };
        match w.law {
            WindLawSpec::UniformNormal => WindLoad::UniformNormal(UniformNormal {
                direction,
                pressure_n_per_m: w.pressure_n_per_m.unwrap_or(0.0),
                mu_over_u,
            }),
            WindLawSpec::Aerodynamic => {
                let qd = 0.5 * w.air_density_kg_per_m3 * w.speed_m_per_s.powi(2) * cd.diameter_m.unwrap_or(0.0);
                WindLoad::Aerodynamic(Aerodynamic {
                    direction,
                    qd_cn: qd * w.normal_coefficient,
                    qd_ct: qd * w.tangential_coefficient,
                    mu_over_u,
                })
            }
        }
    });
    let loads = Loads {
        gravity_m_per_s2: s.loads.gravity_m_per_s2,
        uniform_load_n_per_m: s.loads.uniform_load_n_per_m,
        wind,
        // A wind ramp `[loads.wind] ramp_s` starts from still air: the multiplier is 0 at `t = 0` (and in the
        // equilibrium solved there) and a `wind` event at `t = 0` ramps it up to `initial_scale` (below; none for 0).
        wind_scale: s.loads.wind.as_ref().map_or(1.0, |w| if w.ramp_s > 0.0 { 0.0 } else { w.initial_scale }),
        wind_gate: WindGate::Always,
    };
    let mut warnings = super::warnings::warnings(s);
    // A clamp or crossarm that sets the step (module doc of `super::section`): the conductor's own step is
    // validation's `C ds / c` over the section's fastest wave and shortest crossing time.
    if let Some(sg) = &d.section
        && let Some(limit) = &sg.step_limit
    {
        let cw = sg.wave_speed_max_m_per_s;
        let conductor_step_s = crate::scheme::courant::time_step(s.numerics.courant, sg.crossing_time_s * cw, cw);
        let n = &s.numerics;
        warnings.extend(super::warnings::step_limit(limit, n.courant, conductor_step_s, dt, n.smoothing));
    }
    let params = StepParams {
        dt_s: dt,
        smoothing: s.numerics.smoothing,
        mass_damping_per_s: s.numerics.mass_damping_per_s,
        max_speed_m_per_s: s.numerics.max_speed_m_per_s.unwrap_or(c),
    };
    let stop = match (s.duration.end_time_s, &s.duration.until_settled) {
        (Some(t), _) => Stop::EndTime(t),
        (None, Some(st)) => {
            Stop::Settled { fraction: st.kinetic_energy_fraction, window_s: st.window_s, max_time_s: st.max_time_s }
        }
        (None, None) => return Err(vec![missing("duration")]),
    };
    let mut snaps = s.output.snapshot_times_s.clone();
    snaps.sort_by(f64::total_cmp);
    snaps.dedup();
    let (a, b) = (wire.position(0), wire.position(n));
    let mut events: Vec<Event> =
        s.events.iter().flat_map(|e| events_of(e, n, &spans, &wire, &support_node, cd.diameter_m)).collect();
    events.sort_by(|p, q| p.time_s.total_cmp(&q.time_s));
    if let Some(w) = s.loads.wind.as_ref().filter(|w| w.ramp_s > 0.0 && w.initial_scale > 0.0) {
        let ramp = Action::Wind { scale: w.initial_scale, gate: WindGate::Always, ramp_s: w.ramp_s };
        events.insert(0, Event { time_s: 0.0, action: ramp });
    }
    // The same stable sort keeps the heat_conduction events in the order `events` has them.
    let mut heat_conduction: Vec<(f64, usize)> = (s.events.iter().enumerate())
        .filter(|(_, e)| matches!(e, EventSpec::HeatConduction { .. }))
        .map(|(k, e)| (e.time_s(), k))
        .collect();
    heat_conduction.sort_by(|p, q| p.0.total_cmp(&q.0));
    let heat_conduction_events = heat_conduction.into_iter().map(|(_, k)| k).collect();
    // A section's spans each get a mid-span probe `span{k}_mid`, measured from the span's own chord.
    let mut probes: Vec<(String, ProbeAt)> = Vec::new();
    if d.section.is_some() {
        for (k, &(first, n_k)) in spans.iter().enumerate() {
            probes.push((format!("span{k}_mid"), ProbeAt::Span { first, last: first + n_k, fraction: 0.5 }));
        }
    }
    probes.extend(s.output.probes.iter().map(|p| (p.name.clone(), ProbeAt::Line(p.at_fraction))));
    // The `[thermal]` history: its temperature at t = 0 is the initial state (and that of the static
    // solve); a de-icing shell is ice on its spans from t = 0 and sheds at its computed time.
    let horizon = match stop {
        Stop::EndTime(t) => t,
        Stop::Settled { max_time_s, .. } => max_time_s,
    };
    let thermal = match &s.thermal {
        Some(t) => Some(super::thermal::thermal_history(t, horizon, &spans).map_err(|p| vec![p])?),
        None => None,
    };
    if let Some(h) = &thermal {
        wire.set_temperature(0..n, h.samples[0].1);
        if let Some(shed) = &h.shed {
            for &k in &shed.spans {
                let (first, n_k) = spans[k];
                let segments = first..first + n_k;
                events.push(Event {
                    time_s: 0.0,
                    action: Action::Ice { segments: segments.clone(), delta_kg_per_m: shed.ice_kg_per_m },
                });
                events.push(Event {
                    time_s: shed.time_s,
                    action: Action::Ice { segments, delta_kg_per_m: -shed.ice_kg_per_m },
                });
            }
            events.sort_by(|p, q| p.time_s.total_cmp(&q.time_s));
        }
    }
    let mut solver = Explicit::new(wire, loads, params);
    let initial_equilibrium = match s.initial.shape {
        ShapeSpec::Equilibrium => {
            // Ice present from the start (events at t = 0) is part of the state whose equilibrium is
            // solved: applied to the wire here and taken off the timeline.
            let (now, later): (Vec<Event>, Vec<Event>) =
                events.into_iter().partition(|e| e.time_s == 0.0 && e.action.is_ice());
            events = later;
            for e in now {
                if e.action.apply_ice(solver.wire_mut()) == Some(false) {
                    return Err(vec![missing("events (ice at t = 0)")]);
                }
            }
            Some(equilibrium(&mut solver, s)?)
        }
        _ => None,
    };
    solver.set_ground(s.ground.as_ref().filter(|g| g.active).map(GroundSpec::ground));
    Ok(Plan {
        name: s.name.clone().unwrap_or_else(|| "scenario".into()),
        solver,
        left_support_m: a,
        right_support_m: b,
        chord_m,
        wave_speed_m_per_s: c,
        courant: s.numerics.courant,
        stop,
        sample_interval_s: s.output.sample_interval_s,
        snapshot_times_s: snaps,
        tau_speed_m_per_s: s.output.tau_speed_m_per_s,
        events,
        ground: s.ground.as_ref().map(GroundSpec::ground),
        probes,
        peaks_from_s: s.output.peaks_from_s,
        initial_equilibrium,
        warnings,
        spans: if d.section.is_some() { spans.iter().map(|&(f, n)| (f, f + n)).collect() } else { Vec::new() },
        thermal,
        heat_conduction_events,
    })
}

/// Move the solver's wire to the static equilibrium of its loads at `t = 0` (before ground contact is
/// switched on). A failed solve, or an equilibrium below the ground plane, is a problem of the field
/// `initial.shape`, with the solver's iterations and residual.
fn equilibrium(solver: &mut Explicit, s: &Scenario) -> Result<StaticReport, Vec<Problem>> {
    let fail =
        |why: String| vec![Problem { field: "initial.shape".into(), value: "\"equilibrium\"".into(), allowed: why }];
    let report = statics::solve(solver, &StaticOptions::default())
        .map_err(|e| fail(format!("the static equilibrium of the loads at t = 0 was not found: {e}")))?;
    if let Some(g) = s.ground.as_ref().filter(|g| g.active) {
        let w = solver.wire();
        let (g, n) = (g.ground(), w.segments());
        if let Some(i) = (0..=n).find(|&i| g.clearance_m(w.position(i)) < 0.0) {
            return Err(fail(format!(
                "the equilibrium reaches x3 = {:.6} m at node {i} (x2 = {:.3} m), below the ground there ({} m)",
                w.x[2][i],
                w.x[1][i],
                g.height_at(w.x[1][i])
            )));
        }
    }
    Ok(report)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bisection as first written: 200 halvings at most, ending only at `hi - lo < 1e-16`.
    fn full_bisection(arc: impl Fn(f64) -> f64, target: f64) -> (f64, f64) {
        let (mut lo, mut hi) = (0.0_f64, 1.0_f64);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if arc(mid) < target {
                lo = mid
            } else {
                hi = mid
            }
            if hi - lo < 1e-16 {
                break;
            }
        }
        (lo, hi)
    }

    /// The parabola start's bisection with comparisons decided from the Newton root gives the same
    /// numbers, bit for bit, as evaluating the arc length at every midpoint, and evaluates it fewer than
    /// 25 times a node in the halvings (15 to 18 in these cases; the Newton root adds a few), against 53
    /// to 200 (above `u = 1/2` the halvings never reached `hi - lo < 1e-16` and ran all 200).
    #[test]
    fn parabola_start_bisection_is_bitwise_the_full_bisection() {
        // chords and sags from a taut span to a slack one, node counts and every node's target
        for (chord, sag) in [(400.0, 12.0), (160.0, 1e-300), (300.0, 0.3), (50.0, 40.0), (1000.0, 120.0), (1.0, 3.0)] {
            let total = parabola_length(chord, sag);
            let k = 4.0 * sag / chord;
            let arc = |u: f64| 0.5 * chord * (arc_primitive(k, 2.0 * u - 1.0) + arc_primitive(k, 1.0));
            let slope = |u: f64| chord * (1.0 + (k * (2.0 * u - 1.0)).powi(2)).sqrt();
            let counted = std::cell::Cell::new(0);
            let arc_counted = |u: f64| {
                counted.set(counted.get() + 1);
                arc(u)
            };
            for n in [1, 7, 100, 1000] {
                for i in 0..=n {
                    let target = total * i as f64 / n as f64;
                    let full = full_bisection(arc, target);
                    let side = certain_side(arc, slope, target, total, chord);
                    let fast = bisect_arc(arc_counted, |mid| side.side(mid), target);
                    assert_eq!(
                        (fast.0.to_bits(), fast.1.to_bits()),
                        (full.0.to_bits(), full.1.to_bits()),
                        "{chord} {sag} {n} {i}"
                    );
                }
            }
            let nodes = 1 + 7 + 100 + 1000 + 4;
            assert!(counted.get() < 25 * nodes, "{chord} {sag}: {} evaluations for {nodes} nodes", counted.get());
        }
    }

    #[test]
    fn parabola_length_matches_quadrature() {
        // Composite Simpson on sqrt(1 + (k (1 - 2u))^2) l du with 2000 panels: error ~ 1e-13 here.
        let (l, f) = (160.0, 7.27);
        let k = 4.0 * f / l;
        let m = 2000;
        let h = 1.0 / m as f64;
        let g = |u: f64| l * (1.0 + (k * (1.0 - 2.0 * u)).powi(2)).sqrt();
        let mut sum = g(0.0) + g(1.0);
        for i in 1..m {
            sum += if i % 2 == 1 { 4.0 } else { 2.0 } * g(i as f64 * h);
        }
        let simpson = sum * h / 3.0;
        assert!((parabola_length(l, f) - simpson).abs() < 1e-9, "{} vs {simpson}", parabola_length(l, f));
    }

    #[test]
    fn a_vanishing_sag_gives_the_chord_and_evenly_spaced_nodes() {
        // L = l (1 + 8 f^2 / (3 l^2) + O(f^4)): below f = 1e-6 l the correction is under 3e-12 l.
        for f in [1e-3, 1e-5, 1e-9, 1e-300, f64::MIN_POSITIVE] {
            let len = parabola_length(160.0, f);
            let expect = 160.0 * (1.0 + 8.0 * f * f / (3.0 * 160.0 * 160.0));
            assert!((len - expect).abs() < 1e-9, "f = {f}: {len} vs {expect}");
        }
        let text = "[conductor]\naxial_stiffness_n = 792000.0\nlinear_density_kg_per_m = 1.0\n[geometry]\n\
            left_support_m = [0.0, 0.0, 0.0]\nright_support_m = [0.0, 160.0, 0.0]\nsegments = 8\n[initial]\n\
            shape = \"parabola\"\nsag_m = 2.2250738585072014e-308\n[duration]\nend_time_s = 0.5\n";
        let sc: Scenario = toml::from_str(text).unwrap();
        let (x, _) = initial_nodes(&sc, sc.geometry.as_ref().unwrap());
        for i in 0..=8 {
            assert!((x[1][i] - 20.0 * i as f64).abs() < 1e-9 && x[2][i].abs() < 1e-9, "node {i}");
        }
    }
}

//! The event timeline at run time: what each event of a scenario's `[[events]]` does to the solver,
//! and the continuous processes some of them start (a gust, a temperature ramp, heat conduction).
//!
//! The driver ([`crate::run`]) steps exactly onto every event time ([`EventState::next_time`]), applies
//! the events due there ([`EventState::apply_due`]), and around every step calls
//! [`EventState::before_step`] (gust multiplier and temperature ramps at the step's start time) and
//! [`EventState::after_step`] (heat conduction over the step). What each event does:
//!
//! - `break`: [`Wire::break_segment`](crate::wire::Wire::break_segment), the break (3.5); both parts
//!   continue as free-ended wires;
//! - `ice`: [`Wire::add_linear_density`](crate::wire::Wire::add_linear_density) over the span range;
//! - `wind`: a multiplier on the wind load and its gate, at once or as a linear ramp from its current
//!   value ([`wind_ramp`]; ends a gust);
//! - `gust`: the law (4.5) with a physical period ([`gust`]);
//! - `temperature`: a step or a linear ramp ([`ramp`]) of the segment temperatures; the stress-free
//!   lengths follow by (5.5) through [`Wire::update_rest_lengths`](crate::wire::Wire::update_rest_lengths);
//! - `heat_conduction` / `heat_conduction_off`: the heat equation (5.2) along the wire with a held span
//!   range ([`conduction`]);
//! - `ground`: contact with the `[ground]` plane on or off (section 4.4).
//!
//! A `[thermal]` table plays its temperature history onto the wire before every step ([`heating`]).

pub mod conduction;
pub mod event;
pub mod gust;
pub mod heating;
pub mod ramp;
pub mod wind_ramp;

use crate::scheme::{Explicit, Ground};

pub use conduction::Conduction;
pub use event::{Action, Event};
pub use gust::Gust;
pub use heating::Heating;
pub use ramp::Ramp;
pub use wind_ramp::WindRamp;

/// The timeline and the processes running.
#[derive(Clone, Debug)]
pub struct EventState {
    events: Vec<Event>,
    next: usize,
    ground: Option<Ground>,
    gust: Option<Gust>,
    wind_ramp: Option<WindRamp>,
    ramps: Vec<Ramp>,
    conduction: Option<Conduction>,
    heating: Option<Heating>,
    /// events applied so far: (time [s], description)
    pub log: Vec<(f64, String)>,
}

impl EventState {
    /// A timeline of `events` (sorted by time), nothing applied yet: `ground` is the plane a `ground`
    /// event switches on, `heating` a temperature history played before every step. Built from the domain
    /// types only (a scenario's plan gives them: [`crate::scenario::Plan::timeline`]), so the runtime does
    /// not depend on the input format.
    pub fn new(events: Vec<Event>, ground: Option<Ground>, heating: Option<Heating>) -> Self {
        EventState {
            events,
            next: 0,
            ground,
            gust: None,
            wind_ramp: None,
            ramps: Vec::new(),
            conduction: None,
            heating,
            log: Vec::new(),
        }
    }

    /// Time of the next event not yet applied [s].
    pub fn next_time(&self) -> Option<f64> {
        self.events.get(self.next).map(|e| e.time_s)
    }

    /// Apply every event due at or before `t + tol` [s]; returns how many were applied.
    #[inline]
    pub fn apply_due(&mut self, solver: &mut Explicit, t: f64, tol: f64) -> usize {
        // At most levels no event is due: the test of the loop below, inlined into the driver's loop.
        match self.events.get(self.next) {
            Some(e) if e.time_s > t + tol => 0,
            Some(_) => self.apply_due_now(solver, t, tol),
            None => 0,
        }
    }

    #[inline(never)]
    fn apply_due_now(&mut self, solver: &mut Explicit, t: f64, tol: f64) -> usize {
        let mut count = 0;
        // The time is read in place; an event is cloned only when it is applied (this cloned the next
        // event at every level to compare its time).
        while let Some(e) = self.events.get(self.next) {
            if e.time_s > t + tol {
                break;
            }
            let e = e.clone();
            self.next += 1;
            count += 1;
            let text = self.apply(solver, &e.action, e.time_s, t);
            self.log.push((t, text));
        }
        count
    }

    fn apply(&mut self, solver: &mut Explicit, a: &Action, at_s: f64, t: f64) -> String {
        match a.clone() {
            Action::Break { segment: j } => {
                solver.wire_mut().break_segment(j);
                format!("break of segment {j} (between nodes {j} and {})", j + 1)
            }
            Action::RadialIce { segments: r, kg_per_m, diameter_factor } => {
                let text =
                    format!("radial ice {kg_per_m} kg/m, wind diameter factor {diameter_factor} on segments {r:?}");
                if solver.wire_mut().set_radial_ice(r, kg_per_m, diameter_factor) {
                    text
                } else {
                    format!("{text} refused: not a valid shell (the wire is unchanged)")
                }
            }
            Action::Ice { segments: r, delta_kg_per_m } => {
                let text = format!("linear density {delta_kg_per_m:+} kg/m on segments {r:?}");
                if solver.wire_mut().add_linear_density(r, delta_kg_per_m) {
                    text
                } else {
                    format!("{text} refused: it would leave a segment mass non-positive (the wire is unchanged)")
                }
            }
            Action::InsulatorFailure { insulator } => match solver.wire_mut().insulators.get_mut(insulator) {
                Some(ins) => {
                    ins.intact = false;
                    format!("failure of the insulator string at node {}", ins.node)
                }
                None => format!("failure of insulator string {insulator} ignored: no such string"),
            },
            Action::ClampSlip { insulator } => {
                let w = solver.wire_mut();
                match w.insulators.get(insulator).copied() {
                    Some(ins) if ins.intact => {
                        w.insulators[insulator].intact = false;
                        w.point_mass_kg[ins.node] -= ins.mass_kg;
                        w.update_node_masses();
                        format!("conductor slipped out of the clamp at node {}", ins.node)
                    }
                    _ => format!("clamp slip of string {insulator} ignored: no such string holds the conductor"),
                }
            }
            Action::Release { node } => {
                solver.wire_mut().set_constraint(node, crate::wire::Constraint::Free);
                format!("conductor released at node {node}")
            }
            Action::Wind { scale, gate, ramp_s } => {
                // The multiplier now: a gust's value at this time (the last step set it at the step's start).
                let from = match &self.gust {
                    Some(g) => g.scale(t),
                    None => solver.loads().wind_scale,
                };
                self.gust = None;
                self.wind_ramp = None;
                solver.loads_mut().wind_gate = gate;
                if ramp_s > 0.0 {
                    self.wind_ramp = Some(WindRamp { start_s: t, duration_s: ramp_s, from, to: scale });
                    solver.loads_mut().wind_scale = from;
                    format!("wind multiplier {from} to {scale} over a ramp of {ramp_s} s, gate {gate:?}")
                } else {
                    solver.loads_mut().wind_scale = scale;
                    format!("wind multiplier {scale}, gate {gate:?}")
                }
            }
            Action::Gust { period_s, amplitude, gate } => {
                self.wind_ramp = None;
                self.gust = Some(Gust { start_s: at_s, period_s, amplitude });
                solver.loads_mut().wind_gate = gate;
                format!("gust (4.5): period {period_s} s, amplitude {amplitude}, gate {gate:?}")
            }
            Action::Temperature { segments: r, temperature_k, ramp_s } => {
                let text = format!("temperature {temperature_k} K on segments {r:?} (ramp {ramp_s} s)");
                self.conduction = None;
                self.ramps.retain(|p| p.first + p.from_k.len() <= r.start || p.first >= r.end);
                if ramp_s > 0.0 {
                    let from_k = solver.wire().temperature_k[r.clone()].to_vec();
                    self.ramps.push(Ramp {
                        start_s: t,
                        duration_s: ramp_s,
                        first: r.start,
                        from_k,
                        to_k: temperature_k,
                    });
                } else {
                    solver.wire_mut().set_temperature(r, temperature_k);
                }
                text
            }
            Action::HeatConduction { hold_nodes: nodes, hold_temperature_k, heat_time_per_s, boundary } => {
                let text = format!(
                    "heat conduction (5.2), nodes {nodes:?} held at {hold_temperature_k} K, \
                     {heat_time_per_s} units of dimensionless heat time per second, boundary {boundary:?}"
                );
                self.ramps.clear();
                self.conduction =
                    Some(Conduction::start(solver.wire(), nodes, hold_temperature_k, heat_time_per_s, boundary));
                text
            }
            Action::HeatConductionOff => {
                self.conduction = None;
                "heat conduction off".into()
            }
            Action::Ground { on } => {
                solver.set_ground(if on { self.ground.clone() } else { None });
                format!("ground contact {}", if on { "on" } else { "off" })
            }
        }
    }

    /// Before a step from time `t` [s]: the gust multiplier or the wind ramp's, the temperature ramps and
    /// the `[thermal]` temperature at `t` (each once per step).
    pub fn before_step(&mut self, solver: &mut Explicit, t: f64) {
        if let Some(h) = &mut self.heating {
            h.apply(solver, t);
        }
        if let Some(g) = &self.gust {
            solver.loads_mut().wind_scale = g.scale(t);
        }
        if let Some(r) = &self.wind_ramp {
            let (scale, done) = r.scale(t);
            solver.loads_mut().wind_scale = scale;
            if done {
                self.wind_ramp = None;
            }
        }
        if !self.ramps.is_empty() {
            let w = solver.wire_mut();
            self.ramps.retain(|r| !r.apply(w, t));
            w.update_rest_lengths();
        }
    }

    /// After a step of `dt` [s]: heat conduction over the step.
    pub fn after_step(&mut self, solver: &mut Explicit, dt: f64) {
        if let Some(c) = &mut self.conduction {
            c.advance(solver.wire_mut(), dt);
        }
    }
}

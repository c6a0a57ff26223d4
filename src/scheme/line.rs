//! The explicit scheme (3.1), (3.6) for a line of several conductors ([`crate::line::Model`]).
//!
//! Each conductor is advanced by its own kernel ([`Explicit`]: its segment pass with its own material and
//! loads, then its node pass); the attachments between conductors and supports act on the conductor nodes
//! as point forces, one net-force sum per node (MoorDyn's picture: lines attach to shared points). One
//! step from level `n` to `n + 1`:
//!
//! ```text
//! 1. every conductor: segment pass at level n (tension (3.4), distributed loads (2.5)-(2.6))
//! 2. every link l between ends a, b: F_l = force_on_b(r_a^n, r_b^n, v_a^{n-1/2}, v_b^{n-1/2})   (element::link)
//!    node ends receive F_l (end b) and -F_l (end a) as point forces; support ends add them to the
//!    support's load S_s^n
//! 3. every conductor: node pass (kick with its own forces plus the point forces, smoothing, drift)
//! 4. every elastic support: u^{n+1/2} = u^{n-1/2} + (dt_{n-1/2} + dt_{n+1/2}) / 2 (K(p^n) - c u^{n-1/2} + S^n) / M,
//!    p^{n+1} = p^n + dt_{n+1/2} u^{n+1/2}   (horizontal only; rigid supports stay)
//! ```
//!
//! the same kick-drift leapfrog as the conductors', so the coupled scheme stays second order in time.
//! A conductor without attachments steps exactly as a single-conductor run (the point forces enter its
//! node pass after the loop over all nodes, as a single section's strings do), so a line of uncoupled
//! conductors reproduces the single-conductor runs bit for bit (test `uncoupled_conductors_are_bitwise_single_runs`).
//!
//! Time step. The step must satisfy the leapfrog's bound with explicit damping, `W dt^2 / 4 + D dt / 2
//! <= 1`, with `W` a bound on the largest `omega^2` and `D` on the largest modal damping rate. By
//! Gershgorin's theorem on the similar matrices `M^-1 K` and `M^-1/2 K M^-1/2`, `W` is the largest over the
//! nodes and supports of `(K + sum_j k_j) / M` (form A) or of `(K + sum_j k_j sqrt(M / m_j)) / M` (form B),
//! whichever form gives the smaller bound (`K` the sum of the axial stiffnesses joined to the node: `EA /
//! l0` of its segments, `EA / L0` of its links, a support's larger spring; the sums over those whose other
//! end `j`, of mass `m_j`, moves; `M` the node's mass); `D` likewise from the dampers (`eta / l0`, `BA / L0`,
//! `c_d`; on a support's two horizontal unknowns only the horizontal part `|t_h|^2` of a link's axial
//! stiffness, plus its geometric stiffness `T / L`): the
//! damped-leapfrog condition `C^2 + 2 z C <= 1` of [`super::courant`] for each mode. For a conductor's own
//! interior node this is exactly its Courant limit `C <= sqrt(1 + z^2) - z`; for a clamp it is the bound of
//! [`crate::wire::insulator::clamp_stable_step_s`]; links and point masses can only lower it.
//! [`LineExplicit::new`] refuses a step above it, naming the node.

use super::conductor_contact::{ContactState, contact_step_limit_s};
use super::electromagnetic::{EmIntersection, EmState};
use super::explicit::{Explicit, Instability, StepParams};
use crate::line::contact::{ConductorContact, ContactError};
use crate::line::electromagnetic::{Electromagnetic, EmError};
use crate::line::handle::Endpoint;
use crate::line::model::{DeadEnd, Link, Model, ModelError, Role};
use crate::line::support::Support;
use crate::wire::Wire;

/// Why a line solver could not be built.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum LineError {
    /// the model is inconsistent
    #[error(transparent)]
    Model(#[from] ModelError),
    /// the time step is above the stable step of some node or support
    #[error(
        "time step {dt_s:.4e} s is above the stable step {limit_s:.4e} s of {at} (stiffness {stiffness_n_per_m:.4e} N/m, damping {damping_n_s_per_m:.4e} N s/m, mass {mass_kg:.4e} kg)"
    )]
    Step {
        /// the step asked for [s]
        dt_s: f64,
        /// the stable step there [s]
        limit_s: f64,
        /// where: a conductor's node or a support
        at: String,
        /// the stiffness joined there `K` [N/m]
        stiffness_n_per_m: f64,
        /// the damping there `C` [N s/m]
        damping_n_s_per_m: f64,
        /// the mass there `M` [kg]
        mass_kg: f64,
    },
}

/// A conductor of the line went unstable.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("conductor {conductor} ('{name}'): {source}")]
pub struct LineInstability {
    /// the conductor's index
    pub conductor: usize,
    /// its name
    pub name: String,
    /// what happened, when and where
    pub source: Instability,
}

/// The state of a support during a run.
#[derive(Clone, Debug)]
struct SupportState {
    spec: Support,
    /// position of the reference point `p` [m]
    position_m: [f64; 3],
    /// velocity `u` [m/s] at the last half step
    velocity_m_per_s: [f64; 3],
}

/// Energies of the line at a time level [J].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LineEnergies {
    /// kinetic energy of the conductors and the supports [J]
    pub kinetic_j: f64,
    /// elastic energy of the conductors, links and support springs [J]
    pub elastic_j: f64,
    /// potential energy of gravity and uniform loads [J]
    pub potential_j: f64,
}

/// The explicit solver of a line: one kernel per conductor, the links and the supports.
#[derive(Clone, Debug)]
pub struct LineExplicit {
    conductors: Vec<Explicit>,
    names: Vec<String>,
    roles: Vec<Role>,
    supports: Vec<SupportState>,
    links: Vec<Link>,
    dead_ends: Vec<DeadEnd>,
    params: StepParams,
    time_s: f64,
    steps: u64,
    dt_prev: f64,
    /// the link forces of the current level are evaluated and set on the conductors
    fresh: bool,
    /// force on end `b` of each link at the current level [N]
    link_force: Vec<[f64; 3]>,
    /// tension of each link at the current level [N]
    link_tension: Vec<f64>,
    /// point forces per conductor (scratch)
    points: Vec<Vec<(usize, [f64; 3])>>,
    /// sum of the link forces on each support at the current level [N]
    support_load: Vec<[f64; 3]>,
    /// the electromagnetic load of a short circuit, if any ([`LineExplicit::set_electromagnetic`])
    em: Option<EmState>,
    /// contact between conductors, if set ([`LineExplicit::set_contact`])
    contact: Option<ContactState>,
}

impl LineExplicit {
    /// A solver at `t = 0` for the model (copied: the solver does not own the model), every conductor with
    /// the same step parameters. Point masses are lumped into their nodes. Refuses an inconsistent model
    /// and a step above the stable step of any node or support.
    pub fn new(model: &Model, params: StepParams) -> Result<Self, LineError> {
        model.check()?;
        let mut wires: Vec<Wire> = model.conductors.iter().map(|c| c.wire.clone()).collect();
        let mut touched = vec![false; wires.len()];
        for p in &model.point_masses {
            wires[p.node.conductor].point_mass_kg[p.node.node] += p.mass_kg;
            touched[p.node.conductor] = true;
        }
        for (w, t) in wires.iter_mut().zip(&touched) {
            if *t {
                w.update_node_masses();
            }
        }
        let supports: Vec<SupportState> = model
            .supports
            .iter()
            .map(|s| SupportState { spec: s.clone(), position_m: s.position_m, velocity_m_per_s: [0.0; 3] })
            .collect();
        check_step(model, &wires, params.dt_s)?;
        let conductors: Vec<Explicit> =
            wires.into_iter().zip(&model.conductors).map(|(w, c)| Explicit::new(w, c.loads, params)).collect();
        let n = conductors.len();
        Ok(LineExplicit {
            conductors,
            names: model.conductors.iter().map(|c| c.name.clone()).collect(),
            roles: model.conductors.iter().map(|c| c.role).collect(),
            supports,
            links: model.links.clone(),
            dead_ends: model.dead_ends.clone(),
            params,
            time_s: 0.0,
            steps: 0,
            dt_prev: 0.0,
            fresh: false,
            link_force: vec![[0.0; 3]; model.links.len()],
            link_tension: vec![0.0; model.links.len()],
            points: vec![Vec::new(); n],
            support_load: vec![[0.0; 3]; model.supports.len()],
            em: None,
            contact: None,
        })
    }

    /// Advance every conductor and support by one step of length `dt` [s] (at most the nominal step).
    /// Every conductor is stepped even if one fails, so the state stays at one time level; the first
    /// failure is returned.
    pub fn step(&mut self, dt: f64) -> Result<(), LineInstability> {
        self.evaluate_forces();
        let kick = 0.5 * (self.dt_prev + dt);
        let mut failure = None;
        for (i, c) in self.conductors.iter_mut().enumerate() {
            if let Err(source) = c.step(dt)
                && failure.is_none()
            {
                failure = Some(LineInstability { conductor: i, name: self.names[i].clone(), source });
            }
        }
        for (s, load) in self.supports.iter_mut().zip(&self.support_load) {
            let Some(e) = s.spec.elastic else { continue };
            let d = sub(s.position_m, s.spec.position_m);
            let spring = e.spring_force(d, s.velocity_m_per_s);
            for k in 0..2 {
                s.velocity_m_per_s[k] += kick * (spring[k] + load[k]) / e.mass_kg;
                s.position_m[k] += dt * s.velocity_m_per_s[k];
            }
        }
        if let Some(em) = &mut self.em {
            em.after_step(&self.conductors, dt);
        }
        self.dt_prev = dt;
        self.time_s += dt;
        self.steps += 1;
        self.fresh = false;
        match failure {
            None => Ok(()),
            Some(f) => Err(f),
        }
    }

    /// Evaluate the forces of the current level (each conductor's segment pass, every link), so that the
    /// observers read them at no cost and the next step does not repeat them.
    pub fn evaluate_forces(&mut self) {
        if self.fresh {
            return;
        }
        for c in &mut self.conductors {
            c.ensure_forces();
        }
        self.evaluate_links();
        if let Some(em) = &mut self.em {
            em.evaluate(&mut self.conductors, self.time_s, self.steps, self.dt_prev);
        }
        self.fresh = true;
    }

    /// Set (or remove) the electromagnetic load of a short circuit ([`crate::line::electromagnetic`],
    /// evaluated by [`crate::scheme::electromagnetic`]): from the next evaluated level on, every carrier
    /// takes the Biot-Savart force of all carriers' currents while current flows. Refuses carriers that do
    /// not fit the line. Without current flowing (and without the load) the step is bitwise the one
    /// without it. The work counted so far ([`LineExplicit::em_work_j`]) starts again from 0.
    pub fn set_electromagnetic(&mut self, em: Option<Electromagnetic>) -> Result<(), EmError> {
        if let Some(e) = &em {
            e.check(self.conductors.len())?;
        }
        if let Some(old) = &mut self.em {
            old.detach(&mut self.conductors);
        }
        self.em = em.map(|e| EmState::new(e, &self.conductors));
        self.fresh = false;
        Ok(())
    }

    /// Set (or remove) the contact between conductors ([`crate::line::contact`], evaluated by
    /// [`crate::scheme::conductor_contact`]) from the next evaluated level on, its penalty scaled to the
    /// line's nominal step, or given ([`ConductorContact::stiffness_n_per_m2`]: then the nominal step is
    /// lowered by [`LineExplicit::set_time_step`] where the contact needs it). Refuses pairs that do not fit
    /// the line. Without it (the default) nothing is evaluated and the step is bitwise the one without it.
    pub fn set_contact(&mut self, contact: Option<ConductorContact>) -> Result<(), ContactError> {
        if let Some(c) = &contact {
            c.check(self.conductors.len())?;
            if let Some(limit) = contact_step_limit_s(c, &self.conductors)
                && limit < self.params.dt_s
            {
                self.set_time_step(limit);
            }
        }
        self.contact = contact.map(|c| ContactState::new(c, &self.conductors, self.params.dt_s));
        self.fresh = false;
        Ok(())
    }

    /// Lower the nominal step of the line and of every conductor to `dt_s` [s] (a stiffer element than
    /// the conductors' own, as a contact of given stiffness, asks for it), scaling the smoothing
    /// coefficient, which acts per step, by the ratio of the steps so that it stays the same viscosity per
    /// unit time. A smaller step only lowers the stability sum of [`LineExplicit::new`]'s check.
    ///
    /// # Panics
    /// If `dt_s` is not in (0, the current step].
    pub fn set_time_step(&mut self, dt_s: f64) {
        assert!(dt_s > 0.0 && dt_s <= self.params.dt_s, "the step can only be lowered");
        let ratio = dt_s / self.params.dt_s;
        self.params.dt_s = dt_s;
        self.params.smoothing *= ratio;
        for c in &mut self.conductors {
            let p = c.params_mut();
            p.dt_s = dt_s;
            p.smoothing *= ratio;
        }
        self.fresh = false;
    }

    /// The contact between conductors and its state (energy, nodes touching, the first contact), if set.
    pub fn contact(&self) -> Option<&ContactState> {
        self.contact.as_ref()
    }

    /// The electromagnetic load, if any.
    pub fn electromagnetic(&self) -> Option<&Electromagnetic> {
        self.em.as_ref().map(|e| e.load())
    }

    /// The electromagnetic nodal forces on `conductor` at the evaluated level [N] (three arrays of its
    /// nodes; zero while no current flows); `None` if it carries no current.
    pub fn em_force_n(&self, conductor: usize) -> Option<&[Vec<f64>; 3]> {
        assert!(self.fresh, "em_force_n needs evaluate_forces at this time level");
        self.em.as_ref().and_then(|e| e.force_n(conductor))
    }

    /// Work of the electromagnetic forces since t = 0 (or since the load was set) to the evaluated level
    /// [J]: the trapezoidal rule over each step ([`crate::scheme::electromagnetic`]), for the energy budget.
    pub fn em_work_j(&self) -> f64 {
        self.em.as_ref().map_or(0.0, |e| e.work_j())
    }

    /// The first meeting of two carriers (intersecting current filaments, left out of the force), if any.
    pub fn em_intersection(&self) -> Option<EmIntersection> {
        self.em.as_ref().and_then(|e| e.intersection())
    }

    /// The electromagnetic near field's half-width [segments] (two carriers of one phase,
    /// [`super::electromagnetic`]), if the load is set.
    pub fn em_near_window(&self) -> Option<usize> {
        self.em.as_ref().map(|e| e.near_window())
    }

    /// How many times the electromagnetic geometric factors were evaluated (0 without the load).
    pub fn em_refreshes(&self) -> u64 {
        self.em.as_ref().map_or(0, |e| e.refreshes())
    }

    /// The links' forces of the current state only, without the conductors' segment passes: set on the
    /// conductors as point forces and summed on the supports ([`LineExplicit::support_link_loads_n`]). For a
    /// static solver's residual, which evaluates each conductor's net force itself
    /// ([`Explicit::net_force`]); the level is evaluated in full only by [`LineExplicit::evaluate_forces`].
    pub fn evaluate_links(&mut self) {
        for p in &mut self.points {
            p.clear();
        }
        for l in &mut self.support_load {
            *l = [0.0; 3];
        }
        for (k, link) in self.links.iter().enumerate() {
            let (t, f) = if link.intact {
                let (ra, va) = self.endpoint_state(&link.a);
                let (rb, vb) = self.endpoint_state(&link.b);
                link.law.tension_and_force_on_b(ra, rb, va, vb)
            } else {
                (0.0, [0.0; 3])
            };
            self.link_force[k] = f;
            self.link_tension[k] = t;
            for (end, sign) in [(&link.a, -1.0), (&link.b, 1.0)] {
                let g = [sign * f[0], sign * f[1], sign * f[2]];
                match *end {
                    Endpoint::Node(n) => self.points[n.conductor].push((n.node, g)),
                    Endpoint::Support { support, .. } => {
                        for c in 0..3 {
                            self.support_load[support][c] += g[c];
                        }
                    }
                }
            }
        }
        if let Some(ct) = &mut self.contact {
            ct.evaluate(&self.conductors, self.time_s, &mut self.points);
        }
        for (c, p) in self.conductors.iter_mut().zip(&self.points) {
            if !(p.is_empty() && c.point_forces().is_empty()) {
                c.set_point_forces(p);
            }
        }
    }

    /// Position [m] and velocity at the last half step [m/s] of an attachment's end.
    pub fn endpoint_state(&self, e: &Endpoint) -> ([f64; 3], [f64; 3]) {
        match *e {
            Endpoint::Node(n) => {
                let w = self.conductors[n.conductor].wire();
                (w.position(n.node), [w.v[0][n.node], w.v[1][n.node], w.v[2][n.node]])
            }
            Endpoint::Support { support, offset_m } => {
                let s = &self.supports[support];
                (add(s.position_m, offset_m), s.velocity_m_per_s)
            }
        }
    }

    /// The conductors' solvers (read their wires, tensions and support forces at an evaluated level).
    pub fn conductors(&self) -> &[Explicit] {
        &self.conductors
    }

    /// Conductor `i`'s solver, to change it (an event: ice, a break, a temperature); the forces of the
    /// level are evaluated again.
    pub fn conductor_mut(&mut self, i: usize) -> &mut Explicit {
        self.fresh = false;
        &mut self.conductors[i]
    }

    /// The conductors' wires, in model order.
    pub fn wires(&self) -> Vec<&Wire> {
        self.conductors.iter().map(|c| c.wire()).collect()
    }

    /// The conductors' names.
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// The conductors' roles.
    pub fn roles(&self) -> &[Role] {
        &self.roles
    }

    /// The attachments.
    pub fn links(&self) -> &[Link] {
        &self.links
    }

    /// Break attachment `l` (a failing string or spacer arm): it carries nothing from now on.
    pub fn break_link(&mut self, l: usize) {
        self.links[l].intact = false;
        self.fresh = false;
    }

    /// Force of link `l` on its end `b` at the evaluated level [N] (on end `a`: the negative).
    pub fn link_force_n(&self, l: usize) -> [f64; 3] {
        assert!(self.fresh, "link_force_n needs evaluate_forces at this time level");
        self.link_force[l]
    }

    /// Tension of link `l` at the evaluated level [N] (negative: a spacer arm in compression), the value
    /// its force was computed from.
    pub fn link_tension_n(&self, l: usize) -> f64 {
        assert!(self.fresh, "link_tension_n needs evaluate_forces at this time level");
        self.link_tension[l]
    }

    /// Position of support `s`'s reference point [m].
    pub fn support_position_m(&self, s: usize) -> [f64; 3] {
        self.supports[s].position_m
    }

    /// Velocity of support `s` at the last half step [m/s] (zero for a rigid support).
    pub fn support_velocity_m_per_s(&self, s: usize) -> [f64; 3] {
        self.supports[s].velocity_m_per_s
    }

    /// Displacement of support `s` from its rest position [m].
    pub fn support_displacement_m(&self, s: usize) -> [f64; 3] {
        sub(self.supports[s].position_m, self.supports[s].spec.position_m)
    }

    /// Move support `s`'s reference point to `p` [m] (a static solver's iterate, a prescribed motion);
    /// the forces of the level are evaluated again.
    pub fn set_support_position(&mut self, s: usize, p: [f64; 3]) {
        self.supports[s].position_m = p;
        self.fresh = false;
    }

    /// Set the velocity of support `s`'s reference point to `u` [m/s], an implicit integrator's state (the
    /// links' dampers and the support's own damper read it where the explicit step reads the half-step
    /// velocity; an elastic support moves horizontally only, so `u[2]` should be 0); the forces of the
    /// level are evaluated again.
    pub fn set_support_velocity(&mut self, s: usize, u: [f64; 3]) {
        self.supports[s].velocity_m_per_s = u;
        self.fresh = false;
    }

    /// The sum of the link forces on each support [N] (without its own springs), from the last link pass
    /// ([`LineExplicit::evaluate_links`] or [`LineExplicit::evaluate_forces`]).
    pub fn support_link_loads_n(&self) -> &[[f64; 3]] {
        &self.support_load
    }

    /// Stop every motion: conductor and support velocities set to zero (a static state).
    pub fn stop(&mut self) {
        for c in &mut self.conductors {
            for v in &mut c.wire_mut().v {
                v.fill(0.0);
            }
        }
        for s in &mut self.supports {
            s.velocity_m_per_s = [0.0; 3];
        }
        self.fresh = false;
    }

    /// The supports (as built).
    pub fn supports(&self) -> impl Iterator<Item = &Support> {
        self.supports.iter().map(|s| &s.spec)
    }

    /// The resultant force of all attachments on support `s` at the evaluated level [N]: its links' pulls
    /// and the reactions of the conductor nodes fixed on it (the load the tower carries from every phase
    /// and earth wire).
    pub fn support_resultant_n(&self, s: usize) -> [f64; 3] {
        self.support_resultant_into(s, &mut Vec::new())
    }

    /// [`LineExplicit::support_resultant_n`] with the conductors' reactions gathered into `buf` (any
    /// contents; left holding the last one's), so that a run that asks at every level reuses one vector:
    /// the same additions in the same order, the same bits.
    pub fn support_resultant_into(&self, s: usize, buf: &mut Vec<(usize, [f64; 3])>) -> [f64; 3] {
        assert!(self.fresh, "support_resultant_n needs evaluate_forces at this time level");
        let mut f = self.support_load[s];
        for d in self.dead_ends.iter().filter(|d| d.support == s) {
            let c = &self.conductors[d.node.conductor];
            c.support_forces(buf);
            if let Some(&(_, r)) = buf.iter().find(|(i, _)| *i == d.node.node) {
                for k in 0..3 {
                    f[k] += r[k];
                }
            }
        }
        f
    }

    /// Energies of the line at the evaluated level: the conductors' ([`Explicit::level_energies`]),
    /// the links' elastic energy, the supports' springs and motion (velocity synchronised like the nodes').
    pub fn energies(&self) -> LineEnergies {
        assert!(self.fresh, "energies needs evaluate_forces at this time level");
        let mut e = LineEnergies::default();
        for c in &self.conductors {
            let d = c.level_energies();
            e.kinetic_j += d.kinetic_j;
            e.elastic_j += d.elastic_j;
            e.potential_j += d.potential_j;
        }
        for link in self.links.iter().filter(|l| l.intact) {
            let (ra, _) = self.endpoint_state(&link.a);
            let (rb, _) = self.endpoint_state(&link.b);
            let d = sub(rb, ra);
            e.elastic_j += link.law.energy_j((d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt());
        }
        if let Some(ct) = &self.contact {
            e.elastic_j += ct.energy_j();
        }
        let half = 0.5 * self.dt_prev;
        for (s, load) in self.supports.iter().zip(&self.support_load) {
            let Some(el) = s.spec.elastic else { continue };
            let d = sub(s.position_m, s.spec.position_m);
            e.elastic_j += el.spring_energy_j(d);
            let spring = el.spring_force(d, s.velocity_m_per_s);
            for k in 0..2 {
                let u = s.velocity_m_per_s[k] + half * (spring[k] + load[k]) / el.mass_kg;
                e.kinetic_j += 0.5 * el.mass_kg * u * u;
            }
        }
        e
    }

    /// Simulated time `t_n` [s].
    pub fn time_s(&self) -> f64 {
        self.time_s
    }

    /// Set the clock after a step shortened to land on `t_s` [s].
    pub fn land_on(&mut self, t_s: f64) {
        self.time_s = t_s;
        for c in &mut self.conductors {
            c.land_on(t_s);
        }
    }

    /// Steps taken.
    pub fn steps(&self) -> u64 {
        self.steps
    }

    /// The step parameters (the same for every conductor).
    pub fn params(&self) -> &StepParams {
        &self.params
    }
}

/// Refuse a step above the stable step of the line (module doc).
fn check_step(model: &Model, wires: &[Wire], dt: f64) -> Result<(), LineError> {
    // Gershgorin rows, times the node's mass, of the two similar matrices M^-1 K and M^-1/2 K M^-1/2 (and
    // of C): per node (and support) the springs and dampers joined to it (the diagonal) plus, for those
    // whose other end moves, the spring (form A) or the spring times sqrt(m_i / m_j) (form B); an end held
    // fixed adds none. Each form bounds the largest eigenvalue by its largest row; the smaller bound holds.
    #[derive(Clone, Copy, Default)]
    struct Row {
        k: f64,
        c: f64,
        /// row sums of forms A and B [N/m], [N s/m]
        k_row: [f64; 2],
        c_row: [f64; 2],
    }
    impl Row {
        /// A spring and damper on the node's own unknowns (`k`, `c`) and, if its other end moves (with
        /// `sqrt(m_i / m_j)`), their coupling to it (`k_off`, `c_off`).
        fn add(&mut self, (k, k_off): (f64, f64), (c, c_off): (f64, f64), off: Option<f64>) {
            self.k += k;
            self.c += c;
            let (a, b) = off.map_or((0.0, 0.0), |r| (1.0, r));
            self.k_row[0] += k + k_off * a;
            self.k_row[1] += k + k_off * b;
            self.c_row[0] += c + c_off * a;
            self.c_row[1] += c + c_off * b;
        }
    }
    // The mass of an end that moves, `None` for a held one.
    let moving_mass = |e: &Endpoint| match *e {
        Endpoint::Node(n) => {
            let w = &wires[n.conductor];
            (w.free[n.node] > 0.0).then_some(w.mass[n.node])
        }
        Endpoint::Support { support, .. } => model.supports[support].elastic.map(|e| e.mass_kg),
    };
    let mass = |e: &Endpoint| match *e {
        Endpoint::Node(n) => wires[n.conductor].mass[n.node],
        Endpoint::Support { support, .. } => model.supports[support].elastic.map_or(f64::INFINITY, |e| e.mass_kg),
    };
    let mut rows: Vec<Vec<Row>> = wires.iter().map(|w| vec![Row::default(); w.nodes()]).collect();
    let mut srows = vec![Row::default(); model.supports.len()];
    for (i, w) in wires.iter().enumerate() {
        for j in 0..w.segments() {
            let (k, c) = (w.axial_stiffness_n[j] / w.rest_length[j], w.internal_friction_n_s[j] / w.rest_length[j]);
            for (node, other) in [(j, j + 1), (j + 1, j)] {
                let off = (w.free[other] > 0.0).then(|| (w.mass[node] / w.mass[other]).sqrt());
                rows[i][node].add((k, k), (c, c), off);
            }
        }
    }
    for l in &model.links {
        // The link's stiffness `k t t^T + (T / L) (I - t t^T)` and damping `c t t^T`: on a support's two
        // horizontal unknowns only their horizontal part acts (`|t_h|^2` of the axial part; a plumb string
        // hardly moves a tower top sideways), and the coupling of a node to a support is `|t_h|` of it.
        let (k, c) = (l.law.stiffness_n_per_m(), l.law.damping_n_s_per_m());
        let (ra, rb) = (model.endpoint_position(&l.a), model.endpoint_position(&l.b));
        let d = [rb[0] - ra[0], rb[1] - ra[1], rb[2] - ra[2]];
        let len = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        let h = if len > 0.0 { (d[0] * d[0] + d[1] * d[1]).sqrt() / len } else { 1.0 };
        let geometric = if len > 0.0 { l.law.tension(d, [0.0; 3]).0.abs() / len } else { 0.0 };
        let on_support = |e: &Endpoint| matches!(e, Endpoint::Support { .. });
        for (end, other) in [(&l.a, &l.b), (&l.b, &l.a)] {
            let off = moving_mass(other).map(|m| (mass(end) / m).sqrt());
            let own = if on_support(end) { h * h } else { 1.0 };
            let across = if on_support(end) || on_support(other) { h } else { 1.0 };
            let kk = (k * own + geometric, k * across + geometric);
            let cc = (c * own, c * across);
            match *end {
                Endpoint::Node(n) => rows[n.conductor][n.node].add(kk, cc, off),
                Endpoint::Support { support, .. } => srows[support].add(kk, cc, off),
            }
        }
    }
    // Every moving node and support: (where, its row, its mass).
    let mut all: Vec<(String, Row, f64)> = Vec::new();
    for (i, w) in wires.iter().enumerate() {
        for node in (0..w.nodes()).filter(|&n| w.free[n] > 0.0) {
            all.push((format!("conductor '{}' node {node}", model.conductors[i].name), rows[i][node], w.mass[node]));
        }
    }
    for (s, sup) in model.supports.iter().enumerate() {
        let Some(e) = sup.elastic else { continue };
        let mut r = srows[s];
        let spring = e.along_n_per_m.max(e.across_n_per_m);
        r.add((spring, spring), (e.damping_n_s_per_m, e.damping_n_s_per_m), None);
        all.push((format!("support '{}'", sup.name), r, e.mass_kg));
    }
    // W dt^2 / 4 + D dt / 2 <= 1 with W >= omega^2 and D >= the modal damping rate, from each form's
    // largest row; the form with the larger stable step holds.
    let limit = |w: f64, d: f64| 2.0 / (0.5 * d + (0.25 * d * d + w).sqrt());
    let form = |f: usize| {
        let w = all.iter().map(|(_, r, m)| r.k_row[f] / m).fold(0.0, f64::max);
        let d = all.iter().map(|(_, r, m)| r.c_row[f] / m).fold(0.0, f64::max);
        limit(w, d)
    };
    let lim = form(0).max(form(1));
    // A rounding slack so that a conductor run at exactly its Courant limit is not refused.
    if dt <= lim * (1.0 + 1e-9) {
        return Ok(());
    }
    // Name the node with the smallest own limit (the stiffest row of the form that holds).
    let f = if form(0) >= form(1) { 0 } else { 1 };
    let (at, r, m) = all
        .iter()
        .min_by(|a, b| {
            limit(a.1.k_row[f] / a.2, a.1.c_row[f] / a.2).total_cmp(&limit(b.1.k_row[f] / b.2, b.1.c_row[f] / b.2))
        })
        .expect("a refused step has a node");
    Err(LineError::Step {
        dt_s: dt,
        limit_s: lim,
        at: at.clone(),
        stiffness_n_per_m: r.k,
        damping_n_s_per_m: r.c,
        mass_kg: *m,
    })
}

fn sub(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn add(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

//! The model of a line: conductors, the supports they share, and the attachments that join them.

use super::handle::{Endpoint, NodeRef};
use super::support::Support;
use crate::element::LinkLaw;
use crate::scheme::Loads;
use crate::wire::Wire;

/// What a conductor is in the line (for outputs and for the pairs whose clearance matters).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Role {
    /// a phase conductor (a single conductor per phase)
    Phase,
    /// an earth (shield) wire
    EarthWire,
    /// sub-conductor `index` of bundle `bundle` (a phase of several sub-conductors held by spacers)
    SubConductor {
        /// the bundle's index (one per phase)
        bundle: usize,
        /// position in the bundle
        index: usize,
    },
}

impl Role {
    /// The bundle a sub-conductor belongs to; `None` for a phase or an earth wire.
    pub fn bundle(&self) -> Option<usize> {
        match *self {
            Role::SubConductor { bundle, .. } => Some(bundle),
            _ => None,
        }
    }
}

/// One conductor of the line: a chain of nodes and segments with its own material, mass and loads.
#[derive(Clone, Debug)]
pub struct LineConductor {
    /// name (for outputs), e.g. `"phase A"`, `"earth wire"`, `"A.2"`
    pub name: String,
    /// what it is
    pub role: Role,
    /// its nodes and segments, with its own axial stiffness, internal friction, linear density, temperature
    pub wire: Wire,
    /// its own loads: gravity, uniform load, and its own wind (`q d c_n` with its own diameter and drag
    /// coefficients, [`crate::element::aero`])
    pub loads: Loads,
}

/// What an attachment is (its law says how it acts; the kind names it in outputs and checks).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum LinkKind {
    /// a suspension insulator string from a support to a conductor's clamp (tension only)
    SuspensionString,
    /// a tension (dead-end) insulator string in line with the conductor, from a support to the conductor's
    /// end node (tension only)
    TensionString,
    /// one arm of a spacer between two sub-conductors of a bundle (pushes and pulls)
    Spacer,
    /// an interphase spacer between two phases (pushes and pulls)
    InterphaseSpacer,
    /// the joint of a dropper: its first segment, from the span conductor's node (end `a`) to the dropper
    /// wire's first node (end `b`), with the dropper's segment law ([`super::dropper`])
    Clamp,
}

/// An attachment: an axial link ([`LinkLaw`]) between two ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Link {
    /// what it is
    pub kind: LinkKind,
    /// first end (for a string: the support)
    pub a: Endpoint,
    /// second end (for a string: the conductor's clamp)
    pub b: Endpoint,
    /// its axial law
    pub law: LinkLaw,
    /// false once the link has failed: it then carries nothing
    pub intact: bool,
}

/// A conductor node held fixed at an attachment point of a rigid support (a dead-end without a string, or
/// a clamp that does not move): its reaction counts in the support's resultant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DeadEnd {
    /// the conductor node (fixed in its wire)
    pub node: NodeRef,
    /// the rigid support that holds it
    pub support: usize,
}

/// A point mass at a conductor node (a spacer's clamp, a string lumped at its clamp, a marker ball) [kg].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PointMass {
    /// the node
    pub node: NodeRef,
    /// mass `m_p` [kg]
    pub mass_kg: f64,
}

/// A line of several conductors on shared supports.
///
/// Built in code (or from a scenario) and consumed by the integrators ([`crate::scheme::line`]), which
/// take a copy of its state: none of them owns the model.
#[derive(Clone, Debug, Default)]
pub struct Model {
    /// conductors (phases, earth wires, sub-conductors of bundles)
    pub conductors: Vec<LineConductor>,
    /// supports shared by the attachments
    pub supports: Vec<Support>,
    /// attachments between conductors and supports, and between conductors
    pub links: Vec<Link>,
    /// conductor nodes held fixed on rigid supports
    pub dead_ends: Vec<DeadEnd>,
    /// point masses at conductor nodes (spacer clamps, tension strings), lumped into the node masses by
    /// the integrators (a suspension string's mass is already in its conductor's wire, as in a section)
    pub point_masses: Vec<PointMass>,
}

/// A model whose topology or values are inconsistent (misuse of the building API, or a scenario that
/// validation let through).
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum ModelError {
    /// an attachment names a conductor, node or support that does not exist
    #[error("{what}: {detail}")]
    Handle {
        /// which attachment
        what: String,
        /// what is wrong
        detail: String,
    },
    /// a value outside its range
    #[error("{what} = {value} must be {allowed}")]
    Value {
        /// which value
        what: String,
        /// the value
        value: f64,
        /// the allowed range
        allowed: String,
    },
}

impl Model {
    /// An empty line.
    pub fn new() -> Self {
        Self::default()
    }

    /// Add a conductor; returns its index.
    pub fn add_conductor(&mut self, c: LineConductor) -> usize {
        self.conductors.push(c);
        self.conductors.len() - 1
    }

    /// Add a support; returns its index.
    pub fn add_support(&mut self, s: Support) -> usize {
        self.supports.push(s);
        self.supports.len() - 1
    }

    /// Add an attachment; returns its index.
    pub fn add_link(&mut self, l: Link) -> usize {
        self.links.push(l);
        self.links.len() - 1
    }

    /// Position of an endpoint in the model as built [m].
    pub fn endpoint_position(&self, e: &Endpoint) -> [f64; 3] {
        match *e {
            Endpoint::Node(n) => self.conductors[n.conductor].wire.position(n.node),
            Endpoint::Support { support, offset_m } => {
                let p = self.supports[support].position_m;
                [p[0] + offset_m[0], p[1] + offset_m[1], p[2] + offset_m[2]]
            }
        }
    }

    /// Check the topology (every handle exists, dead-ends are fixed nodes on rigid supports, links join two
    /// different points) and the values (positive lengths, stiffnesses, masses; non-negative damping).
    pub fn check(&self) -> Result<(), ModelError> {
        let node_ok = |what: &str, n: NodeRef| -> Result<(), ModelError> {
            let Some(c) = self.conductors.get(n.conductor) else {
                return Err(ModelError::Handle {
                    what: what.into(),
                    detail: format!("conductor {} does not exist ({} conductors)", n.conductor, self.conductors.len()),
                });
            };
            if n.node >= c.wire.nodes() {
                return Err(ModelError::Handle {
                    what: what.into(),
                    detail: format!(
                        "node {} of conductor '{}' does not exist ({} nodes)",
                        n.node,
                        c.name,
                        c.wire.nodes()
                    ),
                });
            }
            Ok(())
        };
        let support_ok = |what: &str, s: usize| -> Result<(), ModelError> {
            if s >= self.supports.len() {
                return Err(ModelError::Handle {
                    what: what.into(),
                    detail: format!("support {s} does not exist ({} supports)", self.supports.len()),
                });
            }
            Ok(())
        };
        let positive = |what: String, v: f64| -> Result<(), ModelError> {
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(ModelError::Value { what, value: v, allowed: "a finite number > 0".into() })
            }
        };
        let non_negative = |what: String, v: f64| -> Result<(), ModelError> {
            if v.is_finite() && v >= 0.0 {
                Ok(())
            } else {
                Err(ModelError::Value { what, value: v, allowed: "a finite number >= 0".into() })
            }
        };
        for (k, s) in self.supports.iter().enumerate() {
            if let Some(e) = &s.elastic {
                positive(format!("supports[{k}].mass_kg"), e.mass_kg)?;
                positive(format!("supports[{k}].along_n_per_m"), e.along_n_per_m)?;
                positive(format!("supports[{k}].across_n_per_m"), e.across_n_per_m)?;
                non_negative(format!("supports[{k}].damping_n_s_per_m"), e.damping_n_s_per_m)?;
                let n = (e.along[0] * e.along[0] + e.along[1] * e.along[1]).sqrt();
                if (n - 1.0).abs() > 1e-9 || e.along[2] != 0.0 {
                    return Err(ModelError::Value {
                        what: format!("supports[{k}].along (length)"),
                        value: n,
                        allowed: "a horizontal unit vector".into(),
                    });
                }
            }
        }
        for (k, l) in self.links.iter().enumerate() {
            let what = format!("links[{k}] ({:?})", l.kind);
            for e in [&l.a, &l.b] {
                match *e {
                    Endpoint::Node(n) => node_ok(&what, n)?,
                    Endpoint::Support { support, .. } => support_ok(&what, support)?,
                }
            }
            if l.a == l.b {
                return Err(ModelError::Handle { what, detail: "both ends are the same point".into() });
            }
            positive(format!("links[{k}].rest_length_m"), l.law.rest_length_m)?;
            positive(format!("links[{k}].axial_stiffness_n"), l.law.axial_stiffness_n)?;
            non_negative(format!("links[{k}].axial_damping_n_s"), l.law.axial_damping_n_s)?;
        }
        for (k, d) in self.dead_ends.iter().enumerate() {
            let what = format!("dead_ends[{k}]");
            node_ok(&what, d.node)?;
            support_ok(&what, d.support)?;
            if self.conductors[d.node.conductor].wire.free[d.node.node] > 0.0 {
                return Err(ModelError::Handle { what, detail: "the node is not fixed in its conductor".into() });
            }
            if self.supports[d.support].elastic.is_some() {
                return Err(ModelError::Handle {
                    what,
                    detail: "an elastic support holds conductors through strings (a fixed node cannot move with it)"
                        .into(),
                });
            }
        }
        for (k, p) in self.point_masses.iter().enumerate() {
            node_ok(&format!("point_masses[{k}]"), p.node)?;
            positive(format!("point_masses[{k}].mass_kg"), p.mass_kg)?;
        }
        Ok(())
    }
}

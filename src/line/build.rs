//! Building a line in code: a conductor strung as a section ([`crate::wire::section`]) whose supports are
//! the model's shared supports, and bundles of sub-conductors with spacers.
//!
//! A section's dead-ends become conductor nodes fixed on rigid supports ([`super::DeadEnd`]) or, with a
//! tension string, free end nodes held by a [`super::LinkKind::TensionString`]; its suspension supports
//! become [`super::LinkKind::SuspensionString`] links from a support's attachment point to the clamp (the
//! string's mass stays lumped at the clamp, as in a single section). The conductor's initial shape is the
//! section's: each span's elastic catenary between plumb clamps.

use super::handle::{Endpoint, NodeRef};
use super::model::{DeadEnd, LineConductor, Link, LinkKind, Model, ModelError, PointMass, Role};
use crate::element::LinkLaw;
use crate::scheme::Loads;
use crate::wire::section::{self, Layout, Section, SectionError, Support as SectionSupport};

/// How support `k` of a section is joined to the model.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Attach {
    /// a dead-end: the conductor's end node is fixed at the section's point, which belongs to the rigid
    /// model support `support`
    Fixed {
        /// the model support
        support: usize,
    },
    /// a suspension string from the model support `support`: the string's top is the section's pivot
    /// (its offset from the support's reference point is kept), its length, stiffness and mass are the
    /// section's; `damping_n_s` is its axial damping `BA` [N s]
    String {
        /// the model support
        support: usize,
        /// axial damping of the string `BA` [N s]
        damping_n_s: f64,
    },
    /// a dead-end through a tension (strain) insulator string in line with the conductor: the string runs
    /// from the section's dead-end point (on model support `support`) towards the span, and the conductor
    /// starts at its lower end
    TensionString {
        /// the model support
        support: usize,
        /// the string's axial law (its rest length, `EA`, `BA`; tension only)
        law: LinkLaw,
        /// the string's mass [kg], lumped at the conductor's end node
        mass_kg: f64,
    },
}

/// Why a conductor could not be added.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum BuildError {
    /// the section could not be built
    #[error(transparent)]
    Section(#[from] SectionError),
    /// the attachments do not fit the model
    #[error(transparent)]
    Model(#[from] ModelError),
}

/// Add a conductor strung as `section`, joined to the model's supports by `attach` (one per section
/// support), with its own `loads`. Returns the conductor's index and the section's layout.
pub fn add_section_conductor(
    model: &mut Model,
    name: impl Into<String>,
    role: Role,
    section: &Section,
    attach: &[Attach],
    loads: Loads,
) -> Result<(usize, Layout), BuildError> {
    let name = name.into();
    if attach.len() != section.supports.len() {
        return Err(ModelError::Handle {
            what: format!("conductor '{name}'"),
            detail: format!("{} attachments for {} section supports", attach.len(), section.supports.len()),
        }
        .into());
    }
    // A tension string moves the conductor's end from the dead-end point towards the span by the string's
    // stretched length (taken at the string's rest length: the dynamics take up the rest).
    let mut sec = section.clone();
    let last = sec.supports.len() - 1;
    let mut string_top = vec![None; sec.supports.len()];
    for k in [0, last] {
        if let (Attach::TensionString { law, .. }, SectionSupport::DeadEnd { point_m }) = (attach[k], sec.supports[k]) {
            let other = section::plumb_clamp(&sec.supports[if k == 0 { 1 } else { last - 1 }], 0.0);
            let d = [other[0] - point_m[0], other[1] - point_m[1], other[2] - point_m[2]];
            let n = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
            let end = [0, 1, 2].map(|c| point_m[c] + law.rest_length_m * d[c] / n);
            sec.supports[k] = SectionSupport::DeadEnd { point_m: end };
            string_top[k] = Some(point_m);
        }
    }
    let (mut wire, layout) = section::build(&sec)?;
    let conductor = model.conductors.len();
    // The model's links replace the wire's own strings.
    wire.insulators.clear();
    let mut links = Vec::new();
    let mut dead_ends = Vec::new();
    let mut masses = Vec::new();
    let offset = |model: &Model, s: usize, p: [f64; 3]| -> Result<[f64; 3], ModelError> {
        let sp = model.supports.get(s).ok_or_else(|| ModelError::Handle {
            what: format!("conductor '{name}'"),
            detail: format!("support {s} does not exist ({} supports)", model.supports.len()),
        })?;
        Ok([p[0] - sp.position_m[0], p[1] - sp.position_m[1], p[2] - sp.position_m[2]])
    };
    for (k, (a, s)) in attach.iter().zip(&section.supports).enumerate() {
        let node = NodeRef::new(conductor, layout.support_node[k]);
        match (*a, *s) {
            (Attach::Fixed { support }, SectionSupport::DeadEnd { point_m }) => {
                offset(model, support, point_m)?;
                dead_ends.push(DeadEnd { node, support });
            }
            (Attach::TensionString { support, law, mass_kg }, SectionSupport::DeadEnd { .. }) => {
                let top = string_top[k].expect("set above for the end supports");
                wire.set_constraint(node.node, crate::wire::Constraint::Free);
                links.push(Link {
                    kind: LinkKind::TensionString,
                    a: Endpoint::Support { support, offset_m: offset(model, support, top)? },
                    b: Endpoint::Node(node),
                    law: LinkLaw { compression: false, ..law },
                    intact: true,
                });
                if mass_kg > 0.0 {
                    masses.push(PointMass { node, mass_kg });
                }
            }
            (
                Attach::String { support, damping_n_s },
                SectionSupport::Suspension { pivot_m, length_m, stiffness_n, .. },
            ) => {
                links.push(Link {
                    kind: LinkKind::SuspensionString,
                    a: Endpoint::Support { support, offset_m: offset(model, support, pivot_m)? },
                    b: Endpoint::Node(node),
                    law: LinkLaw::string(length_m, stiffness_n, damping_n_s),
                    intact: true,
                });
            }
            (a, s) => {
                return Err(ModelError::Handle {
                    what: format!("conductor '{name}', support {k}"),
                    detail: format!("{a:?} does not fit the section's {s:?}"),
                }
                .into());
            }
        }
    }
    model.point_masses.extend(masses);
    model.conductors.push(LineConductor { name, role, wire, loads });
    model.links.extend(links);
    model.dead_ends.extend(dead_ends);
    Ok((conductor, layout))
}

/// A bundle: several sub-conductors of one phase, held apart by spacers.
#[derive(Clone, Debug, PartialEq)]
pub struct BundleSpec {
    /// each sub-conductor's offset from the bundle's centre in the plane across the line: `(across, up)`
    /// [m], across along `e_t = e3 x e_l` (left of the line's direction), up along `e3`
    pub offsets_m: Vec<[f64; 2]>,
    /// spacer positions: `(span, fraction of the span's unstretched length)` [-]
    pub spacers: Vec<(usize, f64)>,
    /// stiffness of each spacer arm `k` [N/m] (every pair of sub-conductors is joined by an arm of rest
    /// length equal to their spacing)
    pub arm_stiffness_n_per_m: f64,
    /// damping of each spacer arm `c` [N s/m]
    pub arm_damping_n_s_per_m: f64,
    /// mass of a spacer [kg], shared equally by its clamps
    pub spacer_mass_kg: f64,
}

impl BundleSpec {
    /// `n` sub-conductors on a circle of diameter `d` [m] (the usual twin: horizontal; triple: apex up;
    /// quad: a square with horizontal sides), with spacers at `spacers`.
    pub fn regular(n: usize, diameter_m: f64, spacers: Vec<(usize, f64)>, arm_stiffness_n_per_m: f64) -> Self {
        let r = 0.5 * diameter_m;
        let start = match n {
            2 => 0.0,
            3 => std::f64::consts::FRAC_PI_2,
            4 => std::f64::consts::FRAC_PI_4,
            _ => 0.0,
        };
        let offsets_m = (0..n)
            .map(|i| {
                let a = start + std::f64::consts::TAU * i as f64 / n as f64;
                // cos(pi) is -1 but sin(pi) is 1.2e-16: snap such rounding to 0, so that a twin bundle is
                // exactly level (its sub-conductors then hang exactly alike).
                let snap = |v: f64| if v.abs() < 1e-12 { 0.0 } else { r * v };
                [snap(a.cos()), snap(a.sin())]
            })
            .collect();
        BundleSpec { offsets_m, spacers, arm_stiffness_n_per_m, arm_damping_n_s_per_m: 0.0, spacer_mass_kg: 0.0 }
    }
}

/// Add a bundle: one sub-conductor per offset, each strung as `section` moved by its offset (every
/// support point and pivot moves with it), joined to the model's supports by `attach`, and spacers at the
/// given positions. Returns the sub-conductors' indices and the layout (the same for all).
pub fn add_bundle(
    model: &mut Model,
    name: &str,
    bundle: usize,
    section: &Section,
    attach: &[Attach],
    loads: Loads,
    spec: &BundleSpec,
) -> Result<(Vec<usize>, Layout), BuildError> {
    let along = {
        let (a, b) = (
            section::plumb_clamp(&section.supports[0], 0.0),
            section::plumb_clamp(&section.supports[section.supports.len() - 1], 0.0),
        );
        let d = [b[0] - a[0], b[1] - a[1]];
        let n = (d[0] * d[0] + d[1] * d[1]).sqrt();
        if n > 0.0 { [d[0] / n, d[1] / n] } else { [0.0, 1.0] }
    };
    let across = [-along[1], along[0]];
    let mut members = Vec::new();
    let mut layout = None;
    for (i, o) in spec.offsets_m.iter().enumerate() {
        let shift = [o[0] * across[0], o[0] * across[1], o[1]];
        let moved = |p: [f64; 3]| [p[0] + shift[0], p[1] + shift[1], p[2] + shift[2]];
        let mut sec = section.clone();
        for s in &mut sec.supports {
            match s {
                SectionSupport::DeadEnd { point_m } => *point_m = moved(*point_m),
                SectionSupport::Suspension { pivot_m, .. } => *pivot_m = moved(*pivot_m),
            }
        }
        let role = Role::SubConductor { bundle, index: i };
        let (c, l) = add_section_conductor(model, format!("{name}.{}", i + 1), role, &sec, attach, loads)?;
        members.push(c);
        layout = Some(l);
    }
    let layout = layout
        .ok_or_else(|| ModelError::Handle { what: format!("bundle '{name}'"), detail: "no sub-conductors".into() })?;
    for &(span, f) in &spec.spacers {
        if span + 1 >= layout.first_node.len() {
            return Err(ModelError::Handle {
                what: format!("bundle '{name}' spacer"),
                detail: format!("span {span} does not exist"),
            }
            .into());
        }
        let arm = (spec.arm_stiffness_n_per_m, spec.arm_damping_n_s_per_m);
        add_spacer(model, &members, &spec.offsets_m, layout.node_at(span, f), arm, spec.spacer_mass_kg);
    }
    Ok((members, layout))
}

/// Add a spacer at node `node` of every member of a bundle (sub-conductors `members` at `offsets_m`,
/// `(across, up)` [m]): an arm between every pair, of rest length their spacing, stiffness `arm.0` [N/m]
/// and damping `arm.1` [N s/m], and the spacer's mass `mass_kg` [kg] shared equally by its clamps.
pub fn add_spacer(
    model: &mut Model,
    members: &[usize],
    offsets_m: &[[f64; 2]],
    node: usize,
    arm: (f64, f64),
    mass_kg: f64,
) {
    let n = members.len();
    for i in 0..n {
        for j in i + 1..n {
            let (a, b) = (offsets_m[i], offsets_m[j]);
            let len = ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt();
            model.links.push(Link {
                kind: LinkKind::Spacer,
                a: Endpoint::Node(NodeRef::new(members[i], node)),
                b: Endpoint::Node(NodeRef::new(members[j], node)),
                law: LinkLaw::spring(len, arm.0, arm.1),
                intact: true,
            });
        }
    }
    if mass_kg > 0.0 {
        for &c in members {
            model.point_masses.push(PointMass { node: NodeRef::new(c, node), mass_kg: mass_kg / n as f64 });
        }
    }
}

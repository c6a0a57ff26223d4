//! A line of several conductors: phases, earth wires and bundles of sub-conductors on shared supports.
//!
//! The model ([`Model`]) is data: conductors ([`LineConductor`]: each a chain of nodes and segments, a
//! [`crate::wire::Wire`] with its own material, diameter, drag and loads), supports ([`Support`]: a tower
//! top or crossarm, rigid or elastic, shared by every attachment on it) and attachments ([`Link`]: an axial
//! spring-damper, [`crate::element::link`], between two ends named by handle, [`Endpoint`]: a conductor
//! node ([`NodeRef`]) or a point of a support). Suspension strings, tension (dead-end) strings, spacer
//! arms, interphase spacers and the joints of droppers ([`dropper`]: a conductor hanging from another's node)
//! are all links; a conductor node fixed on a rigid support is a [`DeadEnd`].
//! Topology is data, not array offsets: adding an element between two conductors adds a link (or, for a
//! distributed pair force, a pair element over two conductors' segments, [`crate::element::pair`]).
//!
//! The integrators consume a model and own none: [`crate::scheme::line::LineExplicit`] copies it into one
//! kernel per conductor plus the links and supports. [`build`] strings conductors and bundles from
//! sections; [`dof`] numbers the unknowns of the implicit solvers; [`clearance`] measures the least distance between every pair of phases at every level.
//!
//! Forces on a conductor node `i` (mass `m_i`, the lumped conductor plus point masses):
//!
//! ```text
//! m_i dv_i/dt = T_{i+1/2} t_{i+1/2} - T_{i-1/2} t_{i-1/2} + (P_{i+1/2} + P_{i-1/2}) / 2 - m_i g e3     (3.1)
//!             + sum over links l with an end at i of (+-) F_l                                          (element::link)
//! ```

pub mod build;
pub mod clearance;
pub mod contact;
pub mod dof;
pub mod dropper;
pub mod electromagnetic;
pub mod handle;
pub mod model;
pub mod support;

pub use handle::{Endpoint, NodeRef};
pub use model::{DeadEnd, LineConductor, Link, LinkKind, Model, ModelError, PointMass, Role};
pub use support::{ElasticSupport, Support};

//! Handles: which node of which conductor, and what an attachment's end is joined to. Topology is data:
//! an attachment names its ends by handle, never by an offset into a shared array.

/// Node `node` of conductor `conductor` of a [`super::Model`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct NodeRef {
    /// index of the conductor in [`super::Model::conductors`]
    pub conductor: usize,
    /// node index along that conductor (0 at its first end)
    pub node: usize,
}

impl NodeRef {
    /// Node `node` of conductor `conductor`.
    pub const fn new(conductor: usize, node: usize) -> Self {
        NodeRef { conductor, node }
    }
}

/// One end of an attachment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Endpoint {
    /// a conductor node (a clamp)
    Node(NodeRef),
    /// an attachment point of a support: the support's position plus a fixed offset [m] (the support is a
    /// rigid body that translates; a crossarm tip, an earth-wire peak, a dead-end eye)
    Support {
        /// index of the support in [`super::Model::supports`]
        support: usize,
        /// offset of the attachment point from the support's reference point [m]
        offset_m: [f64; 3],
    },
}

//! The degree-of-freedom map of a line: which unknowns of a system of equations (the static solver's, an
//! implicit integrator's) belong to which node or support.
//!
//! Today a free conductor node has three unknowns (its translations `x1, x2, x3`) and an elastic support
//! two (its horizontal translations `x1, x2`; it is rigid vertically); fixed nodes and rigid supports have
//! none. The map is built once from the topology: conductors in model order, each's free nodes in node
//! order, then the elastic supports. Every user reads offsets through it ([`DofMap::node`],
//! [`DofMap::support`], [`DofMap::endpoint`]), never computes them, so a rotation about the conductor
//! axis (galloping's torsion) is a fourth slot in a node's entry: `node_width` becomes per node, the force
//! elements that act on it (a torsion spring per segment, the aerodynamic moment) add their blocks, and
//! no other user of the map changes.

use super::handle::Endpoint;

/// The unknowns an attachment's end carries: the first index and how many (3 for a node, 2 for an elastic
/// support), or none for a held end.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EndDofs {
    /// index of the first unknown, `None` for an end that does not move
    pub first: Option<usize>,
    /// number of translation components (3 for a node: x1, x2, x3; 2 for a support: x1, x2)
    pub width: usize,
}

/// Unknowns of a line.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DofMap {
    /// first unknown of each node of each conductor (`None`: fixed)
    node: Vec<Vec<Option<usize>>>,
    /// first unknown of each support (`None`: rigid)
    support: Vec<Option<usize>>,
    /// first unknown of each conductor's block (its free nodes are contiguous)
    conductor_start: Vec<usize>,
    /// total number of unknowns
    len: usize,
}

/// Translations of a free node.
pub const NODE_WIDTH: usize = 3;
/// Horizontal translations of an elastic support.
pub const SUPPORT_WIDTH: usize = 2;

impl DofMap {
    /// The map for conductors whose nodes are free where `free[c][i] > 0` and supports that are elastic
    /// where `elastic[s]`.
    pub fn new(free: &[&[f64]], elastic: &[bool]) -> Self {
        let mut len = 0;
        let mut node = Vec::with_capacity(free.len());
        let mut conductor_start = Vec::with_capacity(free.len());
        for f in free {
            conductor_start.push(len);
            node.push(
                f.iter()
                    .map(|&x| {
                        (x > 0.0).then(|| {
                            len += NODE_WIDTH;
                            len - NODE_WIDTH
                        })
                    })
                    .collect(),
            );
        }
        let support = elastic
            .iter()
            .map(|&e| {
                e.then(|| {
                    len += SUPPORT_WIDTH;
                    len - SUPPORT_WIDTH
                })
            })
            .collect();
        DofMap { node, support, conductor_start, len }
    }

    /// Number of unknowns.
    pub fn len(&self) -> usize {
        self.len
    }

    /// Whether there are no unknowns.
    pub fn is_empty(&self) -> bool {
        self.len == 0
    }

    /// First unknown of node `i` of conductor `c` (`None`: fixed).
    pub fn node(&self, c: usize, i: usize) -> Option<usize> {
        self.node[c][i]
    }

    /// First unknown of conductor `c`'s block: its free nodes' unknowns follow in node order, as the
    /// single-conductor Jacobian numbers them ([`crate::statics::jacobian::unknown_index`]).
    pub fn conductor_start(&self, c: usize) -> usize {
        self.conductor_start[c]
    }

    /// First unknown of support `s` (`None`: rigid).
    pub fn support(&self, s: usize) -> Option<usize> {
        self.support[s]
    }

    /// The unknowns of an attachment's end.
    pub fn endpoint(&self, e: &Endpoint) -> EndDofs {
        match *e {
            Endpoint::Node(n) => EndDofs { first: self.node(n.conductor, n.node), width: NODE_WIDTH },
            Endpoint::Support { support, .. } => EndDofs { first: self.support(support), width: SUPPORT_WIDTH },
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::line::NodeRef;

    #[test]
    fn numbers_free_nodes_then_elastic_supports() {
        let (a, b) = ([0.0, 1.0, 1.0, 0.0], [0.0, 1.0, 0.0]);
        let m = DofMap::new(&[&a, &b], &[false, true, true]);
        assert_eq!(m.len(), 3 * 3 + 2 * 2);
        assert_eq!((m.node(0, 0), m.node(0, 1), m.node(0, 2)), (None, Some(0), Some(3)));
        assert_eq!((m.conductor_start(1), m.node(1, 1)), (6, Some(6)));
        assert_eq!((m.support(0), m.support(1), m.support(2)), (None, Some(9), Some(11)));
        let e = m.endpoint(&Endpoint::Node(NodeRef::new(1, 1)));
        assert_eq!(e, EndDofs { first: Some(6), width: 3 });
    }
}

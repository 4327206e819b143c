//! The naive mode: contract an edge shorter than ε only if it passes the link condition
//! of the surface with boundary; skip it otherwise. What mesh libraries do when they
//! preserve topology at all.
//!
//! **Guarantee.** Every contraction passes the link condition (Dey et al.; RS paper
//! Theorem 3), so the surface's type never changes. O(d_p + d_q) per edge (the common
//! neighbour walk of the pass machinery).

use super::state::{EdgeInfo, Simplifier, Skip};

/// Accepts the edge iff its endpoints have no common neighbour besides the two opposite
/// vertices (the walk has already refused an edge joining two boundary loops; the
/// tetrahedron case is checked by the caller for both modes).
pub(super) fn plan(sim: &Simplifier<'_>, _edge: &EdgeInfo) -> Result<(), Skip> {
    if sim.xs.is_empty() {
        Ok(())
    } else {
        Err(Skip::LinkCondition)
    }
}

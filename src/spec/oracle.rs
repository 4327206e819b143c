//! Naive reference computations that share no logic with the fast paths (only the
//! core's link iteration, itself checked by `Triangulation::validate`).

use crate::core::{Triangulation, VertexId};

/// The neighbours of `v` as a sorted vector.
fn neighbours(tri: &Triangulation, v: VertexId) -> Vec<VertexId> {
    let mut n: Vec<VertexId> = tri.link(v).collect();
    n.sort_unstable();
    n
}

/// The number of critical cycles through edge `[a, b]`: 3-cycles `(a, b, z)` that do not
/// bound a face, i.e. common neighbours of `a` and `b` other than the two link vertices
/// of `[a, b]` (RS Sec. 2). `None` if `[a, b]` is not an edge.
pub fn critical_cycles_through(tri: &Triangulation, a: VertexId, b: VertexId) -> Option<usize> {
    let [x, y] = tri.edge_link(a, b)?;
    let na = neighbours(tri, a);
    let nb = neighbours(tri, b);
    let common = na
        .iter()
        .filter(|z| nb.binary_search(z).is_ok() && **z != x && **z != y)
        .count();
    Some(common)
}

/// Theorem 3: `[a, b]` is contractible iff it is on no critical cycle and the surface is
/// not T4. Computed from [`critical_cycles_through`], independently of the link test.
pub fn contractible_by_theorem_3(tri: &Triangulation, a: VertexId, b: VertexId) -> bool {
    !tri.is_tetrahedron() && critical_cycles_through(tri, a, b) == Some(0)
}

/// Whether every edge at `v` is non-contractible (Def. 4), by the naive link condition.
pub fn is_trapped_naive(tri: &Triangulation, v: VertexId) -> bool {
    tri.link(v).all(|w| !tri.link_condition_naive(v, w))
}

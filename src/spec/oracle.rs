//! Naive reference computations that share no logic with the fast paths (only the
//! core's link iteration, itself checked by `Triangulation::validate`).

use crate::core::{Triangulation, VertexId};

/// The number of critical cycles through edge `[a, b]`: 3-cycles `(a, b, z)` that do not
/// bound a face, i.e. common neighbours of `a` and `b` other than the two link vertices
/// of `[a, b]` (RS Sec. 2). `None` if `[a, b]` is not an edge.
///
/// Walks the lower-degree endpoint's link and asks the graph for each candidate edge, so
/// the cost is O(d_s · min degree) with `d_s = min(d_a, d_b)`, never O(max degree): the
/// vertex RS is processing can have millions of neighbours.
pub fn critical_cycles_through(tri: &Triangulation, a: VertexId, b: VertexId) -> Option<usize> {
    let (s, l) = if tri.degree(a) <= tri.degree(b) {
        (a, b)
    } else {
        (b, a)
    };
    let [x, y] = tri.edge_link(s, l)?;
    Some(
        tri.link(s)
            .filter(|&z| z != l && z != x && z != y && tri.has_edge(z, l))
            .count(),
    )
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

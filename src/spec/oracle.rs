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

/// Euler characteristic and orientability of a closed surface given by its face list
/// alone: no corner table, no link walk, only a sorted edge map and a 2-colouring of the
/// faces (two faces listing their shared edge in the same direction must get opposite
/// orientations). The reference the tests and the fuzz targets hold the core's
/// `euler_characteristic` / `is_orientable` and every algorithm output against.
///
/// Returns `None` when some edge is not in exactly two faces (not a closed surface).
/// O(F log F).
pub fn euler_and_orientability(faces: &[[u32; 3]]) -> Option<(i64, bool)> {
    use std::collections::{BTreeMap, BTreeSet};
    let mut verts = BTreeSet::new();
    // Sorted edge -> (face, whether the face lists it from the smaller vertex).
    let mut edges: BTreeMap<(u32, u32), Vec<(usize, bool)>> = BTreeMap::new();
    for (f, t) in faces.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            verts.insert(a);
            edges
                .entry((a.min(b), a.max(b)))
                .or_default()
                .push((f, a < b));
        }
    }
    let chi = verts.len() as i64 - edges.len() as i64 + faces.len() as i64;
    let mut adj: Vec<Vec<(usize, bool)>> = vec![Vec::new(); faces.len()];
    for uses in edges.values() {
        let [(f, df), (g, dg)] = uses[..] else {
            return None;
        };
        adj[f].push((g, df == dg));
        adj[g].push((f, df == dg));
    }
    let mut flip: Vec<Option<bool>> = vec![None; faces.len()];
    let mut orientable = true;
    for s in 0..faces.len() {
        if flip[s].is_some() {
            continue;
        }
        flip[s] = Some(false);
        let mut stack = vec![s];
        while let Some(f) = stack.pop() {
            let ff = flip[f].unwrap_or(false);
            for &(g, same) in &adj[f] {
                let want = ff ^ same;
                match flip[g] {
                    Some(x) if x != want => orientable = false,
                    Some(_) => {}
                    None => {
                        flip[g] = Some(want);
                        stack.push(g);
                    }
                }
            }
        }
    }
    Some((chi, orientable))
}

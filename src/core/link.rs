//! The link condition (RS paper, Eq. 1, Theorem 3) in two independent implementations.
//!
//! Edge `[u, v]` with link `{x, y}` is contractible iff `lk(u) ∩ lk(v) = lk(uv)`: as
//! simplicial complexes, so the intersection may contain neither a third common vertex
//! (a critical 3-cycle `u, v, w`) nor the edge `[x, y]` (which happens exactly on the
//! tetrahedron boundary T4).

use super::ids::{VertexId, NONE};
use super::tri::Triangulation;

impl Triangulation {
    /// The two link vertices `{x, y}` of edge `[u, v]` (the third vertices of its two
    /// faces), or `None` if `[u, v]` is not an edge. O(degree(u)).
    pub fn edge_link(&self, u: VertexId, v: VertexId) -> Option<[VertexId; 2]> {
        let [c1, c2] = self.edge_corners(u, v)?;
        Some([self.vertex(c1), self.vertex(c2)])
    }

    /// The link condition by definition: `lk(u) ∩ lk(v)` read from the smaller link,
    /// `lk(s)`, one simplex at a time — a vertex `a` of `lk(s)` is in `lk(l)` iff
    /// `[a, l]` is an edge, an edge `[a, b]` of `lk(s)` is in `lk(l)` iff `[b, l]` is an
    /// edge of `lk(a)` (the face `{a, b, l}`), each asked of the lower-degree end. So the
    /// cost does not grow with the larger degree: O(d_s · max over `a` of min(d_a, d_l)),
    /// `d_s = min(d_u, d_v)`, which keeps checks at low-degree vertices cheap beside a
    /// vertex of very high degree. Shares nothing with the fast test but [`Self::link`]
    /// and [`Self::has_edge`]; it is the reference the fast paths are checked against.
    ///
    /// Returns `false` if `[u, v]` is not an edge.
    pub fn link_condition_naive(&self, u: VertexId, v: VertexId) -> bool {
        let (s, l) = if self.degree(u) <= self.degree(v) {
            (u, v)
        } else {
            (v, u)
        };
        let Some([x, y]) = self.edge_link(s, l) else {
            return false;
        };
        // lk(s) is a cycle of distinct vertices (a simplicial surface), so each vertex
        // of the intersection is found once. `l` is in lk(s) but not in lk(l).
        let ls: Vec<VertexId> = self.link(s).collect();
        let mut common: Vec<VertexId> = ls
            .iter()
            .copied()
            .filter(|&a| a != l && self.has_edge(a, l))
            .collect();
        common.sort_unstable();
        let mut expect = vec![x, y];
        expect.sort_unstable();
        if common != expect {
            return false;
        }
        // Edges of lk(s): consecutive pairs of its cycle; none may be an edge of lk(l).
        let in_link_of_l = |a: VertexId, b: VertexId| a != l && b != l && self.has_face(a, b, l);
        !(0..ls.len()).any(|i| in_link_of_l(ls[i], ls[(i + 1) % ls.len()]))
    }

    /// Whether some face has the three vertices `a`, `b`, `c`: whether two of them are
    /// consecutive in the link of the third, asked of the lowest-degree one.
    /// O(min(d_a, d_b, d_c)). The three must be live vertices: its one caller passes the
    /// endpoint of an edge and two vertices of a link.
    fn has_face(&self, a: VertexId, b: VertexId, c: VertexId) -> bool {
        let mut abc = [a, b, c];
        abc.sort_by_key(|&w| self.degree(w));
        let [p, q, r] = abc;
        let joins = |m: VertexId, n: VertexId| (m == q && n == r) || (m == r && n == q);
        let mut link = self.link(p);
        let Some(first) = link.next() else {
            return false;
        };
        let mut prev = first;
        for next in link {
            if joins(prev, next) {
                return true;
            }
            prev = next;
        }
        joins(prev, first)
    }

    /// Whether `[u, v]` is an edge that passes the link condition, without any scratch:
    /// the smaller link is collected and sorted, the larger one looked up in it. O((d_u +
    /// d_v) · log min(d_u, d_v)) time, O(min(d_u, d_v)) memory, never O(V). For loops of
    /// tests, [`Self::is_contractible_with`] with a kept [`LinkTester`] is O(d_u + d_v).
    pub fn is_contractible(&self, u: VertexId, v: VertexId) -> bool {
        if !self.is_vertex(u) || !self.is_vertex(v) || u == v {
            return false;
        }
        let (s, l) = if self.degree(u) <= self.degree(v) {
            (u, v)
        } else {
            (v, u)
        };
        let mut small: Vec<VertexId> = self.link(s).collect();
        small.sort_unstable();
        if small.binary_search(&l).is_err() {
            return false; // not an edge
        }
        if self.degree(s) == 3 && self.degree(l) == 3 {
            return false; // T4 (Prop. 6)
        }
        // Exactly the two link vertices of [s, l] are common neighbours (no critical
        // cycle); with that, lk(s) ∩ lk(l) can only hold the edge [x, y] on T4.
        self.link(l)
            .filter(|w| small.binary_search(w).is_ok())
            .count()
            == 2
    }

    /// The link condition with a caller-kept scratch (as petgraph's `DfsSpace`): marks
    /// `lk(u)` in `tester`, then counts in `lk(v)`. O(d_u + d_v); the scratch grows to the
    /// vertex capacity once and is never cleared.
    pub fn is_contractible_with(&self, u: VertexId, v: VertexId, tester: &mut LinkTester) -> bool {
        tester.test(self, u, v)
    }

    /// Whether no edge passes the link condition (naive test on every edge). O(Σ d_u·d_v).
    /// The tetrahedron is irreducible (Prop. 6): every edge has two degree-3 endpoints.
    pub fn is_irreducible_naive(&self) -> bool {
        self.edges()
            .all(|(a, b, _)| !self.link_condition_naive(a, b))
    }

    /// Whether no edge passes the link condition, by the marked test. O(Σ d_u + d_v) = O(E·d).
    pub fn is_irreducible(&self) -> bool {
        let mut t = LinkTester::new(self.vertex_capacity());
        // Iterate by vertex so each vertex's neighbourhood is marked once.
        for u in self.vertices() {
            t.mark(self, u);
            for w in self.link(u) {
                if u < w && t.test_marked(self, u, w) {
                    return false;
                }
            }
        }
        true
    }
}

/// The marked-neighbour link test of RS Sec. 4.2: with the neighbours of `u` marked
/// (O(d_u), once), each edge `[u, v]` is tested in O(d_v) by counting marked vertices in
/// `lk(v)`: `[u, v]` is contractible iff exactly two (`x` and `y`) are marked and the
/// surface is not T4 (`d_u = d_v = 3`, Prop. 6).
///
/// Marks are generation stamps, so re-marking costs O(d_u), never O(V).
#[derive(Clone, Debug)]
pub struct LinkTester {
    stamp: Vec<u32>,
    generation: u32,
    marked: u32,
}

impl LinkTester {
    /// A tester for triangulations with at most `vertex_capacity` vertex ids.
    pub fn new(vertex_capacity: usize) -> Self {
        LinkTester {
            stamp: vec![0; vertex_capacity],
            generation: 0,
            marked: NONE,
        }
    }

    /// Marks the neighbours of `u`. O(d_u).
    pub fn mark(&mut self, tri: &Triangulation, u: VertexId) {
        if self.stamp.len() < tri.vertex_capacity() {
            self.stamp.resize(tri.vertex_capacity(), 0);
        }
        self.generation = self.generation.wrapping_add(1);
        if self.generation == 0 {
            self.stamp.fill(0);
            self.generation = 1;
        }
        for w in tri.link(u) {
            self.stamp[w.index()] = self.generation;
        }
        self.marked = u.0;
    }

    /// The link test for `[u, v]` given that [`Self::mark`]`(u)` ran on the current
    /// triangulation. O(d_v). Returns `false` if `v` is not a neighbour of `u`.
    pub fn test_marked(&self, tri: &Triangulation, u: VertexId, v: VertexId) -> bool {
        debug_assert_eq!(
            self.marked, u.0,
            "test_marked: marks are for another vertex"
        );
        if self.stamp[v.index()] != self.generation {
            return false;
        }
        if tri.degree(u) == 3 && tri.degree(v) == 3 {
            return false; // T4 (Prop. 6)
        }
        let mut common = 0;
        for w in tri.link(v) {
            if self.stamp[w.index()] == self.generation {
                common += 1;
            }
        }
        common == 2
    }

    /// Marks `u` and tests `[u, v]`. O(d_u + d_v).
    pub fn test(&mut self, tri: &Triangulation, u: VertexId, v: VertexId) -> bool {
        if !tri.is_vertex(u) || !tri.is_vertex(v) {
            return false;
        }
        self.mark(tri, u);
        self.test_marked(tri, u, v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::History;

    /// The fast tests (with and without a kept tester) answer `false`, as the definition
    /// does, for a vertex paired with itself and for a vertex a contraction removed, on either side, with a live
    /// neighbour whose edge would otherwise pass.
    #[test]
    fn the_fast_test_refuses_a_vertex_with_itself_and_removed_vertices() {
        let m = crate::gen::icosahedron();
        let mut t = Triangulation::from_faces(m.vertex_count, &m.faces).expect("icosahedron");
        let (a, b, _) = t.edges().next().expect("an edge");
        assert!(t.is_contractible(a, b) && t.link_condition_naive(a, b));
        assert!(!t.is_contractible(a, a));
        t.contract(a, b, &mut History::new()).expect("contractible");
        // One of the two is gone; its former neighbours are still live.
        let (gone, kept) = if t.is_vertex(a) { (b, a) } else { (a, b) };
        assert!(!t.is_vertex(gone));
        let w = t.link(kept).next().expect("a neighbour");
        assert!(
            t.is_contractible(kept, w),
            "the icosahedron minus one edge still has contractible edges"
        );
        let mut tester = LinkTester::new(t.vertex_capacity());
        assert!(t.is_contractible_with(kept, w, &mut tester));
        for (x, y) in [(gone, w), (w, gone), (gone, kept), (kept, gone)] {
            assert!(!t.is_contractible(x, y), "{x} {y}");
            assert!(!t.is_contractible_with(x, y, &mut tester), "{x} {y}");
            assert!(!t.link_condition_naive(x, y), "{x} {y}");
        }
    }

    /// Every test refuses every edge of the tetrahedron boundary (only the edge
    /// `[x, y]` of the intersection tells, and the face `{x, y, l}` is seen in either
    /// direction of a link) under all 24 labellings of its vertices, in both
    /// orientations.
    #[test]
    fn the_tetrahedron_is_refused_in_every_labelling_and_orientation() {
        let base = crate::gen::tetrahedron();
        let mut seen = 0;
        for p in 0..24u32 {
            // The permutation of rank `p` (factorial base).
            let mut left: Vec<u32> = (0..4).collect();
            let mut rank = p;
            let mut perm = [0u32; 4];
            for (i, slot) in perm.iter_mut().enumerate() {
                let radix = (4 - i) as u32;
                *slot = left.remove((rank % radix) as usize);
                rank /= radix;
            }
            for reversed in [false, true] {
                let faces: Vec<[u32; 3]> = base
                    .faces
                    .iter()
                    .map(|f| {
                        let g = f.map(|v| perm[v as usize]);
                        if reversed {
                            [g[0], g[2], g[1]]
                        } else {
                            g
                        }
                    })
                    .collect();
                let t = Triangulation::from_faces(4, &faces).expect("the tetrahedron");
                let mut tester = LinkTester::new(t.vertex_capacity());
                for (u, v, _) in t.edges() {
                    for (a, b) in [(u, v), (v, u)] {
                        assert!(
                            !t.link_condition_naive(a, b),
                            "{perm:?} {reversed}: {a} {b}"
                        );
                        assert!(!t.is_contractible(a, b), "{perm:?} {reversed}: {a} {b}");
                        assert!(!t.is_contractible_with(a, b, &mut tester));
                        seen += 1;
                    }
                }
            }
        }
        assert_eq!(seen, 24 * 2 * 12);
    }
}

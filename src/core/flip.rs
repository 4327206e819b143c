//! Edge flips (tri-quad paper, Def. 3.3).

use super::ids::{Corner, VertexId};
use super::tri::Triangulation;

/// Why a flip was refused. The triangulation is unchanged.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum FlipError {
    /// `[u, v]` is not an edge.
    #[error("[{u}, {v}] is not an edge")]
    NotAnEdge {
        /// First endpoint.
        u: VertexId,
        /// Second endpoint.
        v: VertexId,
    },
    /// The flipped edge `[w, z]` already exists, so the flip would not give a
    /// triangulation (Def. 3.3: `[u, v]` is not flippable).
    #[error("[{u}, {v}] is not flippable: [{w}, {z}] is already an edge")]
    NotFlippable {
        /// First endpoint.
        u: VertexId,
        /// Second endpoint.
        v: VertexId,
        /// First link vertex.
        w: VertexId,
        /// Second link vertex.
        z: VertexId,
    },
}

impl Triangulation {
    /// Whether `[u, v]` is an edge whose flip gives a triangulation: with faces
    /// `[u, v, w]` and `[u, v, z]`, iff `[w, z]` is not already an edge (which also
    /// guarantees `d(u), d(v) >= 4`). O(d_u + min(d_w, d_z)).
    pub fn is_flippable(&self, u: VertexId, v: VertexId) -> bool {
        match self.edge_link(u, v) {
            Some([w, z]) => !self.has_edge(w, z),
            None => false,
        }
    }

    /// Replaces faces `[u, v, w]`, `[u, v, z]` and edge `[u, v]` by `[u, w, z]`,
    /// `[v, w, z]` and `[w, z]` (Def. 3.3), keeping both face ids. Degrees: u, v lose
    /// one, w, z gain one. Orientation
    /// agreement with the neighbours is preserved. O(d_u + min(d_w, d_z)) for the check,
    /// O(1) for the change. Flipping `[w, z]` afterwards restores the same face set.
    pub fn flip(&mut self, u: VertexId, v: VertexId) -> Result<(), FlipError> {
        let Some([k1, k2]) = self.edge_corners(u, v) else {
            return Err(FlipError::NotAnEdge { u, v });
        };
        let w = self.vertex(k1);
        let z = self.vertex(k2);
        if self.has_edge(w, z) {
            return Err(FlipError::NotFlippable { u, v, w, z });
        }
        self.flip_corners(k1, k2);
        Ok(())
    }

    /// The flip given the two corners `k1`, `k2` opposite the edge (no checks but debug).
    pub(crate) fn flip_corners(&mut self, k1: Corner, k2: Corner) {
        debug_assert_eq!(self.opposite(k1), k2);
        // f1 = [a, b, c] with k1 at c; f2 = [a, b, d] with k2 at d.
        let (c1a, c1b) = (k1.next(), k1.prev());
        let a = self.corner_vertex[c1a.index()];
        let b = self.corner_vertex[c1b.index()];
        let (c2a, c2b) = if self.corner_vertex[k2.next().index()] == a {
            (k2.next(), k2.prev())
        } else {
            (k2.prev(), k2.next())
        };
        let c = self.corner_vertex[k1.index()];
        let d = self.corner_vertex[k2.index()];
        let n_ad = self.opposite[c2b.index()];
        let n_bc = self.opposite[c1a.index()];
        // New f1 = {a, d, c}: slot c1b takes d (keeps its opposite, across [a, c]);
        // new f2 = {c, b, d}: slot c2a takes c (keeps its opposite, across [b, d]).
        self.corner_vertex[c1b.index()] = d;
        self.corner_vertex[c2a.index()] = c;
        let pair = |t: &mut Triangulation, p: u32, q: u32| {
            t.opposite[p as usize] = q;
            t.opposite[q as usize] = p;
        };
        pair(self, c1a.0, c2b.0); // the new edge [c, d]
        pair(self, k1.0, n_ad); // c's corner in f1 faces [a, d]
        pair(self, k2.0, n_bc); // d's corner in f2 faces [b, c]
        self.degree[a as usize] -= 1;
        self.degree[b as usize] -= 1;
        self.degree[c as usize] += 1;
        self.degree[d as usize] += 1;
        self.vertex_corner[a as usize] = c1a.0;
        self.vertex_corner[b as usize] = c2b.0;
    }
}

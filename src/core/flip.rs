//! Edge flips (tri-quad paper, Def. 3.3), corner-addressed, with a record that undoes
//! them slot-exactly.

use super::ids::{Corner, FaceId, VertexId};
use super::tri::{StateStamp, Triangulation};

/// What one flip changed: the corners of the new edge, and enough to restore the
/// previous state exactly ([`Triangulation::unflip`]). `==` ignores the state stamps.
#[derive(Clone, Copy, Debug)]
pub struct FlipRecord {
    /// The endpoints `[a, b]` of the edge that was flipped.
    pub old_edge: [VertexId; 2],
    /// The endpoints `[c, d]` of the new edge (`c` at `moved[0]`, `d` at `moved[1]`).
    pub new_edge: [VertexId; 2],
    /// The two corners opposite the new edge `[c, d]` (one per face, first in the face of
    /// `moved[0]`).
    pub new_corners: [Corner; 2],
    /// The two corners that were opposite `[a, b]`; afterwards they face `[a, d]` and
    /// `[b, c]` respectively.
    pub moved: [Corner; 2],
    /// The two faces (ids kept by the flip).
    pub faces: [FaceId; 2],
    saved_vertex: [u32; 6],
    saved_opposite: [u32; 6],
    saved_vertex_corner: [u32; 2],
    state_before: StateStamp,
    state_after: StateStamp,
}

impl PartialEq for FlipRecord {
    fn eq(&self, o: &Self) -> bool {
        self.old_edge == o.old_edge
            && self.new_edge == o.new_edge
            && self.new_corners == o.new_corners
            && self.moved == o.moved
            && self.faces == o.faces
            && self.saved_vertex == o.saved_vertex
            && self.saved_opposite == o.saved_opposite
            && self.saved_vertex_corner == o.saved_vertex_corner
    }
}
impl Eq for FlipRecord {}

impl FlipRecord {
    /// The triangulation's state stamp right after this flip.
    pub fn state_after(&self) -> StateStamp {
        self.state_after
    }
}

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
    /// The corner named is not a live corner.
    #[error("corner {0} is not a live corner")]
    DeadCorner(Corner),
    /// [`Triangulation::unflip`]: the triangulation is not in the state the flip left.
    #[error(
        "the triangulation changed since flip [{u}, {v}] was recorded; unflip would corrupt it"
    )]
    Modified {
        /// First endpoint of the flipped edge.
        u: VertexId,
        /// Second endpoint of the flipped edge.
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
        let Some([k1, _]) = self.edge_corners(u, v) else {
            return Err(FlipError::NotAnEdge { u, v });
        };
        match self.flip_at(k1) {
            Ok(_) => Ok(()),
            // Report the edge in the caller's order.
            Err(FlipError::NotFlippable { w, z, .. }) => {
                Err(FlipError::NotFlippable { u, v, w, z })
            }
            Err(e) => Err(e),
        }
    }

    /// Flips the edge opposite corner `c` if it is flippable (Def. 3.3), keeping both
    /// face ids. Returns the record: the new edge's corners and what
    /// [`Self::unflip`] needs. O(min(d_w, d_z)) for the check, O(1) for the change.
    pub fn flip_at(&mut self, c: Corner) -> Result<FlipRecord, FlipError> {
        if !self.is_face(c.face()) {
            return Err(FlipError::DeadCorner(c));
        }
        let k1 = c;
        let k2 = self.opposite(k1);
        let [u, v] = self.edge_endpoints(k1);
        let w = self.vertex(k1);
        let z = self.vertex(k2);
        if self.has_edge(w, z) {
            return Err(FlipError::NotFlippable { u, v, w, z });
        }
        let (f1, f2) = (k1.face(), k2.face());
        let (saved_vertex, saved_opposite) = self.save_faces([f1, f2]);
        let saved_vertex_corner = [self.vertex_corner[u.index()], self.vertex_corner[v.index()]];
        let state_before = self.state;
        let new_corners = self.flip_corners(k1, k2);
        self.touch();
        Ok(FlipRecord {
            old_edge: [u, v],
            new_edge: [w, z],
            new_corners,
            moved: [k1, k2],
            faces: [f1, f2],
            saved_vertex,
            saved_opposite,
            saved_vertex_corner,
            state_before,
            state_after: self.state,
        })
    }

    /// Flips the edge opposite live corner `c`, which the caller has *proved* flippable
    /// (the tri-quad expansion, by Prop. 3.3), without the O(min(d_w, d_z)) link walk
    /// of [`Self::flip_at`] and without an undo record. Returns the corners that were
    /// opposite the old edge (`moved`, as in [`FlipRecord`]) and the corners opposite
    /// the new one. O(1).
    ///
    /// The proof is the caller's: when the specification runs (debug assertions or the
    /// `invariants` feature) the test runs too and a non-flippable edge panics; in other
    /// release builds such a call would leave a duplicate edge.
    pub(crate) fn flip_at_proved(&mut self, c: Corner) -> ([Corner; 2], [Corner; 2]) {
        let k2 = self.opposite(c);
        if super::CHECKS {
            assert!(
                self.is_face(c.face()) && !self.has_edge(self.vertex(c), self.vertex(k2)),
                "flip_at_proved: the edge opposite {c} is not flippable (Prop. 3.3 violated)"
            );
        }
        let new_corners = self.flip_corners(c, k2);
        self.touch();
        ([c, k2], new_corners)
    }

    /// Undoes the flip `rec` exactly (same slots, opposite table, vertex corners, degrees
    /// and state stamp), provided the triangulation is in the state the flip left
    /// ([`FlipError::Modified`] otherwise, nothing changed). O(1).
    pub fn unflip(&mut self, rec: &FlipRecord) -> Result<(), FlipError> {
        if self.state != rec.state_after {
            let [u, v] = rec.old_edge;
            return Err(FlipError::Modified { u, v });
        }
        self.restore_faces(rec.faces, &rec.saved_vertex, &rec.saved_opposite);
        let [a, b] = rec.old_edge;
        let [c, d] = rec.new_edge;
        self.degree[a.index()] += 1;
        self.degree[b.index()] += 1;
        self.degree[c.index()] -= 1;
        self.degree[d.index()] -= 1;
        self.vertex_corner[a.index()] = rec.saved_vertex_corner[0];
        self.vertex_corner[b.index()] = rec.saved_vertex_corner[1];
        self.state = rec.state_before;
        Ok(())
    }

    /// The flip given the two corners `k1`, `k2` opposite the edge (no checks but debug).
    /// Returns the two corners opposite the new edge, `k1`'s face first. Does not touch
    /// the state stamp (the caller does).
    pub(crate) fn flip_corners(&mut self, k1: Corner, k2: Corner) -> [Corner; 2] {
        debug_assert_eq!(self.opposite(k1), k2);
        // f1 = [a, b, c] with k1 at c; f2 = [a, b, d] with k2 at d.
        let (c1a, c1b) = (k1.next(), k1.prev());
        let a = self.corner_vertex[c1a.index()];
        let b = self.corner_vertex[c1b.index()];
        let c2a = self.corner_at(k2, VertexId(a));
        let c2b = self.corner_at(k2, VertexId(b));
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
        [c1a, c2b]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::gen::octahedron;

    /// `==` compares every field but the state stamps: a record equals itself with
    /// other stamps, and differs from itself with any one other field changed.
    #[test]
    fn record_equality_is_field_by_field_without_the_stamps() {
        let m = octahedron();
        let mut t = Triangulation::from_faces(m.vertex_count, &m.faces).expect("octahedron");
        let mut twin = t.clone();
        let rec = t.flip_at(Corner(0)).expect("an octahedron edge flips");
        let same = twin.flip_at(Corner(0)).expect("the same flip");
        assert_ne!(rec.state_after(), same.state_after());
        assert_eq!(rec, same);
        let restamped = FlipRecord {
            state_before: StateStamp::fresh(),
            state_after: StateStamp::fresh(),
            ..rec
        };
        assert_eq!(rec, restamped);
        let v = |x: u32| VertexId(x + 100);
        let changed: [FlipRecord; 8] = [
            FlipRecord {
                old_edge: [v(0), v(1)],
                ..rec
            },
            FlipRecord {
                new_edge: [v(0), v(1)],
                ..rec
            },
            FlipRecord {
                new_corners: [Corner(90), Corner(91)],
                ..rec
            },
            FlipRecord {
                moved: [Corner(90), Corner(91)],
                ..rec
            },
            FlipRecord {
                faces: [FaceId(90), FaceId(91)],
                ..rec
            },
            FlipRecord {
                saved_vertex: [99; 6],
                ..rec
            },
            FlipRecord {
                saved_opposite: [99; 6],
                ..rec
            },
            FlipRecord {
                saved_vertex_corner: [99; 2],
                ..rec
            },
        ];
        for (k, c) in changed.iter().enumerate() {
            assert_ne!(&rec, c, "field {k} changed, yet equal");
        }
    }
}

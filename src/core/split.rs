//! The general vertex split (the inverse of a contraction, creating a new vertex).

use super::ids::{Corner, FaceId, VertexId, NONE};
use super::tri::Triangulation;

/// Why a vertex split was refused. The triangulation is unchanged.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum SplitError {
    /// `u` is not a live vertex.
    #[error("{0} is not a vertex")]
    NoVertex(VertexId),
    /// `x` or `y` is not in the link of `u`, or `x == y`.
    #[error("{x} and {y} are not two distinct neighbours of {u}")]
    BadLink {
        /// The vertex to split.
        u: VertexId,
        /// First link vertex.
        x: VertexId,
        /// Second link vertex.
        y: VertexId,
    },
    /// The index space is exhausted.
    #[error("too many vertices or faces for 32-bit indices")]
    TooLarge,
}

impl Triangulation {
    /// Splits `u` along its link vertices `x` and `y` into `u` and a new vertex `v`
    /// (returned, id = [`Self::vertex_capacity`] before the call) joined by a new edge.
    ///
    /// Walking `u`'s star from [`Self::corner_of`]`(u)` lists its link cycle in order; the
    /// faces strictly after `x` up to and including `y` (the faces between `x` and `y` on
    /// that side) move to `v`, and two new faces `[u, v, x]` and `[u, v, y]` (ids
    /// appended) close the gap. The result is always a triangulation of the same surface
    /// (its edge `[u, v]` has link `{x, y}` and passes the link condition). New faces are
    /// oriented to agree with their neighbours on `v`'s side, so a consistently oriented
    /// input stays consistently oriented. O(d_u).
    pub fn split_vertex(
        &mut self,
        u: VertexId,
        x: VertexId,
        y: VertexId,
    ) -> Result<VertexId, SplitError> {
        if !self.is_vertex(u) {
            return Err(SplitError::NoVertex(u));
        }
        let steps: Vec<_> = self.star(u).collect();
        let i = steps.iter().position(|s| s.neighbour == x);
        let j = steps.iter().position(|s| s.neighbour == y);
        let (Some(i), Some(j)) = (i, j) else {
            return Err(SplitError::BadLink { u, x, y });
        };
        if i == j {
            return Err(SplitError::BadLink { u, x, y });
        }
        let nv = self.vertex_capacity();
        let nf = self.face_capacity();
        if nv + 1 >= super::ids::MAX_VERTICES || nf + 2 >= super::ids::MAX_FACES {
            return Err(SplitError::TooLarge);
        }
        let d = steps.len();
        let v = VertexId(nv as u32);
        // Face k of the walk contains u, neighbour(k-1) and neighbour(k); the faces
        // i+1 ..= j (cyclically) lie between x and y.
        let moved: Vec<Corner> = (1..=((j + d - i) % d))
            .map(|k| steps[(i + k) % d].corner)
            .collect();
        // P1 = first moved face (has edge [u, x]); p1 is its corner opposite [u, x].
        let p1 = self.corner_facing(moved[0], x);
        let q1 = self.opposite(p1);
        let p2 = self.corner_facing(*moved.last().expect("nonempty"), y);
        let q2 = self.opposite(p2);

        for c in &moved {
            self.corner_vertex[c.index()] = v.0;
        }
        self.vertex_corner.push(NONE);
        self.degree.push(0);

        let t1 = FaceId(nf as u32);
        let t2 = FaceId(nf as u32 + 1);
        // Orient T1 against P1 along [v, x], T2 against P2 along [v, y].
        let order = |tri: &Triangulation, p: Corner, w: VertexId| -> [u32; 3] {
            if tri.corner_vertex[p.next().index()] == v.0 {
                [w.0, v.0, u.0]
            } else {
                [v.0, w.0, u.0]
            }
        };
        let o1 = order(self, p1, x);
        let o2 = order(self, p2, y);
        self.corner_vertex.extend_from_slice(&o1);
        self.corner_vertex.extend_from_slice(&o2);
        self.opposite.extend_from_slice(&[NONE; 6]);
        let slot = |o: &[u32; 3], w: u32| o.iter().position(|&z| z == w).expect("in face") as u32;
        let link = |tri: &mut Triangulation, a: Corner, b: Corner| {
            tri.opposite[a.index()] = b.0;
            tri.opposite[b.index()] = a.0;
        };
        // In T1: u's corner faces [v, x] (P1's side), v's corner faces [u, x] (Q1's side),
        // x's corner faces [u, v] (T2, at y).
        link(self, t1.corner(slot(&o1, u.0)), p1);
        link(self, t1.corner(slot(&o1, v.0)), q1);
        link(self, t2.corner(slot(&o2, u.0)), p2);
        link(self, t2.corner(slot(&o2, v.0)), q2);
        link(self, t1.corner(slot(&o1, x.0)), t2.corner(slot(&o2, y.0)));

        let m = moved.len() as u32;
        self.degree[v.index()] = m + 2;
        self.degree[u.index()] = self.degree[u.index()] - m + 2;
        self.degree[x.index()] += 1;
        self.degree[y.index()] += 1;
        self.vertex_corner[v.index()] = t1.corner(slot(&o1, v.0)).0;
        self.vertex_corner[u.index()] = t1.corner(slot(&o1, u.0)).0;
        self.live_vertices += 1;
        self.live_faces += 2;
        self.touch();
        Ok(v)
    }
}

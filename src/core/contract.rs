//! Edge contraction (RS paper, Def. 3 and Fig. 7) and its exact inverse.

use super::ids::{Corner, FaceId, VertexId, NONE};
use super::link::LinkTester;
use super::tri::Triangulation;

/// Why a contraction was refused. The triangulation is unchanged.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ContractError {
    /// `[u, v]` is not an edge of the current triangulation.
    #[error("[{u}, {v}] is not an edge")]
    NotAnEdge {
        /// First endpoint.
        u: VertexId,
        /// Second endpoint.
        v: VertexId,
    },
    /// `[u, v]` fails the link condition (a critical cycle, or the surface is T4).
    #[error("[{u}, {v}] fails the link condition")]
    NotContractible {
        /// First endpoint.
        u: VertexId,
        /// Second endpoint.
        v: VertexId,
    },
}

/// What one contraction changed, enough for [`History::undo`] to restore it exactly.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ContractionRecord {
    /// The surviving vertex.
    pub u: VertexId,
    /// The removed vertex (identified with `u`).
    pub v: VertexId,
    /// The link `{x, y}` of `[u, v]` before the contraction.
    pub link: [VertexId; 2],
    /// The two removed faces `[u, v, x]` and `[u, v, y]`.
    pub faces: [FaceId; 2],
    /// Degree of `v` before the contraction.
    pub degree_v: u32,
    /// The removed faces' `corner_vertex` and `opposite` entries.
    saved_vertex: [u32; 6],
    saved_opposite: [u32; 6],
    /// `vertex_corner` of u, x, y, v before the contraction.
    saved_vertex_corner: [u32; 4],
    /// The range of [`History`]'s renamed-corner arena holding the corners that moved
    /// from `v` to `u`.
    renamed: (u32, u32),
}

impl ContractionRecord {
    /// The two edge gluings the contraction made, one per removed face: `(a, b)` where
    /// `a` was the corner across `[v, x]` (resp. `[v, y]`) and `b` the corner across
    /// `[u, x]` (resp. `[u, y]`); afterwards `a` and `b` are opposite each other across
    /// the merged edge `[u, x]` (resp. `[u, y]`). Edge-identity trackers use this to let
    /// the merged edge keep the identity of `[u, x]` (as Alg. 4.7 keeps the record `f`).
    pub fn glued(&self) -> [(Corner, Corner); 2] {
        let mut out = [(Corner(NONE), Corner(NONE)); 2];
        for (k, pair) in out.iter_mut().enumerate() {
            let slot_of = |w: VertexId| {
                (0..3)
                    .find(|&s| self.saved_vertex[3 * k + s] == w.0)
                    .expect("removed face holds u and v")
            };
            let a = self.saved_opposite[3 * k + slot_of(self.u)];
            let b = self.saved_opposite[3 * k + slot_of(self.v)];
            *pair = (Corner(a), Corner(b));
        }
        out
    }

    /// Number of corners renamed from `v` to `u` (`degree(v) - 2`).
    pub fn renamed_len(&self) -> usize {
        (self.renamed.1 - self.renamed.0) as usize
    }
}

/// The contraction stack `S` (Alg. 4.5 l.13): records in order plus one flat arena of
/// renamed corners, so a million contractions cost two allocations, not a million.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct History {
    records: Vec<ContractionRecord>,
    renamed: Vec<Corner>,
}

impl History {
    /// An empty history.
    pub fn new() -> Self {
        Self::default()
    }
    /// Number of recorded contractions.
    pub fn len(&self) -> usize {
        self.records.len()
    }
    /// Whether no contraction is recorded.
    pub fn is_empty(&self) -> bool {
        self.records.is_empty()
    }
    /// The records, oldest first.
    pub fn records(&self) -> &[ContractionRecord] {
        &self.records
    }
    /// The corners renamed from `v` to `u` by `record`.
    pub fn renamed(&self, record: &ContractionRecord) -> &[Corner] {
        &self.renamed[record.renamed.0 as usize..record.renamed.1 as usize]
    }

    /// Undoes the most recent contraction by the vertex split that restores exactly the
    /// previous triangulation: same vertex ids, face ids, corner slots and opposite
    /// table. O(d_v). Returns the record undone, or `None` if the history is empty.
    ///
    /// Precondition: `tri` is the triangulation the contractions were applied to, and
    /// nothing else changed it since the last one (checked in debug builds by
    /// [`Triangulation::validate`] in the tests, not here).
    pub fn undo(&mut self, tri: &mut Triangulation) -> Option<ContractionRecord> {
        let r = self.records.pop()?;
        let (lo, hi) = (r.renamed.0 as usize, r.renamed.1 as usize);
        for c in &self.renamed[lo..hi] {
            tri.corner_vertex[c.index()] = r.v.0;
        }
        self.renamed.truncate(lo);
        for (k, f) in r.faces.iter().enumerate() {
            for s in 0..3 {
                let c = f.corner(s as u32).index();
                tri.corner_vertex[c] = r.saved_vertex[3 * k + s];
                let o = r.saved_opposite[3 * k + s];
                tri.opposite[c] = o;
                tri.opposite[o as usize] = c as u32;
            }
        }
        let [x, y] = r.link;
        tri.degree[r.u.index()] = tri.degree[r.u.index()] + 4 - r.degree_v;
        tri.degree[r.v.index()] = r.degree_v;
        tri.degree[x.index()] += 1;
        tri.degree[y.index()] += 1;
        let [cu, cx, cy, cv] = r.saved_vertex_corner;
        tri.vertex_corner[r.u.index()] = cu;
        tri.vertex_corner[x.index()] = cx;
        tri.vertex_corner[y.index()] = cy;
        tri.vertex_corner[r.v.index()] = cv;
        tri.live_vertices += 1;
        tri.live_faces += 2;
        Some(r)
    }

    /// Undoes every recorded contraction, newest first.
    pub fn undo_all(&mut self, tri: &mut Triangulation) {
        while self.undo(tri).is_some() {}
    }
}

impl Triangulation {
    /// Contracts `[u, v]` keeping `u` if it passes the link condition, recording the
    /// change in `history`. O(d_u + d_v) (the link test marks `lk(u)`).
    ///
    /// Postconditions on success: `v` is removed, every face that had `v` now has `u`,
    /// faces `[u, v, x]` and `[u, v, y]` are removed, `d(u) += d(v) - 4`, `d(x)` and
    /// `d(y)` drop by one, χ and orientability are unchanged. On error nothing changes.
    pub fn contract(
        &mut self,
        u: VertexId,
        v: VertexId,
        history: &mut History,
    ) -> Result<ContractionRecord, ContractError> {
        if !self.has_edge(u, v) {
            return Err(ContractError::NotAnEdge { u, v });
        }
        let mut t = LinkTester::new(self.vertex_capacity());
        if !t.test(self, u, v) {
            return Err(ContractError::NotContractible { u, v });
        }
        Ok(self.contract_tested(u, v, history))
    }

    /// Contracts `[u, v]` keeping `u`, for callers that have already established the
    /// link condition (the RS algorithm tests it separately). O(d_v).
    ///
    /// # Panics
    /// If `[u, v]` is not an edge (a caller bug, not an input error). Debug builds also
    /// assert the link condition.
    pub fn contract_tested(
        &mut self,
        u: VertexId,
        v: VertexId,
        history: &mut History,
    ) -> ContractionRecord {
        debug_assert!(
            self.link_condition_naive(u, v),
            "contract_tested: [{u}, {v}] fails the link condition"
        );
        // Find a corner at v in a face containing u, walking v's star (O(d_v)).
        // One walk around v: its corners in star order, and where u is. The step whose
        // exit neighbour is u and the step after it are the two faces of [u, v].
        let start = history.renamed.len();
        let mut at_u = None;
        for (k, s) in self.star(v).enumerate() {
            history.renamed.push(s.corner);
            if s.neighbour == u {
                at_u = Some(k);
            }
        }
        let d = history.renamed.len() - start;
        let p = at_u.expect("contract_tested: [u, v] is not an edge");
        let q = (p + 1) % d;
        let first = history.renamed[start + p];
        let opp1 = if self.corner_vertex[first.next().index()] == u.0 {
            first.prev()
        } else {
            first.next()
        };
        let opp2 = self.opposite(opp1);
        let f1 = opp1.face();
        let f2 = opp2.face();
        debug_assert_eq!(history.renamed[start + q].face(), f2);
        let x = self.vertex(opp1);
        let y = self.vertex(opp2);
        // Keep only v's corners outside f1 and f2 (remove the later index first).
        history.renamed.remove(start + p.max(q));
        history.renamed.remove(start + p.min(q));
        let start = start as u32;
        let end = history.renamed.len() as u32;

        let mut saved_vertex = [0u32; 6];
        let mut saved_opposite = [0u32; 6];
        for (k, f) in [f1, f2].iter().enumerate() {
            for s in 0..3 {
                let c = f.corner(s as u32).index();
                saved_vertex[3 * k + s] = self.corner_vertex[c];
                saved_opposite[3 * k + s] = self.opposite[c];
            }
        }
        let degree_v = self.degree[v.index()];
        let saved_vertex_corner = [
            self.vertex_corner[u.index()],
            self.vertex_corner[x.index()],
            self.vertex_corner[y.index()],
            self.vertex_corner[v.index()],
        ];

        // Glue the outer neighbours of each removed face: across [v, x] meets across
        // [u, x] (and the same for y). In face f1, the corner at u is opposite [v, x].
        for f in [f1, f2] {
            let cs = f.corners();
            let cu = cs
                .into_iter()
                .find(|c| self.corner_vertex[c.index()] == u.0)
                .expect("face of [u,v] has u");
            let cv = cs
                .into_iter()
                .find(|c| self.corner_vertex[c.index()] == v.0)
                .expect("face of [u,v] has v");
            let a = self.opposite[cu.index()];
            let b = self.opposite[cv.index()];
            self.opposite[a as usize] = b;
            self.opposite[b as usize] = a;
        }
        for &c in &history.renamed[start as usize..end as usize] {
            self.corner_vertex[c.index()] = u.0;
        }
        for f in [f1, f2] {
            for c in f.corners() {
                self.corner_vertex[c.index()] = NONE;
                self.opposite[c.index()] = NONE;
            }
        }
        // d_v - 4 may be negative (d_v = 3): add before subtracting.
        self.degree[u.index()] = self.degree[u.index()] + degree_v - 4;
        self.degree[x.index()] -= 1;
        self.degree[y.index()] -= 1;
        self.degree[v.index()] = 0;
        self.vertex_corner[v.index()] = NONE;
        // u keeps a corner outside f1/f2 (a renamed one always exists: d_v - 2 >= 1).
        self.vertex_corner[u.index()] = history.renamed[start as usize].0;
        for (w, f) in [(x, f1), (y, f2)] {
            if Corner(self.vertex_corner[w.index()]).face() == f {
                // The face across [u, w] from f survives and contains w.
                let c_opp_uw = f
                    .corners()
                    .into_iter()
                    .find(|&c| saved_at(&saved_vertex, f1, f2, c) == v.0)
                    .expect("face has v");
                let across = Corner(saved_at(&saved_opposite, f1, f2, c_opp_uw));
                let cw = if self.corner_vertex[across.next().index()] == w.0 {
                    across.next()
                } else {
                    across.prev()
                };
                self.vertex_corner[w.index()] = cw.0;
            }
        }
        self.live_vertices -= 1;
        self.live_faces -= 2;
        let rec = ContractionRecord {
            u,
            v,
            link: [x, y],
            faces: [f1, f2],
            degree_v,
            saved_vertex,
            saved_opposite,
            saved_vertex_corner,
            renamed: (start, end),
        };
        history.records.push(rec);
        rec
    }
}

/// The saved entry of corner `c` of one of the two removed faces.
fn saved_at(saved: &[u32; 6], f1: FaceId, f2: FaceId, c: Corner) -> u32 {
    if c.face() == f1 {
        saved[c.slot() as usize]
    } else {
        debug_assert_eq!(c.face(), f2);
        saved[3 + c.slot() as usize]
    }
}

//! Edge contraction (RS paper, Def. 3 and Fig. 7) and its exact inverse.

use super::collapse::CollapsePlan;
use super::ids::{Corner, FaceId, VertexId, NONE};
use super::link::LinkTester;
use super::tri::{StateStamp, Triangulation};

/// Degree product up to which [`Triangulation::contract_tested`] re-checks the link
/// condition naively in debug builds (the naive test costs O(d_u · d_v); RS contracts
/// edges at a vertex of degree in the millions, so an unbounded check is quadratic).
const DEBUG_NAIVE_CHECK_WORK: usize = 64 * 64;

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
    /// The corner named is not a live corner.
    #[error("corner {0} is not a live corner")]
    DeadCorner(Corner),
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
///
/// `==` compares what the contraction did, not the state stamps it carries for the undo
/// guard (two runs of a deterministic algorithm give equal records).
#[derive(Clone, Copy, Debug)]
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
    /// The slots of `u` and `v` in the two removed faces, two bits each (face 0's `u`,
    /// face 0's `v`, face 1's `u`, face 1's `v`, from the low bits): with `u`, `v` and
    /// `link` they give the removed faces' `corner_vertex` entries
    /// ([`Self::saved_vertex`]).
    slots: u8,
    /// The removed faces' `opposite` entries at `u` and at `v` (face 0's, then face
    /// 1's). The corners at `x` and `y` were opposite each other across `[u, v]`, so
    /// they need no entry: 88 bytes per record instead of 120, which RS writes 2.1 M
    /// times on B0 ([`Self::saved_opposite`]).
    outer: [u32; 4],
    /// `vertex_corner` of u, x, y, v before the contraction.
    saved_vertex_corner: [u32; 4],
    /// The range of [`History`]'s renamed-corner arena holding the corners that moved
    /// from `v` to `u`.
    renamed: (u32, u32),
    /// The triangulation's state stamp before and after the contraction (the undo guard).
    state_before: StateStamp,
    state_after: StateStamp,
}

impl PartialEq for ContractionRecord {
    fn eq(&self, o: &Self) -> bool {
        self.u == o.u
            && self.v == o.v
            && self.link == o.link
            && self.faces == o.faces
            && self.degree_v == o.degree_v
            && self.slots == o.slots
            && self.outer == o.outer
            && self.saved_vertex_corner == o.saved_vertex_corner
            && self.renamed == o.renamed
    }
}
impl Eq for ContractionRecord {}

/// Why [`History::try_undo`] refused. Nothing was changed.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum UndoError {
    /// The triangulation is not in the state the newest record left it in: something
    /// (a flip, a split, a contraction recorded elsewhere) changed it since, or it is
    /// another triangulation. Slot-exact undo would corrupt it.
    #[error(
        "the triangulation changed since the operation on [{u}, {v}] was recorded \
         (state {found:?}, expected {expected:?}); undo would corrupt it"
    )]
    Modified {
        /// First vertex of the newest record (a contraction's survivor, a flip's edge).
        u: VertexId,
        /// Second vertex of the newest record.
        v: VertexId,
        /// The state the record left.
        expected: StateStamp,
        /// The triangulation's current state.
        found: StateStamp,
    },
}

impl ContractionRecord {
    /// Slot of `u` (`which == 0`) or `v` (`which == 1`) in removed face `k`.
    #[inline]
    fn slot(&self, k: usize, which: usize) -> usize {
        ((self.slots >> (4 * k + 2 * which)) & 3) as usize
    }

    /// The removed faces' `corner_vertex` entries (face 0's three slots, then face 1's).
    #[inline]
    pub(crate) fn saved_vertex(&self) -> [u32; 6] {
        let mut out = [0u32; 6];
        for k in 0..2 {
            let (su, sv) = (self.slot(k, 0), self.slot(k, 1));
            out[3 * k + su] = self.u.0;
            out[3 * k + sv] = self.v.0;
            out[3 * k + 3 - su - sv] = self.link[k].0;
        }
        out
    }

    /// The removed faces' `opposite` entries (face 0's three slots, then face 1's).
    #[inline]
    pub(crate) fn saved_opposite(&self) -> [u32; 6] {
        let mut out = [0u32; 6];
        for k in 0..2 {
            let (su, sv) = (self.slot(k, 0), self.slot(k, 1));
            out[3 * k + su] = self.outer[2 * k];
            out[3 * k + sv] = self.outer[2 * k + 1];
            let other = 1 - k;
            let s_other = 3 - self.slot(other, 0) - self.slot(other, 1);
            out[3 * k + 3 - su - sv] = self.faces[other].corner(s_other as u32).0;
        }
        out
    }

    /// The two edge gluings the contraction made, one per removed face: `(a, b)` where
    /// `a` was the corner across `[v, x]` (resp. `[v, y]`) and `b` the corner across
    /// `[u, x]` (resp. `[u, y]`); afterwards `a` and `b` are opposite each other across
    /// the merged edge `[u, x]` (resp. `[u, y]`). Code that tracks edge identities uses
    /// this to let the merged edge keep the identity of `[u, x]` (as Alg. 4.7 keeps the
    /// record `f`).
    pub fn glued(&self) -> [(Corner, Corner); 2] {
        let mut out = [(Corner(NONE), Corner(NONE)); 2];
        for (k, pair) in out.iter_mut().enumerate() {
            *pair = (Corner(self.outer[2 * k]), Corner(self.outer[2 * k + 1]));
        }
        out
    }

    /// Number of corners renamed from `v` to `u` (`degree(v) - 2`).
    pub fn renamed_len(&self) -> usize {
        (self.renamed.1 - self.renamed.0) as usize
    }

    /// The corner of the first removed face that was opposite `[u, v]` (its corner at
    /// `x`); dead after the contraction, it names the contracted edge in per-corner
    /// tables such as [`crate::core::EdgeNumbering`].
    pub fn corner_opposite_uv(&self) -> Corner {
        let slot = 3 - self.slot(0, 0) - self.slot(0, 1);
        self.faces[0].corner(slot as u32)
    }

    /// The triangulation's state stamp right after this contraction.
    pub fn state_after(&self) -> StateStamp {
        self.state_after
    }
}

/// The contraction stack `S` (Alg. 4.5 l.13): records in order plus one flat arena of
/// renamed corners, so a million contractions cost two allocations, not a million.
///
/// It also owns the scratch of the link test ([`LinkTester`], one stamp per vertex id,
/// grown once), so that [`Triangulation::contract`] costs O(d_u + d_v), not O(V).
///
/// # Undo guard
/// Undo is slot-exact: it writes back absolute corner slots. That is only sound on the
/// very state the newest record left, so each record keeps the triangulation's
/// [`StateStamp`] and [`Self::try_undo`] refuses any other state ([`UndoError`]). To
/// interleave flips with contractions and undo them all, use [`crate::core::Journal`].
#[derive(Clone, Debug, Default)]
pub struct History {
    records: Vec<ContractionRecord>,
    renamed: Vec<Corner>,
    tester: Option<LinkTester>,
}

impl PartialEq for History {
    /// The same records (the link-test scratch takes no part).
    fn eq(&self, other: &Self) -> bool {
        self.records == other.records && self.renamed == other.renamed
    }
}
impl Eq for History {}

impl History {
    /// An empty history.
    pub fn new() -> Self {
        Self::default()
    }
    /// An empty history with room for `contractions` records and `renamed` renamed
    /// corners, so that recording them never reallocates (and copies) the records. A
    /// contraction removes one vertex and every triangulation keeps at least four, so
    /// `vertex_count - 4` bounds the records of any reduction of a connected surface;
    /// the renamed corners of a contraction are `d_v - 2`. Reserved memory that is
    /// never written costs no resident memory on systems that map pages lazily.
    pub fn with_capacity(contractions: usize, renamed: usize) -> Self {
        History {
            records: Vec::with_capacity(contractions),
            renamed: Vec::with_capacity(renamed),
            tester: None,
        }
    }
    /// Drops every record (they can no longer be undone), keeping the allocation and the
    /// link-test scratch: for callers that need contractions done, not undone, this
    /// keeps the history's memory constant. O(1).
    pub fn forget(&mut self) {
        self.records.clear();
        self.renamed.clear();
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
    /// previous triangulation: same vertex ids, face ids, corner slots, opposite table
    /// and state stamp. O(d_v). Returns the record undone, or `None` if the history is
    /// empty.
    ///
    /// # Panics
    /// If `tri` is not in the state the newest record left (see [`Self::try_undo`]):
    /// that is a caller bug, and continuing would corrupt the surface silently.
    pub fn undo(&mut self, tri: &mut Triangulation) -> Option<ContractionRecord> {
        match self.try_undo(tri) {
            Ok(r) => r,
            Err(e) => panic!("History::undo: {e}"),
        }
    }

    /// [`Self::undo`], refusing with [`UndoError::Modified`] (and changing nothing) when
    /// `tri` is not in exactly the state the newest record left: the precondition of a
    /// slot-exact undo. The check is O(1) (a stamp comparison).
    pub fn try_undo(
        &mut self,
        tri: &mut Triangulation,
    ) -> Result<Option<ContractionRecord>, UndoError> {
        let Some(last) = self.records.last() else {
            return Ok(None);
        };
        if tri.state != last.state_after {
            return Err(UndoError::Modified {
                u: last.u,
                v: last.v,
                expected: last.state_after,
                found: tri.state,
            });
        }
        let r = self.records.pop().expect("checked non-empty");
        let (lo, hi) = (r.renamed.0 as usize, r.renamed.1 as usize);
        for c in &self.renamed[lo..hi] {
            tri.corner_vertex[c.index()] = r.v.0;
        }
        self.renamed.truncate(lo);
        tri.restore_faces(r.faces, &r.saved_vertex(), &r.saved_opposite());
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
        tri.state = r.state_before;
        Ok(Some(r))
    }

    /// Undoes every recorded contraction, newest first.
    ///
    /// # Panics
    /// As [`Self::undo`].
    pub fn undo_all(&mut self, tri: &mut Triangulation) {
        while self.undo(tri).is_some() {}
    }

    /// The link-test scratch, sized for `tri`.
    fn tester(&mut self, tri: &Triangulation) -> &mut LinkTester {
        self.tester
            .get_or_insert_with(|| LinkTester::new(tri.vertex_capacity()))
    }
}

impl Triangulation {
    /// Contracts `[u, v]` keeping `u` if it passes the link condition, recording the
    /// change in `history`. O(d_u + d_v): finding the edge walks `u`'s star, the link
    /// test marks `lk(u)` in the history's scratch (allocated once, never cleared), the
    /// contraction walks `v`'s star.
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
        if self.find_edge(u, v).is_none() {
            return Err(ContractError::NotAnEdge { u, v });
        }
        self.contract_if_contractible(u, v, history)
    }

    /// The link test in the history's scratch, then [`Self::contract_tested`].
    fn contract_if_contractible(
        &mut self,
        u: VertexId,
        v: VertexId,
        history: &mut History,
    ) -> Result<ContractionRecord, ContractError> {
        if !history.tester(self).test(self, u, v) {
            return Err(ContractError::NotContractible { u, v });
        }
        Ok(self.contract_tested(u, v, history))
    }

    /// Contracts the edge opposite corner `c` if it passes the link condition, keeping
    /// its first endpoint: with `[a, b] = `[`Self::edge_endpoints`]`(c)`, `b` is
    /// identified with `a`. Returns the record, whose [`ContractionRecord::glued`] pairs
    /// are the corners of the two merged edges. O(d_a + d_b), as [`Self::contract`].
    ///
    /// `c` must be a live corner ([`ContractError::DeadCorner`] otherwise).
    pub fn contract_at(
        &mut self,
        c: Corner,
        history: &mut History,
    ) -> Result<ContractionRecord, ContractError> {
        if !self.is_face(c.face()) {
            return Err(ContractError::DeadCorner(c));
        }
        let [a, b] = self.edge_endpoints(c);
        self.contract_if_contractible(a, b, history)
    }

    /// Contracts `[u, v]` keeping `u`, for callers that have already established the
    /// link condition (the RS algorithm tests it separately). O(d_v).
    ///
    /// # Panics
    /// If `[u, v]` is not an edge (a caller bug, not an input error). Debug builds also
    /// assert the link condition by the naive test when `d_u · d_v ≤ 4096` (beyond that
    /// the naive test would dominate; the `invariants` checks of the algorithms cover
    /// their own contractions by Theorem 3).
    pub fn contract_tested(
        &mut self,
        u: VertexId,
        v: VertexId,
        history: &mut History,
    ) -> ContractionRecord {
        debug_assert!(
            self.degree(u).saturating_mul(self.degree(v)) > DEBUG_NAIVE_CHECK_WORK
                || self.link_condition_naive(u, v),
            "contract_tested: [{u}, {v}] fails the link condition"
        );
        let start = history.renamed.len();
        let plan = self.plan_collapse(u, v, &mut history.renamed);
        self.record_collapse(u, v, plan, start, history)
    }

    /// [`Self::contract_tested`] with `v`'s star already walked: `star_v` is
    /// [`Self::star`]`(v)`'s corners in order and `u` the exit neighbour of step `p`.
    /// Makes the same change and the same record, without walking the star again.
    pub(crate) fn contract_tested_walked(
        &mut self,
        u: VertexId,
        v: VertexId,
        star_v: &[Corner],
        p: usize,
        history: &mut History,
    ) -> ContractionRecord {
        debug_assert_eq!(star_v.len(), self.degree(v));
        debug_assert!(
            self.degree(u).saturating_mul(self.degree(v)) > DEBUG_NAIVE_CHECK_WORK
                || self.link_condition_naive(u, v),
            "contract_tested: [{u}, {v}] fails the link condition"
        );
        let start = history.renamed.len();
        let plan = self.plan_collapse_walked(u, star_v, p, &mut history.renamed);
        self.record_collapse(u, v, plan, start, history)
    }

    /// Applies `plan` (whose renamed corners are `history.renamed[start..]`) and records
    /// it.
    fn record_collapse(
        &mut self,
        u: VertexId,
        v: VertexId,
        plan: CollapsePlan,
        start: usize,
        history: &mut History,
    ) -> ContractionRecord {
        let state_before = self.state;
        let [f1, f2] = plan.faces;
        let [x, y] = plan.link;
        let (saved_vertex, saved_opposite) = self.save_faces([f1, f2]);
        let mut slots = 0u8;
        let mut outer = [0u32; 4];
        for k in 0..2 {
            for s in 0..3 {
                let w = saved_vertex[3 * k + s];
                let which = if w == u.0 {
                    0
                } else if w == v.0 {
                    1
                } else {
                    continue;
                };
                slots |= (s as u8) << (4 * k + 2 * which);
                outer[2 * k + which] = saved_opposite[3 * k + s];
            }
        }
        let degree_v = self.degree[v.index()];
        let saved_vertex_corner = [
            self.vertex_corner[u.index()],
            self.vertex_corner[x.index()],
            self.vertex_corner[y.index()],
            self.vertex_corner[v.index()],
        ];
        self.apply_collapse(u, v, &plan, &history.renamed[start..]);
        let start = start as u32;
        let end = history.renamed.len() as u32;
        let rec = ContractionRecord {
            u,
            v,
            link: [x, y],
            faces: [f1, f2],
            degree_v,
            slots,
            outer,
            saved_vertex_corner,
            renamed: (start, end),
            state_before,
            state_after: self.state,
        };
        if super::CHECKS {
            // The compact record must give back exactly what was saved.
            assert_eq!(rec.saved_vertex(), saved_vertex, "record of [{u}, {v}]");
            assert_eq!(rec.saved_opposite(), saved_opposite, "record of [{u}, {v}]");
        }
        history.records.push(rec);
        rec
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `==` tells records apart by every field it compares (each one changed alone makes
    /// them unequal) and ignores the state stamps.
    #[test]
    fn records_are_equal_exactly_when_the_contractions_are() {
        let oct = crate::gen::octahedron();
        let contract = || {
            let mut t = Triangulation::from_faces(6, &oct.faces).expect("the octahedron");
            let (u, v, _) = t.edges().next().expect("an edge");
            t.contract_tested(u, v, &mut History::new())
        };
        let rec = contract();
        let mut again = contract();
        assert_eq!(rec, again);
        again.state_before = rec.state_after;
        again.state_after = rec.state_before;
        assert_ne!(rec.state_before, again.state_before);
        assert_eq!(rec, again, "the stamps are not compared");

        type Change = fn(&mut ContractionRecord);
        let changes: [(&str, Change); 9] = [
            ("u", |r| r.u = VertexId(r.u.0 + 1)),
            ("v", |r| r.v = VertexId(r.v.0 + 1)),
            ("link", |r| r.link[1] = VertexId(r.link[1].0 + 1)),
            ("faces", |r| r.faces[1] = FaceId(r.faces[1].0 + 1)),
            ("degree_v", |r| r.degree_v += 1),
            ("slots", |r| r.slots ^= 1),
            ("outer", |r| r.outer[3] = r.outer[3].wrapping_add(1)),
            ("saved_vertex_corner", |r| {
                r.saved_vertex_corner[3] = r.saved_vertex_corner[3].wrapping_add(1)
            }),
            ("renamed", |r| r.renamed.1 += 1),
        ];
        for (field, change) in changes {
            let mut other = rec;
            change(&mut other);
            assert_ne!(rec, other, "{field} differs");
        }
    }

    /// A record's renamed corners are the `d_v - 2` corners of `v` outside the two removed
    /// faces: [`ContractionRecord::renamed_len`] counts them, and they are the ones the
    /// history stores for it.
    #[test]
    fn renamed_len_is_the_degree_of_v_less_two() {
        let mesh = crate::gen::subdivide(&crate::gen::icosahedron(), 1).expect("subdivided");
        let mut t = Triangulation::from_faces(mesh.vertex_count, &mesh.faces).expect("a sphere");
        let mut h = History::new();
        let mut degrees = Vec::new();
        loop {
            let next = t
                .edges()
                .map(|(u, v, _)| (u, v))
                .find(|&(u, v)| t.link_condition_naive(u, v));
            let Some((u, v)) = next else { break };
            degrees.push(t.degree(v));
            t.contract_tested(u, v, &mut h);
        }
        assert!(degrees.len() > 30, "{} contractions", degrees.len());
        assert!(degrees.iter().any(|&d| d != 6) && degrees.contains(&6));
        for (r, d) in h.records().iter().zip(&degrees) {
            assert_eq!(r.renamed_len(), d - 2);
            assert_eq!(h.renamed(r).len(), d - 2);
        }
    }

    /// Histories are equal exactly when their records and renamed corners are; the
    /// link-test scratch takes no part.
    #[test]
    fn histories_are_equal_exactly_when_their_contractions_are() {
        let oct = crate::gen::octahedron();
        let run = |edge: usize, contractions: usize| {
            let mut t = Triangulation::from_faces(6, &oct.faces).expect("the octahedron");
            let mut h = History::new();
            for _ in 0..contractions {
                let (u, v, _) = t.edges().nth(edge).expect("an edge");
                t.contract_tested(u, v, &mut h);
            }
            h
        };
        let a = run(0, 1);
        assert_eq!(a, run(0, 1));
        assert_ne!(a, History::new());
        assert_ne!(a, run(0, 2), "a record more");
        assert_ne!(a, run(3, 1), "another edge");
        let mut same_records = a.clone();
        same_records.renamed.reverse();
        same_records.renamed.push(Corner(0));
        assert_eq!(same_records.records, a.records);
        assert_ne!(a, same_records, "other renamed corners");
        let mut fresh = a.clone();
        fresh.tester = None;
        assert_eq!(a, fresh, "the scratch is not compared");
    }
}

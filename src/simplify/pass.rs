//! The pass machinery shared by both modes (on the state of module `state`): the pass loop,
//! the common-neighbour walk, the position and guard decisions, applying a plan, and the
//! per-pass compaction.

use super::geometry::{dist2, fan_move_ok, midpoint, Point};
use super::state::{Claim, EdgeInfo, Run, Simplifier, Skip};
use super::{naive, nested, spec, Mode, Position, SkipCounts};
use crate::core::{Corner, FaceId, VertexId};
use crate::progress::{Progress, Throttle};

/// The stage of the progress reports inside a pass.
pub const SCANNED: &str = "faces scanned in this pass";

/// Degree up to which `examine` looks neighbours up in a list rather than in the marks.
const SMALL_LINK: usize = 24;

impl SkipCounts {
    fn count(&mut self, s: Skip) {
        match s {
            Skip::LinkCondition => self.link_condition += 1,
            Skip::NonDisc => self.non_disc += 1,
            Skip::Foldover => self.foldover += 1,
        }
    }
}

/// What processing an edge will do, decided before anything changes.
#[derive(Copy, Clone, Debug)]
pub(super) struct Plan {
    /// The discs to replace first (nested mode), per side.
    pub(super) discs: [Option<Claim>; 2],
    /// The position of the merged vertex.
    pub(super) position: Point,
}

impl<'o> Simplifier<'o> {
    /// Runs passes until one contracts nothing; `on_pass(pass, contracted, faces)` after
    /// each. Then accounts for every short edge left.
    ///
    /// The nested mode runs exactly the naive mode's passes first, to their fixed point,
    /// and only then passes that use processEdge, again to a fixed point. So it contracts
    /// every edge the naive mode does and then more (the nested mode dominates the naive
    /// one on every input), and it removes discs, which discards the geometry inside
    /// them, only for edges that no sequence of plain contractions reached.
    /// `observer` hears, inside each pass, the face slots scanned out of the pass's
    /// slots (stage [`SCANNED`]), at most every [`crate::progress::REPORT_EVERY`] slots.
    pub(super) fn run(
        &mut self,
        on_pass: &mut dyn FnMut(usize, usize, usize),
        observer: &mut dyn FnMut(Progress),
    ) -> Run {
        loop {
            let contracted = self.pass(observer);
            self.run.passes += 1;
            self.run.edges_contracted += contracted;
            // Compact once a third of the slots are dead: the scan of the next passes
            // then stays proportional to the live faces, and the total compaction work
            // to a constant times the input.
            if 3 * (self.tri.face_capacity() - self.tri.face_count()) > self.tri.face_capacity() {
                self.compact();
            }
            spec::pass_end(self);
            on_pass(self.run.passes, contracted, self.real_face_count());
            if contracted == 0 {
                if self.opts.mode == Mode::Nested && !self.nested_phase {
                    self.nested_phase = true;
                    continue;
                }
                break;
            }
        }
        self.account_remaining();
        std::mem::take(&mut self.run)
    }

    /// Faces with no virtual vertex.
    fn real_face_count(&self) -> usize {
        let cone: usize = (self.first_virtual as usize..self.tri.vertex_capacity())
            .map(|w| self.tri.degree(VertexId(w as u32)))
            .sum();
        self.tri.face_count() - cone
    }

    /// One pass; returns the number of contractions.
    fn pass(&mut self, observer: &mut dyn FnMut(Progress)) -> usize {
        self.pass += 1;
        let mut contracted = 0;
        let nf = self.tri.face_capacity();
        let slots = nf as u64;
        observer(Progress::new(SCANNED, 0, slots));
        let mut throttle = Throttle::new();
        let mut from = 0;
        loop {
            let (fi, frozen) = self.next_candidate(from);
            self.run.skipped.frozen += frozen;
            if fi >= nf {
                break;
            }
            from = fi + 1;
            if throttle.due(fi as u64) {
                observer(Progress::new(SCANNED, fi as u64, slots));
            }
            let f = FaceId(fi as u32);
            let vs = self.tri.face_vertices(f);
            let ps = [
                self.vert[vs[0].index()].pos,
                self.vert[vs[1].index()].pos,
                self.vert[vs[2].index()].pos,
            ];
            // Edge opposite slot s joins slots s+1 and s+2; the short ones, shortest
            // first (ties by slot), by a three-element sorting network.
            let l = [
                dist2(ps[1], ps[2]),
                dist2(ps[2], ps[0]),
                dist2(ps[0], ps[1]),
            ];
            let mut order = [0u32, 1, 2];
            let mut swap = |i: usize, j: usize| {
                if l[order[j] as usize] < l[order[i] as usize] {
                    order.swap(i, j);
                }
            };
            swap(0, 1);
            swap(1, 2);
            swap(0, 1);
            for s in order {
                if l[s as usize] >= self.eps2 {
                    break;
                }
                let c = f.corner(s);
                let [p, q] = self.tri.edge_endpoints(c);
                if self.vert[p.index()].touched == self.pass
                    || self.vert[q.index()].touched == self.pass
                {
                    self.run.skipped.frozen += 1;
                    continue;
                }
                match self.plan(c) {
                    Ok((info, plan)) => {
                        self.apply(&info, &plan);
                        contracted += 1;
                        break;
                    }
                    Err(skip) => self.run.skipped.count(skip),
                }
            }
        }
        observer(Progress::new(SCANNED, slots, slots));
        contracted
    }

    /// The first face slot from `from` on whose visit gets as far as reading positions,
    /// and the number of visits before it deferred as frozen; `face_capacity()` if
    /// none. Skipped: removed faces, cone faces (a virtual vertex) and faces with two
    /// or more vertices frozen in this pass (every edge has a frozen endpoint; most
    /// visits of a pass end here, so they are skipped in a loop that changes nothing).
    fn next_candidate(&self, from: usize) -> (usize, usize) {
        let pass = self.pass;
        let first_virtual = self.first_virtual;
        let frozen = |v: u32| u32::from(self.vert[v as usize].touched == pass);
        let mut deferred = 0;
        let slots = self.tri.corner_vertex.get(3 * from..).unwrap_or(&[]);
        for (k, face) in slots.chunks_exact(3).enumerate() {
            let (a, b, c) = (face[0], face[1], face[2]);
            // A removed face has NONE (above every vertex id) in its slots.
            if a >= first_virtual || b >= first_virtual || c >= first_virtual {
                continue;
            }
            if frozen(a) + frozen(b) + frozen(c) >= 2 {
                deferred += 1;
                continue;
            }
            return (from + k, deferred);
        }
        (self.tri.face_capacity(), deferred)
    }

    /// The edge opposite `c`: its endpoints and opposite vertices, and its other common
    /// neighbours in `self.xs`. Refuses an edge joining two boundary loops.
    pub(super) fn examine(&mut self, c: Corner) -> Result<EdgeInfo, Skip> {
        let [p, q] = self.tri.edge_endpoints(c);
        let a = self.tri.vertex(c);
        let b = self.tri.vertex(self.tri.opposite(c));
        let s = self.fresh_stamp();
        // One walk around each endpoint: q's neighbours listed (and marked, for a high
        // degree), p's checked against them; the corners kept for the guard and the
        // freeze, which then need no walk of their own. A short list scanned linearly
        // beats the marks, which miss the cache.
        let big = self.tri.degree(q) > SMALL_LINK;
        let mut loop_q = None;
        self.star_pq.clear();
        self.nbr_q.clear();
        for st in self.tri.star(q) {
            let n = st.neighbour;
            if big {
                self.vmark[n.index()] = s;
            }
            if n.0 >= self.first_virtual {
                loop_q = Some(n);
            }
            self.nbr_q.push(n);
            self.star_pq.push(st.corner);
        }
        let mut loop_p = None;
        let mut extra = false;
        self.nbr_p.clear();
        for st in self.tri.star(p) {
            let n = st.neighbour;
            self.nbr_p.push(n);
            if n.0 >= self.first_virtual {
                loop_p = Some(n);
            }
            if n != a && n != b && n != q && self.in_link_q(n, big, s) {
                extra = true;
            }
            self.star_pq.push(st.corner);
        }
        if let (Some(x), Some(y)) = (loop_p, loop_q) {
            if x != y {
                return Err(Skip::LinkCondition);
            }
        }
        self.xs.clear();
        if extra {
            // Only now the order: the link of p from the neighbour after q round to the
            // one before it, oriented to run from a to b.
            self.link.clear();
            self.link.extend(self.tri.link(p));
            let at_q = self.link.iter().position(|&n| n == q).unwrap_or(0);
            self.link.rotate_left(at_q + 1);
            self.link.pop();
            if self.link.first() != Some(&a) {
                self.link.reverse();
            }
            debug_assert_eq!(self.link.first(), Some(&a));
            debug_assert_eq!(self.link.last(), Some(&b));
            let inner = &self.link[1..self.link.len() - 1];
            let xs: Vec<VertexId> = inner
                .iter()
                .copied()
                .filter(|&n| self.in_link_q(n, big, s))
                .collect();
            self.xs = xs;
        }
        Ok(EdgeInfo {
            corner: c,
            p,
            q,
            a,
            b,
            boundary: [loop_p.is_some(), loop_q.is_some()],
        })
    }

    /// Whether `n` is a neighbour of q, for `examine` (marks when q's degree is big).
    #[inline]
    fn in_link_q(&self, n: VertexId, big: bool, stamp: u32) -> bool {
        if big {
            self.vmark[n.index()] == stamp
        } else {
            self.nbr_q.contains(&n)
        }
    }

    /// Decides what to do with the edge opposite `c`, changing nothing but scratch.
    pub(super) fn plan(&mut self, c: Corner) -> Result<(EdgeInfo, Plan), Skip> {
        let info = self.examine(c)?;
        let (discs, removed) = match (self.opts.mode, self.nested_phase) {
            (Mode::Naive, _) | (Mode::Nested, false) => {
                naive::plan(self, &info)?;
                ([None, None], None)
            }
            (Mode::Nested, true) => {
                let discs = nested::plan(self, &info)?;
                let removed = self.mark_removed(&discs);
                (discs, removed)
            }
        };
        // After the discs go, the edge must not be an edge of a tetrahedron.
        let degree_after = |v: VertexId, me: &Self| {
            let mut d = me.tri.degree(v);
            for (side, claim) in discs.iter().enumerate() {
                if let Some(cl) = claim {
                    let at = me.grow[side].queue[..cl.faces]
                        .iter()
                        .filter(|&&f| me.tri.face_vertices(f).contains(&v))
                        .count();
                    d = d + 1 - at;
                }
            }
            d
        };
        // (The link condition's last clause, Prop. 6 of the RS paper: no common
        // neighbour is left but the opposite vertices, which suffices unless both
        // endpoints have degree 3.)
        if degree_after(info.p, self) == 3 && degree_after(info.q, self) == 3 {
            return Err(Skip::LinkCondition);
        }
        let position = self.position(&info);
        if self.opts.guard && !self.guard(&info, position, removed) {
            return Err(Skip::Foldover);
        }
        Ok((info, Plan { discs, position }))
    }

    /// Marks the faces of the planned discs with a fresh stamp; returns it.
    fn mark_removed(&mut self, discs: &[Option<Claim>; 2]) -> Option<u32> {
        if discs.iter().all(Option::is_none) {
            return None;
        }
        let s = self.fresh_stamp();
        for (side, claim) in discs.iter().enumerate() {
            if let Some(cl) = claim {
                for &f in &self.grow[side].queue[..cl.faces] {
                    self.fmark[f.index()] = s;
                }
            }
        }
        Some(s)
    }

    /// Where the merged vertex goes (see [`Position`]).
    fn position(&self, e: &EdgeInfo) -> Point {
        let (pp, pq) = (self.vert[e.p.index()].pos, self.vert[e.q.index()].pos);
        match self.opts.position {
            Position::Midpoint => match e.boundary {
                [true, false] => pp,
                [false, true] => pq,
                _ => midpoint(pp, pq),
            },
            Position::Quadric => {
                let mut q = self.quadric[e.p.index()];
                q.add(&self.quadric[e.q.index()]);
                q.best_position_within(pp, pq, self.max_coordinate)
            }
        }
    }

    /// The fold-over guard: every real face at `p` or `q` that survives (not in a
    /// planned disc, not a face of `[p, q]`) must stay non-degenerate and turn by less
    /// than 90° when `p` and `q` move to `to`.
    fn guard(&self, e: &EdgeInfo, to: Point, removed: Option<u32>) -> bool {
        let pos = |v: VertexId| self.vert[v.index()].pos;
        // `star_pq` holds a corner at q or p in every face around them (from `examine`).
        for &c in &self.star_pq {
            let f = c.face();
            if removed.is_some_and(|s| self.fmark[f.index()] == s) {
                continue;
            }
            let (v0, v1, v2) = (
                self.tri.vertex(c),
                self.tri.vertex(c.next()),
                self.tri.vertex(c.prev()),
            );
            // v0 is p or q; skip the faces of [p, q] and cone faces.
            let other = if v0 == e.p { e.q } else { e.p };
            if v1 == other || v2 == other || self.is_virtual(v1) || self.is_virtual(v2) {
                continue;
            }
            if !fan_move_ok(pos(v0), to, pos(v1), pos(v2)) {
                return false;
            }
        }
        true
    }

    /// Carries out a plan: replaces the discs, contracts the edge keeping the smaller
    /// id, moves the kept vertex and freezes its neighbours for the rest of the pass.
    fn apply(&mut self, e: &EdgeInfo, plan: &Plan) {
        // Freeze first: every neighbour of the merged vertex was a neighbour of p or q
        // (removing a disc and contracting add no adjacency), so marking p, q and the
        // links `examine` listed (every vertex of a face around p or q) freezes them
        // without walking the new star.
        let pass = self.pass;
        for &w in self.nbr_q.iter().chain(&self.nbr_p) {
            self.vert[w.index()].touched = pass;
        }
        self.vert[e.p.index()].touched = pass;
        self.vert[e.q.index()].touched = pass;
        for (side, claim) in plan.discs.iter().enumerate() {
            let Some(cl) = claim else { continue };
            let faces = std::mem::take(&mut self.grow[side].queue);
            let region = &faces[..cl.faces];
            let s = self.fresh_stamp();
            self.interior.clear();
            for &f in region {
                for v in self.tri.face_vertices(f) {
                    if v != e.p && v != e.q && v != cl.x && self.vmark[v.index()] != s {
                        self.vmark[v.index()] = s;
                        self.interior.push(v);
                    }
                }
            }
            spec::disc(self, [e.p, e.q, cl.x], region);
            let interior = std::mem::take(&mut self.interior);
            self.tri
                .replace_disc([e.p, e.q, cl.x], region, &interior, cl.sides);
            self.run.discs_removed += 1;
            self.run.vertices_removed_inside += interior.len();
            self.interior = interior;
            self.grow[side].queue = faces;
        }
        let (keep, gone) = if e.p < e.q { (e.p, e.q) } else { (e.q, e.p) };
        if plan.discs.iter().all(Option::is_none) {
            // The stars `examine` walked are still current: no walk needed.
            let dq = self.nbr_q.len();
            let (star, link) = if gone == e.q {
                (&self.star_pq[..dq], &self.nbr_q[..])
            } else {
                (&self.star_pq[dq..], &self.nbr_p[..])
            };
            self.tri
                .collapse_walked(keep, gone, star, link, &mut self.scratch);
        } else {
            self.tri.collapse(keep, gone, &mut self.scratch);
        }
        self.vert[keep.index()].pos = plan.position;
        if !self.quadric.is_empty() {
            let g = self.quadric[gone.index()];
            self.quadric[keep.index()].add(&g);
        }
    }

    /// Renumbers vertices and faces densely and carries the per-vertex data along.
    fn compact(&mut self) {
        let map = self.tri.compact_ids();
        let mut k = 0;
        for (old, &new) in map.iter().enumerate() {
            if new != crate::core::ids::NONE {
                debug_assert_eq!(new as usize, k);
                self.vert[k] = self.vert[old];
                if !self.quadric.is_empty() {
                    self.quadric[k] = self.quadric[old];
                }
                k += 1;
            }
        }
        self.vert.truncate(k);
        self.vert.shrink_to_fit();
        if !self.quadric.is_empty() {
            self.quadric.truncate(k);
            self.quadric.shrink_to_fit();
        }
        self.first_virtual = (k - self.loops) as u32;
        // Marks and pass numbers only ever grow, so stale entries never match: the
        // arrays are cut to size, not cleared.
        self.vmark.truncate(k);
        self.fmark.truncate(self.tri.face_capacity());
    }

    /// Finds every real edge shorter than ε left, the shortest real edge, and the reason
    /// each short edge cannot be processed (the last pass contracted nothing, so none
    /// can: the specification checks it).
    fn account_remaining(&mut self) {
        let edges: Vec<(VertexId, VertexId, Corner)> = self.tri.edges().collect();
        let mut shortest = f64::INFINITY;
        for (p, q, c) in edges {
            if self.is_virtual(p) || self.is_virtual(q) {
                continue;
            }
            let l2 = dist2(self.vert[p.index()].pos, self.vert[q.index()].pos);
            shortest = shortest.min(l2);
            if l2 >= self.eps2 {
                continue;
            }
            // Examine from a real face (a boundary edge has one cone face).
            let c = if self
                .tri
                .face_vertices(c.face())
                .iter()
                .any(|&v| self.is_virtual(v))
            {
                self.tri.opposite(c)
            } else {
                c
            };
            match self.plan(c) {
                Ok(_) => {
                    spec::unaccounted(self, p, q);
                    self.run.remaining.frozen += 1;
                }
                Err(s) => self.run.remaining.count(s),
            }
        }
        // Unscaled (exact: a power of two); `shortest` is infinite only without edges.
        self.run.shortest = shortest.is_finite().then(|| shortest.sqrt() / self.scale);
    }

    /// The real vertices (all live after the final compaction) with their positions,
    /// and the real faces.
    pub(crate) fn into_mesh(mut self) -> (Vec<[u32; 3]>, Vec<Point>) {
        if self.tri.face_capacity() != self.tri.face_count()
            || self.tri.vertex_capacity() != self.tri.vertex_count()
        {
            self.compact();
        }
        let first = self.first_virtual;
        let faces = self
            .tri
            .faces()
            .map(|f| self.tri.face_vertices(f))
            .filter(|vs| vs.iter().all(|v| v.0 < first))
            .map(|vs| vs.map(|v| v.0))
            .collect();
        let points = self.vert[..first as usize]
            .iter()
            .map(|v| v.pos.map(|x| x / self.scale))
            .collect();
        (faces, points)
    }
}

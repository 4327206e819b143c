//! The decimator's state and main loop (see the module documentation of
//! [`crate::decimate`] for the guarantee and the method).

use std::collections::HashMap;

use super::pool;
use super::queue::{key, unpack, Queue};
use super::{
    spec, ComponentStats, Options, Output, Placement, Refusal, Refusals, Schedule, Stats, Stopped,
};
use crate::core::ids::NONE;
use crate::core::{ConedWhole, Corner, Triangulation, VertexId};
use crate::progress::{Progress, Throttle};
use crate::simplify::geometry::{
    area_normal, cross, dot, fan_move_ok, midpoint, power_of_two_scale, sub, Point, Quadric,
};

/// The stage of the progress reports: faces removed of those to remove.
pub const REMOVED: &str = "faces removed";

/// Boundary planes weigh this many times their face's area (as the simplifier's).
const BOUNDARY_WEIGHT: f64 = 10.0;

/// How a vertex is locked.
const FREE: u8 = 0;
const LOCKED: u8 = 1;
const BOUNDARY: u8 = 2;

/// What collapsing an edge would do, decided from the endpoints alone.
#[derive(Copy, Clone, Debug, PartialEq)]
pub(super) struct Candidate {
    pub(super) cost: f64,
    /// The squared error `Q(x) / W` (scaled coordinates).
    pub(super) error2: f64,
    pub(super) position: Point,
    pub(super) keep: VertexId,
    pub(super) gone: VertexId,
}

/// A vertex's state, in one record of two cache lines: what costing an edge reads
/// (quadric, weight, position, lock) and what the queue's staleness test reads.
///
/// **Why one record.** Costing an edge reads both endpoints' quadrics, weights,
/// positions and locks, and the endpoints are all over the mesh: kept in separate
/// lists, they were five to seven cache misses per endpoint, and the loads of the
/// quadrics the largest share of the run (cachegrind with a 2 MiB last-level cache, a
/// per-core L2's size: 16 % fewer misses of the whole `decimate` call on botijo, 82k
/// faces; docs/benchmarks.md, "Cache misses of the run"). Aligned to 64 bytes, the 121
/// bytes of a record take two lines exactly; the fields folded in from their own lists
/// pay for most of the padding.
#[derive(Copy, Clone, Debug, PartialEq)]
#[repr(C, align(64))]
pub(super) struct Vert {
    /// The sum of the plane quadrics of the faces merged into the vertex.
    pub(super) quadric: Quadric,
    /// The position (scaled).
    pub(super) pos: Point,
    /// The sum of the quadrics' weights.
    pub(super) weight: f64,
    /// The vertex it was merged into (`NONE` while live).
    pub(super) merged_into: u32,
    /// An upper bound on the adjusted edges at the vertex (0: none; the exact schedule).
    adjusted_at: u32,
    /// `FREE`, `LOCKED` or `BOUNDARY`.
    pub(super) lock: u8,
}

impl Default for Vert {
    fn default() -> Self {
        Vert {
            quadric: Quadric::default(),
            pos: [0.0; 3],
            weight: 0.0,
            merged_into: NONE,
            adjusted_at: 0,
            lock: FREE,
        }
    }
}

/// The whole mesh being decimated.
pub(crate) struct Decimator<'o> {
    pub(super) tri: Triangulation,
    /// Ids from here on are virtual (cone apexes).
    pub(super) first_virtual: u32,
    /// Per vertex: its state in one record (see [`Vert`]).
    pub(super) vert: Vec<Vert>,
    /// Per vertex: the key of its cheapest edge that its endpoints allow and no guard
    /// has refused since (`NO_KEY` if none; empty under the pass schedule). The queue
    /// holds an entry for every such key; other entries are stale.
    best: Vec<u128>,
    /// The edges whose verdict the neighbourhood decided, until a collapse next to them
    /// (the only thing that can change it): refused by a guard (`true`; the link
    /// condition, or the fold-over guard at every position), or queued at a raised cost
    /// because the guard refused the placement's position and took an alternative
    /// (`false`; the raised cost is in `edge_cost`).
    pub(super) adjusted: HashMap<(u32, u32), bool>,
    heap: Queue,
    pub(super) opts: &'o Options,
    /// The power of two the positions are multiplied by (as the simplifier's `scale`:
    /// exact, and keeps squares of extreme coordinates finite).
    pub(super) scale: f64,
    max_coordinate: f64,
    /// The error cap squared, scaled.
    pub(super) cap2: Option<f64>,
    pub(super) real_faces: usize,
    pub(super) target: usize,
    pub(super) face_label: Vec<u32>,
    pub(super) components: usize,
    vmark: Vec<u32>,
    stamp: u32,
    star_p: Vec<Corner>,
    star_q: Vec<Corner>,
    nbr_p: Vec<VertexId>,
    nbr_q: Vec<VertexId>,
    scratch: Vec<Corner>,
    /// The endpoints whose stars `star_p`/`nbr_p` and `star_q`/`nbr_q` hold.
    walked: [VertexId; 2],
    /// Star steps (corner, exit neighbour), scratch.
    steps: Vec<(Corner, VertexId)>,
    ring: Vec<(Corner, VertexId)>,
    /// Per corner: the cost of the edge opposite it (NaN: its endpoints refuse it), for
    /// real edges.
    edge_cost: Vec<f64>,
    pub(super) collapses: usize,
    /// Passes made (the pass schedule).
    pub(super) passes: usize,
    /// Per vertex: the last pass in which a collapse merged it (the pass schedule; empty
    /// under the exact one).
    pub(super) pass_mark: Vec<u32>,
    /// Per vertex: the last pass in which a collapse merged it or a neighbour (the pass
    /// schedule).
    pub(super) near_mark: Vec<u32>,
    pub(super) max_error2: f64,
    pub(super) refused: Refusals,
    /// The initial quadrics, kept only when the specification checks run.
    pub(super) initial: Vec<(Quadric, f64)>,
}

/// The edge `c` is opposite to, as `(smaller id, larger id)`, if `c` is a live face's
/// corner and the smaller of the edge's two opposite corners: each edge once, in the
/// order of `Triangulation::edges`.
pub(super) fn edge_from(tri: &Triangulation, c: Corner) -> Option<(VertexId, VertexId)> {
    if !tri.is_face(c.face()) || c >= tri.opposite(c) {
        return None;
    }
    let [a, b] = tri.edge_endpoints(c);
    Some((a.min(b), a.max(b)))
}

impl<'o> Decimator<'o> {
    /// Takes over the coned mesh with its positions (checked finite by the caller) and
    /// builds the quadrics and the queue. O(F log F).
    pub(crate) fn new(whole: ConedWhole, positions: &[Point], opts: &'o Options) -> Self {
        let ConedWhole {
            tri,
            face_label,
            components,
            ..
        } = whole;
        let first_virtual = positions.len() as u32;
        let nv = tri.vertex_capacity();
        let largest = (0..positions.len())
            .filter(|&v| tri.is_vertex(VertexId(v as u32)))
            .flat_map(|v| positions[v])
            .fold(0.0f64, |a, x| a.max(x.abs()));
        let scale = power_of_two_scale(largest);
        let mut vert = vec![Vert::default(); nv];
        // The real vertices are the first `first_virtual`, one per position.
        for (k, (v, p)) in vert.iter_mut().zip(positions).enumerate() {
            v.pos = p.map(|x| x * scale);
            if opts.locked.get(k).copied().unwrap_or(false) {
                v.lock = LOCKED;
            }
        }
        if opts.lock_boundary {
            for w in first_virtual as usize..nv {
                let w = VertexId(w as u32);
                if tri.is_vertex(w) {
                    for n in tri.link(w) {
                        if vert[n.index()].lock == FREE {
                            vert[n.index()].lock = BOUNDARY;
                        }
                    }
                }
            }
        }
        let real_faces = tri
            .faces()
            .filter(|&f| tri.face_vertices(f).iter().all(|v| v.0 < first_virtual))
            .count();
        let cap2 = opts.max_error.map(|e| (e * scale) * (e * scale));
        let mut d = Decimator {
            tri,
            first_virtual,
            vert,
            best: Vec::new(),
            adjusted: HashMap::new(),
            heap: Queue::default(),
            opts,
            scale,
            max_coordinate: f64::MAX * scale,
            cap2,
            real_faces,
            target: opts.target_faces,
            face_label,
            components,
            vmark: vec![0; nv],
            stamp: 0,
            star_p: Vec::new(),
            star_q: Vec::new(),
            nbr_p: Vec::new(),
            nbr_q: Vec::new(),
            scratch: Vec::new(),
            walked: [VertexId(0); 2],
            steps: Vec::new(),
            ring: Vec::new(),
            edge_cost: Vec::new(),
            collapses: 0,
            passes: 0,
            pass_mark: Vec::new(),
            near_mark: Vec::new(),
            max_error2: 0.0,
            refused: Refusals::default(),
            initial: Vec::new(),
        };
        d.init_quadrics();
        if crate::spec::ENABLED {
            d.initial = d.vert.iter().map(|v| (v.quadric, v.weight)).collect();
        }
        if opts.schedule == Schedule::Passes {
            // The pass schedule keeps its own sorted list (module `passes`).
            d.pass_mark = vec![0; nv];
            d.near_mark = vec![0; nv];
            return d;
        }
        d.best = vec![NO_KEY; nv];
        // Walked corner by corner rather than collected from `edges()`: the list would
        // be the call's largest allocation at its peak (12 bytes an edge, and the growth
        // of a vector of unknown length), 18–24 bytes an input triangle. Each edge is
        // costed at its smaller corner (on the pool), then copied to the other.
        let mut edge_cost = vec![f64::NAN; d.tri.corner_vertex.len()];
        let this = &d;
        pool::fill(&mut edge_cost, |c| {
            match edge_from(&this.tri, Corner(c as u32)) {
                Some((p, q)) if !this.is_virtual(q) => {
                    this.candidate(p, q).map_or(f64::NAN, |c| c.cost)
                }
                _ => f64::NAN,
            }
        });
        d.edge_cost = edge_cost;
        for c in (0..d.tri.corner_vertex.len() as u32).map(Corner) {
            let Some((p, q)) = edge_from(&d.tri, c) else {
                continue;
            };
            if d.is_virtual(q) {
                continue;
            }
            let o = d.tri.opposite(c);
            d.edge_cost[o.index()] = d.edge_cost[c.index()];
            if let Some(k) = d.cached_key(p, q, c) {
                for v in [p, q] {
                    d.best[v.index()] = d.best[v.index()].min(k);
                }
            }
        }
        let queued = |k: &u128| *k != NO_KEY;
        let count = d.best.iter().filter(|k| queued(k)).count();
        d.heap = Queue::from_keys(count, d.best.iter().copied().filter(queued));
        d
    }

    #[inline]
    pub(super) fn is_virtual(&self, v: VertexId) -> bool {
        v.0 >= self.first_virtual
    }

    /// Area-weighted plane quadrics of the real faces plus the boundary planes, and the
    /// sum of the weights per vertex.
    fn init_quadrics(&mut self) {
        for f in self.tri.faces() {
            let vs = self.tri.face_vertices(f);
            if vs.iter().any(|&v| self.is_virtual(v)) {
                continue;
            }
            let ps = vs.map(|v| self.vert[v.index()].pos);
            let n = area_normal(ps[0], ps[1], ps[2]);
            let twice_area = dot(n, n).sqrt();
            if twice_area == 0.0 {
                continue;
            }
            let unit = n.map(|x| x / twice_area);
            let w = 0.5 * twice_area;
            let q = Quadric::plane(unit, ps[0], w);
            for v in vs {
                self.vert[v.index()].quadric.add(&q);
                self.vert[v.index()].weight += w;
            }
            for c in f.corners() {
                let across = self.tri.vertex(self.tri.opposite(c));
                if !self.is_virtual(across) {
                    continue;
                }
                let [s, t] = self.tri.edge_endpoints(c);
                let (ps_, pt) = (self.vert[s.index()].pos, self.vert[t.index()].pos);
                let m = cross(sub(pt, ps_), unit);
                let len = dot(m, m).sqrt();
                if len == 0.0 {
                    continue;
                }
                let bw = BOUNDARY_WEIGHT * w;
                let q = Quadric::plane(m.map(|x| x / len), ps_, bw);
                for v in [s, t] {
                    self.vert[v.index()].quadric.add(&q);
                    self.vert[v.index()].weight += bw;
                }
            }
        }
    }

    /// The collapse of the real edge `[p, q]` as its endpoints decide it: locks, the
    /// position, the cost and the error cap. O(1).
    pub(super) fn candidate(&self, p: VertexId, q: VertexId) -> Result<Candidate, Refusal> {
        let (p, q) = if p < q { (p, q) } else { (q, p) };
        let (lp, lq) = (self.vert[p.index()].lock, self.vert[q.index()].lock);
        if lp != FREE && lq != FREE {
            return Err(if lp == LOCKED || lq == LOCKED {
                Refusal::Lock
            } else {
                Refusal::Boundary
            });
        }
        let mut quadric = self.vert[p.index()].quadric;
        quadric.add(&self.vert[q.index()].quadric);
        let weight = self.vert[p.index()].weight + self.vert[q.index()].weight;
        let (pp, pq) = (self.vert[p.index()].pos, self.vert[q.index()].pos);
        let (position, keep, gone) = if lp != FREE {
            (pp, p, q)
        } else if lq != FREE {
            (pq, q, p)
        } else {
            match self.opts.placement {
                Placement::Optimal => (
                    quadric.best_position_within(pp, pq, self.max_coordinate),
                    p,
                    q,
                ),
                Placement::Midpoint => (midpoint(pp, pq), p, q),
                Placement::Endpoint => {
                    if quadric.error(pq) < quadric.error(pp) {
                        (pq, q, p)
                    } else {
                        (pp, p, q)
                    }
                }
            }
        };
        // NaN and −0 become +0: the queue orders costs by their bits.
        let error = quadric.error(position);
        let cost = if error > 0.0 { error } else { 0.0 };
        let error2 = if weight > 0.0 { cost / weight } else { 0.0 };
        if self.cap2.is_some_and(|cap| error2 > cap) {
            return Err(Refusal::Error);
        }
        Ok(Candidate {
            cost,
            error2,
            position,
            keep,
            gone,
        })
    }

    fn fresh_stamp(&mut self) -> u32 {
        if self.stamp == u32::MAX {
            self.vmark.fill(0);
            self.stamp = 0;
        }
        self.stamp += 1;
        self.stamp
    }

    /// The link condition of the surface with boundary for the real edge `[p, q]`:
    /// refuses a common neighbour other than the two opposite vertices, endpoints on two
    /// different boundary loops, and an edge of a tetrahedron. Leaves the stars of `p`
    /// and `q` walked in the scratch lists (`walked`); returns the number of real faces
    /// the collapse removes. O(d_p + d_q).
    fn link(&mut self, p: VertexId, q: VertexId) -> Result<usize, Refusal> {
        self.walked = [p, q];
        let s = self.fresh_stamp();
        let mut loop_q = None;
        self.star_q.clear();
        self.nbr_q.clear();
        for st in self.tri.star(q) {
            self.vmark[st.neighbour.index()] = s;
            if self.is_virtual(st.neighbour) {
                loop_q = Some(st.neighbour);
            }
            self.nbr_q.push(st.neighbour);
            self.star_q.push(st.corner);
        }
        self.star_p.clear();
        self.nbr_p.clear();
        let mut loop_p = None;
        let mut at_q = None;
        for (k, st) in self.tri.star(p).enumerate() {
            if st.neighbour == q {
                at_q = Some(k);
            }
            if self.is_virtual(st.neighbour) {
                loop_p = Some(st.neighbour);
            }
            self.nbr_p.push(st.neighbour);
            self.star_p.push(st.corner);
        }
        let Some(k) = at_q else {
            // Not an edge: a caller bug (entries are checked for staleness first).
            debug_assert!(false, "[{p}, {q}] is not an edge");
            return Err(Refusal::LinkCondition);
        };
        let d = self.nbr_p.len();
        let (a, b) = (self.nbr_p[(k + d - 1) % d], self.nbr_p[(k + 1) % d]);
        if let (Some(x), Some(y)) = (loop_p, loop_q) {
            if x != y {
                return Err(Refusal::LinkCondition);
            }
        }
        if self
            .nbr_p
            .iter()
            .any(|&n| n != q && n != a && n != b && self.vmark[n.index()] == s)
        {
            return Err(Refusal::LinkCondition);
        }
        if d == 3 && self.nbr_q.len() == 3 {
            return Err(Refusal::LinkCondition);
        }
        Ok(usize::from(!self.is_virtual(a)) + usize::from(!self.is_virtual(b)))
    }

    /// The other positions a collapse may take when the fold-over guard refuses its
    /// placement's, cheapest first (ties in the order: the smaller endpoint, the larger,
    /// the midpoint): both endpoints and the midpoint, but only the endpoints under
    /// [`Placement::Endpoint`] (so that every position stays an input position), and
    /// none when an endpoint is locked; never the placement's own position, nor one
    /// over the error cap.
    pub(super) fn alternatives(&self, primary: &Candidate) -> Vec<Candidate> {
        let (p, q) = if primary.keep < primary.gone {
            (primary.keep, primary.gone)
        } else {
            (primary.gone, primary.keep)
        };
        if self.vert[p.index()].lock != FREE || self.vert[q.index()].lock != FREE {
            return Vec::new();
        }
        let mut quadric = self.vert[p.index()].quadric;
        quadric.add(&self.vert[q.index()].quadric);
        let weight = self.vert[p.index()].weight + self.vert[q.index()].weight;
        let (pp, pq) = (self.vert[p.index()].pos, self.vert[q.index()].pos);
        let mut options = vec![(pp, p, q), (pq, q, p)];
        if self.opts.placement != Placement::Endpoint {
            options.push((midpoint(pp, pq), p, q));
        }
        let mut out: Vec<Candidate> = options
            .into_iter()
            .filter(|&(x, _, _)| x != primary.position)
            .filter_map(|(position, keep, gone)| {
                let error = quadric.error(position);
                let cost = if error > 0.0 { error } else { 0.0 };
                let error2 = if weight > 0.0 { cost / weight } else { 0.0 };
                if self.cap2.is_some_and(|cap| error2 > cap) {
                    return None;
                }
                Some(Candidate {
                    cost,
                    error2,
                    position,
                    keep,
                    gone,
                })
            })
            .collect();
        // A stable sort: equal costs keep the order above.
        out.sort_by(|a, b| a.cost.total_cmp(&b.cost));
        out
    }

    /// Whether `[p, q]` may be collapsed now, and how: the link condition, then the
    /// placement's position if the fold-over guard (when on) accepts it, else the first
    /// of [`Self::alternatives`] it accepts. Returns the collapse, its queue cost (the
    /// larger of the placement's cost and the chosen position's: never below the
    /// endpoint-only cost the queue starts from) and the real faces it removes; the stars
    /// of `p` and `q` are left walked.
    pub(super) fn resolve(
        &mut self,
        p: VertexId,
        q: VertexId,
    ) -> Result<(Candidate, f64, usize), Refusal> {
        let primary = self.candidate(p, q)?;
        let removed = self.link(p, q)?;
        if !self.opts.guard || self.guard(primary.position) {
            return Ok((primary, primary.cost, removed));
        }
        for alt in self.alternatives(&primary) {
            if self.guard(alt.position) {
                let cost = alt.cost.max(primary.cost);
                return Ok((alt, cost, removed));
            }
        }
        Err(Refusal::Foldover)
    }

    /// The fold-over guard over both walked stars: every real face at either endpoint
    /// but the two of the edge, whose corner moves, must keep a non-zero area and turn
    /// by less than 90°.
    fn guard(&self, to: Point) -> bool {
        let [p, q] = self.walked;
        let pos = |v: VertexId| self.vert[v.index()].pos;
        for (&c, other) in self
            .star_p
            .iter()
            .map(|c| (c, q))
            .chain(self.star_q.iter().map(|c| (c, p)))
        {
            let v0 = self.tri.vertex(c);
            let (v1, v2) = (self.tri.vertex(c.next()), self.tri.vertex(c.prev()));
            if v1 == other || v2 == other || self.is_virtual(v1) || self.is_virtual(v2) {
                continue;
            }
            let from = pos(v0);
            if from == to {
                continue;
            }
            if !fan_move_ok(from, to, pos(v1), pos(v2)) {
                return false;
            }
        }
        true
    }

    /// Collapses a resolved candidate (the stars are still walked) and updates the queue.
    fn collapse(&mut self, c: &Candidate, removed_faces: usize) {
        self.merge(c, removed_faces);
        self.update_around(c.keep, c.gone);
    }

    /// Collapses a resolved candidate (the stars are still walked): the triangulation,
    /// the merged vertex's position and quadric, the counts. Leaves the queue alone.
    pub(super) fn merge(&mut self, c: &Candidate, removed_faces: usize) {
        let (keep, gone) = (c.keep, c.gone);
        let (star, link) = if gone == self.walked[1] {
            (&self.star_q, &self.nbr_q)
        } else {
            (&self.star_p, &self.nbr_p)
        };
        self.tri
            .collapse_walked(keep, gone, star, link, &mut self.scratch);
        self.vert[keep.index()].pos = c.position;
        let g = self.vert[gone.index()].quadric;
        self.vert[keep.index()].quadric.add(&g);
        self.vert[keep.index()].weight += self.vert[gone.index()].weight;
        self.vert[gone.index()].merged_into = keep.0;
        self.real_faces -= removed_faces;
        self.collapses += 1;
        self.max_error2 = self.max_error2.max(c.error2);
    }

    /// The corner opposite the edge `[v, n]` in the face of the star step `step` at `v`
    /// whose exit neighbour is `n`: the face's third corner.
    #[inline]
    pub(super) fn third(&self, step: Corner, n: VertexId) -> Corner {
        if self.tri.vertex(step.next()) == n {
            step.prev()
        } else {
            step.next()
        }
    }

    /// The key of the edge opposite corner `t` (from `v` to `n`) if its endpoints allow
    /// it (its cached cost is a number) and no guard refused it.
    #[inline]
    fn cached_key(&self, v: VertexId, n: VertexId, t: Corner) -> Option<u128> {
        let cost = self.edge_cost[t.index()];
        if cost.is_nan() || self.is_virtual(n) {
            return None;
        }
        if self.vert[v.index()].adjusted_at > 0
            && self.vert[n.index()].adjusted_at > 0
            && self.adjusted.get(&pair(v, n)) == Some(&true)
        {
            return None;
        }
        Some(edge_key(v, n, cost))
    }

    /// Caches the cost of the real edge `[v, n]` opposite corner `t` at both its
    /// opposite corners (NaN if its endpoints refuse it), and returns it.
    fn cache_cost(&mut self, v: VertexId, n: VertexId, t: Corner) -> f64 {
        let cost = self.candidate(v, n).map_or(f64::NAN, |c| c.cost);
        self.edge_cost[t.index()] = cost;
        let o = self.tri.opposite(t);
        self.edge_cost[o.index()] = cost;
        cost
    }

    /// Sets `v`'s best key and queues it if it changed.
    fn set_best(&mut self, v: VertexId, k: u128) {
        if self.best[v.index()] != k {
            self.best[v.index()] = k;
            if k != NO_KEY {
                self.heap.push(k);
            }
        }
    }

    /// Lowers `v`'s best key to `k` if `k` is smaller.
    fn lower(&mut self, v: VertexId, k: u128) {
        if k < self.best[v.index()] {
            self.best[v.index()] = k;
            self.heap.push(k);
        }
    }

    /// Recomputes `v`'s best key over all its edges, from the cached costs. O(d_v).
    fn recompute(&mut self, v: VertexId) {
        let mut best = NO_KEY;
        for st in self.tri.star(v) {
            let t = self.third(st.corner, st.neighbour);
            if let Some(k) = self.cached_key(v, st.neighbour, t) {
                best = best.min(k);
            }
        }
        self.set_best(v, best);
    }

    /// Forgets the adjusted verdicts of every edge at `v` (a collapse changed its
    /// neighbourhood; with `gone`, the vertex merged into `v`, those at it too): raised
    /// costs go back to the endpoints' cost, and each such edge may lower its other
    /// end's best key; `v`'s own best key is left to the caller to recompute.
    fn allow_again(&mut self, v: VertexId, gone: Option<VertexId>) {
        if self.vert[v.index()].adjusted_at == 0
            && gone.is_none_or(|g| self.vert[g.index()].adjusted_at == 0)
        {
            return;
        }
        self.vert[v.index()].adjusted_at = 0;
        let mut steps = std::mem::take(&mut self.steps);
        steps.clear();
        steps.extend(self.tri.star(v).map(|st| (st.corner, st.neighbour)));
        for &(c, w) in &steps {
            let mut was = self.adjusted.remove(&pair(v, w));
            if let Some(g) = gone {
                was = was.or(self.adjusted.remove(&pair(g, w)));
            }
            if let Some(refused) = was {
                let t = self.third(c, w);
                if !refused && !self.is_virtual(w) {
                    self.cache_cost(v, w, t);
                }
                if let Some(k) = self.cached_key(v, w, t) {
                    self.lower(w, k);
                }
            }
        }
        self.steps = steps;
    }

    /// Records an adjusted verdict of the edge `[p, q]` (refused, or queued at the
    /// raised cost `raised`) and recomputes both ends' best keys.
    fn adjust(&mut self, p: VertexId, q: VertexId, raised: Option<f64>) {
        if self.adjusted.insert(pair(p, q), raised.is_none()).is_none() {
            self.vert[p.index()].adjusted_at += 1;
            self.vert[q.index()].adjusted_at += 1;
        }
        if let Some(cost) = raised {
            let step = self.tri.star(p).find(|st| st.neighbour == q);
            if let Some(st) = step {
                let t = self.third(st.corner, q);
                self.edge_cost[t.index()] = cost;
                let o = self.tri.opposite(t);
                self.edge_cost[o.index()] = cost;
            }
        }
        self.recompute(p);
        self.recompute(q);
    }

    /// After a collapse onto `keep`: the costs of its edges (the only ones that
    /// changed), then the best keys of `keep` and of its neighbours (only edges next to
    /// `keep` can have changed verdict). O(d_keep) candidates and O(Σ d_n) cached
    /// reads over the neighbours.
    fn update_around(&mut self, keep: VertexId, gone: VertexId) {
        self.allow_again(keep, Some(gone));
        let mut steps = std::mem::take(&mut self.ring);
        steps.clear();
        steps.extend(self.tri.star(keep).map(|st| (st.corner, st.neighbour)));
        // `allow_again` left no adjusted edge at `keep`: its best key is the cheapest of
        // the costs just cached.
        let mut best = NO_KEY;
        for &(c, n) in &steps {
            if !self.is_virtual(n) {
                let t = self.third(c, n);
                let cost = self.cache_cost(keep, n, t);
                if !cost.is_nan() {
                    best = best.min(edge_key(keep, n, cost));
                }
            }
        }
        debug_assert_eq!(self.vert[keep.index()].adjusted_at, 0);
        self.set_best(keep, best);
        for &(c, n) in &steps {
            if self.is_virtual(n) {
                continue;
            }
            if self.vert[n.index()].adjusted_at > 0 {
                self.allow_again(n, None);
                self.recompute(n);
                continue;
            }
            // `n`'s other edges kept their costs: its best key stands unless it was an
            // edge to `keep` or `gone` (then it is recomputed) or the new edge to `keep`
            // is cheaper.
            let b = self.best[n.index()];
            let (_, x, y) = unpack(b);
            let other = if x == n.0 { y } else { x };
            if b != NO_KEY && (other == keep.0 || other == gone.0) {
                self.recompute(n);
            } else {
                let t = self.third(c, n);
                if let Some(k) = self.cached_key(n, keep, t) {
                    self.lower(n, k);
                }
            }
        }
        self.ring = steps;
    }

    /// Runs the queue to the stop rule; `observer` hears the faces removed. Returns
    /// `false` if `cancelled` said so.
    pub(crate) fn run(
        &mut self,
        observer: &mut dyn FnMut(Progress),
        cancelled: &dyn Fn() -> bool,
    ) -> bool {
        let mut report = Reporter::start(self, observer);
        loop {
            while self.real_faces > self.target {
                let Some(e) = self.heap.pop() else { break };
                if !report.step(self, observer, cancelled) {
                    return false;
                }
                let (cost, p, q) = unpack(e);
                // An entry is current while it is the best key of one of its ends (both
                // then live): a vertex whose best key changes queues the new one, and
                // the old entries are dropped here. (The best keys first: most entries
                // fail there, and the records are read only for the few that pass.)
                if (self.best[p as usize] != e && self.best[q as usize] != e)
                    || self.vert[p as usize].merged_into != NONE
                    || self.vert[q as usize].merged_into != NONE
                {
                    continue;
                }
                let (p, q) = (VertexId(p), VertexId(q));
                spec::current_entry(self, cost, p, q);
                match self.resolve(p, q) {
                    Ok((c, at, removed)) if at.to_bits() == cost.to_bits() => {
                        spec::before_collapse(self, (cost, p.0, q.0), &c);
                        self.collapse(&c, removed);
                    }
                    // The guard took an alternative position: dearer than the key, so
                    // the edge goes back with its true cost.
                    Ok((_, at, _)) => {
                        debug_assert!(at > cost);
                        self.adjust(p, q, Some(at));
                    }
                    Err(r) => {
                        self.refused.count(r);
                        self.adjust(p, q, None);
                    }
                }
            }
            if self.real_faces <= self.target {
                break;
            }
            // The queue is empty. By the invariant no edge passes every guard; a sweep
            // that finds one anyway (the specification check says so) queues it again,
            // so the stop rule holds whatever happens.
            let missed = self.sweep_allowed();
            spec::nothing_missed(self, missed.len());
            if missed.is_empty() {
                break;
            }
            for (p, q, at) in missed {
                self.adjust(p, q, Some(at));
            }
        }
        report.end(self, observer);
        true
    }

    /// Every real edge that passes every guard now, with its queue cost.
    fn sweep_allowed(&mut self) -> Vec<(VertexId, VertexId, f64)> {
        let edges: Vec<(VertexId, VertexId)> = self
            .tri
            .edges()
            .filter(|&(p, q, _)| !self.is_virtual(p) && !self.is_virtual(q))
            .map(|(p, q, _)| (p, q))
            .collect();
        let mut out = Vec::new();
        for (p, q) in edges {
            if let Ok((_, at, _)) = self.resolve(p, q) {
                out.push((p, q, at));
            }
        }
        out
    }

    /// Why the run stopped, and every real edge left classified by the guard refusing
    /// it, per component (none when a target was reached).
    fn account(&mut self) -> (Stopped, Vec<Refusals>) {
        let mut per = vec![Refusals::default(); self.components];
        if self.real_faces <= self.target {
            return (Stopped::Target, per);
        }
        let edges: Vec<(VertexId, VertexId, Corner)> = self
            .tri
            .edges()
            .filter(|&(p, q, _)| !self.is_virtual(p) && !self.is_virtual(q))
            .collect();
        for (p, q, c) in edges {
            let verdict = self.resolve(p, q);
            let k = self.face_label[c.face().index()] as usize;
            match verdict {
                Err(r) => per[k].count(r),
                // The sweep found none; unreachable.
                Ok(_) => debug_assert!(false, "[{p}, {q}] is still collapsible"),
            }
        }
        let errors: usize = per.iter().map(|r| r.error).sum();
        let stopped = if errors > 0 {
            Stopped::Error
        } else {
            Stopped::Blocked
        };
        (stopped, per)
    }

    /// The output in mesh ids, with the statistics. O(V + F).
    pub(crate) fn finish(mut self, mut stats: Stats) -> Output {
        let (stopped, remaining) = self.account();
        spec::at_end(&self, stopped);
        let nv = self.first_virtual as usize;
        let mut out_index = vec![NONE; nv];
        let mut vertex_map = Vec::new();
        let mut positions = Vec::new();
        for (v, slot) in out_index.iter_mut().enumerate() {
            if self.tri.is_vertex(VertexId(v as u32)) {
                *slot = vertex_map.len() as u32;
                vertex_map.push(v as u32);
                positions.push(self.vert[v].pos.map(|x| x / self.scale));
            }
        }
        let mut faces = Vec::new();
        let mut face_origin = Vec::new();
        let mut per: Vec<ComponentStats> = remaining
            .into_iter()
            .map(|r| ComponentStats {
                remaining: r,
                ..ComponentStats::default()
            })
            .collect();
        for f in self.tri.faces() {
            let vs = self.tri.face_vertices(f);
            if vs.iter().any(|&v| self.is_virtual(v)) {
                continue;
            }
            faces.push(vs.map(|v| out_index[v.index()]));
            face_origin.push(f.0);
            per[self.face_label[f.index()] as usize].faces_out += 1;
        }
        // A vertex's component is its corner's face's.
        for &v in &vertex_map {
            let f = self.tri.corner_of(VertexId(v)).face();
            per[self.face_label[f.index()] as usize].vertices_out += 1;
        }
        // Every merged vertex ends in the live vertex at the end of its chain; chains
        // are walked with path halving.
        let mut collapse_map = vec![NONE; nv];
        for (v, slot) in collapse_map.iter_mut().enumerate() {
            let mut r = v as u32;
            if self.vert[v].merged_into == NONE && !self.tri.is_vertex(VertexId(r)) {
                continue; // unused by the input
            }
            while self.vert[r as usize].merged_into != NONE {
                let up = self.vert[r as usize].merged_into;
                let upup = self.vert[up as usize].merged_into;
                if upup != NONE {
                    self.vert[r as usize].merged_into = upup;
                }
                r = self.vert[r as usize].merged_into;
            }
            *slot = out_index[r as usize];
        }
        stats.faces_out = faces.len();
        stats.vertices_out = vertex_map.len();
        stats.stopped = stopped;
        stats.collapses = self.collapses;
        stats.passes = self.passes;
        stats.max_error = self.max_error2.sqrt() / self.scale;
        stats.refused = self.refused;
        for (s, input) in per.iter_mut().zip(&stats.component_list) {
            s.faces_in = input.faces_in;
            s.vertices_in = input.vertices_in;
            s.boundary_loops = input.boundary_loops;
        }
        let mut total = Refusals::default();
        for s in &per {
            let r = &s.remaining;
            total.lock += r.lock;
            total.boundary += r.boundary;
            total.error += r.error;
            total.link_condition += r.link_condition;
            total.foldover += r.foldover;
        }
        stats.remaining = total;
        stats.component_list = per;
        Output {
            faces,
            positions,
            vertex_map,
            collapse_map,
            face_origin,
            stats,
        }
    }
}

/// The input's statistics per component, before any collapse: faces, vertices and
/// boundary loops of each, from the coned mesh's labels.
pub(crate) fn input_stats(whole: &ConedWhole, vertex_count: usize) -> Stats {
    let tri = &whole.tri;
    let mut per = vec![ComponentStats::default(); whole.components];
    for f in tri.faces() {
        let k = whole.face_label[f.index()] as usize;
        if tri
            .face_vertices(f)
            .iter()
            .all(|v| v.index() < vertex_count)
        {
            per[k].faces_in += 1;
        }
    }
    for v in 0..tri.vertex_capacity() {
        let id = VertexId(v as u32);
        if !tri.is_vertex(id) {
            continue;
        }
        let k = whole.face_label[tri.corner_of(id).face().index()] as usize;
        if v < vertex_count {
            per[k].vertices_in += 1;
        } else {
            per[k].boundary_loops += 1;
        }
    }
    Stats {
        faces_in: per.iter().map(|c| c.faces_in).sum(),
        vertices_in: per.iter().map(|c| c.vertices_in).sum(),
        components: whole.components,
        boundary_loops: per.iter().map(|c| c.boundary_loops).sum(),
        component_list: per,
        ..Stats::default()
    }
}

/// The progress reports of a run (faces removed of those to remove, throttled) and its
/// cancellation checks, shared by both schedules.
pub(super) struct Reporter {
    start_faces: usize,
    total: u64,
    throttle: Throttle,
    steps: u64,
}

impl Reporter {
    /// Reports the start of the run.
    pub(super) fn start(d: &Decimator<'_>, observer: &mut dyn FnMut(Progress)) -> Self {
        let total = d.real_faces.saturating_sub(d.target) as u64;
        observer(Progress::new(REMOVED, 0, total));
        Reporter {
            start_faces: d.real_faces,
            total,
            throttle: Throttle::new(),
            steps: 0,
        }
    }

    /// One step of the run: reports now and then; `false` if `cancelled` says so.
    #[inline]
    pub(super) fn step(
        &mut self,
        d: &Decimator<'_>,
        observer: &mut dyn FnMut(Progress),
        cancelled: &dyn Fn() -> bool,
    ) -> bool {
        self.steps += 1;
        if self.throttle.due(self.steps) {
            if cancelled() {
                return false;
            }
            self.end(d, observer);
        }
        true
    }

    /// Reports where the run is.
    pub(super) fn end(&self, d: &Decimator<'_>, observer: &mut dyn FnMut(Progress)) {
        observer(Progress::new(
            REMOVED,
            (self.start_faces - d.real_faces) as u64,
            self.total,
        ));
    }
}

/// The queue key of the edge `[p, q]` at `cost`.
pub(super) fn edge_key(p: VertexId, q: VertexId, cost: f64) -> u128 {
    let (p, q) = if p < q { (p, q) } else { (q, p) };
    key(cost, p.0, q.0)
}

/// The best key of a vertex without an allowed edge.
const NO_KEY: u128 = u128::MAX;

/// An edge as an ordered pair of ids.
pub(super) fn pair(p: VertexId, q: VertexId) -> (u32, u32) {
    (p.0.min(q.0), p.0.max(q.0))
}

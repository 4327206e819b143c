//! The decimator's state and main loop (see the module documentation of
//! [`crate::decimate`] for the guarantee and the method).

use std::cmp::Ordering;
use std::collections::BinaryHeap;

use super::{spec, ComponentStats, Options, Output, Placement, Refusal, Refusals, Stats, Stopped};
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

/// A queue entry: the edge `[p, q]` (`p < q`) with its cost when both endpoints had
/// the versions recorded; stale once either changed.
#[derive(Copy, Clone, Debug)]
pub(super) struct Entry {
    pub(super) cost: f64,
    pub(super) p: u32,
    pub(super) q: u32,
    vp: u32,
    vq: u32,
}

impl Entry {
    /// The queue's order: cheapest first, then the smaller endpoints.
    fn key(&self) -> (f64, u32, u32) {
        (self.cost, self.p, self.q)
    }
}

impl PartialEq for Entry {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}
impl Eq for Entry {}
impl PartialOrd for Entry {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}
impl Ord for Entry {
    /// Reversed, so that `BinaryHeap` (a max-heap) pops the cheapest.
    fn cmp(&self, other: &Self) -> Ordering {
        other
            .cost
            .total_cmp(&self.cost)
            .then(other.p.cmp(&self.p))
            .then(other.q.cmp(&self.q))
            .then(other.vp.cmp(&self.vp))
            .then(other.vq.cmp(&self.vq))
    }
}

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

/// The whole mesh being decimated.
pub(crate) struct Decimator<'o> {
    pub(super) tri: Triangulation,
    /// Ids from here on are virtual (cone apexes).
    pub(super) first_virtual: u32,
    pub(super) pos: Vec<Point>,
    pub(super) quadric: Vec<Quadric>,
    pub(super) weight: Vec<f64>,
    pub(super) version: Vec<u32>,
    /// Per vertex: edges at it refused (link condition or fold-over) since its edges
    /// last entered the queue.
    refused_at: Vec<u32>,
    pub(super) lock: Vec<u8>,
    heap: BinaryHeap<Entry>,
    pub(super) opts: &'o Options,
    /// The power of two the positions are multiplied by (as the simplifier's `scale`:
    /// exact, and keeps squares of extreme coordinates finite).
    pub(super) scale: f64,
    max_coordinate: f64,
    /// The error cap squared, scaled.
    pub(super) cap2: Option<f64>,
    pub(super) real_faces: usize,
    pub(super) target: usize,
    /// Per vertex: the vertex it was merged into (`NONE` while live).
    pub(super) merged_into: Vec<u32>,
    pub(super) face_label: Vec<u32>,
    pub(super) components: usize,
    vmark: Vec<u32>,
    stamp: u32,
    star_p: Vec<Corner>,
    star_q: Vec<Corner>,
    nbr_p: Vec<VertexId>,
    nbr_q: Vec<VertexId>,
    scratch: Vec<Corner>,
    around: Vec<VertexId>,
    pub(super) collapses: usize,
    pub(super) max_error2: f64,
    pub(super) refused: Refusals,
    /// The cost of the last collapse (for the specification's priority check).
    pub(super) last: Option<(f64, u32, u32)>,
    /// The initial quadrics, kept only when the specification checks run.
    pub(super) initial: Vec<(Quadric, f64)>,
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
        let mut pos: Vec<Point> = positions.iter().map(|p| p.map(|x| x * scale)).collect();
        pos.resize(nv, [0.0; 3]);
        let mut lock = vec![FREE; nv];
        for (v, l) in lock.iter_mut().enumerate().take(first_virtual as usize) {
            if opts.locked.get(v).copied().unwrap_or(false) {
                *l = LOCKED;
            }
        }
        if opts.lock_boundary {
            for w in first_virtual as usize..nv {
                let w = VertexId(w as u32);
                if tri.is_vertex(w) {
                    for n in tri.link(w) {
                        if lock[n.index()] == FREE {
                            lock[n.index()] = BOUNDARY;
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
            pos,
            quadric: vec![Quadric::default(); nv],
            weight: vec![0.0; nv],
            version: vec![0; nv],
            refused_at: vec![0; nv],
            lock,
            heap: BinaryHeap::new(),
            opts,
            scale,
            max_coordinate: f64::MAX * scale,
            cap2,
            real_faces,
            target: opts.target_faces,
            merged_into: vec![NONE; nv],
            face_label,
            components,
            vmark: vec![0; nv],
            stamp: 0,
            star_p: Vec::new(),
            star_q: Vec::new(),
            nbr_p: Vec::new(),
            nbr_q: Vec::new(),
            scratch: Vec::new(),
            around: Vec::new(),
            collapses: 0,
            max_error2: 0.0,
            refused: Refusals::default(),
            last: None,
            initial: Vec::new(),
        };
        d.init_quadrics();
        if crate::spec::ENABLED {
            d.initial = d
                .quadric
                .iter()
                .copied()
                .zip(d.weight.iter().copied())
                .collect();
        }
        let mut entries = Vec::with_capacity(3 * d.real_faces / 2 + 16);
        for (p, q, _) in d.tri.edges() {
            if d.is_virtual(q) {
                continue;
            }
            if let Ok(c) = d.candidate(p, q) {
                entries.push(d.entry(p, q, c.cost));
            }
        }
        d.heap = BinaryHeap::from(entries);
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
            let ps = vs.map(|v| self.pos[v.index()]);
            let n = area_normal(ps[0], ps[1], ps[2]);
            let twice_area = dot(n, n).sqrt();
            if twice_area == 0.0 {
                continue;
            }
            let unit = n.map(|x| x / twice_area);
            let w = 0.5 * twice_area;
            let q = Quadric::plane(unit, ps[0], w);
            for v in vs {
                self.quadric[v.index()].add(&q);
                self.weight[v.index()] += w;
            }
            for c in f.corners() {
                let across = self.tri.vertex(self.tri.opposite(c));
                if !self.is_virtual(across) {
                    continue;
                }
                let [s, t] = self.tri.edge_endpoints(c);
                let (ps_, pt) = (self.pos[s.index()], self.pos[t.index()]);
                let m = cross(sub(pt, ps_), unit);
                let len = dot(m, m).sqrt();
                if len == 0.0 {
                    continue;
                }
                let bw = BOUNDARY_WEIGHT * w;
                let q = Quadric::plane(m.map(|x| x / len), ps_, bw);
                for v in [s, t] {
                    self.quadric[v.index()].add(&q);
                    self.weight[v.index()] += bw;
                }
            }
        }
    }

    fn entry(&self, p: VertexId, q: VertexId, cost: f64) -> Entry {
        let (p, q) = if p < q { (p, q) } else { (q, p) };
        Entry {
            cost,
            p: p.0,
            q: q.0,
            vp: self.version[p.index()],
            vq: self.version[q.index()],
        }
    }

    /// The collapse of the real edge `[p, q]` as its endpoints decide it: locks, the
    /// position, the cost and the error cap. O(1).
    pub(super) fn candidate(&self, p: VertexId, q: VertexId) -> Result<Candidate, Refusal> {
        let (p, q) = if p < q { (p, q) } else { (q, p) };
        let (lp, lq) = (self.lock[p.index()], self.lock[q.index()]);
        if lp != FREE && lq != FREE {
            return Err(if lp == LOCKED || lq == LOCKED {
                Refusal::Lock
            } else {
                Refusal::Boundary
            });
        }
        let mut quadric = self.quadric[p.index()];
        quadric.add(&self.quadric[q.index()]);
        let weight = self.weight[p.index()] + self.weight[q.index()];
        let (pp, pq) = (self.pos[p.index()], self.pos[q.index()]);
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
        let cost = quadric.error(position).max(0.0);
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

    /// The topological and geometric checks of a candidate: the link condition of the
    /// surface with boundary, then the fold-over guard. Leaves both stars walked in the
    /// scratch lists; returns the number of real faces the collapse removes.
    pub(super) fn check(&mut self, c: &Candidate) -> Result<usize, Refusal> {
        let (p, q) = (c.keep, c.gone);
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
        if self.opts.guard && !self.guard(p, q, c.position) {
            return Err(Refusal::Foldover);
        }
        Ok(usize::from(!self.is_virtual(a)) + usize::from(!self.is_virtual(b)))
    }

    /// The fold-over guard over both walked stars: every real face at `p` or `q` but the
    /// two of `[p, q]` whose corner moves must keep a non-zero area and turn by less
    /// than 90°.
    fn guard(&self, p: VertexId, q: VertexId, to: Point) -> bool {
        let pos = |v: VertexId| self.pos[v.index()];
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

    /// Collapses a candidate that passed [`Self::check`] (the stars are still walked).
    fn collapse(&mut self, c: &Candidate, removed_faces: usize) {
        let (keep, gone) = (c.keep, c.gone);
        self.tri
            .collapse_walked(keep, gone, &self.star_q, &self.nbr_q, &mut self.scratch);
        self.pos[keep.index()] = c.position;
        let g = self.quadric[gone.index()];
        self.quadric[keep.index()].add(&g);
        self.weight[keep.index()] += self.weight[gone.index()];
        self.version[keep.index()] = self.version[keep.index()].wrapping_add(1);
        self.version[gone.index()] = self.version[gone.index()].wrapping_add(1);
        self.merged_into[gone.index()] = keep.0;
        self.refused_at[keep.index()] = 0;
        self.real_faces -= removed_faces;
        self.collapses += 1;
        self.max_error2 = self.max_error2.max(c.error2);
        // The merged vertex's edges with their new costs; then again every refused
        // edge of a neighbour (only a collapse next to an edge changes its verdict).
        self.push_edges_of(keep, None);
        self.nbr_p.clear();
        self.nbr_p.extend(self.tri.link(keep));
        for i in 0..self.nbr_p.len() {
            let n = self.nbr_p[i];
            if self.is_virtual(n) || self.refused_at[n.index()] == 0 {
                continue;
            }
            self.refused_at[n.index()] = 0;
            self.push_edges_of(n, Some(keep));
        }
    }

    /// Queues every real edge at `v` (but the one to `skip`) that its endpoints allow.
    fn push_edges_of(&mut self, v: VertexId, skip: Option<VertexId>) {
        let mut around = std::mem::take(&mut self.around);
        around.clear();
        around.extend(self.tri.link(v));
        for &n in &around {
            if self.is_virtual(n) || Some(n) == skip {
                continue;
            }
            if let Ok(c) = self.candidate(v, n) {
                let e = self.entry(v, n, c.cost);
                self.heap.push(e);
            }
        }
        self.around = around;
    }

    fn is_current(&self, e: &Entry) -> bool {
        self.merged_into[e.p as usize] == NONE
            && self.merged_into[e.q as usize] == NONE
            && self.version[e.p as usize] == e.vp
            && self.version[e.q as usize] == e.vq
    }

    /// Runs the queue to the stop rule; `observer` hears the faces removed. Returns
    /// `false` if `cancelled` said so.
    pub(crate) fn run(
        &mut self,
        observer: &mut dyn FnMut(Progress),
        cancelled: &dyn Fn() -> bool,
    ) -> bool {
        let start_faces = self.real_faces;
        let total = start_faces.saturating_sub(self.target) as u64;
        observer(Progress::new(REMOVED, 0, total));
        let mut throttle = Throttle::new();
        let mut steps = 0u64;
        loop {
            while self.real_faces > self.target {
                let Some(e) = self.heap.pop() else { break };
                steps += 1;
                if throttle.due(steps) {
                    if cancelled() {
                        return false;
                    }
                    observer(Progress::new(
                        REMOVED,
                        (start_faces - self.real_faces) as u64,
                        total,
                    ));
                }
                if !self.is_current(&e) {
                    continue;
                }
                let (p, q) = (VertexId(e.p), VertexId(e.q));
                let c = match self.candidate(p, q) {
                    Ok(c) => c,
                    Err(r) => {
                        // Entries are made only for allowed candidates, and the
                        // endpoints are unchanged: unreachable, but counted.
                        self.refused.count(r);
                        continue;
                    }
                };
                match self.check(&c) {
                    Ok(removed) => {
                        spec::before_collapse(self, &e, &c);
                        self.last = Some(e.key());
                        self.collapse(&c, removed);
                    }
                    Err(r) => {
                        self.refused.count(r);
                        self.refused_at[p.index()] += 1;
                        self.refused_at[q.index()] += 1;
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
            self.heap.extend(missed);
        }
        observer(Progress::new(
            REMOVED,
            (start_faces - self.real_faces) as u64,
            total,
        ));
        true
    }

    /// Every real edge that passes every guard now, as queue entries.
    fn sweep_allowed(&mut self) -> Vec<Entry> {
        let edges: Vec<(VertexId, VertexId)> = self
            .tri
            .edges()
            .filter(|&(p, q, _)| !self.is_virtual(p) && !self.is_virtual(q))
            .map(|(p, q, _)| (p, q))
            .collect();
        let mut out = Vec::new();
        for (p, q) in edges {
            if let Ok(c) = self.candidate(p, q) {
                if self.check(&c).is_ok() {
                    out.push(self.entry(p, q, c.cost));
                }
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
            let verdict = self.candidate(p, q).and_then(|cand| self.check(&cand));
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
                positions.push(self.pos[v].map(|x| x / self.scale));
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
            if self.merged_into[v] == NONE && !self.tri.is_vertex(VertexId(r)) {
                continue; // unused by the input
            }
            while self.merged_into[r as usize] != NONE {
                let up = self.merged_into[r as usize];
                let upup = self.merged_into[up as usize];
                if upup != NONE {
                    self.merged_into[r as usize] = upup;
                }
                r = self.merged_into[r as usize];
            }
            *slot = out_index[r as usize];
        }
        stats.faces_out = faces.len();
        stats.vertices_out = vertex_map.len();
        stats.stopped = stopped;
        stats.collapses = self.collapses;
        stats.max_error = self.max_error2.sqrt() / self.scale;
        stats.refused = self.refused;
        for (s, input) in per.iter_mut().zip(&stats.per_component) {
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
        stats.per_component = per;
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
        per_component: per,
        ..Stats::default()
    }
}

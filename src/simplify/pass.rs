//! The pass machinery shared by both modes: the state of one component, the pass loop,
//! the common-neighbour walk, the position and guard decisions, applying a plan, and the
//! per-pass compaction.
//!
//! **The naive passes decide first, then apply, on up to two threads, with the output
//! of the sequential sweep.** Within a pass, a contraction of `[p', q']` changes only
//! the faces containing `p'` or `q'` (renamed corners, the two removed faces, the
//! re-glued `opposite` entries, which all lie in faces across an edge at `p'` or `q'`),
//! the degree and stored corner of `p'`, `q'` and of the edge's two opposite vertices,
//! and the position (and quadric) of the kept vertex; and it freezes every vertex of
//! every face around `p'` or `q'` (all of the above). So a vertex that is still
//! unfrozen has its pass-start star (faces, `opposite` entries, degree, stored corner,
//! hence the same walk in the same order), and so has every neighbour of it its
//! pass-start position (a moved vertex is a kept one, all of whose neighbours are
//! frozen). The naive plan of an edge `[p, q]` with both endpoints unfrozen —
//! [`Walk::examine`] (both stars, the degree of `q`, cone apexes), the tetrahedron test
//! (degrees of `p` and `q`), the position (positions and quadrics of `p`, `q`) and the
//! guard (positions of `p`, `q` and their neighbours) — therefore reads exactly the
//! pass-start state, and so does the sweep's visit of a face with at most one frozen
//! vertex (its lengths: a face with a kept vertex has three frozen vertices). The faces
//! a contraction removes are the two faces of its edge, which the sweep then skips
//! without counting (a list of them, `dead`). Hence the whole pass can be *decided* on
//! the pass-start state (which edges contract, in which order, every skip count) and
//! the contractions *applied* afterwards in the same order, each onto a state in which
//! its stars are still the pass-start ones (the stars walked while deciding are reused).
//!
//! Deciding is split at the middle face slot `m`: the calling thread decides `[0, m)`
//! (exactly, since nothing before `0` exists), a second thread decides `[m, nf)` as if
//! nothing before `m` had frozen anything (a speculative sweep, on its own freeze stamp
//! and `dead` list, recording every plan it computed), and then the calling thread
//! decides `[m, nf)` exactly, taking every plan the speculative sweep computed from its
//! record (a plan is a function of the pass-start state, whoever computes it) and
//! computing only the others. It stops early once the two sweeps provably agree on the
//! rest: every `CHECKPOINT` faces it compares the two sweeps' successes so far; the
//! frozen sets of the two differ at most on `D` = (the vertices the exact sweep froze
//! before `m`) ∪ (the vertices frozen by a success only one of the sweeps made), so if
//! every vertex id in `D` is below the smallest vertex id of the faces from the
//! checkpoint `g` on (the speculative sweep's `suffix_min`), the two sweeps read equal
//! freeze states and `dead` lists from `g` on and make the same decisions with the same
//! counts (virtual vertices are never read: faces with one are skipped first). The
//! exact sweep then adopts the speculative successes and counts from `g` on. Whatever
//! the split, the timing or the thread count, the decisions are those of the single
//! sequential sweep, so outputs are identical for 1 and 2 threads (tested).
//!
//! The nested passes (after the naive fixed point) stay sequential: a nested plan grows
//! regions that can reach far from the edge, into faces changed earlier in the pass.

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::sync::atomic::{AtomicU32, Ordering::Relaxed};

use super::geometry::{area_normal, dist2, fan_move_ok, midpoint, Point, Quadric};
use super::nested::{self, Claim, Grow};
use super::{naive, spec, Mode, Options, Position, SkipCounts};
use crate::core::{ConedComponent, Corner, FaceId, Triangulation, VertexId};
use crate::progress::{Progress, Throttle};
use crate::topology::SurfaceType;

/// The stage of the progress reports inside a pass.
pub const SCANNED: &str = "faces scanned in this pass";

/// Degree up to which `examine` looks neighbours up in a list rather than in the marks.
const SMALL_LINK: usize = 24;

/// Face slots between two points at which the exact sweep checks whether the
/// speculative one has become exact (see the module documentation).
const CHECKPOINT: usize = 512;

/// Face slots below which a pass is decided on one thread (a thread costs more).
const PARALLEL_MIN: usize = 8 * CHECKPOINT;

/// Why an edge is not processed now (frozen edges are counted before planning).
#[derive(Copy, Clone, Debug, PartialEq, Eq)]
pub(super) enum Skip {
    LinkCondition,
    NonDisc,
    Foldover,
}

impl SkipCounts {
    fn count(&mut self, s: Skip) {
        match s {
            Skip::LinkCondition => self.link_condition += 1,
            Skip::NonDisc => self.non_disc += 1,
            Skip::Foldover => self.foldover += 1,
        }
    }

    fn minus(&self, o: &SkipCounts) -> SkipCounts {
        SkipCounts {
            link_condition: self.link_condition - o.link_condition,
            non_disc: self.non_disc - o.non_disc,
            foldover: self.foldover - o.foldover,
            frozen: self.frozen - o.frozen,
        }
    }
}

/// The totals of one component's run.
#[derive(Clone, Debug, Default)]
pub(super) struct Run {
    pub(super) edges_contracted: usize,
    pub(super) discs_removed: usize,
    pub(super) vertices_removed_inside: usize,
    pub(super) skipped: SkipCounts,
    pub(super) remaining: SkipCounts,
    pub(super) passes: usize,
    pub(super) shortest: Option<f64>,
}

/// The edge being examined: endpoints, opposite vertices, and whether each endpoint is
/// on the boundary. `xs` (in the simplifier) holds the other common neighbours.
#[derive(Copy, Clone, Debug)]
pub(super) struct EdgeInfo {
    /// The corner opposite the edge in the triangle being visited (side "a").
    pub(super) corner: Corner,
    pub(super) p: VertexId,
    pub(super) q: VertexId,
    pub(super) a: VertexId,
    pub(super) b: VertexId,
    pub(super) boundary: [bool; 2],
}

/// What processing an edge will do, decided before anything changes.
#[derive(Copy, Clone, Debug)]
pub(super) struct Plan {
    /// The discs to replace first (nested mode), per side.
    pub(super) discs: [Option<Claim>; 2],
    /// The position of the merged vertex.
    pub(super) position: Point,
}

/// A vertex's position.
#[derive(Copy, Clone, Debug)]
pub(super) struct Vertex {
    pub(super) pos: Point,
}

impl Vertex {
    fn new(pos: Point) -> Self {
        Vertex { pos }
    }
}

/// The read-only state a plan reads (the pass-start state while a pass is decided).
#[derive(Copy, Clone)]
pub(super) struct View<'a> {
    tri: &'a Triangulation,
    vert: &'a [Vertex],
    touched: [&'a [AtomicU32]; 2],
    quadric: &'a [Quadric],
    first_virtual: u32,
    opts: &'a Options,
    eps2: f64,
    pass: u32,
}

/// A [`View`] of a simplifier, borrowing only the fields it names (so that scratch
/// fields can be borrowed mutably beside it).
macro_rules! view {
    ($s:expr) => {
        View {
            tri: &$s.tri,
            vert: &$s.vert,
            touched: [&$s.touched[0], &$s.touched[1]],
            quadric: &$s.quadric,
            first_virtual: $s.first_virtual,
            opts: $s.opts,
            eps2: $s.eps2,
            pass: $s.pass,
        }
    };
}

impl View<'_> {
    /// Whether `x` was frozen in this pass, on freeze stamp `slot`.
    #[inline]
    fn frozen(&self, slot: usize, x: VertexId) -> bool {
        self.touched[slot][x.index()].load(Relaxed) == self.pass
    }

    #[inline]
    fn freeze(&self, slot: usize, x: VertexId) {
        self.touched[slot][x.index()].store(self.pass, Relaxed);
    }

    #[inline]
    fn is_virtual(&self, v: VertexId) -> bool {
        v.0 >= self.first_virtual
    }

    #[inline]
    fn pos(&self, v: VertexId) -> Point {
        self.vert[v.index()].pos
    }

    /// Where the merged vertex goes (see [`Position`]).
    fn position(&self, e: &EdgeInfo) -> Point {
        let (pp, pq) = (self.pos(e.p), self.pos(e.q));
        match self.opts.position {
            Position::Midpoint => match e.boundary {
                [true, false] => pp,
                [false, true] => pq,
                _ => midpoint(pp, pq),
            },
            Position::Quadric => {
                let mut q = self.quadric[e.p.index()];
                q.add(&self.quadric[e.q.index()]);
                q.best_position(pp, pq)
            }
        }
    }
}

/// The scratch of the common-neighbour walk, one per deciding thread.
#[derive(Default)]
pub(super) struct Walk {
    /// Marks for a high-degree `q` (sized on first use), compared with `stamp`.
    vmark: Vec<u32>,
    stamp: u32,
    /// A corner at q, then at p, in every face around them.
    star_pq: Vec<Corner>,
    /// The neighbours of q and of p, in the order of their corners in `star_pq`.
    nbr_q: Vec<VertexId>,
    nbr_p: Vec<VertexId>,
    link: Vec<VertexId>,
    /// The common neighbours of the edge other than its opposite vertices, in order
    /// along the link of `p` from `a` to `b`.
    xs: Vec<VertexId>,
}

impl Walk {
    /// The edge opposite `c`: its endpoints and opposite vertices, and its other common
    /// neighbours in `self.xs`. Refuses an edge joining two boundary loops. O(d_p + d_q).
    fn examine(&mut self, v: &View<'_>, c: Corner) -> Result<EdgeInfo, Skip> {
        let tri = v.tri;
        let [p, q] = tri.edge_endpoints(c);
        let a = tri.vertex(c);
        let b = tri.vertex(tri.opposite(c));
        // One walk around each endpoint: q's neighbours listed (and marked, for a high
        // degree), p's checked against them; the corners kept for the guard and the
        // freeze, which then need no walk of their own. A short list scanned linearly
        // beats the marks, which miss the cache.
        let big = tri.degree(q) > SMALL_LINK;
        let s = if big {
            if self.vmark.len() < tri.vertex_capacity() {
                self.vmark.resize(tri.vertex_capacity(), 0);
            }
            if self.stamp == u32::MAX {
                self.vmark.fill(0);
                self.stamp = 0;
            }
            self.stamp += 1;
            self.stamp
        } else {
            0
        };
        let mut loop_q = None;
        self.star_pq.clear();
        self.nbr_q.clear();
        for st in tri.star(q) {
            let n = st.neighbour;
            if big {
                self.vmark[n.index()] = s;
            }
            if n.0 >= v.first_virtual {
                loop_q = Some(n);
            }
            self.nbr_q.push(n);
            self.star_pq.push(st.corner);
        }
        let mut loop_p = None;
        let mut extra = false;
        self.nbr_p.clear();
        for st in tri.star(p) {
            let n = st.neighbour;
            self.nbr_p.push(n);
            if n.0 >= v.first_virtual {
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
            self.link.extend(tri.link(p));
            let at_q = self.link.iter().position(|&n| n == q).unwrap_or(0);
            self.link.rotate_left(at_q + 1);
            self.link.pop();
            if self.link.first() != Some(&a) {
                self.link.reverse();
            }
            debug_assert_eq!(self.link.first(), Some(&a));
            debug_assert_eq!(self.link.last(), Some(&b));
            for k in 1..self.link.len() - 1 {
                let n = self.link[k];
                if self.in_link_q(n, big, s) {
                    self.xs.push(n);
                }
            }
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

    /// The fold-over guard: every real face at `p` or `q` that survives (not marked
    /// `removed` in `fmark`, not a face of `[p, q]`) must stay non-degenerate and turn by
    /// less than 90° when `p` and `q` move to `to`. Uses the stars `examine` walked.
    fn guard(
        &self,
        v: &View<'_>,
        e: &EdgeInfo,
        to: Point,
        removed: Option<(&[u32], u32)>,
    ) -> bool {
        let tri = v.tri;
        for &c in &self.star_pq {
            let f = c.face();
            if removed.is_some_and(|(fmark, s)| fmark[f.index()] == s) {
                continue;
            }
            let (v0, v1, v2) = (tri.vertex(c), tri.vertex(c.next()), tri.vertex(c.prev()));
            // v0 is p or q; skip the faces of [p, q] and cone faces.
            let other = if v0 == e.p { e.q } else { e.p };
            if v1 == other || v2 == other || v.is_virtual(v1) || v.is_virtual(v2) {
                continue;
            }
            if !fan_move_ok(v.pos(v0), to, v.pos(v1), v.pos(v2)) {
                return false;
            }
        }
        true
    }

    /// The naive plan of the edge opposite `c` (the link condition, the tetrahedron
    /// test, the position, the guard): what `Simplifier::plan` decides for it in a
    /// naive pass. Reads only the stars of both endpoints and the positions on them.
    fn plan_naive(&mut self, v: &View<'_>, c: Corner) -> Result<(EdgeInfo, Point), Skip> {
        let info = self.examine(v, c)?;
        if !self.xs.is_empty() {
            return Err(Skip::LinkCondition);
        }
        if v.tri.degree(info.p) == 3 && v.tri.degree(info.q) == 3 {
            return Err(Skip::LinkCondition);
        }
        let position = v.position(&info);
        if v.opts.guard && !self.guard(v, &info, position, None) {
            return Err(Skip::Foldover);
        }
        Ok((info, position))
    }
}

/// A decided contraction: the edge, the new position, and where its walked stars are
/// kept in its sweep's `corners` / `verts`.
#[derive(Copy, Clone, Debug)]
struct Win {
    face: u32,
    slot: u32,
    p: VertexId,
    q: VertexId,
    position: Point,
    /// `corners[at_c..]`: `star_pq` (`dq + dp` corners); `verts[at_v..]`: `nbr_q` (`dq`)
    /// then `nbr_p` (`dp`).
    at_c: u32,
    at_v: u32,
    dq: u32,
    dp: u32,
}

/// A plan the speculative sweep computed: face, slot, and the index of its `Win` or
/// the reason it was refused.
#[derive(Copy, Clone, Debug)]
struct Tried {
    face: u32,
    slot: u32,
    outcome: Result<u32, Skip>,
}

/// The speculative sweep's state at a checkpoint: its counts and successes before it.
#[derive(Copy, Clone, Debug, Default)]
struct Mark {
    counts: SkipCounts,
    wins: usize,
}

/// The decisions of one sweep over a face range (reused from pass to pass).
#[derive(Default)]
pub(super) struct Sweep {
    walk: Walk,
    wins: Vec<Win>,
    corners: Vec<Corner>,
    verts: Vec<VertexId>,
    /// Speculative sweep only: every plan computed, in order.
    tried: Vec<Tried>,
    /// Speculative sweep only: the state at each checkpoint of its range.
    marks: Vec<Mark>,
    /// Speculative sweep only, per vertex: `pass << 32 | (f + 1)` for the last face
    /// slot `f` of its range that uses it (any other value: none does).
    last_use: Vec<u64>,
    counts: SkipCounts,
    /// Faces a success removes that the sweep has not reached yet.
    dead: BinaryHeap<Reverse<u32>>,
}

impl Sweep {
    fn reset(&mut self) {
        self.wins.clear();
        self.corners.clear();
        self.verts.clear();
        self.tried.clear();
        self.marks.clear();
        self.counts = SkipCounts::default();
        self.dead.clear();
    }

    /// Records the success of the plan `walk` holds, freezing its vertices on `slot`.
    fn win(&mut self, v: &View<'_>, slot: usize, face: u32, s: u32, info: &EdgeInfo, position: Point) {
        let w = &self.walk;
        for &n in w.nbr_q.iter().chain(&w.nbr_p).chain(&[info.p, info.q]) {
            v.freeze(slot, n);
        }
        self.wins.push(Win {
            face,
            slot: s,
            p: info.p,
            q: info.q,
            position,
            at_c: self.corners.len() as u32,
            at_v: self.verts.len() as u32,
            dq: w.nbr_q.len() as u32,
            dp: w.nbr_p.len() as u32,
        });
        self.corners.extend_from_slice(&w.star_pq);
        self.verts.extend_from_slice(&w.nbr_q);
        self.verts.extend_from_slice(&w.nbr_p);
        let other = v.tri.opposite(info.corner).face().0;
        if other > face {
            self.dead.push(Reverse(other));
        }
    }

    /// Takes over the success `w` of sweep `from` (a plan it computed), freezing on
    /// `slot` as `win` does.
    fn adopt(&mut self, v: &View<'_>, slot: usize, from: &Sweep, w: &Win) {
        let (c0, v0) = (w.at_c as usize, w.at_v as usize);
        let d = (w.dq + w.dp) as usize;
        for &n in &from.verts[v0..v0 + d] {
            v.freeze(slot, n);
        }
        v.freeze(slot, w.p);
        v.freeze(slot, w.q);
        let mut own = *w;
        own.at_c = self.corners.len() as u32;
        own.at_v = self.verts.len() as u32;
        self.corners.extend_from_slice(&from.corners[c0..c0 + d]);
        self.verts.extend_from_slice(&from.verts[v0..v0 + d]);
        self.wins.push(own);
        let other = v.tri.opposite(w.face_corner()).face().0;
        if other > w.face {
            self.dead.push(Reverse(other));
        }
    }
}

impl Win {
    /// The corner opposite the edge in the face the sweep visited.
    fn face_corner(&self) -> Corner {
        FaceId(self.face).corner(self.slot)
    }

    /// One more than the last face slot of the speculative range that uses a real
    /// vertex this contraction freezes (0 if none does), from `last_use` of `pass`.
    fn reach(&self, sw: &Sweep, last_use: &[u64], v: &View<'_>) -> u64 {
        let v0 = self.at_v as usize;
        let d = (self.dq + self.dp) as usize;
        let pass = u64::from(v.pass);
        sw.verts[v0..v0 + d]
            .iter()
            .chain(&[self.p, self.q])
            .filter(|n| !v.is_virtual(**n))
            .map(|n| {
                let x = last_use[n.index()];
                if x >> 32 == pass {
                    x & 0xffff_ffff
                } else {
                    0
                }
            })
            .max()
            .unwrap_or(0)
    }
}

pub static HIT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
pub static MISS: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
pub static TA: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
pub static TR: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
pub static TP: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);

/// Whose plans a sweep computes and keeps (see the module documentation).
enum Role<'s> {
    /// The exact sweep, planning every edge itself.
    Exact,
    /// The speculative sweep, recording every plan in `tried`.
    Speculative,
    /// The exact sweep over the speculative sweep's range, reusing its plans
    /// (`cursor`: the first `tried` entry not behind the current face).
    Repair(&'s Sweep, usize),
}

/// The first face slot in `[from, to)` whose visit gets as far as reading positions,
/// and the number of visits before it deferred as frozen (on freeze stamp `slot`); `to`
/// if none. Skipped: faces removed earlier in the pass (`dead`, popped as they are
/// passed) or before it, cone faces (a virtual vertex) and faces with two or more
/// vertices frozen in this pass (every edge has a frozen endpoint; most visits of a
/// pass end here, so they are skipped in a loop that changes nothing), which alone are
/// counted.
fn next_candidate(
    v: &View<'_>,
    slot: usize,
    from: usize,
    to: usize,
    dead: &mut BinaryHeap<Reverse<u32>>,
    last_use: &mut [u64],
) -> (usize, usize) {
    let track = !last_use.is_empty();
    let stamp = u64::from(v.pass) << 32;
    let pass = v.pass;
    let first_virtual = v.first_virtual;
    let frozen = |x: u32| u32::from(v.touched[slot][x as usize].load(Relaxed) == pass);
    let mut next_dead = dead.peek().map_or(usize::MAX, |d| d.0 as usize);
    let mut deferred = 0;
    let slots = v.tri.corner_vertex.get(3 * from..3 * to).unwrap_or(&[]);
    for (k, face) in slots.chunks_exact(3).enumerate() {
        let fi = from + k;
        if fi >= next_dead {
            let mut hit = false;
            while let Some(&Reverse(d)) = dead.peek() {
                if d as usize > fi {
                    break;
                }
                hit |= d as usize == fi;
                dead.pop();
            }
            next_dead = dead.peek().map_or(usize::MAX, |d| d.0 as usize);
            if hit {
                continue;
            }
        }
        let (a, b, c) = (face[0], face[1], face[2]);
        if track && a != crate::core::ids::NONE {
            let used = stamp | (fi as u64 + 1);
            last_use[a as usize] = used;
            last_use[b as usize] = used;
            last_use[c as usize] = used;
        }
        // A removed face has NONE (above every vertex id) in its slots.
        if a >= first_virtual || b >= first_virtual || c >= first_virtual {
            continue;
        }
        if frozen(a) + frozen(b) + frozen(c) >= 2 {
            deferred += 1;
            continue;
        }
        return (fi, deferred);
    }
    (to, deferred)
}

/// Visits face `fi` as the sequential pass does: its edges shorter than ε, shortest
/// first (ties by slot), frozen ones counted, the others planned until one succeeds.
fn visit(v: &View<'_>, slot: usize, sw: &mut Sweep, fi: usize, role: &mut Role<'_>) {
    let f = FaceId(fi as u32);
    let vs = v.tri.face_vertices(f);
    let ps = [v.pos(vs[0]), v.pos(vs[1]), v.pos(vs[2])];
    // Edge opposite slot s joins slots s+1 and s+2; the short ones, shortest first
    // (ties by slot), by a three-element sorting network.
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
        if l[s as usize] >= v.eps2 {
            break;
        }
        let c = f.corner(s);
        let [p, q] = v.tri.edge_endpoints(c);
        if v.frozen(slot, p) || v.frozen(slot, q) {
            sw.counts.frozen += 1;
            continue;
        }
        let cached = match role {
            Role::Repair(spec, cursor) => {
                let tried = &spec.tried;
                while *cursor < tried.len() && (tried[*cursor].face as usize) < fi {
                    *cursor += 1;
                }
                tried[*cursor..]
                    .iter()
                    .take_while(|t| t.face as usize == fi)
                    .find(|t| t.slot == s)
                    .map(|t| (*spec, t.outcome))
            }
            _ => None,
        };
        if cached.is_some() {
            HIT.fetch_add(1, Relaxed);
        }
        let outcome = match cached {
            Some((spec, Ok(i))) => {
                sw.adopt(v, slot, spec, &spec.wins[i as usize]);
                Ok(())
            }
            Some((_, Err(k))) => Err(k),
            None => {
                if matches!(role, Role::Repair(..)) {
                    MISS.fetch_add(1, Relaxed);
                }
                let planned = sw.walk.plan_naive(v, c);
                let outcome = match planned {
                    Ok((info, position)) => {
                        sw.win(v, slot, fi as u32, s, &info, position);
                        Ok(sw.wins.len() as u32 - 1)
                    }
                    Err(k) => Err(k),
                };
                if matches!(role, Role::Speculative) {
                    sw.tried.push(Tried {
                        face: fi as u32,
                        slot: s,
                        outcome,
                    });
                }
                outcome.map(|_| ())
            }
        };
        match outcome {
            Ok(()) => break,
            Err(k) => sw.counts.count(k),
        }
    }
}

/// Decides faces `[from, to)` on freeze stamp `slot`, continuing `sw`'s state;
/// `progress(face)` now and then.
fn sweep_range(
    v: &View<'_>,
    slot: usize,
    sw: &mut Sweep,
    from: usize,
    to: usize,
    role: &mut Role<'_>,
    progress: &mut dyn FnMut(usize),
) {
    let mut from = from;
    loop {
        let (fi, deferred) = next_candidate(v, slot, from, to, &mut sw.dead, &mut sw.last_use);
        sw.counts.frozen += deferred;
        if fi >= to {
            break;
        }
        from = fi + 1;
        progress(fi);
        visit(v, slot, sw, fi, role);
    }
}

/// The speculative sweep over `[m, nf)` (stamp 1, nothing frozen at `m`), with its
/// checkpoint marks and suffix minima.
fn speculate(v: &View<'_>, sw: &mut Sweep, m: usize, nf: usize) {
    // Sized here (it is only ever read for vertices below the capacity), filled by
    // `next_candidate`; older passes' entries do not match this pass's stamp.
    sw.last_use.resize(v.tri.vertex_capacity(), 0);
    let mut g = m;
    let mut role = Role::Speculative;
    while g < nf {
        sw.marks.push(Mark {
            counts: sw.counts,
            wins: sw.wins.len(),
        });
        let end = (g + CHECKPOINT).min(nf);
        sweep_range(v, 1, sw, g, end, &mut role, &mut |_| {});
        g = end;
    }
}

/// The exact sweep over `[m, nf)` after the exact one over `[0, m)` (in `a`) and the
/// speculative one (in `b`): returns the index of `b`'s first success to adopt if the
/// two sweeps became provably equal at a checkpoint (then `a`'s counts include `b`'s
/// from there on), `None` if `a` decided the whole range.
fn repair(
    v: &View<'_>,
    a: &mut Sweep,
    b: &Sweep,
    m: usize,
    nf: usize,
    progress: &mut dyn FnMut(usize),
) -> Option<usize> {
    // One more than the last face slot that uses a vertex whose freeze states may
    // differ between the two sweeps (see the module documentation).
    let last_use = &b.last_use[..];
    let mut reach = a.wins.iter().map(|w| w.reach(a, last_use, v)).max().unwrap_or(0);
    let (mut ia, mut ib) = (a.wins.len(), 0);
    let mut role = Role::Repair(b, 0);
    let mut g = m;
    let mut k = 0;
    loop {
        // Compare the successes before g: equal ones freeze the same vertices.
        loop {
            let fa = a.wins.get(ia).filter(|w| (w.face as usize) < g);
            let fb = b.wins.get(ib).filter(|w| (w.face as usize) < g);
            match (fa, fb) {
                (None, None) => break,
                (Some(x), Some(y)) if x.face == y.face => {
                    if x.slot == y.slot { HIT.fetch_add(1 << 40, Relaxed); } else { MISS.fetch_add(1 << 40, Relaxed); }
                    if x.slot != y.slot {
                        reach = reach
                            .max(x.reach(a, last_use, v))
                            .max(y.reach(b, last_use, v));
                    }
                    ia += 1;
                    ib += 1;
                }
                (Some(x), y) if y.is_none_or(|y| x.face < y.face) => {
                    MISS.fetch_add(1 << 40, Relaxed);
                    reach = reach.max(x.reach(a, last_use, v));
                    ia += 1;
                }
                (_, Some(y)) => {
                    MISS.fetch_add(1 << 40, Relaxed);
                    reach = reach.max(y.reach(b, last_use, v));
                    ib += 1;
                }
                (Some(_), None) => unreachable!("handled by the arm above"),
            }
        }
        if g >= nf {
            if std::env::var_os("SIMPAR_DEBUG").is_some() {
                eprintln!("no convergence (nf {nf}) reach {reach}");
            }
            return None;
        }
        if reach <= g as u64 {
            if std::env::var_os("SIMPAR_DEBUG").is_some() {
                eprintln!("converged at checkpoint {k} of {} (g {g}, m {m}, nf {nf})", b.marks.len());
            }
            let mark = &b.marks[k];
            a.counts.add(&b.counts.minus(&mark.counts));
            return Some(mark.wins);
        }
        let end = (g + CHECKPOINT).min(nf);
        sweep_range(v, 0, a, g, end, &mut role, progress);
        g = end;
        k += 1;
    }
}

/// One component being simplified.
pub(crate) struct Simplifier<'o> {
    pub(super) tri: Triangulation,
    /// Per vertex: position.
    pub(super) vert: Vec<Vertex>,
    /// Per vertex, the pass that froze it: stamp 0 for the exact sweep (and the
    /// sequential passes), stamp 1 for the speculative one. Atomic only so that the two
    /// deciding threads can each write their own while both read the rest; relaxed
    /// loads and stores are plain moves. Dense (4 bytes a vertex), since most visits of
    /// a pass read only these.
    touched: [Vec<AtomicU32>; 2],
    pub(super) quadric: Vec<Quadric>,
    /// Vertex ids from here on are virtual (cone apexes); they stay last through
    /// compaction since they are never removed.
    pub(super) first_virtual: u32,
    loops: usize,
    pub(super) opts: &'o Options,
    pub(super) eps2: f64,
    pub(super) pass: u32,
    /// Threads a naive pass may decide on (1 or 2).
    workers: usize,
    /// Scratch marks of the nested mode (compared with `stamp`).
    pub(super) vmark: Vec<u32>,
    pub(super) fmark: Vec<u32>,
    stamp: u32,
    scratch: Vec<Corner>,
    /// The decisions of a pass's exact sweep (its walk also serves the sequential
    /// passes) and of its speculative sweep.
    sweep_a: Sweep,
    sweep_b: Sweep,
    /// The common neighbours of the edge other than its opposite vertices, in order
    /// along the link of `p` from `a` to `b` (moved here from the walk by `plan`).
    pub(super) xs: Vec<VertexId>,
    pub(super) grow: [Grow; 2],
    interior: Vec<VertexId>,
    /// The coned surface's type at the start, recorded only when the specification
    /// checks run (it checks it after every pass; computing it is an O(F) pass).
    pub(super) surface: Option<SurfaceType>,
    /// Whether processEdge (the nested plan) is in use: the nested mode first runs naive
    /// passes to a fixed point, then nested ones (see `run`).
    nested_phase: bool,
    run: Run,
}

impl<'o> Simplifier<'o> {
    /// Takes over a component, with the positions of the mesh it came from (indexed by
    /// mesh vertex; the component's `vertex_origin` picks its own).
    pub(crate) fn new(component: ConedComponent, positions: &[Point], opts: &'o Options) -> Self {
        let loops = component.virtual_vertices().count();
        let first_virtual = component.real_vertex_count() as u32;
        let nv = component.tri.vertex_capacity();
        let mut vert = Vec::with_capacity(nv);
        vert.extend(
            component
                .vertex_origin
                .iter()
                .map(|&m| Vertex::new(positions[m as usize])),
        );
        let tri = component.tri;
        let nf = tri.face_capacity();
        vert.resize_with(nv, || Vertex::new([0.0; 3]));
        let surface = spec::ENABLED.then(|| SurfaceType::of(&tri));
        let mut s = Simplifier {
            tri,
            vert,
            touched: [
                (0..nv).map(|_| AtomicU32::new(0)).collect(),
                (0..nv).map(|_| AtomicU32::new(0)).collect(),
            ],
            quadric: Vec::new(),
            first_virtual,
            loops,
            opts,
            eps2: opts.eps * opts.eps,
            pass: 0,
            workers: opts.workers(),
            vmark: vec![0; nv],
            fmark: vec![0; nf],
            stamp: 0,
            scratch: Vec::new(),
            sweep_a: Sweep::default(),
            sweep_b: Sweep::default(),
            xs: Vec::new(),
            grow: [Grow::default(), Grow::default()],
            interior: Vec::new(),
            surface,
            nested_phase: false,
            run: Run::default(),
        };
        if opts.position == Position::Quadric {
            s.init_quadrics();
        }
        s
    }

    /// Boundary loops of the component (constant).
    pub(super) fn loop_count(&self) -> usize {
        self.loops
    }

    #[inline]
    pub(super) fn is_virtual(&self, v: VertexId) -> bool {
        v.0 >= self.first_virtual
    }

    /// A stamp no mark holds yet.
    pub(super) fn fresh_stamp(&mut self) -> u32 {
        if self.stamp == u32::MAX {
            self.vmark.fill(0);
            self.fmark.fill(0);
            self.stamp = 0;
        }
        self.stamp += 1;
        self.stamp
    }

    /// Area-weighted plane quadrics of the real faces, plus a plane through every
    /// boundary edge perpendicular to its face (weight: the face's area times
    /// `BOUNDARY_WEIGHT`), so that boundary curves resist moving.
    fn init_quadrics(&mut self) {
        const BOUNDARY_WEIGHT: f64 = 10.0;
        self.quadric = vec![Quadric::default(); self.tri.vertex_capacity()];
        for f in self.tri.faces() {
            let vs = self.tri.face_vertices(f);
            if vs.iter().any(|&v| self.is_virtual(v)) {
                continue;
            }
            let ps = vs.map(|v| self.vert[v.index()].pos);
            let n = area_normal(ps[0], ps[1], ps[2]);
            let twice_area = super::geometry::dot(n, n).sqrt();
            if twice_area == 0.0 {
                continue;
            }
            let unit = n.map(|x| x / twice_area);
            let q = Quadric::plane(unit, ps[0], 0.5 * twice_area);
            for v in vs {
                self.quadric[v.index()].add(&q);
            }
            for c in f.corners() {
                let across = self.tri.vertex(self.tri.opposite(c));
                if !self.is_virtual(across) {
                    continue;
                }
                let [s, t] = self.tri.edge_endpoints(c);
                let (ps_, pt) = (self.vert[s.index()].pos, self.vert[t.index()].pos);
                let m = super::geometry::cross(super::geometry::sub(pt, ps_), unit);
                let len = super::geometry::dot(m, m).sqrt();
                if len == 0.0 {
                    continue;
                }
                let q = Quadric::plane(m.map(|x| x / len), ps_, BOUNDARY_WEIGHT * 0.5 * twice_area);
                self.quadric[s.index()].add(&q);
                self.quadric[t.index()].add(&q);
            }
        }
    }

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
            // Two threads decide a naive pass when allowed and the pass is large
            // enough; otherwise the sequential pass (the same decisions either way).
            let contracted = if self.nested_phase
                || self.workers < 2
                || self.tri.face_capacity() < PARALLEL_MIN
            {
                self.pass(observer)
            } else {
                self.pass_decided(observer)
            };
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

    /// One naive pass, decided on the pass-start state (on two threads when allowed
    /// and the pass is large enough), then applied in the sequential order: the same
    /// contractions, the same counts and the same state as deciding and applying face
    /// by face (see the module documentation). Returns the number of contractions.
    fn pass_decided(&mut self, observer: &mut dyn FnMut(Progress)) -> usize {
        self.pass += 1;
        let nf = self.tri.face_capacity();
        let slots = nf as u64;
        let two = self.workers >= 2 && nf >= PARALLEL_MIN;
        let m = if two { nf / 2 } else { nf };
        observer(Progress::new(SCANNED, 0, slots));
        let mut throttle = Throttle::new();
        let mut progress = |fi: usize| {
            if throttle.due(fi as u64) {
                observer(Progress::new(SCANNED, fi as u64, slots));
            }
        };
        self.sweep_a.reset();
        self.sweep_b.reset();
        let v = view!(self);
        let (a, b) = (&mut self.sweep_a, &mut self.sweep_b);
        let t0 = std::time::Instant::now();
        let adopt = if two {
            std::thread::scope(|scope| {
                let spec = scope.spawn(|| speculate(&v, b, m, nf));
                sweep_range(&v, 0, a, 0, m, &mut Role::Exact, &mut progress);
                if let Err(panic) = spec.join() {
                    std::panic::resume_unwind(panic);
                }
            });
            TA.fetch_add(t0.elapsed().as_micros() as usize, Relaxed);
            let t1 = std::time::Instant::now();
            let r = repair(&v, a, b, m, nf, &mut progress);
            TR.fetch_add(t1.elapsed().as_micros() as usize, Relaxed);
            r
        } else {
            sweep_range(&v, 0, a, 0, nf, &mut Role::Exact, &mut progress);
            TA.fetch_add(t0.elapsed().as_micros() as usize, Relaxed);
            None
        };
        let t2 = std::time::Instant::now();
        observer(Progress::new(SCANNED, slots, slots));
        let a = std::mem::take(&mut self.sweep_a);
        let b = std::mem::take(&mut self.sweep_b);
        self.run.skipped.add(&a.counts);
        for w in &a.wins {
            self.apply_win(w, &a);
        }
        let mut contracted = a.wins.len();
        if let Some(from) = adopt {
            for w in &b.wins[from..] {
                self.apply_win(w, &b);
            }
            contracted += b.wins.len() - from;
        }
        self.sweep_a = a;
        self.sweep_b = b;
        TP.fetch_add(t2.elapsed().as_micros() as usize, Relaxed);
        contracted
    }

    /// Contracts a decided edge (the vertices were frozen while deciding) with the star
    /// its sweep walked, keeping the smaller id, and moves the kept vertex.
    fn apply_win(&mut self, w: &Win, sw: &Sweep) {
        let (keep, gone) = if w.p < w.q { (w.p, w.q) } else { (w.q, w.p) };
        let (c0, v0) = (w.at_c as usize, w.at_v as usize);
        let (dq, dp) = (w.dq as usize, w.dp as usize);
        let (star, link) = if gone == w.q {
            (&sw.corners[c0..c0 + dq], &sw.verts[v0..v0 + dq])
        } else {
            (
                &sw.corners[c0 + dq..c0 + dq + dp],
                &sw.verts[v0 + dq..v0 + dq + dp],
            )
        };
        self.tri
            .collapse_walked(keep, gone, star, link, &mut self.scratch);
        self.vert[keep.index()].pos = w.position;
        if !self.quadric.is_empty() {
            let g = self.quadric[gone.index()];
            self.quadric[keep.index()].add(&g);
        }
    }

    /// One pass, deciding and applying face by face (the nested passes); returns the
    /// number of contractions.
    fn pass(&mut self, observer: &mut dyn FnMut(Progress)) -> usize {
        self.pass += 1;
        let mut contracted = 0;
        let nf = self.tri.face_capacity();
        let slots = nf as u64;
        observer(Progress::new(SCANNED, 0, slots));
        let mut throttle = Throttle::new();
        let mut from = 0;
        let mut dead = BinaryHeap::new();
        loop {
            let (fi, frozen) = next_candidate(&view!(self), 0, from, nf, &mut dead, &mut []);
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
                if self.touched[0][p.index()].load(Relaxed) == self.pass
                    || self.touched[0][q.index()].load(Relaxed) == self.pass
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

    /// Decides what to do with the edge opposite `c`, changing nothing but scratch.
    pub(super) fn plan(&mut self, c: Corner) -> Result<(EdgeInfo, Plan), Skip> {
        let info = self.sweep_a.walk.examine(&view!(self), c)?;
        std::mem::swap(&mut self.xs, &mut self.sweep_a.walk.xs);
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
        let position = view!(self).position(&info);
        if self.opts.guard
            && !self.sweep_a.walk.guard(
                &view!(self),
                &info,
                position,
                removed.map(|s| (&self.fmark[..], s)),
            )
        {
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

    /// Carries out a plan: replaces the discs, contracts the edge keeping the smaller
    /// id, moves the kept vertex and freezes its neighbours for the rest of the pass.
    fn apply(&mut self, e: &EdgeInfo, plan: &Plan) {
        // Freeze first: every neighbour of the merged vertex was a neighbour of p or q
        // (removing a disc and contracting add no adjacency), so marking p, q and the
        // links `examine` listed (every vertex of a face around p or q) freezes them
        // without walking the new star.
        let pass = self.pass;
        let walk = &self.sweep_a.walk;
        for &w in walk.nbr_q.iter().chain(&walk.nbr_p).chain(&[e.p, e.q]) {
            self.touched[0][w.index()].store(pass, Relaxed);
        }
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
            let walk = &self.sweep_a.walk;
            let dq = walk.nbr_q.len();
            let (star, link) = if gone == e.q {
                (&walk.star_pq[..dq], &walk.nbr_q[..])
            } else {
                (&walk.star_pq[dq..], &walk.nbr_p[..])
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
        // Stamps of earlier passes never match a later pass: cut, not carried along.
        for t in &mut self.touched {
            t.truncate(k);
        }
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
        self.run.shortest = shortest.is_finite().then(|| shortest.sqrt());
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
        let points = self.vert[..first as usize].iter().map(|v| v.pos).collect();
        (faces, points)
    }
}

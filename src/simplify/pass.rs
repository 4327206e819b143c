//! The pass machinery shared by both modes: the state of one component, the pass loop,
//! the common-neighbour walk, the position and guard decisions, applying a plan, and the
//! per-pass compaction.
//!
//! **A second thread plans ahead, with the sequential pass's output.** Within a pass, a
//! contraction of `[p', q']` changes only the faces containing `p'` or `q'` (renamed
//! corners, the two removed faces, and the re-glued `opposite` entries, which lie in
//! faces across an edge at `p'` or `q'`), the degree and stored corner of `p'`, `q'` and
//! of the edge's two opposite vertices, and the position and quadric of the kept
//! vertex; and it freezes every vertex of every face around `p'` or `q'`, which covers
//! all of them. So a vertex still unfrozen has its pass-start star (the same faces,
//! `opposite` entries, degree and stored corner, hence the same walk in the same order),
//! and every neighbour of it has its pass-start position (a moved vertex is a kept one,
//! all of whose neighbours are frozen). The naive plan of an edge whose endpoints are
//! both unfrozen — [`Walk::examine`] (both stars, the degree of `q`, cone apexes), the
//! tetrahedron test (both degrees), the position (positions and quadrics of the
//! endpoints) and the guard (positions of the endpoints and their neighbours) — hence
//! reads exactly the pass-start state: it is a function of that state alone, whoever
//! computes it and whenever in the pass. Nor are moved positions read within their pass
//! at all (a face with a kept vertex has three frozen vertices and is not visited).
//!
//! A large naive pass therefore splits its face slots at `m`: the calling thread runs
//! the pass as before over `[0, m)`, contracting as it goes, while a helper thread
//! sweeps `[m, F)` on a copy of the pass-start corner table as if nothing before `m`
//! had frozen anything (its own freeze stamps; the two faces of each edge it would
//! contract skipped uncounted, as removed faces are), planning the edges it meets and
//! recording every plan with the stars it walked. The calling thread defers writing
//! positions and quadrics while the helper reads them, then runs the pass on over
//! `[m, F)` exactly as before, except that an edge the helper planned takes the
//! helper's plan instead of planning it again. The helper's guesses about freezing only
//! decide which plans it records, never what the calling thread does with them, so the
//! output, the statistics and every skip count are those of the sequential pass, for
//! any thread count (tested; `simplify_fingerprint --threads`).
//!
//! The nested passes (after the naive fixed point) stay on one thread: a nested plan
//! grows regions that can reach far from the edge, into faces changed earlier in the
//! pass.

use std::cmp::Reverse;
use std::collections::BinaryHeap;
use std::sync::atomic::{AtomicU32, Ordering::Relaxed};
use std::sync::Arc;

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

/// Face slots below which a pass runs on one thread (a thread and the copy of the
/// corner table cost more than they save).
const PARALLEL_MIN: usize = 4096;

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

/// A vertex's position and the pass in which it was replaced or frozen (see
/// `Simplifier::vert`). The stamp is atomic only so that the calling thread can freeze
/// while the helper thread reads positions; relaxed loads and stores are plain moves.
#[derive(Debug)]
pub(super) struct Vertex {
    pub(super) pos: Point,
    touched: AtomicU32,
}

impl Vertex {
    fn new(pos: Point) -> Self {
        Vertex {
            pos,
            touched: AtomicU32::new(0),
        }
    }

    #[inline]
    fn frozen(&self, pass: u32) -> bool {
        self.touched.load(Relaxed) == pass
    }

    #[inline]
    fn freeze(&self, pass: u32) {
        self.touched.store(pass, Relaxed);
    }
}

impl Clone for Vertex {
    fn clone(&self) -> Self {
        Vertex {
            pos: self.pos,
            touched: AtomicU32::new(self.touched.load(Relaxed)),
        }
    }
}

/// The read-only pass-start state the helper thread plans on: its own copy of the
/// corner table, and the positions and quadrics, which the calling thread does not
/// write while the helper runs (see `Simplifier::set_moved`).
#[derive(Copy, Clone)]
struct View<'a> {
    tri: &'a Triangulation,
    vert: &'a [Vertex],
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
            quadric: &$s.quadric,
            first_virtual: $s.first_virtual,
            opts: $s.opts,
            eps2: $s.eps2,
            pass: $s.pass,
        }
    };
}

impl View<'_> {
    #[inline]
    fn is_virtual(&self, v: VertexId) -> bool {
        v.0 >= self.first_virtual
    }

    #[inline]
    fn pos(&self, v: VertexId) -> Point {
        self.vert[v.index()].pos
    }

    /// [`Simplifier::position`] on this state.
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
    fn guard(&self, v: &View<'_>, e: &EdgeInfo, to: Point, removed: Option<(&[u32], u32)>) -> bool {
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

/// A plan the helper thread made: the edge, the new position, and where the stars it
/// walked are kept in its `corners` / `verts`.
#[derive(Copy, Clone, Debug)]
struct Win {
    info: EdgeInfo,
    position: Point,
    /// `corners[at_c..]`: `star_pq` (`dq + dp` corners); `verts[at_v..]`: `nbr_q` (`dq`)
    /// then `nbr_p` (`dp`).
    at_c: u32,
    at_v: u32,
    dq: u32,
    dp: u32,
}

/// A plan the helper thread computed, in sweep order: face, slot of the corner opposite
/// the edge, and the index of its `Win` or the reason it was refused.
#[derive(Copy, Clone, Debug)]
struct Tried {
    face: u32,
    slot: u32,
    outcome: Result<u32, Skip>,
}

/// The helper thread's state (reused from pass to pass).
#[derive(Default)]
struct Helper {
    walk: Walk,
    /// Its copy of the pass-start corner table.
    tri: Option<Triangulation>,
    /// Its freeze stamps, per vertex (the pass that froze it).
    frozen: Vec<u32>,
    /// Faces its successes removed that its sweep has not reached yet.
    dead: BinaryHeap<Reverse<u32>>,
    wins: Vec<Win>,
    corners: Vec<Corner>,
    verts: Vec<VertexId>,
    tried: Vec<Tried>,
}

impl Helper {
    /// The outcome of the helper's plan of the edge opposite slot `s` of face `fi`, if it
    /// made one. `cursor` (the first record not behind the face) only moves forward, as
    /// the faces asked about do.
    fn lookup(&self, cursor: &mut usize, fi: usize, s: u32) -> Option<Result<u32, Skip>> {
        let tried = &self.tried;
        while *cursor < tried.len() && (tried[*cursor].face as usize) < fi {
            *cursor += 1;
        }
        tried[*cursor..]
            .iter()
            .take_while(|t| t.face as usize == fi)
            .find(|t| t.slot == s)
            .map(|t| t.outcome)
    }

    /// Sweeps `[m, nf)` of its copy as the pass would with nothing frozen at `m`,
    /// recording every plan. O(faces swept + the plans' stars).
    fn sweep(&mut self, v: &View<'_>, m: usize, nf: usize) {
        self.wins.clear();
        self.corners.clear();
        self.verts.clear();
        self.tried.clear();
        self.dead.clear();
        if self.frozen.len() < v.tri.vertex_capacity() {
            self.frozen.resize(v.tri.vertex_capacity(), 0);
        }
        let mut from = m;
        while let Some(fi) = self.next_candidate(v, from, nf) {
            from = fi + 1;
            self.visit(v, fi);
        }
    }

    /// The pass's `next_candidate` on the helper's state: the first face slot from
    /// `from` on (below `to`) with at most one frozen vertex, not removed, not a cone
    /// face, not removed by the helper's own successes.
    fn next_candidate(&mut self, v: &View<'_>, from: usize, to: usize) -> Option<usize> {
        let (pass, first_virtual) = (v.pass, v.first_virtual);
        let frozen = &self.frozen;
        let dead = &mut self.dead;
        let mut next_dead = dead.peek().map_or(usize::MAX, |d| d.0 as usize);
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
            if a >= first_virtual || b >= first_virtual || c >= first_virtual {
                continue;
            }
            let f = |x: u32| u32::from(frozen[x as usize] == pass);
            if f(a) + f(b) + f(c) < 2 {
                return Some(fi);
            }
        }
        None
    }

    /// The pass's visit of face `fi` on the helper's state, recording each plan.
    fn visit(&mut self, v: &View<'_>, fi: usize) {
        let f = FaceId(fi as u32);
        let vs = v.tri.face_vertices(f);
        let ps = [v.pos(vs[0]), v.pos(vs[1]), v.pos(vs[2])];
        for s in short_edges_in_order(ps, v.eps2) {
            let c = f.corner(s);
            let [p, q] = v.tri.edge_endpoints(c);
            if self.frozen[p.index()] == v.pass || self.frozen[q.index()] == v.pass {
                continue;
            }
            let outcome = match self.walk.plan_naive(v, c) {
                Ok((info, position)) => {
                    let w = &self.walk;
                    for &n in w.nbr_q.iter().chain(&w.nbr_p).chain(&[p, q]) {
                        self.frozen[n.index()] = v.pass;
                    }
                    self.wins.push(Win {
                        info,
                        position,
                        at_c: self.corners.len() as u32,
                        at_v: self.verts.len() as u32,
                        dq: w.nbr_q.len() as u32,
                        dp: w.nbr_p.len() as u32,
                    });
                    self.corners.extend_from_slice(&w.star_pq);
                    self.verts.extend_from_slice(&w.nbr_q);
                    self.verts.extend_from_slice(&w.nbr_p);
                    let other = v.tri.opposite(c).face().0;
                    if other as usize > fi {
                        self.dead.push(Reverse(other));
                    }
                    Ok(self.wins.len() as u32 - 1)
                }
                Err(k) => Err(k),
            };
            self.tried.push(Tried {
                face: fi as u32,
                slot: s,
                outcome,
            });
            if outcome.is_ok() {
                break;
            }
        }
    }
}

/// The slots whose opposite edges are shorter than ε (`l2` of the corners' positions
/// `ps` against `eps2`), shortest first, ties by slot: the order in which a visit tries
/// a face's edges. (Edge opposite slot s joins slots s+1 and s+2; a three-element
/// sorting network.)
#[inline(always)]
fn short_edges_in_order(ps: [Point; 3], eps2: f64) -> impl Iterator<Item = u32> {
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
    order.into_iter().take_while(move |&s| l[s as usize] < eps2)
}

/// Copies the arrays of `src` into `dst`, reusing `dst`'s allocations.
fn copy_tri(dst: &mut Option<Triangulation>, src: &Triangulation) {
    match dst {
        Some(d) => {
            d.corner_vertex.clone_from(&src.corner_vertex);
            d.opposite.clone_from(&src.opposite);
            d.vertex_corner.clone_from(&src.vertex_corner);
            d.degree.clone_from(&src.degree);
            d.live_vertices = src.live_vertices;
            d.live_faces = src.live_faces;
        }
        None => *dst = Some(src.clone()),
    }
}

/// One component being simplified.
pub(crate) struct Simplifier<'o> {
    pub(super) tri: Triangulation,
    /// Per vertex: position and the pass that froze it, side by side, so that the
    /// freezing test of a visit and the position loads that follow it (and the guard's
    /// position loads and the freeze after it) share cache lines. Shared with the helper
    /// thread during a pass (see `set_moved`).
    pub(super) vert: Arc<Vec<Vertex>>,
    /// Per vertex, for [`Position::Quadric`] only (empty otherwise).
    pub(super) quadric: Arc<Vec<Quadric>>,
    /// Positions and quadric sums (kept, gone) of contractions made while the helper
    /// thread reads the positions, written when it has finished.
    moved: Vec<(VertexId, Point)>,
    moved_quadric: Vec<(VertexId, VertexId)>,
    /// Vertex ids from here on are virtual (cone apexes); they stay last through
    /// compaction since they are never removed.
    pub(super) first_virtual: u32,
    loops: usize,
    pub(super) opts: &'o Options,
    pub(super) eps2: f64,
    pub(super) pass: u32,
    /// Threads a naive pass may use (1 or 2).
    workers: usize,
    /// Scratch marks of the nested mode (compared with `stamp`).
    pub(super) vmark: Vec<u32>,
    pub(super) fmark: Vec<u32>,
    stamp: u32,
    scratch: Vec<Corner>,
    /// The common-neighbour walk of this thread.
    walk: Walk,
    /// The helper thread's state, between passes.
    helper: Helper,
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
        let vert = Arc::new(vert);
        let surface = spec::ENABLED.then(|| SurfaceType::of(&tri));
        let mut s = Simplifier {
            tri,
            vert,
            quadric: Arc::new(Vec::new()),
            moved: Vec::new(),
            moved_quadric: Vec::new(),
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
            walk: Walk::default(),
            helper: Helper::default(),
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
        let mut quadric = vec![Quadric::default(); self.tri.vertex_capacity()];
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
                quadric[v.index()].add(&q);
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
                quadric[s.index()].add(&q);
                quadric[t.index()].add(&q);
            }
        }
        self.quadric = Arc::new(quadric);
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

    /// One pass; returns the number of contractions. A naive pass of at least
    /// `PARALLEL_MIN` face slots, with two workers allowed, has the helper thread plan
    /// the second half ahead (module documentation); the result is the same.
    fn pass(&mut self, observer: &mut dyn FnMut(Progress)) -> usize {
        self.pass += 1;
        let nf = self.tri.face_capacity();
        let slots = nf as u64;
        observer(Progress::new(SCANNED, 0, slots));
        let mut throttle = Throttle::new();
        let mut progress = |fi: usize| {
            if throttle.due(fi as u64) {
                observer(Progress::new(SCANNED, fi as u64, slots));
            }
        };
        let helped = !self.nested_phase && self.workers >= 2 && nf >= PARALLEL_MIN;
        let contracted = if helped {
            let m = nf / 2;
            let mut helper = std::mem::take(&mut self.helper);
            copy_tri(&mut helper.tri, &self.tri);
            let (vert, quadric) = (Arc::clone(&self.vert), Arc::clone(&self.quadric));
            let opts = *self.opts;
            let (first_virtual, eps2, pass) = (self.first_virtual, self.eps2, self.pass);
            let (first, joined) = std::thread::scope(|scope| {
                let job = scope.spawn(move || {
                    if let Some(tri) = helper.tri.take() {
                        let v = View {
                            tri: &tri,
                            vert: &vert,
                            quadric: &quadric,
                            first_virtual,
                            opts: &opts,
                            eps2,
                            pass,
                        };
                        helper.sweep(&v, m, nf);
                        helper.tri = Some(tri);
                    }
                    // Released here, so that the positions can be written again.
                    drop((vert, quadric));
                    helper
                });
                let first = self.sweep(0, m, None, &mut progress);
                (first, job.join())
            });
            let helper = joined.unwrap_or_else(|panic| std::panic::resume_unwind(panic));
            self.flush_moved();
            let second = self.sweep(m, nf, Some(&helper), &mut progress);
            self.helper = helper;
            first + second
        } else {
            self.sweep(0, nf, None, &mut progress)
        };
        observer(Progress::new(SCANNED, slots, slots));
        contracted
    }

    /// The pass over face slots `[from, to)`: each face's edges shorter than ε,
    /// shortest first, skipping those with a frozen endpoint; the first edge it can
    /// process is processed. An edge `helper` planned takes its plan. Returns the
    /// number of contractions.
    fn sweep(
        &mut self,
        from: usize,
        to: usize,
        helper: Option<&Helper>,
        progress: &mut dyn FnMut(usize),
    ) -> usize {
        let mut contracted = 0;
        let mut from = from;
        let mut cursor = 0;
        loop {
            let (fi, frozen) = self.next_candidate(from, to);
            self.run.skipped.frozen += frozen;
            if fi >= to {
                break;
            }
            from = fi + 1;
            progress(fi);
            let f = FaceId(fi as u32);
            let vs = self.tri.face_vertices(f);
            let vert = &self.vert[..];
            let ps = [
                vert[vs[0].index()].pos,
                vert[vs[1].index()].pos,
                vert[vs[2].index()].pos,
            ];
            for s in short_edges_in_order(ps, self.eps2) {
                let c = f.corner(s);
                let [p, q] = self.tri.edge_endpoints(c);
                let vert = &self.vert[..];
                if vert[p.index()].frozen(self.pass) || vert[q.index()].frozen(self.pass) {
                    self.run.skipped.frozen += 1;
                    continue;
                }
                let made = helper.and_then(|h| Some((h, h.lookup(&mut cursor, fi, s)?)));
                let planned = match made {
                    Some((h, Ok(i))) => Ok(self.take_plan(h, i as usize)),
                    Some((_, Err(skip))) => Err(skip),
                    None => self.plan(c),
                };
                match planned {
                    Ok((info, plan)) => {
                        self.apply(&info, &plan);
                        contracted += 1;
                        break;
                    }
                    Err(skip) => self.run.skipped.count(skip),
                }
            }
        }
        contracted
    }

    /// The first face slot in `[from, to)` whose visit gets as far as reading
    /// positions, and the number of visits before it deferred as frozen; `to` if none.
    /// Skipped: removed faces, cone faces (a virtual vertex) and faces with two or more
    /// vertices frozen in this pass (every edge has a frozen endpoint; most visits of a
    /// pass end here, so they are skipped in a loop that changes nothing).
    fn next_candidate(&self, from: usize, to: usize) -> (usize, usize) {
        let pass = self.pass;
        let first_virtual = self.first_virtual;
        let vert = &self.vert[..];
        let frozen = |v: u32| u32::from(vert[v as usize].frozen(pass));
        let mut deferred = 0;
        let slots = self.tri.corner_vertex.get(3 * from..3 * to).unwrap_or(&[]);
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
        (to, deferred)
    }

    /// The helper's plan `i` as `plan` would return it, with its walked stars put where
    /// `examine` leaves them for `apply`.
    fn take_plan(&mut self, h: &Helper, i: usize) -> (EdgeInfo, Plan) {
        let w = &h.wins[i];
        let (c0, v0) = (w.at_c as usize, w.at_v as usize);
        let (dq, d) = (w.dq as usize, (w.dq + w.dp) as usize);
        let walk = &mut self.walk;
        walk.star_pq.clear();
        walk.star_pq.extend_from_slice(&h.corners[c0..c0 + d]);
        walk.nbr_q.clear();
        walk.nbr_q.extend_from_slice(&h.verts[v0..v0 + dq]);
        walk.nbr_p.clear();
        walk.nbr_p.extend_from_slice(&h.verts[v0 + dq..v0 + d]);
        (
            w.info,
            Plan {
                discs: [None, None],
                position: w.position,
            },
        )
    }

    /// Moves `keep` to `to` and adds `gone`'s quadric to it, now, or when the helper
    /// thread has stopped reading them (`flush_moved`): a moved vertex is frozen, and
    /// nothing reads a frozen vertex's position or quadric for the rest of its pass.
    fn set_moved(&mut self, keep: VertexId, gone: VertexId, to: Point) {
        match Arc::get_mut(&mut self.vert) {
            Some(vert) => vert[keep.index()].pos = to,
            None => self.moved.push((keep, to)),
        }
        if !self.quadric.is_empty() {
            match Arc::get_mut(&mut self.quadric) {
                Some(quadric) => {
                    let g = quadric[gone.index()];
                    quadric[keep.index()].add(&g);
                }
                None => self.moved_quadric.push((keep, gone)),
            }
        }
    }

    /// Writes what `set_moved` deferred.
    fn flush_moved(&mut self) {
        if !self.moved.is_empty() {
            let vert = Arc::make_mut(&mut self.vert);
            for (keep, to) in self.moved.drain(..) {
                vert[keep.index()].pos = to;
            }
        }
        if !self.moved_quadric.is_empty() {
            let quadric = Arc::make_mut(&mut self.quadric);
            for (keep, gone) in self.moved_quadric.drain(..) {
                let g = quadric[gone.index()];
                quadric[keep.index()].add(&g);
            }
        }
    }

    /// Decides what to do with the edge opposite `c`, changing nothing but scratch.
    pub(super) fn plan(&mut self, c: Corner) -> Result<(EdgeInfo, Plan), Skip> {
        let info = self.walk.examine(&view!(self), c)?;
        std::mem::swap(&mut self.xs, &mut self.walk.xs);
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
            && !self.walk.guard(
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
        let walk = &self.walk;
        for &w in walk.nbr_q.iter().chain(&walk.nbr_p).chain(&[e.p, e.q]) {
            self.vert[w.index()].freeze(pass);
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
            let walk = &self.walk;
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
        self.set_moved(keep, gone, plan.position);
    }

    /// Renumbers vertices and faces densely and carries the per-vertex data along.
    fn compact(&mut self) {
        let map = self.tri.compact_ids();
        // Not shared between passes: no copy is made.
        let vert = Arc::make_mut(&mut self.vert);
        let quadric = Arc::make_mut(&mut self.quadric);
        let mut k = 0;
        for (old, &new) in map.iter().enumerate() {
            if new != crate::core::ids::NONE {
                debug_assert_eq!(new as usize, k);
                vert.swap(k, old);
                if !quadric.is_empty() {
                    quadric[k] = quadric[old];
                }
                k += 1;
            }
        }
        vert.truncate(k);
        vert.shrink_to_fit();
        if !quadric.is_empty() {
            quadric.truncate(k);
            quadric.shrink_to_fit();
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

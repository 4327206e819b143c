//! The Ramaswami–Siqueira algorithm (RS paper, Sec. 4, Algorithms 4.1–4.7).
//!
//! **Guarantee.** The output is irreducible (no edge passes the link condition), has the
//! input's surface (every contraction passes the link condition), and keeps the input's
//! vertex ids. Each edge is tested against the link condition at most once per processed
//! vertex, and in fact at most once overall (ε = 0, checked in the tests).
//!
//! **Complexity.** O(g² + g·n) time, Θ(n) space (Sec. 4.7); for genus 0 every
//! contraction happens while the first vertex is processed (Sec. 4.6).
//!
//! **How.** Vertices are processed in id order (the queue Q of Alg. 4.1). Processing `u`
//! contracts edges `[u, v]` (identifying `v` with `u`) until `u` is trapped. Candidate
//! edges are named by their other endpoint and kept in two intrusive doubly-linked lists
//! over vertex ids: `lue` (untested; degree-3 endpoints first, Prop. 8(2)) and `lte`
//! (tested and failed; counters `c = 0` first, Prop. 10). The counter `c(w)` of an
//! edge `[u, w]` in `lte` is kept equal to its number of critical cycles (Prop. 11) by
//! the time stamps `o` and `t`, so an edge that becomes contractible again is found
//! without a second link test (Prop. 7).
//!
//! Departures from the printed pseudo-code (all recorded with evidence in
//! `spec/ERRATA.md`): Alg. 4.3 l.13 uses `t(x) >= o(y)`; l.22 means `lte`; Alg. 4.2 resets
//! `c(v)` of the initial neighbours; and the processing of `u` ends only when `lue` is
//! empty *and* the front of `lte` is not contractible (the printed `until lue = ∅` can
//! stop with a contractible edge left in `lte`).

use std::fmt;
use std::time::Instant;

use super::{finish, start_stats, Algorithm, Options, Reduction, RetestCounter};
use crate::core::{Corner, EdgeIds, History, Triangulation, VertexId};
use crate::progress::{self, Progress, Throttle};

/// The stage RS reports progress in.
const SETTLED: &str = "vertices settled";

mod spec;

/// "nil" in the link arrays of [`Lists`]: never a vertex id (the core reserves
/// `u32::MAX`, see [`crate::core::MAX_VERTICES`]).
const NIL: u32 = u32::MAX;

const LUE: usize = 0;
const LTE: usize = 1;

/// A value of the global time stamp `ts` of Sec. 4.3: how many contractions RS has made.
/// Always below `u32::MAX` (there are fewer contractions than vertices, and the core
/// reserves `u32::MAX`), which [`Stamp`] uses for the paper's −1.
#[derive(Copy, Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Time(u32);

impl Time {
    const START: Time = Time(0);

    /// The time stamp after one more contraction.
    #[inline]
    fn next(self) -> Time {
        Time(self.0 + 1)
    }
}

impl fmt::Display for Time {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.0)
    }
}

/// A time stamp `o(v)` or `t(v)` of Table 1: a [`Time`], or unset (the paper's −1). Four
/// bytes, like the raw `u32` it replaces, so the per-vertex arrays stay flat: unset is
/// stored as `u32::MAX`, which no [`Time`] reaches.
#[derive(Copy, Clone, PartialEq, Eq)]
struct Stamp(u32);

impl Stamp {
    /// −1 of the paper.
    const UNSET: Stamp = Stamp(u32::MAX);

    /// The stamp holding `time`.
    #[inline]
    fn at(time: Time) -> Stamp {
        Stamp(time.0)
    }

    /// The time held, or `None` for −1.
    #[inline]
    fn get(self) -> Option<Time> {
        self.is_set().then_some(Time(self.0))
    }

    /// Whether the stamp holds a time (is not −1).
    #[inline]
    fn is_set(self) -> bool {
        self != Stamp::UNSET
    }

    /// Whether the stamp is set and earlier than `time`. One comparison: unset is stored
    /// above every [`Time`].
    #[inline]
    fn is_before(self, time: Time) -> bool {
        self.0 < time.0
    }
}

/// Shows −1 for an unset stamp, as the paper writes it.
impl fmt::Display for Stamp {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self.get() {
            Some(t) => write!(f, "{t}"),
            None => write!(f, "-1"),
        }
    }
}

/// `n(v)` of Table 1: the vertex `v` was last found to be a neighbour of, or nil. Four
/// bytes (nil is [`NIL`], never a vertex id) so the per-vertex array stays flat; the
/// algorithm only ever asks whether it is the vertex being processed.
#[derive(Copy, Clone, PartialEq, Eq)]
struct NeighbourOf(u32);

impl NeighbourOf {
    const NIL: NeighbourOf = NeighbourOf(NIL);

    /// `n(v) = u`.
    #[inline]
    fn of(u: VertexId) -> NeighbourOf {
        NeighbourOf(u.0)
    }

    /// Whether `n(v) = u` (never for nil).
    #[inline]
    fn is(self, u: VertexId) -> bool {
        self.0 == u.0
    }
}

/// Two intrusive doubly-linked lists over vertex ids sharing `next`/`prev` arrays; a
/// vertex is in at most one of them (`tag`). All operations O(1). The arrays hold raw ids
/// with [`NIL`] as the end marker; the interface takes and gives [`VertexId`]s.
#[derive(Clone, Debug)]
struct Lists {
    next: Vec<u32>,
    prev: Vec<u32>,
    tag: Vec<u8>,
    head: [u32; 2],
    tail: [u32; 2],
}

impl Lists {
    fn new(n: usize) -> Self {
        Lists {
            next: vec![NIL; n],
            prev: vec![NIL; n],
            tag: vec![0; n],
            head: [NIL; 2],
            tail: [NIL; 2],
        }
    }
    #[inline]
    fn contains(&self, l: usize, z: VertexId) -> bool {
        self.tag[z.index()] == l as u8 + 1
    }
    #[inline]
    fn front(&self, l: usize) -> Option<VertexId> {
        (self.head[l] != NIL).then_some(VertexId(self.head[l]))
    }
    #[inline]
    fn is_empty(&self, l: usize) -> bool {
        self.head[l] == NIL
    }
    #[inline]
    fn push_front(&mut self, l: usize, z: VertexId) {
        let (z, zi) = (z.0, z.index());
        debug_assert_eq!(self.tag[zi], 0);
        let h = self.head[l];
        self.next[zi] = h;
        self.prev[zi] = NIL;
        if h == NIL {
            self.tail[l] = z;
        } else {
            self.prev[h as usize] = z;
        }
        self.head[l] = z;
        self.tag[zi] = l as u8 + 1;
    }
    #[inline]
    fn push_back(&mut self, l: usize, z: VertexId) {
        let (z, zi) = (z.0, z.index());
        debug_assert_eq!(self.tag[zi], 0);
        let t = self.tail[l];
        self.prev[zi] = t;
        self.next[zi] = NIL;
        if t == NIL {
            self.head[l] = z;
        } else {
            self.next[t as usize] = z;
        }
        self.tail[l] = z;
        self.tag[zi] = l as u8 + 1;
    }
    #[inline]
    fn remove(&mut self, z: VertexId) {
        let zi = z.index();
        let l = match self.tag[zi] {
            0 => return,
            k => (k - 1) as usize,
        };
        let (p, n) = (self.prev[zi], self.next[zi]);
        if p == NIL {
            self.head[l] = n;
        } else {
            self.next[p as usize] = n;
        }
        if n == NIL {
            self.tail[l] = p;
        } else {
            self.prev[n as usize] = p;
        }
        self.tag[zi] = 0;
    }
    #[inline]
    fn pop_front(&mut self, l: usize) -> Option<VertexId> {
        let z = self.front(l)?;
        self.remove(z);
        Some(z)
    }
    fn clear(&mut self, l: usize) {
        while self.pop_front(l).is_some() {}
    }
    /// The members of list `l` in order, lazily (for the specification checks, which
    /// look at a bounded prefix: collecting a list of a million entries per check would
    /// make the checks quadratic).
    fn iter(&self, l: usize) -> impl Iterator<Item = VertexId> + '_ {
        let mut z = self.head[l];
        std::iter::from_fn(move || {
            (z != NIL).then(|| {
                let here = z;
                z = self.next[z as usize];
                VertexId(here)
            })
        })
    }
}

crate::spec::mutation_switches! {
/// Deliberate deviations, for tests that show a check or an erratum can fail.
pub struct Variant {
    /// Use the printed `until lue = ∅` loop exit of Alg. 4.2 l.34.
    pub printed_loop_exit: bool,
    /// Use the printed strict `t(x) > o(y)` of Alg. 4.3 l.13 (l.19 is printed `>=`).
    pub printed_strict_stamp: bool,
    /// Skip resetting `c(v)` of the initial neighbours (as printed in Alg. 4.2).
    pub printed_no_counter_reset: bool,
    /// Skip the counter decrements of Alg. 4.3 (a mutation that must be caught).
    pub skip_degree3_decrement: bool,
    /// Mutation: Alg. 4.4 also counts the two link vertices of `[u, v]` as critical
    /// (the classic off-by-two of forgetting that `x, y` bound faces).
    pub count_link_vertices: bool,
    /// Mutation: take the degree-3 path of Alg. 4.3 for degree-4 endpoints too.
    pub degree3_path_up_to_4: bool,
    /// Mutation: Alg. 4.5 marks the link vertex `x` as processed with `v`.
    pub mark_link_vertex_processed: bool,
    /// Mutation: end the processing of `u` after one pass over `lue` (never revisit
    /// `lte`, whose counters may have dropped to 0).
    pub single_pass: bool,
    /// Mutation: an edge whose counter leaves 0 stays where it is in `lte`.
    pub no_move_on_increment: bool,
}
}

/// The state of Alg. 4.2: the triangulation K, the stack S, the vertex attributes of
/// Table 1 (`d` is the core's degree) and the two lists. The fields are private to this
/// module; the checks of [`spec`] read them as its child module.
struct Rs {
    tri: Triangulation,
    history: History,
    /// Whether `history` keeps its records ([`Options::keep_history`]).
    keep_history: bool,
    /// Contractions so far (the history's length when it keeps its records).
    contractions: u64,
    /// p: processed (or removed).
    processed: Vec<bool>,
    /// n: the vertex whose neighbour this vertex was last found to be.
    nbr: Vec<NeighbourOf>,
    /// c: critical cycles through `[u, v]` (exact for edges in `lte` at Alg. 4.2 l.32).
    count: Vec<u32>,
    /// o: when v became a neighbour of u.
    o: Vec<Stamp>,
    /// t: when `[u, v]` left `lue`.
    t: Vec<Stamp>,
    lists: Lists,
    /// ts: the global time stamp, incremented by each contraction.
    ts: Time,
    link_tests: u64,
    counter: RetestCounter,
    variant: Variant,
    /// The vertex being processed (none before the first) and how many were processed.
    current: Option<VertexId>,
    processed_count: u64,
    /// Contractions made while processing the first processed vertex.
    contractions_first_vertex: u64,
    scratch: Vec<VertexId>,
    /// The corners of the star whose link is in `scratch` (filled by `link_around`),
    /// so that a contraction does not walk `v`'s star a second time.
    scratch_star: Vec<Corner>,
    scratch2: Vec<VertexId>,
    /// Edge numbers kept through every contraction for the caller
    /// ([`reduce_numbered`]).
    follow: Option<EdgeIds>,
}

/// Runs RS on `tri`. See the module documentation.
pub fn reduce(tri: Triangulation, options: &Options) -> Reduction {
    reduce_observed(tri, options, &mut progress::ignore)
}

/// [`reduce`], reporting the vertices settled (processed until trapped, or contracted
/// away) out of the input's vertices to `observer` at most every
/// [`progress::REPORT_EVERY`] settled vertices or link tests (genus 0 makes every
/// contraction while the first vertex is processed, so the count moves inside that
/// vertex too). Same result as [`reduce`].
pub fn reduce_observed(
    tri: Triangulation,
    options: &Options,
    observer: &mut dyn FnMut(Progress),
) -> Reduction {
    reduce_variant_observed(tri, options, Variant::SPECIFIED, observer, None).0
}

/// [`reduce`], also keeping `numbers` (edge numbers of `tri`, e.g. [`EdgeIds::new`]) in
/// step with every contraction, as [`EdgeIds::contracted`] would if fed the history
/// afterwards, but while each record's corners are still in cache. Same reduction as
/// [`reduce`]; returns the numbers of the reduced triangulation.
pub fn reduce_numbered(
    tri: Triangulation,
    options: &Options,
    numbers: EdgeIds,
) -> (Reduction, EdgeIds) {
    let (red, _, numbers) = reduce_variant_observed(
        tri,
        options,
        Variant::SPECIFIED,
        &mut progress::ignore,
        Some(numbers),
    );
    (red, numbers.unwrap_or_default())
}

/// RS with a deliberate [`Variant`]; also returns how many contractions happened while
/// the first vertex was processed (Sec. 4.6).
#[cfg(feature = "mutation-tests")]
#[doc(hidden)]
pub fn reduce_variant(tri: Triangulation, options: &Options, variant: Variant) -> (Reduction, u64) {
    let (red, first, _) =
        reduce_variant_observed(tri, options, variant, &mut progress::ignore, None);
    (red, first)
}

fn reduce_variant_observed(
    tri: Triangulation,
    options: &Options,
    variant: Variant,
    observer: &mut dyn FnMut(Progress),
    follow: Option<EdgeIds>,
) -> (Reduction, u64, Option<EdgeIds>) {
    let started = Instant::now();
    let mut stats = start_stats(&tri);
    let total = tri.vertex_count() as u64;
    observer(Progress::new(SETTLED, 0, total));
    let mut rs = Rs::new(tri, options, variant);
    rs.follow = follow;
    rs.run(&mut |done| observer(Progress::new(SETTLED, done, total)));
    observer(Progress::new(SETTLED, total, total));
    stats.link_tests = rs.link_tests;
    stats.edges_tested_more_than_once = rs.counter.more_than_once();
    let first = rs.contractions_first_vertex;
    let follow = rs.follow.take();
    (
        finish(
            Algorithm::Rs,
            rs.tri,
            rs.history,
            rs.contractions,
            stats,
            started,
        ),
        first,
        follow,
    )
}

impl Rs {
    fn new(tri: Triangulation, options: &Options, variant: Variant) -> Self {
        let n = tri.vertex_capacity();
        let live = tri.vertex_count();
        let counter = RetestCounter::new(&tri, options.count_retests);
        Rs {
            // Alg. 4.1: p = false, n = nil, c = 0, o = t = −1 (removed ids count as
            // processed so the queue skips them).
            processed: (0..n).map(|v| !tri.is_vertex(VertexId(v as u32))).collect(),
            nbr: vec![NeighbourOf::NIL; n],
            count: vec![0; n],
            o: vec![Stamp::UNSET; n],
            t: vec![Stamp::UNSET; n],
            lists: Lists::new(n),
            tri,
            // RS contracts all but a few vertices of large meshes: reserving the bound
            // avoids copying hundreds of megabytes of records while the history grows.
            // About four corners are renamed per contraction (mean d_v − 2).
            history: if options.keep_history {
                History::with_capacity(live.saturating_sub(4), 4 * live)
            } else {
                History::new()
            },
            keep_history: options.keep_history,
            contractions: 0,
            ts: Time::START,
            link_tests: 0,
            counter,
            variant,
            current: None,
            processed_count: 0,
            contractions_first_vertex: 0,
            scratch: Vec::new(),
            scratch_star: Vec::new(),
            scratch2: Vec::new(),
            follow: None,
        }
    }

    #[inline]
    fn degree(&self, v: VertexId) -> usize {
        self.tri.degree(v)
    }

    /// Alg. 4.2: the queue Q is the vertex ids in increasing order.
    fn run(&mut self, report: &mut dyn FnMut(u64)) {
        let mut throttle = Throttle::new();
        for u in 0..self.tri.vertex_capacity() as u32 {
            let u = VertexId(u);
            if self.processed[u.index()] {
                continue;
            }
            self.process(u, &mut throttle, report);
        }
        spec::at_end(self);
    }

    /// Vertices settled so far: processed until trapped, or contracted away.
    fn settled(&self) -> u64 {
        self.processed_count + self.contractions
    }

    /// Alg. 4.2 l.6–36: processes `u` until it is trapped.
    fn process(&mut self, u: VertexId, throttle: &mut Throttle, report: &mut dyn FnMut(u64)) {
        self.begin(u);
        loop {
            // l.22–30
            spec::at_line_22(self, crate::spec::FULL_CHECK_DEGREE);
            while let Some(v) = self.lists.pop_front(LUE) {
                // Progress: settled vertices plus link tests, so that a vertex whose
                // tests contract nothing for a while still moves the count's clock.
                if throttle.due(self.settled() + self.link_tests) {
                    report(self.settled());
                }
                spec::leaving_lue(self, v);
                self.t[v.index()] = Stamp::at(self.ts);
                if self.degree(v) == 3
                    || (self.variant.degree3_path_up_to_4() && self.degree(v) == 4)
                {
                    self.degree3(u, v);
                } else {
                    self.test(u, v);
                }
                spec::at_line_22(self, 2);
            }
            // l.31–33 (Prop. 11 holds here).
            spec::at_line_32(self);
            if self.lists.is_empty(LTE) || self.variant.single_pass() {
                break;
            }
            self.process_edge_list(u);
            if self.lists.is_empty(LUE) {
                let more = match self.lists.front(LTE) {
                    Some(v) => self.degree(v) == 3 || self.count[v.index()] == 0,
                    None => false,
                };
                if !more || self.variant.printed_loop_exit() {
                    break;
                }
            }
        }
        self.lists.clear(LTE);
        self.processed[u.index()] = true;
        if self.processed_count == 0 {
            // The history starts empty: all of it was made while processing `u`.
            self.contractions_first_vertex = self.contractions;
        }
        self.processed_count += 1;
        spec::vertex_trapped(self, u);
    }

    /// Alg. 4.2 l.8–19: makes `u` current and puts its unprocessed neighbours in `lue`
    /// (degree 3 first), stamping `o = ts`, `t = −1`, `c = 0` (the reset is erratum E3).
    fn begin(&mut self, u: VertexId) {
        self.current = Some(u);
        let mut link = std::mem::take(&mut self.scratch);
        link.clear();
        link.extend(self.tri.link(u));
        for &v in &link {
            let vi = v.index();
            self.nbr[vi] = NeighbourOf::of(u);
            self.o[vi] = Stamp::at(self.ts);
            self.t[vi] = Stamp::UNSET;
            if !self.variant.printed_no_counter_reset() {
                self.count[vi] = 0;
            }
            if !self.processed[vi] {
                if self.degree(v) == 3 {
                    self.lists.push_front(LUE, v);
                } else {
                    self.lists.push_back(LUE, v);
                }
            }
        }
        self.scratch = link;
    }

    /// Alg. 4.6: contracts degree-3 edges at the front of `lte`, then the front edge if
    /// its counter is 0.
    fn process_edge_list(&mut self, u: VertexId) {
        while let Some(v) = self.lists.front(LTE) {
            if self.degree(v) != 3 {
                break;
            }
            self.lists.remove(v);
            self.degree3(u, v);
        }
        if let Some(v) = self.lists.front(LTE) {
            if self.count[v.index()] == 0 {
                // l.12: c(v) = 0 must still mean "contractible" here, after the counter
                // updates since l.32 (the paper states Prop. 11 at l.32 only).
                spec::at_alg46_line_12(self, u, v);
                self.lists.remove(v);
                self.contract(u, v);
            }
        }
    }

    /// Alg. 4.3: `d(v) = 3`, so `[u, v]` is contractible unless K is T4 (Prop. 6).
    fn degree3(&mut self, u: VertexId, v: VertexId) {
        if self.degree(u) == 3 {
            spec::degree3(self, u, v);
            return; // K is T4: nothing is contractible.
        }
        spec::degree3(self, u, v);
        let [x, y] = self.contract(u, v);
        spec::degree3_untested(self, x, y);
        if self.variant.skip_degree3_decrement() {
            return;
        }
        // The critical cycle lk(v) = (u, x, y) is gone (Prop. 7). c(x) counted it iff
        // [u, x] was tested with y already a neighbour (t(x) >= o(y)) or [u, y] was
        // tested after [u, x] (then both counted it): see spec/ERRATA.md, E1. (o(x) and
        // o(y) are set: x and y are neighbours of u.)
        let counted = |t_a: Time, o_b: Stamp, strict: bool| {
            o_b.get()
                .is_some_and(|o_b| if strict { t_a > o_b } else { t_a >= o_b })
        };
        let strict = self.variant.printed_strict_stamp();
        match (self.t[x.index()].get(), self.t[y.index()].get()) {
            (Some(_), Some(_)) => {
                self.decrement(x);
                self.decrement(y);
            }
            (Some(tx), None) if counted(tx, self.o[y.index()], strict) => self.decrement(x),
            // l.19 is printed with `>=` already; only l.13 is misprinted (E1).
            (None, Some(ty)) if counted(ty, self.o[x.index()], false) => self.decrement(y),
            _ => {}
        }
    }

    /// c(w) ← c(w) − 1 for `[u, w]` in `lte`; a counter reaching 0 moves to the front.
    fn decrement(&mut self, w: VertexId) {
        spec::decrement(self, w);
        let c = &mut self.count[w.index()];
        *c = c.saturating_sub(1);
        if *c == 0 {
            self.lists.remove(w);
            self.lists.push_front(LTE, w);
        }
    }

    /// c(w) ← c(w) + 1 for `[u, w]` in `lte`; a counter leaving 0 moves to the rear.
    fn increment(&mut self, w: VertexId) {
        let c = &mut self.count[w.index()];
        *c += 1;
        if *c == 1 && self.lists.contains(LTE, w) && !self.variant.no_move_on_increment() {
            self.lists.remove(w);
            self.lists.push_back(LTE, w);
        }
    }

    /// Fills `scratch` with lk(v) (and `scratch_star` with the corners of v's star, in
    /// the same walk) and returns the position of `u` in it. O(d_v).
    fn link_around(&mut self, v: VertexId, u: VertexId) -> usize {
        self.scratch.clear();
        self.scratch_star.clear();
        for s in self.tri.star(v) {
            self.scratch.push(s.neighbour);
            self.scratch_star.push(s.corner);
        }
        self.scratch
            .iter()
            .position(|&w| w == u)
            .expect("u is a neighbour of v")
    }

    /// A corner opposite edge `[u, v]`, found from `v`'s side in O(d_v) (`u`'s degree can
    /// be in the millions while it is processed).
    fn edge_corner(&self, u: VertexId, v: VertexId) -> Corner {
        let c = self
            .tri
            .star(v)
            .find(|s| s.neighbour == u)
            .expect("[u, v] is an edge")
            .corner;
        self.tri.corner_facing(c, u)
    }

    /// Alg. 4.4: the link test of `[u, v]` with `d(v) > 3`, counting critical cycles.
    fn test(&mut self, u: VertexId, v: VertexId) {
        self.link_tests += 1;
        if self.counter.is_enabled() {
            let c = self.edge_corner(u, v);
            self.counter.tested(c);
        }
        let i = self.link_around(v, u);
        let d = self.scratch.len();
        // `[u, v]` comes from `lue`, so `o(v)` is set (Prop. 8(4)).
        let ov = self.o[v.index()].get().expect("o(v) is set");
        let mut cv = 0u32;
        // lk(v) minus u and the link {x, y} of [u, v] (its cyclic neighbours of u) is Π_uv.
        let window = if self.variant.count_link_vertices() {
            1..d
        } else {
            2..d - 1
        };
        for k in window {
            let z = self.scratch[(i + k) % d];
            if self.nbr[z.index()].is(u) {
                cv += 1; // (u, v, z) is a critical cycle
                if self.t[z.index()].is_before(ov) {
                    self.increment(z);
                }
            }
        }
        self.count[v.index()] = cv;
        spec::after_test(self, u, v, cv);
        if cv == 0 {
            // `scratch` still holds lk(v) with u at position i.
            self.contract_with_link(u, v, Some(i));
        } else {
            self.lists.push_back(LTE, v);
        }
    }

    /// Alg. 4.5: contracts `[u, v]` (identifying v with u) and updates the attributes of
    /// the new neighbours, `lue`, and the counters of edges in `lte`. Returns `[x, y]`.
    fn contract(&mut self, u: VertexId, v: VertexId) -> [VertexId; 2] {
        self.contract_with_link(u, v, None)
    }

    /// [`Self::contract`], reusing `scratch = lk(v)` (and `scratch_star`, its star) with
    /// `u` at `link_pos` when given.
    fn contract_with_link(
        &mut self,
        u: VertexId,
        v: VertexId,
        link_pos: Option<usize>,
    ) -> [VertexId; 2] {
        // l.4–11 on Π_uv, collected before the collapse.
        let i = match link_pos {
            Some(i) => i,
            None => self.link_around(v, u),
        };
        let d = self.scratch.len();
        let mut pi = std::mem::take(&mut self.scratch2);
        pi.clear();
        pi.extend((2..d - 1).map(|k| self.scratch[(i + k) % d]));
        self.ts = self.ts.next();
        for &z in &pi {
            spec::new_neighbour(self, z);
            let zi = z.index();
            self.nbr[zi] = NeighbourOf::of(u);
            self.count[zi] = 0;
            self.o[zi] = Stamp::at(self.ts);
            self.t[zi] = Stamp::UNSET;
        }
        spec::before_contraction(self, u, v);
        self.processed[v.index()] = true;
        if self.variant.mark_link_vertex_processed() {
            // `scratch` is still lk(v) with u at i: its cyclic successor is a link vertex.
            let x = self.scratch[(i + 1) % d];
            self.processed[x.index()] = true;
        }
        let before = spec::prop7_before(self);
        // `scratch_star` is still v's star, walked with `scratch`.
        let rec = self
            .tri
            .contract_tested_walked(u, v, &self.scratch_star, i, &mut self.history);
        self.contractions += 1;
        if !self.keep_history {
            self.history.forget();
        }
        self.counter.contracted(&rec);
        if let Some(numbers) = &mut self.follow {
            numbers.contracted(&rec);
        }
        spec::after_contraction(self, &rec, &pi);
        let [x, y] = rec.link;
        // l.19–24: keep degree-3 endpoints at the front of lue (Prop. 8(2)).
        for w in [x, y] {
            if self.degree(w) == 3 && !self.processed[w.index()] && !self.t[w.index()].is_set() {
                self.lists.remove(w);
                self.lists.push_front(LUE, w);
            }
        }
        // l.25–43
        for &z in &pi {
            if !self.processed[z.index()] {
                if self.degree(z) == 3 {
                    self.lists.push_front(LUE, z);
                } else {
                    self.lists.push_back(LUE, z);
                }
            } else {
                // New critical cycles (u, z, w) through an edge [u, w] already in lte.
                let j = self.link_around(z, u);
                let dz = self.scratch.len();
                for k in 2..dz - 1 {
                    let w = self.scratch[(j + k) % dz];
                    if self.nbr[w.index()].is(u) && self.t[w.index()].is_set() {
                        self.increment(w);
                    }
                }
            }
        }
        self.scratch2 = pi;
        spec::prop7(self, before, &rec);
        [x, y]
    }
}

#[cfg(test)]
mod tests {
    use super::{Lists, Stamp, Time, LTE, LUE};
    use crate::core::VertexId;

    /// The two lists of Alg. 4.1 keep their order under pushes at both ends and removals
    /// from anywhere, and membership names the list a vertex is in (or none).
    #[test]
    fn the_lists_keep_order_and_membership() {
        let mut lists = Lists::new(6);
        let v = VertexId;
        lists.push_back(LUE, v(1));
        lists.push_back(LUE, v(2));
        lists.push_front(LUE, v(0));
        lists.push_back(LTE, v(4));
        lists.push_front(LTE, v(3));
        let members = |lists: &Lists, l| lists.iter(l).map(|z: VertexId| z.0).collect::<Vec<_>>();
        assert_eq!(members(&lists, LUE), [0, 1, 2]);
        assert_eq!(members(&lists, LTE), [3, 4]);
        assert!(lists.contains(LUE, v(1)) && !lists.contains(LTE, v(1)));
        assert!(lists.contains(LTE, v(4)) && !lists.contains(LUE, v(4)));
        assert!(!lists.contains(LUE, v(5)) && !lists.contains(LTE, v(5)));

        lists.remove(v(1));
        lists.remove(v(5)); // in no list: nothing happens
        assert_eq!(members(&lists, LUE), [0, 2]);
        assert!(!lists.contains(LUE, v(1)));
        lists.remove(v(2));
        lists.push_back(LUE, v(1));
        assert_eq!(
            members(&lists, LUE),
            [0, 1],
            "the tail follows a removal at the end"
        );
        lists.remove(v(0));
        assert_eq!(
            lists.front(LUE),
            Some(v(1)),
            "the head follows a removal at the front"
        );
        assert_eq!(lists.pop_front(LTE), Some(v(3)));
        assert_eq!(members(&lists, LTE), [4]);
        lists.clear(LTE);
        assert!(lists.is_empty(LTE) && lists.front(LTE).is_none());
        assert!(!lists.is_empty(LUE));
    }

    /// Stamps print as the paper writes them: a time, or −1 when unset.
    #[test]
    fn stamps_print_as_in_the_paper() {
        assert_eq!(Time(7).to_string(), "7");
        assert_eq!(Stamp::at(Time(3)).to_string(), "3");
        assert_eq!(Stamp::UNSET.to_string(), "-1");
        assert!(Stamp::at(Time(2)).is_before(Time(3)));
        assert!(!Stamp::at(Time(3)).is_before(Time(3)));
        assert!(!Stamp::UNSET.is_before(Time(u32::MAX - 1)));
    }
}

//! [`CoverTree`]: the choice between Frink's two reconnections from a spanning tree of
//! the current graph kept in a link–cut tree, with per tree edge its *cover count* (the
//! number of non-tree edges whose tree path crosses it). A connected graph is bridgeless
//! iff every tree edge has cover count ≥ 1.
//!
//! This is this crate's own design, in the spirit of Gawrychowski–Wasylkiewicz (ESA 2024,
//! arXiv 2405.03856: "a spanning tree `T_i` of each reduced graph and a cover for every
//! tree edge, link–cut trees only"), whose Sections 2–4 could not be read here; it is
//! *not* their algorithm. The strategy picks the reduction edge itself (Frink leaves it
//! free) among *tree-stable* configurations, for which the new spanning tree is the old
//! one with two leaves removed or one tree path shortened, so every cover count stays
//! exact after O(1) link–cut operations:
//! - **S1**: a non-tree edge `uw` between two tree leaves;
//! - **S2**: the tree edge `uv` from a leaf `u` to a node `v` of tree degree 2;
//! - **S4**: the tree edge `uv` between two nodes `u`, `v` of tree degree 2, with tree
//!   neighbours `y` (of `u`) and `z` (of `v`), taking the reconnection that pairs `y`
//!   with `z` (the tree path `y u v z` becomes the new edge `yz`) when it is bridgeless.
//!
//! In S1 and S2, `T − {u, v}` spans `H' = H − {u, v}` and both new edges are non-tree, so
//! the tentative counts decide each reconnection exactly; Frink's lemma says one passes.
//! In S4 the paired reconnection is tested the same way and the configuration is skipped
//! if it fails. When no tree-stable configuration is found among the nodes whose
//! neighbourhood changed, the tree is rebuilt (one DFS, O(n)) and all nodes are tried;
//! if still none, that one step is decided by the naive DFS test and the tree is rebuilt
//! after it.
//!
//! # Complexity
//! O(log n) amortised per tree-stable step (a bounded number of link–cut operations);
//! O(n) per rebuild or naive step, so O(n²) in the worst case. The counters
//! ([`CoverTree::counters`]) show how often that happens: on the B family it is rare
//! (docs/benchmarks.md). Memory: a link–cut tree over `2n` nodes (28 bytes each), plus
//! about 20 bytes per node and 5 bytes per edge id.
//!
//! # Determinism
//! No randomness; the worklist order is a function of the graph.

use super::graph::{Dfs, NONE};
use super::{Candidate, Cubic, Reconnection, Reduction, Strategy};
use crate::dyngraph::Lct;

/// Value of the vertex nodes of the link–cut tree: never the minimum of a path that has
/// an edge (path additions move it by at most the number of operations, far below this).
const INF: i32 = 1 << 30;

/// How often each kind of step was taken.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct CoverCounters {
    /// Steps of kind S1, S2, S4.
    pub s1: u64,
    /// See `s1`.
    pub s2: u64,
    /// See `s1`.
    pub s4: u64,
    /// S4 configurations tried and skipped (the paired reconnection has a bridge).
    pub s4_skipped: u64,
    /// Rebuilds of the spanning tree (one DFS each; the first is the start).
    pub rebuilds: u64,
    /// Steps decided by the naive DFS test.
    pub naive_steps: u64,
}

/// What `pick` found and already applied to the link–cut tree.
#[derive(Clone, Copy, Debug)]
struct Plan {
    cand: Candidate,
    recon: Reconnection,
    /// The new edge (0: `p`, 1: `q`) that is a tree edge (S4), if any.
    tree_new: Option<usize>,
    /// Live nodes that lost a tree edge (S1, S2).
    lost: [u32; 2],
}

/// The link–cut cover-count strategy (module documentation).
#[derive(Clone, Debug, Default)]
pub struct CoverTree {
    n: usize,
    lct: Lct,
    /// Per edge id: its link–cut node (`n + slot`) if it is a tree edge, else `NONE`.
    enode: Vec<u32>,
    free: Vec<u32>,
    tdeg: Vec<u8>,
    queue: Vec<u32>,
    queued: Vec<bool>,
    plan: Option<Plan>,
    dirty: bool,
    fresh: bool,
    dfs: Dfs,
    counters: CoverCounters,
    /// Test knob: find no tree-stable configuration (every step naive, then a rebuild).
    #[cfg(test)]
    pub(crate) only_fallback: bool,
}

impl CoverTree {
    /// A fresh strategy.
    pub fn new() -> Self {
        Self::default()
    }

    /// How often each kind of step was taken.
    pub fn counters(&self) -> CoverCounters {
        self.counters
    }

    /// Whether the link–cut slots are consistent: each of the `n` odd ids `2x + 1` is
    /// either free or the node of exactly one tree edge, and no other id is either (a
    /// vertex's node `2x` never is). For the tests.
    #[cfg(test)]
    pub(crate) fn slots_are_consistent(&self) -> bool {
        let mut seen = vec![false; self.n];
        let tree = self.enode.iter().copied().filter(|&k| k != NONE);
        for k in self.free.iter().copied().chain(tree) {
            let x = (k / 2) as usize;
            if k % 2 == 0 || x >= self.n || seen[x] {
                return false;
            }
            seen[x] = true;
        }
        seen.iter().all(|&s| s)
    }

    fn is_tree(&self, e: u32) -> bool {
        self.enode.get(e as usize).is_some_and(|&k| k != NONE)
    }

    fn push(&mut self, x: u32) {
        if !self.queued[x as usize] {
            self.queued[x as usize] = true;
            self.queue.push(x);
        }
    }

    /// A DFS spanning tree of the live graph and its cover counts (every non-tree edge
    /// joins an ancestor and a descendant, so a subtree sum gives each count). O(n).
    fn rebuild(&mut self, g: &Cubic) {
        self.counters.rebuilds += 1;
        let n = g.node_capacity();
        self.n = n;
        let m = g.ends.len();
        self.enode.clear();
        self.enode.resize(m, NONE);
        self.tdeg.clear();
        self.tdeg.resize(n, 0);
        self.queued.clear();
        self.queued.resize(n, false);
        self.queue.clear();
        let mut disc = vec![NONE; n];
        let mut pe = vec![NONE; n];
        let mut order: Vec<u32> = Vec::with_capacity(g.node_count());
        let mut stack: Vec<(u32, u8)> = Vec::new();
        if let Some(root) = (0..n as u32).find(|&x| g.is_alive(x)) {
            disc[root as usize] = 0;
            order.push(root);
            stack.push((root, 0));
            while let Some(top) = stack.last_mut() {
                let (x, i) = *top;
                if i == 3 {
                    stack.pop();
                    continue;
                }
                top.1 += 1;
                let e = g.slots[x as usize][i as usize];
                let w = g.other(e, x);
                if disc[w as usize] == NONE {
                    disc[w as usize] = order.len() as u32;
                    pe[w as usize] = e;
                    order.push(w);
                    stack.push((w, 0));
                }
            }
        }
        // Link-cut ids: vertex x is 2x, the tree edge to x's DFS parent is 2x + 1 (so a
        // vertex and its parent edge share a cache line); the other odd ids are free.
        let mut parent = vec![NONE; 2 * n];
        let mut vals = vec![INF; 2 * n];
        let mut sum = vec![0i32; n];
        for &x in &order {
            for e in g.slots[x as usize] {
                let w = g.other(e, x);
                if pe[x as usize] != e && pe[w as usize] != e && disc[x as usize] > disc[w as usize]
                {
                    sum[x as usize] += 1;
                    sum[w as usize] -= 1;
                }
            }
        }
        self.free.clear();
        for &x in order.iter().rev() {
            let e = pe[x as usize];
            if e == NONE {
                continue;
            }
            let p = g.other(e, x);
            sum[p as usize] += sum[x as usize];
            let k = 2 * x + 1;
            self.enode[e as usize] = k;
            vals[k as usize] = sum[x as usize];
            parent[2 * x as usize] = k;
            parent[k as usize] = 2 * p;
            self.tdeg[x as usize] += 1;
            self.tdeg[p as usize] += 1;
        }
        self.free.extend(
            (0..n as u32)
                .rev()
                .filter(|&x| pe[x as usize] == NONE)
                .map(|x| 2 * x + 1),
        );
        self.lct = Lct::with_parents(&vals, &parent);
        for &x in order.iter().rev() {
            self.push(x);
        }
    }

    /// Cuts tree edge `e` = `a`–`b` out; returns its count. Does not free its slot.
    fn tree_cut(&mut self, e: u32, a: u32, b: u32) -> i32 {
        let k = self.enode[e as usize];
        self.lct.cut(2 * a, k);
        self.lct.cut(k, 2 * b);
        self.lct.isolated_value(k)
    }

    fn tree_relink(&mut self, e: u32, a: u32, b: u32) {
        let k = self.enode[e as usize];
        self.lct.link(2 * a, k);
        self.lct.link(k, 2 * b);
    }

    fn padd(&mut self, a: u32, b: u32, d: i32) {
        self.lct.path_add(2 * a, 2 * b, d);
    }

    fn pmin(&mut self, a: u32, b: u32) -> i32 {
        self.lct.path_min(2 * a, 2 * b)
    }

    fn release(&mut self, e: u32) {
        let k = self.enode[e as usize];
        self.enode[e as usize] = NONE;
        self.free.push(k);
    }

    /// The ends of the new edges `[p, q]` of `cand` under `recon` (as [`Cubic::reduce`]).
    fn new_ends(cand: &Candidate, recon: Reconnection) -> [[u32; 2]; 2] {
        let [x1, x2, x3, x4] = cand.x;
        match recon {
            Reconnection::H1 => [[x1, x3], [x2, x4]],
            Reconnection::H2 => [[x1, x4], [x2, x3]],
        }
    }

    /// S1 / S2: `T − {u, v}` spans the rest. Applies the choice to the link–cut tree and
    /// returns the plan; `None` (tree restored) only if neither reconnection passes.
    fn try_leafy(&mut self, g: &Cubic, cand: &Candidate) -> Option<Plan> {
        let (u, v) = (cand.u, cand.v);
        let five = [cand.e, cand.a[0], cand.a[1], cand.b[0], cand.b[1]];
        // Anchor of u and of v: the live node their tree branch hangs from (the branch
        // is u alone, v alone, or the tree edge uv).
        let live_tree_nbr = |s: &Self, x: u32| -> u32 {
            for e in g.slots[x as usize] {
                let w = g.other(e, x);
                if s.is_tree(e) && w != u && w != v {
                    return w;
                }
            }
            NONE
        };
        let anchor = |s: &Self, x: u32| -> u32 {
            let a = live_tree_nbr(s, x);
            if a != NONE {
                a
            } else {
                live_tree_nbr(s, if x == u { v } else { u })
            }
        };
        let (au, av) = (anchor(self, u), anchor(self, v));
        let map = |x: u32| {
            if x == u {
                au
            } else if x == v {
                av
            } else {
                x
            }
        };
        let mut removed: Vec<[u32; 2]> = Vec::with_capacity(3);
        let mut cut: Vec<(u32, [u32; 2])> = Vec::with_capacity(2);
        for e in five {
            let [s, t] = g.ends(e);
            if self.is_tree(e) {
                cut.push((e, [s, t]));
            } else {
                self.padd(s, t, -1);
                removed.push([map(s), map(t)]);
            }
        }
        debug_assert_eq!(cut.len(), 2);
        for &(e, [s, t]) in &cut {
            self.tree_cut(e, s, t);
        }
        for recon in [Reconnection::H1, Reconnection::H2] {
            let ends = Self::new_ends(cand, recon);
            if ends.iter().any(|[a, b]| a == b) {
                continue;
            }
            for [a, b] in ends {
                self.padd(a, b, 1);
            }
            let ok = removed.iter().all(|&[a, b]| self.pmin(a, b) >= 1);
            if ok {
                for &(e, _) in &cut {
                    self.release(e);
                }
                // The live end of each cut tree edge loses a tree edge.
                let mut lost = [NONE; 2];
                for (k, &(_, [s, t])) in cut.iter().enumerate() {
                    lost[k] = if s == u || s == v { t } else { s };
                    if lost[k] == u || lost[k] == v {
                        lost[k] = NONE;
                    }
                }
                return Some(Plan {
                    cand: *cand,
                    recon,
                    tree_new: None,
                    lost,
                });
            }
            for [a, b] in ends {
                self.padd(a, b, -1);
            }
        }
        // Restore (impossible on a bridgeless graph, kept for robustness).
        for &(e, [s, t]) in cut.iter().rev() {
            self.tree_relink(e, s, t);
        }
        for e in five {
            if !self.is_tree(e) {
                let [s, t] = g.ends(e);
                self.padd(s, t, 1);
            }
        }
        None
    }

    /// S4 at the tree edge `cand.e` between two tree-degree-2 nodes: tries the
    /// reconnection pairing their tree neighbours; restores everything if it fails.
    fn try_chain(&mut self, g: &Cubic, cand: &Candidate) -> Option<Plan> {
        let (u, v) = (cand.u, cand.v);
        // Index (0/1) of u's and v's tree edge among a / b.
        let iu = usize::from(!self.is_tree(cand.a[0]));
        let iv = usize::from(!self.is_tree(cand.b[0]));
        let (fu, fv) = (cand.a[iu], cand.b[iv]);
        let (hu, hv) = (cand.a[1 - iu], cand.b[1 - iv]);
        if !self.is_tree(fu) || !self.is_tree(fv) || self.is_tree(hu) || self.is_tree(hv) {
            return None;
        }
        let (y, z) = (cand.x[iu], cand.x[2 + iv]);
        let (a, b) = (cand.x[1 - iu], cand.x[3 - iv]);
        if a == b || y == z {
            return None;
        }
        let recon = if iu == iv {
            Reconnection::H1
        } else {
            Reconnection::H2
        };
        self.padd(u, a, -1);
        self.padd(v, b, -1);
        // The new tree edge (x[iu], x[2 + iv]) is p in H1 iff iu = 0, and in H2 (iu ≠ iv)
        // p = x1x4 iff iu = 0: so it is new edge number iu either way.
        let which = iu;
        let id = g.ends.len() as u32 + which as u32;
        // Every remaining tree path through y u v z crosses all three edges, so the new
        // edge yz takes their common count (that of uv).
        let k = self
            .free
            .pop()
            .expect("a free link-cut slot (n − 1 tree edges at most)");
        if self.enode.len() <= id as usize {
            self.enode.resize(id as usize + 1, NONE);
        }
        self.enode[id as usize] = k;
        let ke = self.enode[cand.e as usize];
        self.lct.replace_path(2 * y, 2 * z, k, ke);
        self.padd(a, b, 1);
        // The counts that dropped lie on the old paths u…a and v…b, now inside a…y or
        // a…z (one contains the other and the edge yz), b…y or b…z.
        let ok = [(y, a), (z, a), (y, b), (z, b)]
            .iter()
            .all(|&(s, t)| self.pmin(s, t) >= 1);
        if ok {
            for e in [fu, cand.e, fv] {
                self.release(e);
            }
            return Some(Plan {
                cand: *cand,
                recon,
                tree_new: Some(which),
                lost: [NONE, NONE],
            });
        }
        self.padd(a, b, -1);
        self.tree_cut(id, y, z);
        self.release(id);
        self.tree_relink(fu, y, u);
        self.tree_relink(cand.e, u, v);
        self.tree_relink(fv, v, z);
        self.padd(u, a, 1);
        self.padd(v, b, 1);
        self.counters.s4_skipped += 1;
        None
    }

    /// Tries every tree-stable configuration with `x` as `u`.
    fn try_at(&mut self, g: &Cubic, x: u32) -> Option<Plan> {
        #[cfg(test)]
        if self.only_fallback {
            return None;
        }
        if !g.is_alive(x) {
            return None;
        }
        let slots = g.slots[x as usize];
        match self.tdeg[x as usize] {
            1 => {
                for e in slots {
                    let w = g.other(e, x);
                    let kind_ok = if self.is_tree(e) {
                        self.tdeg[w as usize] == 2
                    } else {
                        self.tdeg[w as usize] == 1
                    };
                    if !kind_ok {
                        continue;
                    }
                    let tree = self.is_tree(e);
                    if let Some(c) = g.candidate_for(x, e) {
                        if let Some(p) = self.try_leafy(g, &c) {
                            if tree {
                                self.counters.s2 += 1;
                            } else {
                                self.counters.s1 += 1;
                            }
                            return Some(p);
                        }
                    }
                }
                None
            }
            2 => {
                for e in slots {
                    if !self.is_tree(e) {
                        continue;
                    }
                    let w = g.other(e, x);
                    let d = self.tdeg[w as usize];
                    if d == 1 {
                        if let Some(c) = g.candidate_for(w, e) {
                            if let Some(p) = self.try_leafy(g, &c) {
                                self.counters.s2 += 1;
                                return Some(p);
                            }
                        }
                    } else if d == 2 {
                        if let Some(c) = g.candidate_for(x, e) {
                            if let Some(p) = self.try_chain(g, &c) {
                                self.counters.s4 += 1;
                                return Some(p);
                            }
                        }
                    }
                }
                None
            }
            _ => None,
        }
    }
}

impl Strategy for CoverTree {
    fn start(&mut self, g: &Cubic) {
        self.counters = CoverCounters::default();
        self.plan = None;
        self.dirty = false;
        self.rebuild(g);
        self.fresh = true;
    }

    fn pick(&mut self, g: &Cubic) -> Option<Candidate> {
        if self.dirty {
            self.rebuild(g);
            self.dirty = false;
            self.fresh = true;
        }
        loop {
            while let Some(x) = self.queue.pop() {
                self.queued[x as usize] = false;
                if let Some(p) = self.try_at(g, x) {
                    self.plan = Some(p);
                    self.fresh = false;
                    return Some(p.cand);
                }
            }
            if self.fresh {
                self.plan = None;
                return None;
            }
            self.rebuild(g);
            self.fresh = true;
        }
    }

    fn choose(&mut self, g: &mut Cubic, cand: &Candidate) -> Option<Reconnection> {
        if let Some(p) = self.plan {
            if p.cand == *cand {
                return Some(p.recon);
            }
        }
        // Naive step (no tree-stable configuration): the tree is rebuilt afterwards.
        self.plan = None;
        self.counters.naive_steps += 1;
        super::naive_choice(&mut self.dfs, g, cand)
    }

    fn applied(&mut self, g: &Cubic, r: &Reduction) {
        // Without a plan (a naive step), or when the reduction applied is not the one
        // planned (a wrapper overruled the choice), the link–cut tree no longer matches
        // `g`: it is rebuilt before the next pick.
        let Some(p) = self
            .plan
            .take()
            .filter(|p| p.recon == r.recon && p.cand == r.cand)
        else {
            self.dirty = true;
            return;
        };
        if self.enode.len() < g.ends.len() {
            self.enode.resize(g.ends.len(), NONE);
        }
        if let Some(w) = p.tree_new {
            debug_assert!(self.enode[r.new[w] as usize] != NONE);
        }
        for x in p.lost {
            if x != NONE {
                self.tdeg[x as usize] -= 1;
            }
        }
        for x in r.cand.x {
            if g.is_alive(x) {
                self.push(x);
                for e in g.slots[x as usize] {
                    if self.is_tree(e) {
                        let w = g.other(e, x);
                        self.push(w);
                    }
                }
            }
        }
    }
}

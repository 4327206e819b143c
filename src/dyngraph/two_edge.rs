//! [`TwoEdge`]: fully dynamic 2-edge-connectivity on a multigraph with stable edge ids
//! (insert, delete, "are `a` and `b` connected / 2-edge-connected"), the structure behind
//! [`crate::quad::frink::BiedlBoseDemaineLubiw`].
//!
//! # Guarantee
//! After every operation, [`TwoEdge::connected`] and [`TwoEdge::two_edge_connected`]
//! answer exactly as a static search of the current graph would (tested after every
//! operation of thousands of random insert/delete sequences on small multigraphs with
//! parallel edges and loops against a BFS / bridge-removal oracle; [`TwoEdge::check`]
//! verifies every invariant below from scratch).
//!
//! # Design (the cover idea of Holm–de Lichtenberg–Thorup Sec. 3, at a single level)
//! Holm, de Lichtenberg and Thorup (JACM 48(4), 2001, Sec. 3; recapped by
//! Holm–Rotenberg–Thorup, "Dynamic bridge-finding in Õ(log² n) amortized time", SODA
//! 2018, Sec. 2) keep a spanning forest `F` and say that a non-tree edge `(v, w)`
//! *covers* the tree edges of the `F`-path `v…w`: a tree edge is a bridge iff nothing
//! covers it, so `a`, `b` are 2-edge-connected iff they are connected and every edge of
//! their `F`-path is covered. This module keeps exactly that, with *cover counts* instead
//! of HDT's cover levels:
//! - `F` lives in a link–cut tree (module `lct`) whose nodes are the graph's vertices and
//!   one node per tree edge (subdividing it), so that path operations reach edges under
//!   re-rooting. A tree-edge node holds its cover count, a vertex node a large constant.
//! - Inserting a non-tree edge adds 1 along its `F`-path, deleting one subtracts 1
//!   (O(log n) amortised); inserting an edge between two trees links them; loops are kept
//!   but cover nothing (a loop is on no path and never a bridge).
//! - Deleting a tree edge `t = ab` with cover count 0 is a cut (a bridge goes). With a
//!   positive count, the non-tree edges crossing the cut are exactly those covering `t`;
//!   they are found by scanning the smaller side, which two interleaved breadth-first
//!   searches over tree edges from `a` and `b` delimit (the one that finishes first is
//!   the smaller side, up to one vertex). Their covers are removed along the old paths,
//!   `t` is cut, the first of them becomes the replacement tree edge (HDT's *Swap*), and
//!   the others are covered again along their new paths (which run through the
//!   replacement).
//!
//! HDT instead keep levels on non-tree edges and the *maximum* cover level per tree edge,
//! which lets a swap touch one path and bounds the rescans (*Uncover*/*Recover*) by
//! promoting edges: O(log⁴ n) amortised, with top trees. That machinery is not
//! implemented here; cover counts make every answer exact, but a swap must re-cover every
//! edge crossing the cut.
//!
//! # Complexity (weaker than HDT; stated honestly)
//! - [`TwoEdge::connected`], [`TwoEdge::two_edge_connected`]: O(log n) amortised.
//! - insertion, deletion of a non-tree edge or a loop: O(log n) amortised.
//! - deletion of a tree edge: O(s + k log n) amortised, where `s` is the sum of the
//!   degrees on the smaller side of the cut (at most about `m`) and `k` the number of
//!   non-tree edges covering the deleted edge. So O(m + n log n) in the worst case per
//!   deletion (not polylogarithmic; HDT Sec. 3 would give O(log⁴ n) amortised). Measured
//!   under Frink's reduction on the B family in docs/benchmarks.md (superlinear: 3–10×
//!   the time of the O(n log² n) Diks–Stańczyk strategy from 16k to 594k triangles).
//!
//! Memory: per vertex a 28-byte link–cut node (`lct::Lct`) plus its incidence list; per
//! tree edge one more link–cut node (at most `n − 1`); per edge id 21 bytes.
//! [`TwoEdge::check`] takes O(n·m).

use super::lct::{Lct, NODE_BYTES};

/// No node / no position / no link–cut node.
const NONE: u32 = u32::MAX;

/// The value of a vertex's link–cut node: above any cover count (counts stay below
/// 2^29 because edge ids are below 2^29, checked on insertion), so that a path minimum
/// is the minimum cover of the path's edges.
const VERTEX: i32 = 1 << 30;

/// Node ids and edge ids must be below this (the link–cut values: a cover count is at
/// most the number of edges, which stays below `VERTEX`).
pub(crate) const MAX_ID: usize = 1 << 29;

/// What an edge id currently is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Kind {
    Absent,
    Loop,
    NonTree,
    Tree,
}

/// Counters of the operations done so far.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct TwoEdgeCounters {
    /// Edge insertions.
    pub inserts: u64,
    /// Edge deletions.
    pub deletes: u64,
    /// Tree edges deleted (cuts of the forest).
    pub cuts: u64,
    /// Cuts that found a replacement edge (HDT's swap).
    pub swaps: u64,
    /// Vertices visited by the interleaved searches of the cuts (both sides).
    pub scanned: u64,
    /// Non-tree edges covered again along a new path after a swap.
    pub recovered: u64,
}

/// Fully dynamic connectivity and 2-edge-connectivity of a multigraph on nodes `0..n`
/// with stable edge ids (module documentation: design, bounds).
#[derive(Clone, Debug)]
pub struct TwoEdge {
    n: usize,
    /// Live edges.
    live: usize,
    kind: Vec<Kind>,
    ends: Vec<[u32; 2]>,
    /// Per edge, its index in the incidence lists of its two ends (non-loops only).
    pos: Vec<[u32; 2]>,
    /// Per tree edge, its link–cut node (`n..2n − 1`), else `NONE`.
    lnode: Vec<u32>,
    /// Per vertex, its live non-loop edges.
    adj: Vec<Vec<u32>>,
    lct: Lct,
    /// Unused tree-edge nodes.
    free: Vec<u32>,
    /// Search marks: `2·epoch` side of `a`, `2·epoch + 1` side of `b`.
    mark: Vec<u32>,
    epoch: u32,
    queues: [Vec<u32>; 2],
    crossing: Vec<u32>,
    counters: TwoEdgeCounters,
    /// Broken variant for the tests: after a swap, the other crossing edges are not
    /// covered again.
    #[cfg(test)]
    skip_recover: bool,
}

impl TwoEdge {
    /// The edgeless graph on nodes `0..n`. O(n).
    ///
    /// # Panics
    /// If `n ≥ 2^29` (the link–cut tree's values and ids would overflow).
    pub fn new(n: usize) -> TwoEdge {
        assert!(n < MAX_ID, "TwoEdge: {n} nodes, too many");
        let mut vals = vec![VERTEX; n];
        vals.extend(std::iter::repeat_n(0, n.saturating_sub(1)));
        TwoEdge {
            n,
            live: 0,
            kind: Vec::new(),
            ends: Vec::new(),
            pos: Vec::new(),
            lnode: Vec::new(),
            adj: vec![Vec::new(); n],
            lct: Lct::new(&vals),
            free: (n as u32..(2 * n).saturating_sub(1) as u32).rev().collect(),
            mark: vec![0; n],
            epoch: 0,
            queues: [Vec::new(), Vec::new()],
            crossing: Vec::new(),
            counters: TwoEdgeCounters::default(),
            #[cfg(test)]
            skip_recover: false,
        }
    }

    /// Counters of the operations so far.
    pub fn counters(&self) -> TwoEdgeCounters {
        self.counters
    }

    /// Number of nodes.
    pub fn node_count(&self) -> usize {
        self.n
    }

    /// Whether edge id `e` is live.
    pub fn contains(&self, e: u32) -> bool {
        self.kind
            .get(e as usize)
            .is_some_and(|&k| k != Kind::Absent)
    }

    /// The ends of live edge `e`, `None` if `e` is not live.
    pub fn ends(&self, e: u32) -> Option<[u32; 2]> {
        self.contains(e).then(|| self.ends[e as usize])
    }

    /// Number of live edges.
    pub fn edge_count(&self) -> usize {
        self.live
    }

    /// Whether live edge `e` is an edge of the spanning forest.
    pub fn is_tree_edge(&self, e: u32) -> bool {
        self.kind.get(e as usize) == Some(&Kind::Tree)
    }

    /// Bytes held (approximate: the vectors' lengths, not their capacities, except for
    /// the incidence lists).
    pub fn bytes(&self) -> usize {
        let edges = self.kind.len() * (1 + 8 + 8 + 4);
        let adj: usize = self.adj.iter().map(|a| 24 + 4 * a.capacity()).sum();
        edges + adj + (2 * self.n) * NODE_BYTES + self.n * 4
    }

    /// Inserts edge `e = ab` (a loop if `a = b`). O(log n) amortised.
    ///
    /// # Panics
    /// If `e` is live, `e ≥ 2^29`, or an end is not below `n`.
    pub fn insert(&mut self, e: u32, a: u32, b: u32) {
        assert!(
            (a as usize) < self.n && (b as usize) < self.n,
            "TwoEdge::insert: edge {e} = {a}{b} outside 0..{}",
            self.n
        );
        assert!(
            (e as usize) < MAX_ID,
            "TwoEdge::insert: edge id {e} too large"
        );
        let i = e as usize;
        if i >= self.kind.len() {
            self.kind.resize(i + 1, Kind::Absent);
            self.ends.resize(i + 1, [NONE; 2]);
            self.pos.resize(i + 1, [NONE; 2]);
            self.lnode.resize(i + 1, NONE);
        }
        assert_eq!(
            self.kind[i],
            Kind::Absent,
            "TwoEdge::insert: edge {e} is live"
        );
        self.counters.inserts += 1;
        self.live += 1;
        self.ends[i] = [a, b];
        if a == b {
            self.kind[i] = Kind::Loop;
            return;
        }
        for (k, x) in [a, b].into_iter().enumerate() {
            self.pos[i][k] = self.adj[x as usize].len() as u32;
            self.adj[x as usize].push(e);
        }
        if self.lct.connected(a, b) {
            self.kind[i] = Kind::NonTree;
            self.lct.path_add(a, b, 1);
        } else {
            self.link(e);
        }
    }

    /// Deletes live edge `e`. O(log n) amortised for a non-tree edge or a loop; for a
    /// tree edge O(s + k log n), `s` the degree sum of the smaller side of the cut and
    /// `k` the edges covering `e` (module documentation).
    ///
    /// # Panics
    /// If `e` is not live.
    pub fn delete(&mut self, e: u32) {
        let i = e as usize;
        let kind = self.kind.get(i).copied().unwrap_or(Kind::Absent);
        assert_ne!(kind, Kind::Absent, "TwoEdge::delete: edge {e} is not live");
        self.counters.deletes += 1;
        self.live -= 1;
        let [a, b] = self.ends[i];
        match kind {
            Kind::Absent => {}
            Kind::Loop => {}
            Kind::NonTree => {
                self.lct.path_add(a, b, -1);
                self.unlist(e);
            }
            Kind::Tree => {
                self.unlist(e);
                self.delete_tree(e);
            }
        }
        self.kind[i] = Kind::Absent;
        self.ends[i] = [NONE; 2];
    }

    /// Whether `a` and `b` are connected. O(log n) amortised.
    pub fn connected(&mut self, a: u32, b: u32) -> bool {
        self.lct.connected(a, b)
    }

    /// Whether `a` and `b` are 2-edge-connected (connected, and no single edge deletion
    /// separates them; true for `a = b`): connected and every tree edge on their forest
    /// path covered. O(log n) amortised.
    pub fn two_edge_connected(&mut self, a: u32, b: u32) -> bool {
        a == b || self.lct.connected(a, b) && self.lct.path_min(a, b) > 0
    }

    /// Makes edge `e` (ends in two trees) a tree edge with cover count 0.
    fn link(&mut self, e: u32) {
        let i = e as usize;
        let [a, b] = self.ends[i];
        let Some(k) = self.free.pop() else {
            unreachable!("more than n − 1 tree edges in a forest on n nodes")
        };
        self.kind[i] = Kind::Tree;
        self.lnode[i] = k;
        self.lct.link(a, k);
        self.lct.link(k, b);
    }

    /// Removes non-loop edge `e` from its ends' incidence lists. O(1).
    fn unlist(&mut self, e: u32) {
        let i = e as usize;
        for k in 0..2 {
            let x = self.ends[i][k] as usize;
            let p = self.pos[i][k] as usize;
            let last = self.adj[x].len() - 1;
            self.adj[x].swap(p, last);
            self.adj[x].pop();
            if p < last {
                let moved = self.adj[x][p] as usize;
                // Its end at x: for a parallel edge to the same pair, the matching slot.
                let slot = usize::from(self.ends[moved][0] != x as u32);
                self.pos[moved][slot] = p as u32;
            }
            self.pos[i][k] = NONE;
        }
    }

    /// Cuts tree edge `e` (already unlisted) and swaps in a replacement if one exists,
    /// keeping every cover count exact (module documentation).
    fn delete_tree(&mut self, e: u32) {
        let i = e as usize;
        let [a, b] = self.ends[i];
        let k = self.lnode[i];
        self.counters.cuts += 1;
        if self.lct.path_min(k, k) == 0 {
            // A bridge: nothing crosses the cut, no search needed.
            self.lct.cut(a, k);
            self.lct.cut(k, b);
            self.free.push(k);
            self.lnode[i] = NONE;
            return;
        }
        let side = self.smaller_side(a, b);
        // The non-tree edges leaving the smaller side: exactly those covering e.
        let mut crossing = std::mem::take(&mut self.crossing);
        crossing.clear();
        let own = 2 * self.epoch + side as u32;
        for &x in &self.queues[side] {
            for &f in &self.adj[x as usize] {
                if self.kind[f as usize] != Kind::NonTree {
                    continue;
                }
                let [p, q] = self.ends[f as usize];
                let y = if p == x { q } else { p };
                if self.mark[y as usize] != own {
                    crossing.push(f);
                }
            }
        }
        debug_assert_eq!(
            self.lct.path_min(k, k),
            crossing.len() as i32,
            "cover count of tree edge {e} differs from the edges crossing its cut"
        );
        for &f in &crossing {
            let [p, q] = self.ends[f as usize];
            self.lct.path_add(p, q, -1);
        }
        self.lct.cut(a, k);
        self.lct.cut(k, b);
        // Its cover count is back to 0 for its next use: every edge covering it crossed
        // the cut and was uncovered above (`check` verifies that unused nodes hold 0).
        debug_assert_eq!(self.lct.isolated_value(k), 0, "cover left on tree edge {e}");
        self.free.push(k);
        self.lnode[i] = NONE;
        if let Some(&r) = crossing.first() {
            self.counters.swaps += 1;
            self.link(r);
            #[cfg(test)]
            let skip = self.skip_recover;
            #[cfg(not(test))]
            let skip = false;
            if !skip {
                for &f in &crossing[1..] {
                    let [p, q] = self.ends[f as usize];
                    self.lct.path_add(p, q, 1);
                }
                self.counters.recovered += crossing.len() as u64 - 1;
            }
        }
        self.crossing = crossing;
    }

    /// Two breadth-first searches over tree edges, from `a` and from `b` (the tree edge
    /// between them already unlisted), one vertex at a time each; the first to run out
    /// has visited its whole side, and the other at most one vertex more. Returns that
    /// side (0: `a`'s, 1: `b`'s), its vertices in `queues[side]`, marked
    /// `2·epoch + side`. O(degree sum of the smaller side).
    fn smaller_side(&mut self, a: u32, b: u32) -> usize {
        self.epoch = self.epoch.wrapping_add(1);
        if self.epoch >= u32::MAX / 2 {
            self.mark.iter_mut().for_each(|m| *m = 0);
            self.epoch = 1;
        }
        let mut head = [0usize; 2];
        for (s, x) in [a, b].into_iter().enumerate() {
            self.queues[s].clear();
            self.queues[s].push(x);
            self.mark[x as usize] = 2 * self.epoch + s as u32;
        }
        loop {
            for s in 0..2 {
                let Some(&x) = self.queues[s].get(head[s]) else {
                    self.counters.scanned += (head[0] + head[1]) as u64;
                    return s;
                };
                head[s] += 1;
                let own = 2 * self.epoch + s as u32;
                for idx in 0..self.adj[x as usize].len() {
                    let f = self.adj[x as usize][idx] as usize;
                    if self.kind[f] != Kind::Tree {
                        continue;
                    }
                    let [p, q] = self.ends[f];
                    let y = if p == x { q } else { p };
                    if self.mark[y as usize] != own {
                        self.mark[y as usize] = own;
                        self.queues[s].push(y);
                    }
                }
            }
        }
    }

    /// The cover count of live tree edge `e`. O(log n) amortised.
    fn cover(&mut self, e: u32) -> i32 {
        let k = self.lnode[e as usize];
        self.lct.path_min(k, k)
    }

    /// Checks the invariants from scratch, O(n·m): incidence lists and positions; the
    /// tree edges form a spanning forest of the live graph; each tree edge's link–cut
    /// node is connected to both its ends, and every vertex to its forest tree's root
    /// (its smallest vertex); no two forest trees, and no unused tree-edge node and a
    /// forest tree, are connected in the link–cut tree (by their link–cut roots);
    /// unused tree-edge nodes hold cover 0; every tree edge's cover count equals the
    /// number of non-tree edges whose forest path contains it (by naive parent walks);
    /// every vertex value is at least `VERTEX`. Takes `&mut self` only for the link–cut
    /// queries (splaying), which change no represented value.
    pub fn check(&mut self) -> Result<(), String> {
        let n = self.n;
        let mut listed = 0usize;
        let live = self.kind.iter().filter(|&&k| k != Kind::Absent).count();
        if live != self.live {
            return Err(format!("{live} live edges, {} counted", self.live));
        }
        for (i, &kind) in self.kind.iter().enumerate() {
            let [a, b] = self.ends[i];
            match kind {
                Kind::Absent => {
                    if self.pos[i] != [NONE; 2] || self.lnode[i] != NONE {
                        return Err(format!("absent edge {i} still listed"));
                    }
                }
                Kind::Loop => {
                    if a != b || self.pos[i] != [NONE; 2] {
                        return Err(format!("loop {i} = {a}{b} malformed"));
                    }
                }
                Kind::NonTree | Kind::Tree => {
                    if a == b {
                        return Err(format!("edge {i} is a loop but kept as {kind:?}"));
                    }
                    for (k, x) in [a, b].into_iter().enumerate() {
                        let p = self.pos[i][k] as usize;
                        if self.adj[x as usize].get(p) != Some(&(i as u32)) {
                            return Err(format!("edge {i} not at position {p} of node {x}"));
                        }
                    }
                    listed += 2;
                    if (kind == Kind::Tree) != (self.lnode[i] != NONE) {
                        return Err(format!("edge {i}: tree flag and link-cut node disagree"));
                    }
                }
            }
        }
        if self.adj.iter().map(Vec::len).sum::<usize>() != listed {
            return Err("incidence lists hold dead or duplicate edges".into());
        }
        // Forest: acyclic, and spanning (same components as the whole graph).
        let mut uf_tree: Vec<u32> = (0..n as u32).collect();
        let mut uf_all: Vec<u32> = (0..n as u32).collect();
        let mut tree_edges = 0usize;
        for (i, &kind) in self.kind.iter().enumerate() {
            let [a, b] = self.ends[i];
            if matches!(kind, Kind::NonTree | Kind::Tree) {
                union(&mut uf_all, a, b);
            }
            if kind == Kind::Tree {
                if !union(&mut uf_tree, a, b) {
                    return Err(format!("tree edge {i} closes a cycle of the forest"));
                }
                tree_edges += 1;
            }
        }
        for x in 0..n as u32 {
            let (rt, ra) = (find(&mut uf_tree, x), find(&mut uf_all, x));
            let rt_all = find(&mut uf_all, rt);
            if rt_all != ra {
                return Err(format!(
                    "node {x}: forest component differs from the graph's"
                ));
            }
        }
        let comps_tree = (0..n as u32)
            .filter(|&x| find(&mut uf_tree, x) == x)
            .count();
        let comps_all = (0..n as u32).filter(|&x| find(&mut uf_all, x) == x).count();
        if comps_tree != comps_all {
            return Err(format!(
                "the forest has {comps_tree} trees, the graph {comps_all} components"
            ));
        }
        if tree_edges + self.free.len() != n.saturating_sub(1) {
            return Err("tree-edge nodes lost or duplicated".into());
        }
        // The link–cut tree: each tree edge's node joined to both ends, every vertex
        // connected to its forest root, distinct forest trees not connected.
        for i in 0..self.kind.len() {
            if self.kind[i] != Kind::Tree {
                continue;
            }
            let [a, b] = self.ends[i];
            let k = self.lnode[i];
            if !(self.lct.connected(a, k) && self.lct.connected(k, b)) {
                return Err(format!("tree edge {i} not linked in the link-cut tree"));
            }
        }
        let mut roots = Vec::new();
        for x in 0..n as u32 {
            let r = find(&mut uf_tree, x);
            if r == x {
                roots.push(x);
            } else if !self.lct.connected(x, r) {
                return Err(format!(
                    "node {x} not linked to its tree in the link-cut tree"
                ));
            }
            if self.lct.path_min(x, x) < VERTEX {
                return Err(format!("node {x}'s value fell below the vertex constant"));
            }
        }
        // Distinct forest trees have distinct link–cut roots, and no unused tree-edge
        // node is in the link–cut tree of any of them (their roots found in one pass:
        // find_root changes no root).
        let mut lct_roots: Vec<(u32, u32)> =
            roots.iter().map(|&r| (self.lct.find_root(r), r)).collect();
        lct_roots.sort_unstable();
        if let Some(w) = lct_roots.windows(2).find(|w| w[0].0 == w[1].0) {
            return Err(format!(
                "trees of {} and {} joined in the link-cut tree",
                w[0].1, w[1].1
            ));
        }
        for &k in &self.free {
            let root = self.lct.find_root(k);
            if lct_roots.binary_search_by_key(&root, |&(l, _)| l).is_ok() {
                return Err(format!("unused tree-edge node {k} still linked"));
            }
            if self.lct.path_min(k, k) != 0 {
                return Err(format!("unused tree-edge node {k} has a cover count"));
            }
        }
        // Cover counts by naive parent walks in the forest, rooted by BFS.
        let mut parent = vec![NONE; n];
        let mut pedge = vec![NONE; n];
        let mut depth = vec![0u32; n];
        let mut seen = vec![false; n];
        for &r in &roots {
            seen[r as usize] = true;
            let mut queue = vec![r];
            while let Some(x) = queue.pop() {
                for &f in &self.adj[x as usize] {
                    if self.kind[f as usize] != Kind::Tree {
                        continue;
                    }
                    let [p, q] = self.ends[f as usize];
                    let y = if p == x { q } else { p };
                    if !seen[y as usize] {
                        seen[y as usize] = true;
                        parent[y as usize] = x;
                        pedge[y as usize] = f;
                        depth[y as usize] = depth[x as usize] + 1;
                        queue.push(y);
                    }
                }
            }
        }
        let mut count = vec![0i32; self.kind.len()];
        for i in 0..self.kind.len() {
            if self.kind[i] != Kind::NonTree {
                continue;
            }
            let [mut p, mut q] = self.ends[i];
            while p != q {
                if depth[p as usize] < depth[q as usize] {
                    std::mem::swap(&mut p, &mut q);
                }
                count[pedge[p as usize] as usize] += 1;
                p = parent[p as usize];
            }
        }
        for (i, &want) in count.iter().enumerate() {
            if self.kind[i] == Kind::Tree {
                let c = self.cover(i as u32);
                if c != want {
                    return Err(format!(
                        "tree edge {i}: cover count {c}, but {want} non-tree edges cover it"
                    ));
                }
            }
        }
        Ok(())
    }

    /// Test hook: adds `d` to the cover count of tree edge `e` (corrupting the state).
    #[cfg(test)]
    fn corrupt_cover(&mut self, e: u32, d: i32) {
        let k = self.lnode[e as usize];
        self.lct.path_add(k, k, d);
    }
}

fn find(uf: &mut [u32], x: u32) -> u32 {
    let mut r = x;
    while uf[r as usize] != r {
        r = uf[r as usize];
    }
    let mut y = x;
    while uf[y as usize] != r {
        let next = uf[y as usize];
        uf[y as usize] = r;
        y = next;
    }
    r
}

/// Joins the sets of `a` and `b`; false if they were one set already.
fn union(uf: &mut [u32], a: u32, b: u32) -> bool {
    let (ra, rb) = (find(uf, a), find(uf, b));
    if ra == rb {
        return false;
    }
    uf[ra.max(rb) as usize] = ra.min(rb);
    true
}

#[cfg(test)]
mod tests {
    use super::TwoEdge;
    use crate::rng::Rng;

    /// The oracle: the live multigraph as an edge list, connectivity by BFS and
    /// 2-edge-connectivity by deleting each edge in turn.
    #[derive(Default)]
    struct Oracle {
        n: usize,
        edges: Vec<Option<[u32; 2]>>,
    }

    impl Oracle {
        fn reach(&self, a: u32, skip: usize) -> Vec<bool> {
            self.reach_by(a, |i| i != skip)
        }

        /// The nodes reached from `a` over the live edges whose ids `keep` accepts.
        fn reach_by(&self, a: u32, keep: impl Fn(usize) -> bool) -> Vec<bool> {
            let mut seen = vec![false; self.n];
            seen[a as usize] = true;
            let mut stack = vec![a];
            while let Some(x) = stack.pop() {
                for (i, e) in self.edges.iter().enumerate() {
                    let Some([p, q]) = *e else { continue };
                    if !keep(i) {
                        continue;
                    }
                    for (s, t) in [(p, q), (q, p)] {
                        if s == x && !seen[t as usize] {
                            seen[t as usize] = true;
                            stack.push(t);
                        }
                    }
                }
            }
            seen
        }

        /// Per pair: connected, 2-edge-connected.
        fn relations(&self) -> Vec<Vec<(bool, bool)>> {
            let n = self.n;
            let base: Vec<Vec<bool>> = (0..n as u32).map(|a| self.reach(a, usize::MAX)).collect();
            let mut two: Vec<Vec<bool>> = base.clone();
            for (i, e) in self.edges.iter().enumerate() {
                if e.is_none() {
                    continue;
                }
                for (a, row) in two.iter_mut().enumerate() {
                    let r = self.reach(a as u32, i);
                    for (t, reached) in row.iter_mut().zip(r) {
                        *t &= reached;
                    }
                }
            }
            (0..n)
                .map(|a| (0..n).map(|b| (base[a][b], two[a][b])).collect())
                .collect()
        }
    }

    /// What deleting tree edge `e` must do, read off the oracle and the forest the
    /// structure reports (`tree`): the non-tree edges crossing the cut, and the vertices
    /// the two interleaved searches visit before the smaller side runs out (`2|A|` if
    /// `a`'s side `A` is not larger, else `2|B| + 1`: they alternate, `a`'s first).
    fn cut_model(o: &Oracle, tree: &[bool], e: u32) -> (Vec<u32>, u64) {
        let Some([a, b]) = o.edges[e as usize] else {
            unreachable!("a live edge")
        };
        let forest = |i: usize| i != e as usize && tree[i];
        let side_a = o.reach_by(a, forest);
        let side_b = o.reach_by(b, forest);
        let crossing = (0..o.edges.len())
            .filter(|&f| f != e as usize && !tree[f])
            .filter(|&f| {
                o.edges[f].is_some_and(|[p, q]| {
                    side_a[p as usize] && side_b[q as usize]
                        || side_b[p as usize] && side_a[q as usize]
                })
            })
            .map(|f| f as u32)
            .collect();
        let size = |side: &[bool]| side.iter().filter(|&&x| x).count() as u64;
        let (na, nb) = (size(&side_a), size(&side_b));
        let scanned = if na <= nb { 2 * na } else { 2 * nb + 1 };
        (crossing, scanned)
    }

    /// Random insert/delete sequences on small multigraphs (parallel edges, loops): after
    /// every operation, every pair's answers agree with the oracle and `check` passes;
    /// the accessors agree with the oracle's edge list; the tree edges are a spanning
    /// forest that changes only as stated (a new edge between two trees joins it, a
    /// deleted tree edge leaves it, with one of the edges crossing its cut as replacement
    /// if any); the counters are exact.
    /// Returns the number of (operation, pair) disagreements, stopping at the first
    /// operation with one (0 for the real structure).
    fn run(seed: u64, rounds: usize, skip_recover: bool) -> usize {
        let mut rng = Rng::new(seed);
        let mut swaps = 0;
        // The broken variant is held to the answers and `check` only.
        let strict = !skip_recover;
        for round in 0..rounds {
            let n = 2 + rng.index(7);
            let mut t = TwoEdge::new(n);
            t.skip_recover = skip_recover;
            let mut o = Oracle {
                n,
                ..Oracle::default()
            };
            let mut live: Vec<u32> = Vec::new();
            let mut next_id = 0u32;
            let mut expected = super::TwoEdgeCounters::default();
            for op in 0..40 {
                let insert = live.is_empty() || rng.index(100) < 55;
                let tree_before: Vec<bool> = (0..next_id).map(|e| t.is_tree_edge(e)).collect();
                if insert {
                    // Reuse a dead id now and then (stable ids are reused by Frink).
                    let e = match (0..next_id).find(|&e| o.edges[e as usize].is_none()) {
                        Some(e) if rng.index(3) == 0 => e,
                        _ => {
                            next_id += 1;
                            o.edges.push(None);
                            next_id - 1
                        }
                    };
                    let a = rng.index(n) as u32;
                    // Loops now and then, parallel edges often (few nodes).
                    let b = if rng.index(10) == 0 {
                        a
                    } else {
                        rng.index(n) as u32
                    };
                    let joins = a != b && !o.reach(a, usize::MAX)[b as usize];
                    t.insert(e, a, b);
                    o.edges[e as usize] = Some([a, b]);
                    live.push(e);
                    expected.inserts += 1;
                    if strict {
                        assert_eq!(t.is_tree_edge(e), joins, "round {round} op {op}: {e}");
                        for f in (0..next_id).filter(|&f| f != e) {
                            assert_eq!(t.is_tree_edge(f), tree_before[f as usize], "{f}");
                        }
                    }
                } else {
                    let e = live.swap_remove(rng.index(live.len()));
                    let was_tree = t.is_tree_edge(e);
                    let (crossing, scanned) = cut_model(&o, &tree_before, e);
                    t.delete(e);
                    o.edges[e as usize] = None;
                    expected.deletes += 1;
                    expected.cuts += u64::from(was_tree);
                    let mut tree_now: Vec<bool> = (0..next_id).map(|f| t.is_tree_edge(f)).collect();
                    assert!(!tree_now[e as usize], "round {round} op {op}: {e} deleted");
                    if strict && was_tree && !crossing.is_empty() {
                        expected.swaps += 1;
                        expected.scanned += scanned;
                        expected.recovered += crossing.len() as u64 - 1;
                        // Exactly one crossing edge joins the forest.
                        let joined: Vec<&u32> =
                            crossing.iter().filter(|&&f| tree_now[f as usize]).collect();
                        assert_eq!(joined.len(), 1, "round {round} op {op}: swap {joined:?}");
                        tree_now[*joined[0] as usize] = false;
                    }
                    let mut unchanged = tree_before;
                    unchanged[e as usize] = false;
                    if strict {
                        assert_eq!(tree_now, unchanged, "round {round} op {op}: forest");
                    }
                }
                assert_eq!(
                    (
                        t.counters().inserts,
                        t.counters().deletes,
                        t.counters().cuts
                    ),
                    (expected.inserts, expected.deletes, expected.cuts)
                );
                if strict {
                    assert_eq!(t.counters(), expected, "round {round} op {op}");
                }
                assert_eq!((t.node_count(), t.edge_count()), (n, live.len()));
                for e in 0..next_id + 2 {
                    let ends = o.edges.get(e as usize).copied().flatten();
                    assert_eq!(t.ends(e), ends, "round {round} op {op}: edge {e}");
                    assert_eq!(t.contains(e), ends.is_some(), "edge {e}");
                }
                let components = (0..n as u32)
                    .filter(|&x| o.reach(x, usize::MAX).iter().position(|&r| r) == Some(x as usize))
                    .count();
                let forest = (0..next_id).filter(|&f| t.is_tree_edge(f)).count();
                if strict {
                    assert_eq!(
                        forest,
                        n - components,
                        "round {round} op {op}: spanning forest"
                    );
                }
                let rel = o.relations();
                let mut wrong = 0;
                for a in 0..n as u32 {
                    for b in 0..n as u32 {
                        let (c, two) = rel[a as usize][b as usize];
                        wrong += usize::from(t.connected(a, b) != c);
                        wrong += usize::from(t.two_edge_connected(a, b) != two);
                    }
                }
                if wrong > 0 {
                    assert!(skip_recover, "round {round} op {op}: {wrong} wrong answers");
                    return wrong;
                }
                if let Err(m) = t.check() {
                    assert!(skip_recover, "round {round} op {op}: {m}");
                    return 1;
                }
            }
            swaps += t.counters().swaps;
        }
        assert!(swaps > 100, "only {swaps} swaps exercised");
        0
    }

    #[test]
    fn agrees_with_the_oracle_after_every_operation() {
        assert_eq!(run(41, 1500, false), 0);
    }

    /// The oracle comparison and `check` catch a broken swap (the other crossing edges
    /// not covered again).
    #[test]
    fn a_broken_swap_is_caught() {
        let mut caught = 0;
        for seed in 0..20 {
            caught += usize::from(run(100 + seed, 200, true) > 0);
        }
        assert!(caught >= 18, "caught {caught} of 20");
    }

    /// `bytes` counts 21 bytes per edge-id slot, 24 bytes per incidence list plus 4 per
    /// slot of its capacity, and per node two link–cut nodes and a 4-byte mark.
    #[test]
    fn bytes_count_id_slots_incidence_capacity_and_nodes() {
        let node = 2 * super::NODE_BYTES + 4;
        let mut t = TwoEdge::new(5);
        assert_eq!(t.bytes(), 5 * (24 + node));
        // Loops take an id slot and no incidence.
        t.insert(9, 3, 3);
        assert_eq!(t.bytes(), 10 * 21 + 5 * (24 + node));
        for (e, [a, b]) in [[0, 1], [1, 2], [2, 0], [0, 1], [4, 0]]
            .into_iter()
            .enumerate()
        {
            t.insert(e as u32, a, b);
        }
        let capacity: Vec<usize> = t.adj.iter().map(Vec::capacity).collect();
        assert!(capacity[0] >= 4 && capacity[3] == 0, "{capacity:?}");
        let slots: usize = capacity.iter().sum();
        assert_eq!(t.bytes(), 10 * 21 + 5 * (24 + node) + 4 * slots);
    }

    /// `check` fails on a corrupted cover count, and on a tree edge whose cover count is
    /// off only by the count of another edge (both directions).
    #[test]
    fn check_catches_a_corrupted_cover_count() {
        // A 4-cycle 0-1-2-3 plus a chord 0-2: tree edges get covers 1 or 2.
        let mut t = TwoEdge::new(4);
        for (e, [a, b]) in [[0, 1], [1, 2], [2, 3], [3, 0], [0, 2]]
            .into_iter()
            .enumerate()
        {
            t.insert(e as u32, a, b);
        }
        assert_eq!(t.check(), Ok(()));
        assert!(t.two_edge_connected(0, 3) && t.two_edge_connected(1, 3));
        let tree: Vec<u32> = (0..5).filter(|&e| t.is_tree_edge(e)).collect();
        assert_eq!(tree.len(), 3);
        for d in [1, -1] {
            let mut bad = t.clone();
            bad.corrupt_cover(tree[1], d);
            let m = bad.check().expect_err("corrupted cover count accepted");
            assert!(m.contains("cover count"), "{m}");
        }
        // Deleting two cycle edges leaves bridges the structure reports.
        t.delete(4);
        t.delete(3);
        assert_eq!(t.check(), Ok(()));
        assert!(t.connected(0, 3) && !t.two_edge_connected(0, 3));
    }

    /// `check` fails on a malformed edge record: an absent edge that keeps its link-cut
    /// node or one incidence position, a loop with an incidence position, a tree edge
    /// whose link-cut node is cut from one of its ends.
    #[test]
    fn check_catches_malformed_edge_records() {
        let mut t = TwoEdge::new(4);
        for (e, [a, b]) in [[0, 1], [1, 2], [2, 2], [2, 3]].into_iter().enumerate() {
            t.insert(e as u32, a, b);
        }
        t.insert(4, 0, 3);
        t.delete(4);
        assert_eq!(t.check(), Ok(()));
        let expect = |bad: &mut TwoEdge, what: &str| {
            let m = bad.check().expect_err(what);
            assert!(m.contains(what), "{m}");
        };
        let mut bad = t.clone();
        bad.lnode[4] = 6;
        expect(&mut bad, "still listed");
        let mut bad = t.clone();
        bad.pos[4][1] = 0;
        expect(&mut bad, "still listed");
        let mut bad = t.clone();
        bad.pos[2][0] = 0;
        expect(&mut bad, "malformed");
        let mut bad = t.clone();
        let k = bad.lnode[3];
        bad.lct.cut(k, 3);
        expect(&mut bad, "tree edge 3 not linked");
    }

    /// `check` fails when two forest trees, or an unused tree-edge node and a forest
    /// tree, are joined in the link–cut tree, whichever trees they are (not only
    /// consecutive ones).
    #[test]
    fn check_catches_joined_link_cut_trees() {
        // Three forest trees {0, 1}, {2, 3}, {4, 5}; tree-edge nodes 6.. (7 and 8 used).
        let mut t = TwoEdge::new(6);
        for (e, [a, b]) in [[0, 1], [2, 3], [4, 5]].into_iter().enumerate() {
            t.insert(e as u32, a, b);
        }
        assert_eq!(t.check(), Ok(()));
        let mut bad = t.clone();
        bad.lct.link(0, 4); // the first and the last tree
        let m = bad.check().expect_err("joined trees accepted");
        assert!(m.contains("joined"), "{m}");
        let free = *t.free.last().expect("an unused tree-edge node");
        let mut bad = t.clone();
        bad.lct.link(free, 5); // an unused node into the last tree
        let m = bad.check().expect_err("linked unused node accepted");
        assert!(m.contains("still linked"), "{m}");
    }
}

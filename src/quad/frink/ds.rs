//! [`DiksStanczyk`]: Frink's reduction driven as Diks and Stańczyk describe it (SOFSEM
//! 2010, "Perfect matching for biconnected cubic graphs in O(n log² n) time"): a
//! forbidden edge that travels (Biedl–Bose–Demaine–Lubiw, J. Algorithms 38(1), 2001,
//! so that Appendix A's case (iv) never arises), and the choice between the two
//! reconnections made from a fully dynamic connectivity structure and a dynamic tree
//! with LCA queries instead of a dynamic 2-edge-connectivity structure.
//!
//! # Guarantee
//! Every reconnection this strategy returns is connected and bridgeless (the proof is
//! below; `spec` F1 re-checks it independently on small graphs, and the tests check it
//! against the naive DFS at every step of random runs). With it [`super::solve`] returns
//! a perfect matching of every connected bridgeless cubic multigraph.
//!
//! # The decision (our derivation; the DS paper's case analysis could not be read here)
//! Only the DS abstract and the authors' slides were readable (errata T12, T13): they
//! "remove the reduction edge with its ends; two cases: the resulting graph is not
//! connected / is connected", using dynamic connectivity (HDT, O(log² n) amortised) and
//! Sleator–Tarjan trees (link, cut, change of root, LCA). The following decision uses
//! exactly those tools and is proved here. Let `H` be connected and bridgeless,
//! `e = uv` the reduction edge, `x1, x2` the other ends at `u`, `x3, x4` at `v`,
//! `H' = H − {u, v}`, and `T'` the maintained spanning forest of `H'`.
//! - **`H'` disconnected**: it has exactly two components (a component reached by a
//!   single edge of `u`, `v` would hang on a bridge of `H`), each holding two of the
//!   `x_i`, and `{x1, x2} | {x3, x4}` is impossible (`uv` would be a bridge). If `x1 ~ x3`
//!   the split is `{x1, x3} | {x2, x4}`: `H2` (`x1x4`, `x2x3`) joins the components by two
//!   edges and every bridge inside a component separates two `x_i` that the other
//!   component now joins, so `H2` passes and `H1` is disconnected. Else `x1 ~ x4` and
//!   `H1` passes. One connectivity query decides. Whether `H'` is connected needs no
//!   query: `H` is one tree, every cut the forest could not repair adds a tree, and `u`,
//!   `v` end as two of them, so `H'` is connected iff exactly two cuts went unrepaired.
//! - **`H'` connected**: every bridge `b` of `H'` is an edge of `T'` on the subtree
//!   spanning `x1..x4` (a bridge with all `x_i` on one side would be a bridge of `H`).
//!   `H_k` (`H'` plus two edges) is bridgeless iff each such bridge is crossed by one of
//!   the new edges. The sides of a tree edge split the `x_i`; a bridge is crossed by both
//!   pairs of `H1` and of `H2` unless its split is `{x1, x3} | {x2, x4}` (fatal for `H1`
//!   only) or `{x1, x4} | {x2, x3}` (fatal for `H2` only). The splits of the edges of one
//!   tree are pairwise compatible, and these two are not, so `T'` has edges of at most
//!   one of the two kinds: if it has a `{x1, x3} | {x2, x4}` edge, `H2` passes whatever
//!   the bridges are; if a `{x1, x4} | {x2, x3}` edge, `H1`; if neither, both. With `T'`
//!   rooted at `x1`, the three pairwise LCAs of `x2, x3, x4` lie on one root path, two of
//!   them coincide, and a third one that differs is strictly deeper: if it is
//!   `lca(x2, x4)`, the edge above it splits `{x2, x4} | {x1, x3}` (so `H2`); if
//!   `lca(x2, x3)`, `{x2, x3} | {x1, x4}` (so `H1`); if `lca(x3, x4)` or none, neither
//!   split exists (both pass; `H1` is taken). Equal `x_i` need no special case: an `x_i`
//!   adjacent to both `u` and `v` has degree 1 in `H'`, so it is a leaf of `T'` (or the
//!   root, when it is `x1`), and the rule then avoids the reconnection that would make
//!   it a loop (e.g. `x2 = x4` makes `lca(x2, x4) = x2` the deeper one: `H2`).
//!
//! No bridge query is needed: the decision reads only the *shape* of `T'`. That is why
//! dynamic connectivity (to keep `T'` spanning as `u`, `v` and their five edges go: the
//! replacement edges of Holm–de Lichtenberg–Thorup) and a dynamic tree mirroring `T'`
//! (for `make_root` and LCAs) suffice.
//!
//! # The travelling forbidden edge (BBDL)
//! A bridgeless cubic graph has a perfect matching avoiding any one edge `f`. The
//! strategy keeps one such `f` and reduces next to it, so that no lift ever meets the
//! reduction's new edge `p` matched (cases (ii) and (iv) of Appendix A never occur):
//! - **next to `f`**: an edge `e = uv` with `f = ux1`; the new edge at `x1` (the
//!   reduction's `p`) becomes the new `f`. A matching of the reduced graph avoiding `p`
//!   lifts by case (i) or (iii), and so avoids `f`.
//! - **digon at `f`** (neither end of `f` has a simple edge besides `f`: both ends lie on
//!   2-cycles of parallel edges): with `f = xo` and the digon `x ⇉ w`, reduce at `w`'s
//!   third edge `h = wy` (`u = w`, so `x1 = x2 = x`). `f` survives unchanged (`y ≠ o`,
//!   else `{x, w, o}` would hang on a bridge) and stays forbidden. A matching of the
//!   reduced graph avoiding `f` matches `x` through exactly one of the two new edges at
//!   `x`, so the lift is case (ii) or (iii), never (i) or (iv), and leaves `f` unmatched
//!   ([`DsCounters::digon_steps`]).
//!
//! By induction the final matching avoids `f`, and the base case's matched edge is
//! chosen to (`Strategy::forbidden`). If neither kind of reduction were found (never on
//! a connected bridgeless graph) the step would drop `f` and take the default reduction
//! ([`DsCounters::restarts`]); the lifts would then fall back on case (ii)/(iv).
//!
//! # Complexity
//! Per reduction: five edge deletions and two insertions in the connectivity structure
//! (O(log² n) amortised each, HDT Sec. 2), the mirrored links and cuts, one `make_root`
//! and four accesses for the three LCAs in the link–cut tree (O(log n) amortised), O(1)
//! for the edge choice. O(n log² n) in all, plus the load of the graph (one pass,
//! `Hdt::load`: O(m log n) in the worst case for its union–find, O(n) besides; the
//! link–cut tree from parent pointers, O(n)); each lift is O(1).
//! Memory: the connectivity structure, a link–cut tree over the nodes (16 bytes each,
//! `lct::PlainLct`).
//!
//! # Determinism
//! No randomness: the forest starts as the breadth-first tree from the smallest live node
//! (tree edges inserted first, in BFS order, then every other edge in node order); the
//! first forbidden edge is the first slot of node 0; candidates are
//! tried at the ends of `f` in edge-end order, edges in slot order; ties (both
//! reconnections pass) take `H1`.

use super::graph::{max_nodes_for_edge_ids, NONE};
use super::shared::{bfs_edge_order, non_tree_first, removed, ForbiddenEdge};
use super::{Candidate, Cubic, Reconnection, Reduction, Strategy};
use crate::dyngraph::hdt::{ForestChange, Hdt, MAX_EDGE_ID};
use crate::dyngraph::PlainLct;

/// A spanning forest kept under edge insertions and deletions, reporting every change of
/// the forest (the connectivity structure behind [`DiksStanczyk`]; also implemented
/// naively in the tests, as the reference).
pub(crate) trait SpanningForest {
    /// The edgeless graph on nodes `0..n`.
    fn with_nodes(n: usize) -> Self;
    /// The most nodes the structure takes without an id or count overflowing (and so
    /// without failing an assertion on one).
    fn max_nodes() -> usize
    where
        Self: Sized,
    {
        usize::MAX
    }
    /// Edge ids must be below this.
    fn max_edge_ids() -> usize
    where
        Self: Sized,
    {
        usize::MAX
    }
    /// Inserts edge `e = ab` (`a ≠ b`), pushing the forest's changes.
    fn insert(&mut self, e: u32, a: u32, b: u32, changes: &mut Vec<ForestChange>);
    /// Inserts `edges` (`[e, a, b]` each) in this order into the edgeless graph; the
    /// same as one [`SpanningForest::insert`] each, which is the default.
    fn load(&mut self, edges: &[[u32; 3]], changes: &mut Vec<ForestChange>) {
        for &[e, a, b] in edges {
            self.insert(e, a, b, changes);
        }
    }
    /// Deletes live edge `e`, pushing the forest's changes (a cut, then the replacement
    /// link if one exists).
    fn delete(&mut self, e: u32, changes: &mut Vec<ForestChange>);
    /// Whether live edge `e` is an edge of the forest.
    fn is_tree_edge(&self, e: u32) -> bool;
    /// Whether nodes `a` and `b` are connected.
    fn connected(&mut self, a: u32, b: u32) -> bool;
    /// The structure's own invariant check (for the specification's F3).
    fn check(&self) -> Result<(), String> {
        Ok(())
    }
}

impl SpanningForest for Hdt {
    fn with_nodes(n: usize) -> Self {
        Hdt::new(n)
    }
    fn max_nodes() -> usize {
        Hdt::max_vertices()
    }
    fn max_edge_ids() -> usize {
        MAX_EDGE_ID as usize
    }
    fn insert(&mut self, e: u32, a: u32, b: u32, changes: &mut Vec<ForestChange>) {
        Hdt::insert(self, e, a, b, changes);
    }
    fn load(&mut self, edges: &[[u32; 3]], changes: &mut Vec<ForestChange>) {
        Hdt::load(self, edges, changes);
    }
    fn delete(&mut self, e: u32, changes: &mut Vec<ForestChange>) {
        Hdt::delete(self, e, changes);
    }
    fn is_tree_edge(&self, e: u32) -> bool {
        Hdt::is_tree_edge(self, e)
    }
    fn connected(&mut self, a: u32, b: u32) -> bool {
        Hdt::connected(self, a, b)
    }
    fn check(&self) -> Result<(), String> {
        Hdt::check(self)
    }
}

/// What the steps of one run did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DsCounters {
    /// Steps where `H' = H − {u, v}` was disconnected (one connectivity query decided).
    pub disconnected: u64,
    /// Steps where `H'` was connected and the tree forced one reconnection.
    pub forced: u64,
    /// Steps where `H'` was connected and both reconnections pass (`H1` taken).
    pub free: u64,
    /// Steps at the third edge of a digon next to the forbidden edge (which stays).
    pub digon_steps: u64,
    /// Steps that found neither kind of reduction and dropped the forbidden edge (none on
    /// a connected bridgeless graph; counted so that the tests can say so).
    pub restarts: u64,
    /// Cuts of the spanning forest (tree edges deleted).
    pub cuts: u64,
    /// Replacement edges linked after a cut.
    pub replacements: u64,
    /// Edge level increments in the connectivity structure (HDT's amortisation).
    pub promotions: u64,
    /// The highest HDT level any edge reached.
    pub max_level: u32,
    /// Bytes held by the connectivity structure at the end.
    pub forest_bytes: u64,
}

/// Sums of several runs (`max_level`: the maximum), e.g. over the components of a mesh.
impl std::ops::AddAssign for DsCounters {
    fn add_assign(&mut self, c: DsCounters) {
        self.disconnected += c.disconnected;
        self.forced += c.forced;
        self.free += c.free;
        self.digon_steps += c.digon_steps;
        self.restarts += c.restarts;
        self.cuts += c.cuts;
        self.replacements += c.replacements;
        self.promotions += c.promotions;
        self.max_level = self.max_level.max(c.max_level);
        self.forest_bytes += c.forest_bytes;
    }
}

/// The strategy over any [`SpanningForest`]; [`DiksStanczyk`] is it over [`Hdt`].
pub(crate) struct Ds<F> {
    forest: Option<F>,
    lct: PlainLct,
    fe: ForbiddenEdge,
    /// The reduction [`Strategy::choose`] has prepared the forest for.
    pending: Option<Candidate>,
    changes: Vec<ForestChange>,
    counters: DsCounters,
}

impl<F> Default for Ds<F> {
    fn default() -> Self {
        Ds {
            forest: None,
            lct: PlainLct::default(),
            fe: ForbiddenEdge::default(),
            pending: None,
            changes: Vec::new(),
            counters: DsCounters::default(),
        }
    }
}

impl<F: SpanningForest> Ds<F> {
    pub(crate) fn counters(&self) -> DsCounters {
        DsCounters {
            digon_steps: self.fe.digon_steps,
            restarts: self.fe.restarts,
            ..self.counters
        }
    }

    /// Mirrors the forest's pending changes into the link–cut tree.
    fn mirror(&mut self) {
        for c in self.changes.drain(..) {
            match c {
                ForestChange::Link { a, b, .. } => {
                    self.lct.link(a, b);
                }
                ForestChange::Cut { a, b, .. } => {
                    self.counters.cuts += 1;
                    self.lct.cut(a, b);
                }
            }
        }
    }

    fn forest(&mut self) -> &mut F {
        match &mut self.forest {
            Some(f) => f,
            None => unreachable!("Strategy::start loads the forest first"),
        }
    }

    /// The reconnection for `cand`, with the forest already reduced to `H'`: the
    /// decision of the module documentation. `h_connected`: whether `H'` is connected.
    fn decide(&mut self, cand: &Candidate, h_connected: bool) -> Reconnection {
        let [x1, x2, x3, x4] = cand.x;
        if !h_connected {
            self.counters.disconnected += 1;
            // {x1, x3} | {x2, x4} forces H2; otherwise {x1, x4} | {x2, x3} forces H1.
            return if self.forest().connected(x1, x3) {
                Reconnection::H2
            } else {
                Reconnection::H1
            };
        }
        let lct = &mut self.lct;
        // Rooted at x1, the pairwise LCAs of x2, x3, x4: two coincide and the third, if
        // different, is deeper, below the edge that splits its pair from the other two.
        // Each `walk_to` answers the LCA with the node exposed before: four accesses
        // after the re-rooting, instead of six for three `lca` calls.
        lct.make_root(x1);
        lct.walk_to(x2);
        let l23 = lct.walk_to(x3);
        let l34 = lct.walk_to(x4);
        let l24 = lct.walk_to(x2);
        if l23 == l34 && l24 != l23 {
            // {x2, x4} | {x1, x3}: H2 crosses it.
            self.counters.forced += 1;
            Reconnection::H2
        } else if l24 == l34 && l23 != l24 {
            // {x2, x3} | {x1, x4}: H1 crosses it.
            self.counters.forced += 1;
            Reconnection::H1
        } else {
            debug_assert!(l23 == l24, "three distinct pairwise LCAs in a tree");
            self.counters.free += 1;
            Reconnection::H1
        }
    }
}

/// The parent of every node in the forest made by the `Link` changes `links` (rooted
/// at each tree's smallest node; `NONE` at a root). O(n).
fn forest_parents(n: usize, links: &[ForestChange]) -> Vec<u32> {
    let mut deg = vec![0u32; n + 1];
    for c in links {
        if let ForestChange::Link { a, b, .. } = *c {
            deg[a as usize + 1] += 1;
            deg[b as usize + 1] += 1;
        }
    }
    for i in 0..n {
        deg[i + 1] += deg[i];
    }
    let mut fill = deg.clone();
    let mut adj = vec![0u32; deg[n] as usize];
    for c in links {
        if let ForestChange::Link { a, b, .. } = *c {
            adj[fill[a as usize] as usize] = b;
            fill[a as usize] += 1;
            adj[fill[b as usize] as usize] = a;
            fill[b as usize] += 1;
        }
    }
    let mut parent = vec![NONE; n];
    let mut seen = vec![false; n];
    let mut stack = Vec::new();
    for s in 0..n {
        if seen[s] {
            continue;
        }
        seen[s] = true;
        stack.push(s as u32);
        while let Some(x) = stack.pop() {
            for &y in &adj[deg[x as usize] as usize..deg[x as usize + 1] as usize] {
                if !seen[y as usize] {
                    seen[y as usize] = true;
                    parent[y as usize] = x;
                    stack.push(y);
                }
            }
        }
    }
    parent
}

impl<F: SpanningForest> Strategy for Ds<F> {
    /// The forest's limits, its node count and the edge ids of a run (for [`Hdt`] the
    /// Euler-tour pool's ids bind: about 55.06M nodes).
    fn max_nodes(&self) -> usize {
        F::max_nodes().min(max_nodes_for_edge_ids(F::max_edge_ids()))
    }

    fn start(&mut self, g: &Cubic) {
        let n = g.node_capacity();
        let mut forest = F::with_nodes(n);
        self.counters = DsCounters::default();
        self.pending = None;
        self.changes.clear();
        // Breadth-first tree edges first, so that the forest starts as a BFS tree
        // (shallow: the pieces a reduction cuts off are small), then the other edges;
        // loaded in one pass (`SpanningForest::load`).
        let edges = bfs_edge_order(g, None);
        forest.load(&edges, &mut self.changes);
        drop(edges);
        self.forest = Some(forest);
        // The link–cut mirror of the initial forest in O(n) (instead of one link per
        // edge): parents by a search over the linked edges, every node its own path.
        self.lct = PlainLct::with_parents(&forest_parents(n, &self.changes));
        self.changes.clear();
        self.fe = ForbiddenEdge::start(g);
    }

    fn pick(&mut self, g: &Cubic) -> Option<Candidate> {
        let forest = self.forest.as_ref();
        self.fe
            .pick(g, |e| forest.is_some_and(|f| f.is_tree_edge(e)))
    }

    fn choose(&mut self, g: &mut Cubic, cand: &Candidate) -> Option<Reconnection> {
        let mut changes = std::mem::take(&mut self.changes);
        let forest = self.forest();
        for e in non_tree_first(removed(cand), |e| forest.is_tree_edge(e)) {
            forest.delete(e, &mut changes);
        }
        let links = changes
            .iter()
            .filter(|c| matches!(c, ForestChange::Link { .. }))
            .count();
        // Every cut without a replacement adds a tree; `u` and `v` end as two of them,
        // so `H'` (one tree before, as `H` is connected) is connected iff exactly two
        // trees were added.
        let h_connected = changes.len() - links == links + 2;
        self.counters.replacements += links as u64;
        self.changes = changes;
        self.mirror();
        if let Some(forest) = &self.forest {
            super::spec::ds_forest(g, cand, |e| forest.is_tree_edge(e), || forest.check());
        }
        self.pending = Some(*cand);
        Some(self.decide(cand, h_connected))
    }

    fn applied(&mut self, g: &Cubic, r: &Reduction) {
        debug_assert_eq!(self.pending.take(), Some(r.cand), "applied without choose");
        let mut changes = std::mem::take(&mut self.changes);
        let forest = self.forest();
        for e in r.new {
            let [a, b] = g.ends(e);
            forest.insert(e, a, b, &mut changes);
        }
        self.changes = changes;
        self.mirror();
        self.fe.applied(r);
    }

    fn forbidden(&self) -> Option<u32> {
        self.fe.get()
    }
}

/// The Diks–Stańczyk strategy: the travelling forbidden edge and the decision of the
/// module documentation, over Holm–de Lichtenberg–Thorup dynamic connectivity and a
/// link–cut tree. O(log² n) amortised per reduction.
#[derive(Default)]
pub struct DiksStanczyk(Ds<Hdt>);

impl DiksStanczyk {
    /// A fresh strategy.
    pub fn new() -> Self {
        Self::default()
    }

    /// What the steps of the last run did.
    pub fn counters(&self) -> DsCounters {
        let mut c = self.0.counters();
        if let Some(f) = &self.0.forest {
            let s = f.stats();
            c.promotions = s.promotions;
            c.max_level = s.max_level;
            c.forest_bytes = f.bytes() as u64;
        }
        c
    }
}

impl Strategy for DiksStanczyk {
    fn max_nodes(&self) -> usize {
        self.0.max_nodes()
    }
    fn start(&mut self, g: &Cubic) {
        self.0.start(g);
    }
    fn pick(&mut self, g: &Cubic) -> Option<Candidate> {
        self.0.pick(g)
    }
    fn choose(&mut self, g: &mut Cubic, cand: &Candidate) -> Option<Reconnection> {
        self.0.choose(g, cand)
    }
    fn applied(&mut self, g: &Cubic, r: &Reduction) {
        self.0.applied(g, r);
    }
    fn forbidden(&self) -> Option<u32> {
        self.0.forbidden()
    }
}

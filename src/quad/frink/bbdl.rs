//! [`BiedlBoseDemaineLubiw`]: Frink's reduction driven as Biedl, Bose, Demaine and Lubiw
//! describe it ("Efficient algorithms for Petersen's matching theorem", J. Algorithms
//! 38(1), 2001): a travelling forbidden edge, so that Appendix A's case (iv) never
//! arises, and the choice between the two reconnections decided by querying a fully
//! dynamic 2-edge-connectivity structure ([`crate::dyngraph::TwoEdge`]).
//!
//! # Guarantee
//! Every reconnection this strategy returns is connected and bridgeless (proof below;
//! `spec` F1 re-checks it independently on small graphs, and the tests check it against
//! the naive DFS at every step of random runs). With it [`super::solve`] returns a
//! perfect matching of every connected bridgeless cubic multigraph.
//!
//! # The decision
//! The structure mirrors the current graph `H`. For the reduction `e = uv` (`x1, x2` the
//! other ends at `u`, `x3, x4` at `v`) the five edges at `u`, `v` are deleted, `H1`'s
//! edges `x1x3`, `x2x4` inserted, and `H1` is taken iff `x1` is 2-edge-connected to
//! `x2`, `x3` and `x4` in it (three queries; 2-edge-connectivity is an equivalence
//! relation, so the four are then pairwise 2-edge-connected). Otherwise the two edges are
//! deleted again, `H2`'s `x1x4`, `x2x3` inserted, and `H2` is checked the same way
//! (Frink: it passes; if it did not, the step reports no reconnection).
//!
//! **Claim.** With `H` connected and bridgeless and `Hk` either reconnection, `Hk` is
//! connected and bridgeless iff `x1..x4` are pairwise 2-edge-connected in `Hk`.
//! *Proof.* (⇒) In a connected bridgeless graph every two nodes are 2-edge-connected.
//! (⇐) Connected: every component of `H' = H − {u, v}` holds an `x_i` (`H` is
//! connected, so each component is reached from `u` or `v` by an edge, whose other end is
//! an `x_i`), and the `x_i` are connected to each other in `Hk`. Bridgeless: let `b` be a
//! bridge of `Hk`. It is not a new edge (a new edge joins two `x_i`, which its removal
//! would separate), so `b` is an edge of `H'`. As the `x_i` are 2-edge-connected, they all
//! lie in one component of `Hk − b`; let `S` be the other one. `S` holds no `x_i`, so no
//! edge of `H` at `u` or `v` ends in `S` and no new edge does either; hence the edges of
//! `H` leaving `S` are those of `Hk` leaving `S`, i.e. `b` alone, and `S` misses `u`:
//! `b` is a bridge of `H`, a contradiction. Loops need no special case: a loop is never a
//! bridge, and a reconnection with a loop (`x1 = x3`, say) fails the test, as the looped
//! node's third edge separates it from the other `x_i`. ∎
//!
//! # The reduction edge
//! As [`super::DiksStanczyk`] (module `ds`, errata T13): next to the forbidden edge `f`
//! with `f` as the candidate's `ux1`, so the reduction's `p` becomes the new `f`; when
//! neither end of `f` has a simple edge besides `f`, at the third edge of a digon at an
//! end of `f` (the digon rule, this crate's own: BBDL do not treat multigraph digons),
//! keeping `f`. Among the candidates next to `f`, the one removing the fewest forest
//! edges of the 2-edge structure is taken (each tree-edge deletion may cost a swap; a
//! non-tree deletion is one path update). The reason no lift meets case (iv) is BBDL's:
//! module `ds`, "The travelling forbidden edge".
//!
//! # Complexity
//! Per reduction, in the 2-edge structure: five deletions, then two insertions and
//! three queries when `H1` passes, or six updates (`H1`'s two edges inserted and deleted
//! again, both non-tree edges then, and `H2`'s two inserted) and four to six queries
//! (one to three for `H1`, three for `H2`) when it fails; O(1) for the choice. With HDT Sec. 3 that would be
//! O(log⁴ n) amortised per step as BBDL state. The structure here ([`crate::dyngraph::TwoEdge`]) is
//! weaker: O(log n) amortised per query and per non-tree update, but O(s + k log n) per
//! tree-edge deletion (`s`: degree sum of the smaller side of the cut, `k`: edges
//! covering it), so O(n² log n) in the worst case in all; measured on the B family in
//! docs/benchmarks.md. Memory: the structure, O(n).
//!
//! # Determinism
//! No randomness: the forest starts as the breadth-first tree rooted at the node that a
//! breadth-first search from the smallest live node reaches last (tree edges inserted
//! first, in BFS order, then the other edges in node order; rooted far from where the
//! reductions start, the tree loses leaves first rather than its root: the vertices
//! searched on B6 fell from 124M to 53M); the
//! first forbidden edge is the first slot of node 0; candidates are tried at the ends of
//! `f` in edge-end order, edges in slot order; ties (both reconnections pass) take `H1`.

use super::graph::max_nodes_for_edge_ids;
use super::shared::{bfs_edge_order, non_tree_first, ForbiddenEdge};
use super::{Candidate, Cubic, Reconnection, Reduction, Strategy};
use crate::dyngraph::two_edge::{TwoEdge, TwoEdgeCounters, MAX_ID};

/// What the steps of one run did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct BbdlCounters {
    /// Steps that took `H1` (it passed the 2-edge test).
    pub took_h1: u64,
    /// Steps that took `H2` after `H1` failed.
    pub took_h2: u64,
    /// 2-edge-connectivity queries.
    pub queries: u64,
    /// Steps at the third edge of a digon next to the forbidden edge (which stays).
    pub digon_steps: u64,
    /// Steps that found neither kind of reduction and dropped the forbidden edge (none on
    /// a connected bridgeless graph; counted so that the tests can say so).
    pub restarts: u64,
    /// The 2-edge structure's own counters (cuts, swaps, scanned vertices...).
    pub structure: TwoEdgeCounters,
    /// Bytes held by the structure at the end.
    pub structure_bytes: u64,
}

/// The Biedl–Bose–Demaine–Lubiw strategy: the travelling forbidden edge and the decision
/// by 2-edge-connectivity queries (module documentation, with the proof and the bound).
#[derive(Default)]
pub struct BiedlBoseDemaineLubiw {
    te: Option<TwoEdge>,
    fe: ForbiddenEdge,
    /// The reduction, reconnection and new edge ids the structure now holds.
    pending: Option<(Candidate, Reconnection, [u32; 2])>,
    counters: BbdlCounters,
}

impl BiedlBoseDemaineLubiw {
    /// A fresh strategy.
    pub fn new() -> Self {
        Self::default()
    }

    /// What the steps of the last run did.
    pub fn counters(&self) -> BbdlCounters {
        let mut c = BbdlCounters {
            digon_steps: self.fe.digon_steps,
            restarts: self.fe.restarts,
            ..self.counters
        };
        if let Some(te) = &self.te {
            c.structure = te.counters();
            c.structure_bytes = te.bytes() as u64;
        }
        c
    }

    fn te(&mut self) -> &mut TwoEdge {
        match &mut self.te {
            Some(t) => t,
            None => unreachable!("Strategy::start loads the structure first"),
        }
    }

    /// Whether `x1` is 2-edge-connected to `x2`, `x3`, `x4` in the structure.
    fn all_two_edge_connected(&mut self, x: [u32; 4]) -> bool {
        let mut ok = true;
        for &y in &x[1..] {
            self.counters.queries += 1;
            if !self.te().two_edge_connected(x[0], y) {
                ok = false;
                break;
            }
        }
        ok
    }

    /// Applies `recon` to `g` only to learn its new edges' ids and ends (undone at once),
    /// and inserts them into the structure.
    fn insert_new(&mut self, g: &mut Cubic, cand: &Candidate, recon: Reconnection) -> [u32; 2] {
        let r = g.reduce(cand, recon);
        let ends = r.new.map(|e| g.ends(e));
        g.undo(&r);
        let te = self.te();
        for (e, [a, b]) in r.new.into_iter().zip(ends) {
            te.insert(e, a, b);
        }
        r.new
    }
}

/// The node a breadth-first search of `g` from live node `s` reaches last. O(n).
fn farthest(g: &Cubic, s: u32) -> u32 {
    let mut seen = vec![false; g.node_capacity()];
    let mut queue = std::collections::VecDeque::from([s]);
    seen[s as usize] = true;
    let mut last = s;
    while let Some(x) = queue.pop_front() {
        last = x;
        for e in g.incident(x) {
            let y = g.other(e, x);
            if !seen[y as usize] {
                seen[y as usize] = true;
                queue.push_back(y);
            }
        }
    }
    last
}

impl Strategy for BiedlBoseDemaineLubiw {
    /// [`TwoEdge`] takes node and edge ids below 2^29: about 214.7M nodes (the edge ids,
    /// `5n/2 − 2` of them, are the binding limit).
    fn max_nodes(&self) -> usize {
        (MAX_ID - 1).min(max_nodes_for_edge_ids(MAX_ID))
    }

    fn start(&mut self, g: &Cubic) {
        let n = g.node_capacity();
        let mut te = TwoEdge::new(n);
        self.counters = BbdlCounters::default();
        self.pending = None;
        // Breadth-first tree edges first (the forest starts as a shallow BFS tree, as in
        // module `ds`), then the other edges, each once. Rooted at the node last reached
        // from the first forbidden edge's node: the reductions start far from the root,
        // where cutting a node splits off small subtrees, instead of at the root, which
        // would split the tree into its largest branches.
        let start = (0..n as u32).find(|&x| g.is_alive(x));
        let root = start.map(|s| farthest(g, s));
        for [e, a, b] in bfs_edge_order(g, root) {
            te.insert(e, a, b);
        }
        self.te = Some(te);
        self.fe = ForbiddenEdge::start(g);
    }

    fn pick(&mut self, g: &Cubic) -> Option<Candidate> {
        let te = self.te.as_ref();
        self.fe.pick(g, |e| te.is_some_and(|t| t.is_tree_edge(e)))
    }

    fn choose(&mut self, g: &mut Cubic, cand: &Candidate) -> Option<Reconnection> {
        // `uv` last: cut first, it would split the forest between `u`'s two outer parts
        // and `v`'s, two large sides to search; cut last it is a bridge (no search).
        let five = [cand.a[0], cand.a[1], cand.b[0], cand.b[1], cand.e];
        let te = self.te();
        for e in non_tree_first(five, |e| te.is_tree_edge(e)) {
            te.delete(e);
        }
        let new1 = self.insert_new(g, cand, Reconnection::H1);
        let (recon, new) = if self.all_two_edge_connected(cand.x) {
            self.counters.took_h1 += 1;
            (Reconnection::H1, new1)
        } else {
            // With `H` connected and bridgeless both new edges are non-tree edges here,
            // so the order of their deletion is immaterial (no non-tree-first reordering
            // to do): a tree edge among them would join two components of `H'`, which
            // then has exactly two, each with two of the `x_i` (module `ds`, "`H'`
            // disconnected"), and `x1x3` or `x2x4` crossing them makes the split
            // `{x1, x4} | {x2, x3}`, where `H1` passes.
            for e in new1 {
                self.te().delete(e);
            }
            let new2 = self.insert_new(g, cand, Reconnection::H2);
            if !self.all_two_edge_connected(cand.x) {
                return None;
            }
            self.counters.took_h2 += 1;
            (Reconnection::H2, new2)
        };
        self.pending = Some((*cand, recon, new));
        Some(recon)
    }

    fn applied(&mut self, g: &Cubic, r: &Reduction) {
        let Some((cand, recon, new)) = self.pending.take() else {
            unreachable!("applied without choose")
        };
        debug_assert_eq!(cand, r.cand, "applied another reduction than chosen");
        if recon != r.recon || new != r.new {
            // Not this strategy's choice (a wrapper overrode it, e.g. the tests' broken
            // variant): make the structure hold the applied graph.
            let te = self.te();
            for e in new {
                te.delete(e);
            }
            for e in r.new {
                let [a, b] = g.ends(e);
                te.insert(e, a, b);
            }
        }
        self.fe.applied(r);
        if let Some(te) = &mut self.te {
            super::spec::bbdl_structure(g, te);
        }
    }

    fn forbidden(&self) -> Option<u32> {
        self.fe.get()
    }
}

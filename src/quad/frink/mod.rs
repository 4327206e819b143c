//! Frink's reduction: a perfect matching of a connected bridgeless cubic multigraph (the
//! dual graph of a closed triangulation) by repeatedly removing an edge's two ends and
//! reconnecting their four other neighbours, then lifting the base case's matching back
//! (tri-quad paper, Lemos–Ramaswami–Siqueira, Sec. 3.2 and Appendix A; Frink 1926, as
//! corrected in König's book; Biedl–Bose–Demaine–Lubiw, J. Algorithms 38(1), 2001).
//!
//! # Guarantee
//! [`solve`] returns a *perfect* matching of every connected bridgeless cubic multigraph
//! (Petersen's theorem, by Frink's constructive proof), and refuses (an error, no panic)
//! any other input: not cubic, disconnected, with a bridge or a loop. [`perfect_matching`]
//! applies it to the dual graph of a closed triangulation, which is cubic, connected and
//! bridgeless (every dual edge lies on the cycle of faces around either end of its
//! primal edge), so it always returns a perfect [`Pairing`].
//!
//! # Algorithm (Appendix A)
//! The graph `H` is stored in flat arrays ([`Cubic`]: per edge its two ends, per node its
//! three edge ids; ids stable, parallel edges distinct).
//! 1. **Reduction**, while more than two nodes are live: `u` is the live node of smallest
//!    id, `e = uv` its first simple edge in slot order ([`Cubic::candidate_at`]; a node
//!    with no simple edge lies on a triple edge, which in a connected cubic graph means
//!    the whole graph is the 2-node base). With `x1, x2` the other ends at `u` and
//!    `x3, x4` those at `v` (slot order, not necessarily distinct), `u`, `v` and their five
//!    edges are removed and either `H1` (`x1x3`, `x2x4`) or `H2` (`x1x4`, `x2x3`) is added.
//!    At least one is connected and bridgeless (Frink); the [`Strategy`] picks one that
//!    is. A record of the reduction is pushed on an explicit stack (no recursion).
//! 2. **Base case**: two nodes joined by three parallel edges; the first edge at the
//!    smaller node is matched.
//! 3. **Lifting**, records popped in reverse, the reduced graph `H_k` with its perfect
//!    matching `M_k`; the new edges are `p` (at `x1`) and `q` (at `x2`):
//!    - (i) neither matched: `M = M_k + uv`;
//!    - (ii) only `p = x1y` matched: `M = M_k − p + ux1 + vy`;
//!    - (iii) only `q = x2y'` matched: `M = M_k − q + ux2 + vy'`;
//!    - (iv) both matched: an `M_k`-alternating cycle through `p` is flipped first
//!      (module `cycle`: one Edmonds search in `H_k − p` between the ends of `p`), which
//!      leaves `p` unmatched, and then (i) or (iii) applies.
//!
//!    The reduction is undone exactly ([`Cubic::undo`]) and the matching rewritten as
//!    above, so after each lift the matching is perfect on the then-current graph.
//!
//! # Strategies
//! The choice between `H1` and `H2` is a [`Strategy`], which may also pick the reduction
//! edge itself ([`Strategy::pick`]; step 1 above is the default). [`Naive`] is the
//! reference: it applies `H1` tentatively and tests it by one iterative DFS lowpoint
//! computation (connected and bridgeless), else tests `H2` the same way: O(n) per step.
//! [`CoverTree`] (module `cover`, this crate's own design in the spirit of
//! Gawrychowski–Wasylkiewicz, ESA 2024, whose case analysis could not be read here; it is
//! not their algorithm) keeps a spanning tree of the current graph in a link–cut tree
//! ([`crate::dyngraph::Lct`]) with a cover count per tree edge, picks reductions for which the tree
//! changes only locally and decides them exactly in O(log n) amortised; it falls back to
//! a tree rebuild and a naive step when no such reduction is found (never observed on
//! the B family or the shared meshes). [`DiksStanczyk`] (module `ds`) reduces next to a
//! travelling forbidden edge (Biedl–Bose–Demaine–Lubiw), so case (iv) never occurs, and
//! decides each step from the shape of a spanning forest of `H − {u, v}` kept by
//! Holm–de Lichtenberg–Thorup dynamic connectivity ([`crate::dyngraph::Hdt`]) and mirrored in the
//! link–cut tree for LCA queries: O(log² n) amortised per step; the decision is derived
//! and proved in module `ds` (the DS paper's own case analysis could not be read;
//! errata T13). [`BiedlBoseDemaineLubiw`] (module `bbdl`) reduces next to the same
//! travelling forbidden edge and decides each step as BBDL do, by querying a fully
//! dynamic 2-edge-connectivity structure ([`TwoEdge`], from [`crate::dyngraph`]): `H1` is
//! applied and kept iff `x1` is 2-edge-connected to `x2`, `x3`, `x4` in it (sound and
//! complete, proved in module `bbdl`), else `H2`. BBDL's O(log⁴ n) per step assumes
//! HDT Sec. 3; [`TwoEdge`] keeps HDT's cover idea with exact cover counts but without
//! HDT's levels, so its tree-edge deletions search the smaller side of the cut (errata
//! T14).
//!
//! # Complexity
//! With [`Naive`]: O(n²) time in the worst case and in practice (n/2 reductions, each
//! one or two DFS of the current graph, which shrinks by two nodes per step: about
//! n²/4 node visits), plus O(n·α(n)) per case-(iv) lift for the Edmonds search (bounded
//! by the part of the graph it labels). With [`CoverTree`]: O(log n) amortised per
//! reduction plus O(n) per fallback step, O(n²) in the worst case, O(n log n) when no
//! fallback occurs; the case-(iv) searches come on top with either strategy (about a
//! quarter of the time on the B family, docs/benchmarks.md). With [`DiksStanczyk`]:
//! O(n log² n) amortised in all, no case (iv). With [`BiedlBoseDemaineLubiw`]: per step
//! O(log n) amortised per query and non-tree update of [`TwoEdge`], plus O(s + k log n)
//! per forest-edge deletion (`s` the degree sum of the smaller side of the cut, `k` the
//! edges covering it): O(n² log n) in the worst case, no case (iv); measured superlinear on
//! the B family (docs/benchmarks.md). Memory: O(n): the graph
//! (8 bytes per edge, `5n/2 − 2` edges ever created), one 72-byte record per reduction,
//! the DFS and search scratch (about 30 bytes per node); [`CoverTree`] adds about 80
//! bytes per node.
//!
//! # Determinism
//! No randomness: the output is a function of the graph (node and edge ids, slot order),
//! and for [`perfect_matching`] of the triangulation's face ids and corner slots (the
//! dual's nodes are the live faces in id order, its edges those of
//! [`Triangulation::edges`], in that order).
//!
//! # Specification
//! In debug builds and with the `invariants` feature, module `spec` checks F1 (the
//! chosen reduced graph is loop-free, and on small graphs connected and bridgeless by an
//! independent edge-removal test) after every reduction and F2 (the matching is perfect on the current graph)
//! after every lift and at the end.
//!
//! # Where the sources are loose
//! Appendix A writes case (ii) as `M = M_1 ∪ {ux1, vx3}`: `x1x3` must also be removed
//! (it is no edge of `H`, and `x1`, `x3` would be matched twice); likewise (iii). It
//! states case (iv)'s alternating cycle exists ("Frink proved that every edge in `M_1`
//! belongs to an alternating cycle") without saying how to find one; here it is an
//! augmenting path between the ends of `p` in `H_k − p` (see module `cycle`). Which edge
//! is reduced is left open (BBDL choose an edge next to a forbidden edge so that (iv)
//! never occurs; this reference takes the first simple edge of the smallest live node, so
//! (iv) does occur and is exercised; [`CoverTree`] picks tree-stable edges, where (iv)
//! occurs too; [`DiksStanczyk`] and [`BiedlBoseDemaineLubiw`] follow BBDL, with a rule
//! of their own for digons next to the forbidden edge). Recorded in `spec/ERRATA.md`
//! (T9–T14).

mod bbdl;
mod cover;
mod cycle;
mod ds;
mod graph;
mod shared;
mod spec;

pub use crate::dyngraph::{TwoEdge, TwoEdgeCounters};
pub use bbdl::{BbdlCounters, BiedlBoseDemaineLubiw};
pub use cover::{CoverCounters, CoverTree};
pub use ds::{DiksStanczyk, DsCounters};
pub use graph::{Candidate, Cubic, Reconnection, Reduction};

use super::Pairing;
use crate::core::{FaceId, Triangulation};
use cycle::CycleSearch;
use graph::{Dfs, NONE};

/// Why [`solve`] refused its input.
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
pub enum FrinkError {
    /// An edge names a node outside `0..n`.
    #[error("edge {edge} names node {node}, out of range")]
    NodeOutOfRange {
        /// The edge index.
        edge: usize,
        /// The node.
        node: u32,
    },
    /// A node's degree is not 3.
    #[error("node {node} does not have degree 3")]
    NotCubic {
        /// The node.
        node: u32,
    },
    /// The node or edge count does not fit the 32-bit ids, or the node count exceeds
    /// what the strategy's structures hold ([`Strategy::max_nodes`]).
    #[error("{0} nodes: too many for 32-bit ids or for the strategy (Strategy::max_nodes)")]
    TooLarge(usize),
    /// The graph is disconnected, has a bridge or a loop.
    #[error("the graph is not connected and bridgeless")]
    NotBridgeless,
    /// The strategy accepted neither reconnection (impossible on a connected bridgeless
    /// input: Frink's lemma).
    #[error("neither reconnection of the reduction at {u}{v} is connected and bridgeless")]
    NoReconnection {
        /// The reduced edge's ends.
        u: u32,
        /// See `u`.
        v: u32,
    },
    /// No simple edge at a node while more than two nodes are live, or the last two
    /// nodes are not a triple edge (impossible on a connected bridgeless input).
    #[error("no reduction edge at node {0}")]
    NoReductionEdge(u32),
    /// Case (iv) found no alternating cycle (impossible on a bridgeless graph).
    #[error("no alternating cycle through edge {0}")]
    NoAlternatingCycle(u32),
}

/// Chooses between the two reconnections of a reduction (Appendix A's `H1`, `H2`).
pub trait Strategy {
    /// The most nodes an input may have for this strategy: with at most that many,
    /// none of its structures can overflow an id or a count, or fail an assertion on
    /// one, during [`solve`] (which allocates at most `5n/2 − 2` edge ids on `n`
    /// nodes); with more, [`solve`] refuses the input ([`FrinkError::TooLarge`]) before
    /// [`Strategy::start`]. The default, no limit, is for strategies whose structures
    /// are sized by `n` only within the 32-bit ids [`Cubic::from_edges`] checks.
    fn max_nodes(&self) -> usize {
        usize::MAX
    }

    /// Called once before the first reduction, with the input graph.
    fn start(&mut self, g: &Cubic) {
        let _ = g;
    }

    /// The next reduction, if the strategy chooses it itself (Frink leaves the edge
    /// free); `None`: [`solve`]'s default, the first simple edge of the smallest live
    /// node ([`Cubic::candidate_at`]). Must be a valid reduction of `g` (e.g. from
    /// [`Cubic::candidate_for`]); [`Strategy::choose`] is then called with it.
    fn pick(&mut self, g: &Cubic) -> Option<Candidate> {
        let _ = g;
        None
    }

    /// A reconnection of the reduction `cand` of `g` whose result is connected and
    /// bridgeless, or `None` if neither is (impossible when `g` is connected and
    /// bridgeless). May apply reductions to `g` tentatively but must return it as it
    /// was (every [`Cubic::reduce`] undone by [`Cubic::undo`]).
    fn choose(&mut self, g: &mut Cubic, cand: &Candidate) -> Option<Reconnection>;

    /// Called after the reduction `r` has been applied to `g`. Usually `r` is the one
    /// [`Strategy::choose`] returned, but a caller may apply the other valid
    /// reconnection instead (a wrapper that overrules the choice): a strategy must then
    /// bring its own structures in line with `g` as it now is.
    fn applied(&mut self, g: &Cubic, r: &Reduction) {
        let _ = (g, r);
    }

    /// An edge of the base case (two nodes, three parallel edges) that its matched edge
    /// must avoid, or `None`. Lets a strategy keep one edge out of the final matching
    /// (Biedl–Bose–Demaine–Lubiw's forbidden edge, which [`DiksStanczyk`] moves along).
    fn forbidden(&self) -> Option<u32> {
        None
    }
}

/// The reference strategy: apply `H1`, test it by one iterative DFS lowpoint
/// computation (connected and no bridge), undo; if it fails, the same for `H2`.
/// O(n) per decision (one or two DFS of the current graph).
#[derive(Clone, Debug, Default)]
pub struct Naive {
    dfs: Dfs,
}

impl Naive {
    /// A fresh strategy.
    pub fn new() -> Self {
        Self::default()
    }

    /// DFS runs so far.
    pub fn dfs_runs(&self) -> u64 {
        self.dfs.runs
    }
}

impl Strategy for Naive {
    fn choose(&mut self, g: &mut Cubic, cand: &Candidate) -> Option<Reconnection> {
        naive_choice(&mut self.dfs, g, cand)
    }
}

/// The naive decision: the first of `H1`, `H2` that the DFS lowpoint test finds
/// connected and bridgeless, each applied tentatively and undone (`g` is left as it
/// was). O(n). [`Naive`]'s strategy, and [`CoverTree`]'s fallback.
fn naive_choice(dfs: &mut Dfs, g: &mut Cubic, cand: &Candidate) -> Option<Reconnection> {
    [Reconnection::H1, Reconnection::H2]
        .into_iter()
        .find(|&recon| {
            let r = g.reduce(cand, recon);
            let ok = dfs.connected_bridgeless(g, cand.x[0]);
            g.undo(&r);
            ok
        })
}

/// Counters of one run of [`solve`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Stats {
    /// Reductions applied (`n/2 − 1` for `n ≥ 2` nodes).
    pub reductions: usize,
    /// Reductions that took `H1` (the others took `H2`).
    pub took_h1: usize,
    /// Lifts that ended in case (i), (ii), (iii) of Appendix A (after the flip of case
    /// (iv), which ends in (i) or (iii)).
    pub cases: [usize; 3],
    /// Lifts in case (iv): both new edges matched, an alternating cycle flipped first.
    pub case_iv: usize,
    /// Total nodes on the cycles flipped in case (iv).
    pub cycle_nodes: usize,
    /// Blossoms shrunk by the searches of case (iv).
    pub blossoms: u64,
}

/// A perfect matching of a connected bridgeless cubic multigraph.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Solution {
    /// Per node (of the input graph) the id of its matched edge.
    pub mate: Vec<u32>,
    /// Counters.
    pub stats: Stats,
}

/// A perfect matching of `g` (per node its matched edge) if `g` is connected and
/// bridgeless, else an error (its size against [`Strategy::max_nodes`] first, then
/// connected and bridgeless by one DFS, O(n)); a step finding its
/// theorem violated (only a wrong strategy can cause it) is also an error. Time: n/2
/// reductions, each one `strategy` decision plus O(1), and n/2 lifts, each O(1) plus the
/// Edmonds search of case (iv), O(n·α(n)); with [`Naive`], O(n²) in all. Algorithm:
/// Appendix A, as the module documentation details.
pub fn solve<S: Strategy>(mut g: Cubic, strategy: &mut S) -> Result<Solution, FrinkError> {
    let n = g.node_capacity();
    let mut stats = Stats::default();
    if n == 0 {
        return Ok(Solution {
            mate: Vec::new(),
            stats,
        });
    }
    if n > strategy.max_nodes() {
        return Err(FrinkError::TooLarge(n));
    }
    if !Dfs::default().connected_bridgeless(&g, 0) {
        return Err(FrinkError::NotBridgeless);
    }
    strategy.start(&g);
    let mut records: Vec<Reduction> = Vec::with_capacity(n / 2);
    let mut cursor = 0u32;
    while g.node_count() > 2 {
        while !g.is_alive(cursor) {
            cursor += 1;
        }
        let cand = match strategy.pick(&g) {
            Some(c) => c,
            None => g
                .candidate_at(cursor)
                .ok_or(FrinkError::NoReductionEdge(cursor))?,
        };
        let recon = strategy
            .choose(&mut g, &cand)
            .ok_or(FrinkError::NoReconnection {
                u: cand.u,
                v: cand.v,
            })?;
        let r = g.reduce(&cand, recon);
        spec::after_reduction(&g, &r);
        debug_assert!(
            r.new.iter().all(|&e| g.ends(e)[0] != g.ends(e)[1]),
            "a loop in the chosen reduced graph"
        );
        strategy.applied(&g, &r);
        stats.reductions += 1;
        stats.took_h1 += usize::from(recon == Reconnection::H1);
        records.push(r);
    }
    // Base case: two nodes, three parallel edges.
    let mut mate = vec![NONE; n];
    let a = (cursor..n as u32)
        .find(|&x| g.is_alive(x))
        .ok_or(FrinkError::NoReductionEdge(cursor))?;
    let b = g.other(g.incident(a)[0], a);
    if b == a || g.incident(a).iter().any(|&f| g.other(f, a) != b) {
        return Err(FrinkError::NoReductionEdge(a));
    }
    let avoid = strategy.forbidden();
    let e = g
        .incident(a)
        .into_iter()
        .find(|&f| Some(f) != avoid)
        .ok_or(FrinkError::NoReductionEdge(a))?;
    mate[a as usize] = e;
    mate[b as usize] = e;
    let mut pairs = 1;
    let mut search = CycleSearch::default();
    while let Some(r) = records.pop() {
        let changed = lift(&mut g, &mut mate, &r, &mut search, &mut stats)?;
        pairs += 1;
        spec::after_lift(&g, &mate, pairs, &changed, &r);
    }
    stats.blossoms = search.blossoms;
    spec::at_end(&g, &mate, pairs);
    Ok(Solution { mate, stats })
}

/// Undoes the reduction `r` (the last one not yet undone) and lifts the perfect matching
/// `mate` of the reduced graph to one of the restored graph: cases (i)–(iv) of
/// Appendix A (module documentation). Returns the nodes whose mate changed. O(1), plus
/// the Edmonds search in case (iv).
fn lift(
    g: &mut Cubic,
    mate: &mut [u32],
    r: &Reduction,
    search: &mut CycleSearch,
    stats: &mut Stats,
) -> Result<Vec<u32>, FrinkError> {
    let c = &r.cand;
    let [p, q] = r.new;
    let [x1, x2] = [c.x[0], c.x[1]];
    let mut changed = Vec::new();
    if mate[x1 as usize] == p && mate[x2 as usize] == q {
        // Case (iv): flip an alternating cycle through p first.
        let cycle = search
            .flip_cycle_through(g, mate, p)
            .ok_or(FrinkError::NoAlternatingCycle(p))?;
        stats.case_iv += 1;
        stats.cycle_nodes += cycle.len();
        changed = cycle;
    }
    let pm = mate[x1 as usize] == p;
    let qm = mate[x2 as usize] == q;
    g.undo(r);
    let (case, [s, t, es, et]) = match (pm, qm) {
        (false, false) => (0, [c.u, c.v, c.e, c.e]),
        (true, false) => (1, [x1, r.y[0], c.a[0], r.bv[0]]),
        (false, true) => (2, [x2, r.y[1], c.a[1], r.bv[1]]),
        (true, true) => return Err(FrinkError::NoAlternatingCycle(p)),
    };
    stats.cases[case] += 1;
    if case == 0 {
        mate[c.u as usize] = c.e;
        mate[c.v as usize] = c.e;
    } else {
        // s–u and v–t replace the matched new edge s–t.
        mate[s as usize] = es;
        mate[c.u as usize] = es;
        mate[t as usize] = et;
        mate[c.v as usize] = et;
    }
    changed.extend([c.u, c.v, s, t]);
    Ok(changed)
}

/// The dual graph of `tri` as a [`Cubic`]: node `k` is the `k`-th live face in id order,
/// one edge per edge of `tri` ([`Triangulation::edges`] order). Returns the graph and
/// the face of each node. O(F).
pub fn dual_graph(tri: &Triangulation) -> Result<(Cubic, Vec<FaceId>), FrinkError> {
    let faces: Vec<FaceId> = tri.faces().collect();
    let mut node = vec![NONE; tri.face_capacity()];
    for (k, f) in faces.iter().enumerate() {
        node[f.index()] = k as u32;
    }
    let edges: Vec<[u32; 2]> = tri
        .edges()
        .map(|(_, _, c)| [node[c.face().index()], node[tri.opposite(c).face().index()]])
        .collect();
    Ok((Cubic::from_edges(faces.len(), &edges)?, faces))
}

/// A perfect pairing of the closed triangulation `tri` (capacity
/// `tri.face_capacity()`), in O(F²) time and O(F) memory: Frink's reduction with the
/// [`Naive`] strategy, the dual graph ([`dual_graph`]) matched by [`solve`].
/// Deterministic (module documentation).
///
/// # Errors
/// Only if `tri` broke its invariants (its dual graph is always cubic, connected and
/// bridgeless), or has 2^32 faces or more.
pub fn perfect_matching(tri: &Triangulation) -> Result<Pairing, FrinkError> {
    perfect_matching_with(tri, &mut Naive::new()).map(|(p, _)| p)
}

/// [`perfect_matching`] with any strategy, also returning the counters.
///
/// # Errors
/// As [`perfect_matching`]; [`FrinkError::TooLarge`] when the dual graph has more nodes
/// than `strategy` holds ([`Strategy::max_nodes`]); and any error of a run in which
/// `strategy` chose a reconnection that is not connected and bridgeless.
pub fn perfect_matching_with<S: Strategy>(
    tri: &Triangulation,
    strategy: &mut S,
) -> Result<(Pairing, Stats), FrinkError> {
    let (g, faces) = dual_graph(tri)?;
    let ends: Vec<[u32; 2]> = g.ends.clone();
    let sol = solve(g, strategy)?;
    let mut pairing = Pairing::new(tri.face_capacity());
    for (k, &m) in sol.mate.iter().enumerate() {
        let [a, b] = ends[m as usize];
        let other = if a as usize == k { b } else { a };
        if (k as u32) < other {
            pairing.pair(faces[k], faces[other as usize]);
        }
    }
    Ok((pairing, sol.stats))
}

#[cfg(test)]
mod tests;

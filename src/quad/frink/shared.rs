//! What the two forbidden-edge strategies, [`super::DiksStanczyk`] (module `ds`) and
//! [`super::BiedlBoseDemaineLubiw`] (module `bbdl`), do alike: the travelling forbidden
//! edge and the reduction next to it ([`ForbiddenEdge`]), the edges a reduction removes
//! ([`removed`]), the order in which they are deleted from a dynamic structure
//! ([`non_tree_first`]), and the breadth-first order in which the input graph is loaded
//! into one ([`bfs_edge_order`]). The rules themselves are explained, and proved, in
//! module `ds` ("The travelling forbidden edge").

use super::graph::NONE;
use super::{Candidate, Cubic, Reduction};
use std::collections::VecDeque;

/// The five edges the reduction `cand` removes, in this order: `uv`, `ux1`, `ux2`,
/// `vx3`, `vx4`.
pub(super) fn removed(cand: &Candidate) -> [u32; 5] {
    [cand.e, cand.a[0], cand.a[1], cand.b[0], cand.b[1]]
}

/// How many of the five edges `cand` removes are forest edges (`tree`): the cost by
/// which both strategies choose among the reductions next to the forbidden edge (a
/// forest edge's deletion may cost a replacement search or swap, a non-tree edge's is
/// one cheap update).
fn tree_edges_removed(cand: &Candidate, tree: impl Fn(u32) -> bool) -> usize {
    removed(cand).into_iter().filter(|&e| tree(e)).count()
}

/// `edges` reordered for deletion from a structure keeping a spanning forest: the
/// non-tree edges first, then the tree edges (`tree`), each group in its given order
/// (stable). Deleted after a tree edge, a non-tree edge could have become that edge's
/// replacement, to be cut (and replaced) again; deleted first it is one cheap update.
pub(super) fn non_tree_first<const N: usize>(
    edges: [u32; N],
    tree: impl Fn(u32) -> bool,
) -> [u32; N] {
    let is_tree = edges.map(&tree);
    let mut out = edges;
    let mut k = 0;
    for want in [false, true] {
        for (&e, &t) in edges.iter().zip(&is_tree) {
            if t == want {
                out[k] = e;
                k += 1;
            }
        }
    }
    out
}

/// The live edges of `g` as `[e, a, b]` (`ends(e) = [a, b]`), each non-loop edge exactly
/// once and no loop (a loop is never in a bridgeless input): first the edges of a
/// breadth-first forest, in the order the search takes them (from `root` if given, then
/// from every live node not yet reached, in id order; a node's edges in slot order), then
/// every other edge, in the order of its smaller end and then of its slot there. Inserted
/// in this order into a structure that keeps a spanning forest by first come, the forest
/// is that breadth-first forest (shallow, so that the pieces a reduction cuts off are
/// small). O(n).
pub(super) fn bfs_edge_order(g: &Cubic, root: Option<u32>) -> Vec<[u32; 3]> {
    let n = g.node_capacity();
    let mut seen = vec![false; n];
    let mut tree = vec![false; g.ends.len()];
    let mut edges = Vec::with_capacity(g.ends.len());
    let mut queue = VecDeque::new();
    for s in root.into_iter().chain(0..n as u32) {
        if !g.is_alive(s) || seen[s as usize] {
            continue;
        }
        seen[s as usize] = true;
        queue.push_back(s);
        while let Some(x) = queue.pop_front() {
            for e in g.incident(x) {
                let y = g.other(e, x);
                if !seen[y as usize] {
                    seen[y as usize] = true;
                    tree[e as usize] = true;
                    let [a, b] = g.ends(e);
                    edges.push([e, a, b]);
                    queue.push_back(y);
                }
            }
        }
    }
    for x in 0..n as u32 {
        if !g.is_alive(x) {
            continue;
        }
        for e in g.incident(x) {
            let [a, b] = g.ends(e);
            // Once, from its smaller end.
            if !tree[e as usize] && (a == x && a < b || b == x && b < a) {
                edges.push([e, a, b]);
            }
        }
    }
    edges
}

/// The travelling forbidden edge of Biedl–Bose–Demaine–Lubiw (module `ds`): which edge
/// it is, the reduction next to it, and what a step did to it. Guarantees, as long as a
/// reduction is found at every step (always on a connected bridgeless graph): every
/// reduction [`ForbiddenEdge::pick`] returns keeps the final matching off the edge, so
/// no lift meets case (iv) and [`ForbiddenEdge::get`] names an edge of the base case
/// to avoid.
#[derive(Clone, Copy, Debug)]
pub(super) struct ForbiddenEdge {
    /// The forbidden edge, or `NONE`.
    f: u32,
    /// Whether the pending reduction moves `f` on to its `p`.
    moves: bool,
    /// Steps at the third edge of a digon next to `f` (which stays).
    pub(super) digon_steps: u64,
    /// Steps that found no reduction next to `f` and dropped it.
    pub(super) restarts: u64,
}

impl Default for ForbiddenEdge {
    fn default() -> Self {
        ForbiddenEdge {
            f: NONE,
            moves: true,
            digon_steps: 0,
            restarts: 0,
        }
    }
}

impl ForbiddenEdge {
    /// The first forbidden edge of `g`: the first slot of its smallest live node (none
    /// if `g` has no live node); the counts at zero.
    pub(super) fn start(g: &Cubic) -> Self {
        let f = (0..g.node_capacity() as u32)
            .find(|&x| g.is_alive(x))
            .map_or(NONE, |x| g.incident(x)[0]);
        ForbiddenEdge {
            f,
            ..ForbiddenEdge::default()
        }
    }

    /// The forbidden edge, if one is kept.
    pub(super) fn get(&self) -> Option<u32> {
        (self.f != NONE).then_some(self.f)
    }

    /// The next reduction keeping the forbidden edge `f` out of the matching: among the
    /// edges next to `f` (at the ends of `f` in edge-end order, slot order at each; `f`
    /// made the candidate's `ux1`, so the reduction's `p` continues it) the first whose
    /// five removed edges hold the fewest forest edges (`tree`, the caller's structure);
    /// when neither end of `f` has one, at the third edge of a digon at an
    /// end of `f` (which then stays). If there is neither (never on a connected
    /// bridgeless graph), drops `f` and returns `None` (the caller's default reduction).
    /// Counts digon steps and restarts; [`ForbiddenEdge::applied`] then moves `f`.
    pub(super) fn pick(&mut self, g: &Cubic, tree: impl Fn(u32) -> bool) -> Option<Candidate> {
        self.moves = true;
        if self.f != NONE {
            if let Some((c, moves)) = self.next_to_forbidden(g, tree) {
                self.moves = moves;
                self.digon_steps += u64::from(!moves);
                return Some(c);
            }
        }
        // Kept so that a broken invariant costs a case (iv) search, not a wrong matching.
        self.restarts += 1;
        self.f = NONE;
        None
    }

    /// After the reduction `r` picked by [`ForbiddenEdge::pick`] was applied: `f` moves
    /// on to `r`'s `p`, unless the step was a digon step.
    pub(super) fn applied(&mut self, r: &Reduction) {
        if self.moves {
            self.f = r.new[0];
        }
    }

    /// [`ForbiddenEdge::pick`]'s search, with whether `f` moves on to `p`.
    fn next_to_forbidden(
        &self,
        g: &Cubic,
        tree: impl Fn(u32) -> bool,
    ) -> Option<(Candidate, bool)> {
        let f = self.f;
        let ends = g.ends(f);
        let mut best: Option<(usize, Candidate)> = None;
        for u in ends {
            for e in g.incident(u) {
                if e == f {
                    continue;
                }
                let Some(mut c) = g.candidate_for(u, e) else {
                    continue;
                };
                if c.a[1] == f {
                    c.a.swap(0, 1);
                    c.x.swap(0, 1);
                }
                debug_assert_eq!(c.a[0], f);
                let cost = tree_edges_removed(&c, &tree);
                if best.is_none_or(|(b, _)| cost < b) {
                    best = Some((cost, c));
                }
            }
        }
        if let Some((_, c)) = best {
            return Some((c, true));
        }
        ends.into_iter().find_map(|x| {
            let (h, w) = digon_exit(g, f, x)?;
            g.candidate_for(w, h).map(|c| (c, false))
        })
    }
}

/// If `x` (an end of `f`) has its two other edges on a digon `x ⇉ w` (`w` not `f`'s other
/// end), the third edge `h` of `w`, and `w`.
fn digon_exit(g: &Cubic, f: u32, x: u32) -> Option<(u32, u32)> {
    let s = g.incident(x);
    let i = s.iter().position(|&e| e == f)?;
    let (r0, r1) = (s[(i + 1) % 3], s[(i + 2) % 3]);
    let w = g.other(r0, x);
    if w != g.other(r1, x) || w == x || w == g.other(f, x) {
        return None;
    }
    let h = g.incident(w).into_iter().find(|&e| e != r0 && e != r1)?;
    Some((h, w))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The fallback for a broken invariant (a connected bridgeless graph always has a
    /// reduction next to the forbidden edge): on the theta graph, where no reduction
    /// exists, the edge is dropped and every such step counted.
    #[test]
    fn without_a_reduction_next_to_it_the_forbidden_edge_is_dropped_and_counted() {
        let g = Cubic::from_edges(2, &[[0, 1], [0, 1], [0, 1]]).expect("cubic");
        let mut fe = ForbiddenEdge::start(&g);
        assert_eq!(fe.get(), Some(g.incident(0)[0]));
        assert!(fe.pick(&g, |_| false).is_none());
        assert_eq!((fe.get(), fe.restarts, fe.digon_steps), (None, 1, 0));
        assert!(fe.pick(&g, |_| false).is_none());
        assert_eq!((fe.get(), fe.restarts, fe.digon_steps), (None, 2, 0));
    }

    #[test]
    fn non_tree_first_is_a_stable_partition() {
        let order = non_tree_first([5, 1, 4, 2, 3], |e| e % 2 == 1);
        assert_eq!(order, [4, 2, 5, 1, 3]);
        assert_eq!(non_tree_first([7, 8], |_| true), [7, 8]);
        assert_eq!(non_tree_first([7, 8], |e| e == 7), [8, 7]);
    }
}
